#include "sim/host/simhost.h"

#include "sim/host/simworker.h"
#include "sim/model/simdevice.h"
#include "sim/serve/simresponder.h"

#include <QElapsedTimer>
#include <QMutexLocker>
#include <QThread>
#include <QTimer>

#include <algorithm>

namespace stepcom {

SimHost::SimHost(QObject *parent)
    : QObject(parent)
{}

SimHost::~SimHost()
{
    stop();
}

std::unique_ptr<SimDevice> SimHost::makeDevice(const SimOptions &options, int id,
                                               const QString &statePath, QString *error)
{
    auto device = std::make_unique<SimDevice>(options.map);
    SimDevice &d = *device;
    for (int n = 1; n <= d.motorCount(); ++n) {
        d.setTravel(n, options.travel);
        d.setMachinePosition(n, options.startPosition);
    }
    if (options.machine) {
        for (auto it = options.machine->axes.begin(); it != options.machine->axes.end(); ++it) {
            if (it.key() > d.motorCount()) {
                if (error)
                    *error = tr("%1: axes.motor%2: the register map has %3 motors")
                                 .arg(options.machine->source)
                                 .arg(it.key())
                                 .arg(d.motorCount());
                return nullptr;
            }
        }
        d.setMachine(*options.machine);
        for (int n = 1; n <= d.motorCount(); ++n) {
            // A shorter travel without a start: a quarter of it, as --travel does.
            const AxisPhysics p = options.machine->axis(n);
            if (p.travelMm && !p.startMm)
                d.setMachinePosition(n, std::min(options.startPosition, *p.travelMm / 4));
        }
    }
    d.setStatePath(statePath);
    d.setStrictReads(options.strictReads);
    QSet<QString> lacking;
    for (const QString &name : options.lacks) {
        bool isNumber = false;
        const int plc = name.toInt(&isNumber);
        const Parameter *p = isNumber && plc > 40000 && plc <= 40000 + 0x10000
                                 ? d.map().holdingAt(quint16(plc - 40001))
                                 : d.map().find(name);
        if (!p || !p->isHolding()) {
            if (error)
                *error = tr("--lacks: %1 is no listed register of the map").arg(name);
            return nullptr;
        }
        lacking.insert(p->key);
    }
    d.setLacking(lacking);
    QString loadError;
    if (!d.loadState(&loadError)) {
        if (error)
            *error = loadError;
        return nullptr;
    }
    if (!loadError.isEmpty())
        Q_EMIT message(loadError); // some saved values were not taken
    // Its flash holds the id it was given, so a power cycle keeps it.
    if (id != 0 && !d.setSavedValue(QStringLiteral("device.id"), id, error))
        return nullptr;
    for (const auto &[input, force] : options.inputs)
        d.setInput(input, force);
    if (!options.manualClock) {
        QElapsedTimer clock;
        clock.start();
        d.setClock([clock] { return clock.elapsed(); });
    }
    return device;
}

QList<SimDevice *> SimHost::devices() const
{
    QList<SimDevice *> list;
    for (const auto &d : m_devices)
        list.append(d.get());
    return list;
}

SimDevice *SimHost::deviceAt(int id) const
{
    for (const auto &d : m_devices)
        if (d->deviceId() == id)
            return d.get();
    return nullptr;
}

bool SimHost::start(const SimOptions &options, QString *error)
{
    stop();
    m_options = options;
    m_devices.clear();
    const QList<int> ids = options.ids.isEmpty() ? QList<int>{options.deviceId} : options.ids;
    for (qsizetype i = 0; i < ids.size(); ++i) {
        QString statePath = options.statePath;
        if (i > 0 && !statePath.isEmpty())
            statePath += QStringLiteral("-%1").arg(i + 1);
        auto device = makeDevice(options, ids.at(i), statePath, error);
        if (!device)
            return false;
        m_devices.push_back(std::move(device));
    }

    m_thread = new QThread(this);
    m_thread->setObjectName(QStringLiteral("stepcom-sim"));
    m_worker = new SimWorker(devices(), options);
    m_worker->onPtyPath = [this](const QString &path) {
        QMutexLocker lock(&m_pathMutex);
        m_ptyPath = path;
    };
    m_worker->moveToThread(m_thread);
    connect(m_worker, &SimWorker::hungUp, this, &SimHost::hungUp);
    connect(m_worker, &SimWorker::reopened, this, &SimHost::reopened);
    connect(m_worker, &SimWorker::message, this, &SimHost::message);
    m_thread->start();
    bool ok = false;
    QString openError;
    QMetaObject::invokeMethod(
        m_worker, [&] { ok = m_worker->open(&openError); }, Qt::BlockingQueuedConnection);
    if (!ok) {
        stop();
        if (error)
            *error = openError;
        return false;
    }
    m_tcpPort = m_worker->tcpPort();
    m_rtuTcpPort = m_worker->rtuTcpPort();
    schedulePowerCycles();
    return true;
}

void SimHost::schedulePowerCycles()
{
    m_schedule = new QObject(this);
    for (const auto &[atMs, offMs] : std::as_const(m_options.powerCycles)) {
        const QString seconds = QString::number(offMs / 1000.0);
        QTimer::singleShot(atMs, m_schedule, [this, offMs, seconds] {
            powerCycle(offMs);
            Q_EMIT message(tr("power cycle: 24 V off for %1 s").arg(seconds));
        });
        // The device's own clock decides when power returns; with a manual one no time is known.
        if (!m_options.manualClock)
            QTimer::singleShot(atMs + offMs, m_schedule,
                               [this] { Q_EMIT message(tr("power cycle: 24 V back on")); });
    }
}

bool SimHost::powerCycle(int offMs, int id)
{
    bool found = false;
    for (const auto &d : m_devices) {
        if (id == 0 || d->deviceId() == id) {
            d->powerCycle(offMs);
            found = true;
        }
    }
    return found;
}

void SimHost::stop()
{
    delete m_schedule; // pending power cycles are cancelled with it
    m_schedule = nullptr;
    if (!m_thread)
        return;
    QMetaObject::invokeMethod(
        m_worker, [this] { m_worker->close(); }, Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
    delete m_worker; // its thread has finished: safe to delete from here
    m_worker = nullptr;
    delete m_thread;
    m_thread = nullptr;
    m_tcpPort = 0;
    m_rtuTcpPort = 0;
    QMutexLocker lock(&m_pathMutex);
    m_ptyPath.clear();
}

QString SimHost::ptyPath() const
{
    QMutexLocker lock(&m_pathMutex);
    return m_ptyPath;
}

QString SimHost::rtuPath() const
{
    QMutexLocker lock(&m_pathMutex);
    if (m_ptyPath.isEmpty())
        return {};
    return m_options.linkPath.isEmpty() ? m_ptyPath : m_options.linkPath;
}

void SimHost::hangUp(int pauseMs)
{
    if (m_worker)
        QMetaObject::invokeMethod(m_worker, [w = m_worker, pauseMs] { w->hangUp(pauseMs); });
}

SimHost::Stats SimHost::stats() const
{
    Stats s;
    if (!m_worker)
        return s;
    SimResponder::Counters &c = m_worker->responder()->counters();
    s.requests = c.requests;
    s.answers = c.answers;
    s.exceptions = c.exceptions;
    s.dropped = c.dropped;
    s.corrupted = c.corrupted;
    s.late = c.late;
    s.wrongBaud = c.wrongBaud;
    s.collisions = c.collisions;
    return s;
}

} // namespace stepcom

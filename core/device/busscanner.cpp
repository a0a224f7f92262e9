#include "device/busscanner.h"

#include "bus/modbuslink.h"
#include "map/registermap.h"

#include <QCoreApplication>

namespace stepcom {

BusScanner::BusScanner(QObject *parent)
    : QObject(parent)
    , m_map(&RegisterMap::builtin())
{}

QString BusScanner::Found::summary() const
{
    return QCoreApplication::translate("stepcom::BusScanner", "id %1 at %2 — %3")
        .arg(deviceId)
        .arg(where, detail);
}

QString BusScanner::where(const LinkSettings &settings)
{
    if (settings.transport == LinkSettings::Transport::Tcp)
        return QStringLiteral("%1:%2").arg(settings.host).arg(settings.tcpPort);
    const QChar parity = settings.parity == QSerialPort::EvenParity  ? QLatin1Char('E')
                         : settings.parity == QSerialPort::OddParity ? QLatin1Char('O')
                                                                     : QLatin1Char('N');
    return QStringLiteral("%1 8%2%3")
        .arg(settings.baud)
        .arg(parity)
        .arg(settings.stopBits == QSerialPort::TwoStop ? 2 : 1);
}

QString BusScanner::describe(const Found &found, const RegisterMap &map)
{
    if (found.exceptionCode != 0)
        return tr("a device that refused the first register: %1")
            .arg(exceptionText(found.exceptionCode));
    const Parameter *angle =
        map.blockParameter(QStringLiteral("motor"), 1, QStringLiteral("step_angle"));
    QStringList angles;
    for (const qint64 raw : found.stepAngles)
        angles << (angle ? angle->displayRaw(raw).remove(QLatin1Char(' ')) : QString::number(raw));
    angles.removeDuplicates();
    const int motors = int(found.stepAngles.size());
    // Only as many axes as the device answered for: never more than it showed.
    const QString what = motors >= 2 && motors == found.motorsInMap
                             ? tr("a %1-axis controller").arg(motors)
                             : tr("a controller");
    if (angles.isEmpty())
        return what;
    QString text = angles.size() == 1
                       ? tr("%1, step angle %2").arg(what, angles.first())
                       : tr("%1, step angles %2").arg(what, angles.join(tr(" and ")));
    if (motors < found.motorsInMap && found.motorsInMap > 1)
        text += tr(" (only %1 of %2 motors answered)").arg(motors).arg(found.motorsInMap);
    return text;
}

BusScanner::~BusScanner()
{
    delete m_link;
}

void BusScanner::start(const LinkSettings &base, const QList<int> &bauds, int firstId, int lastId,
                       int probeTimeoutMs, bool stopAtFirst)
{
    cancel();
    m_base = base;
    m_bauds = base.transport == LinkSettings::Transport::Tcp ? QList<int>{base.baud} : bauds;
    m_firstId = std::clamp(firstId, 1, 255);
    m_lastId = std::clamp(lastId, m_firstId, 255);
    m_timeoutMs = std::max(20, probeTimeoutMs);
    m_stopAtFirst = stopAtFirst;
    m_found.clear();
    m_done = 0;
    m_total = int(m_bauds.size()) * (m_lastId - m_firstId + 1);
    m_baudIndex = -1;
    m_running = true;
    if (m_bauds.isEmpty()) {
        finish(false, tr("no baud rate to try"));
        return;
    }
    openNextBaud();
}

void BusScanner::cancel()
{
    if (!m_running)
        return;
    finish(true, QString());
}

void BusScanner::finish(bool cancelled, const QString &error)
{
    m_running = false;
    if (m_link) {
        m_link->disconnect(this);
        m_link->close(tr("scan finished"));
        m_link->deleteLater();
        m_link = nullptr;
    }
    Q_EMIT finished(cancelled, error);
}

void BusScanner::openNextBaud()
{
    if (!m_running)
        return;
    if (++m_baudIndex >= m_bauds.size()) {
        finish(false, QString());
        return;
    }
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
        m_link->deleteLater();
    }
    m_link = new ModbusLink(this);
    LinkSettings s = m_base;
    s.baud = m_bauds.at(m_baudIndex);
    s.timeoutMs = m_timeoutMs;
    s.retries = 0;
    s.deviceId = m_firstId;
    m_link->setQuietTimeMs(std::min(50, m_timeoutMs));
    connect(m_link, &ModbusLink::opened, this, [this](bool ok, const QString &reason) {
        if (!ok) {
            finish(false, reason);
            return;
        }
        m_id = m_firstId;
        probeNext();
    });
    m_link->open(s);
}

void BusScanner::probeNext()
{
    if (!m_running)
        return;
    if (m_id > m_lastId) {
        openNextBaud();
        return;
    }
    const int id = m_id++;
    const int baud = m_bauds.at(m_baudIndex);
    m_link->setDeviceId(id);
    Request probe = Request::read(0, 1, Priority::Read);
    probe.retryable = false;
    probe.what = tr("scan id %1 at %2 baud").arg(id).arg(baud);
    m_link->submit(
        probe,
        [this, id, baud](const Result &r) {
            if (!m_running)
                return;
            ++m_done;
            Q_EMIT progress(m_done, m_total, baud, id);
            if (r.ok || r.exceptionCode != 0) {
                Found f;
                f.baud = baud;
                f.deviceId = id;
                LinkSettings s = m_base;
                s.baud = baud;
                f.where = where(s);
                f.exceptionCode = r.ok ? 0 : r.exceptionCode;
                f.motorsInMap = m_map ? m_map->blockCount(QStringLiteral("motor")) : 0;
                if (r.ok)
                    f.stepAngles << r.values.value(0); // 40001 is motor 1's step angle
                if (r.ok && f.motorsInMap > 1) {
                    identify(f);
                    return;
                }
                report(f);
                return;
            }
            probeNext();
        },
        this);
}

void BusScanner::identify(Found found)
{
    // One read from 40001 to the last motor's step angle: a 2-axis controller answers both.
    const Parameter *last = m_map->blockParameter(QStringLiteral("motor"), found.motorsInMap,
                                                  QStringLiteral("step_angle"));
    if (!last) {
        report(found);
        return;
    }
    Request read = Request::read(0, quint16(last->address + 1), Priority::Read);
    read.retryable = false;
    read.what = tr("identify id %1").arg(found.deviceId);
    m_link->submit(
        read,
        [this, found](const Result &r) mutable {
            if (!m_running)
                return;
            if (r.ok) {
                found.stepAngles.clear();
                for (int n = 1; n <= found.motorsInMap; ++n) {
                    const Parameter *p = m_map->blockParameter(QStringLiteral("motor"), n,
                                                               QStringLiteral("step_angle"));
                    if (p && p->address < r.values.size())
                        found.stepAngles << r.values.at(p->address);
                }
            }
            report(found);
        },
        this);
}

void BusScanner::report(Found found)
{
    found.detail = describe(found, m_map ? *m_map : RegisterMap::builtin());
    m_found << found;
    Q_EMIT foundDevice(found);
    if (m_stopAtFirst) {
        finish(false, QString());
        return;
    }
    probeNext();
}

} // namespace stepcom

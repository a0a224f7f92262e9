#include "session/reconnector.h"

#include <QFileInfo>

#include <algorithm>

namespace stepcom {

namespace {

// Whether `port` (as typed or saved: "ttyUSB0", "/dev/ttyUSB0" or a by-id link) is this entry.
bool names(const SerialPortEntry &e, const QString &port)
{
    if (port.isEmpty())
        return false;
    if (port == e.portName || port == e.systemLocation || (!e.byId.isEmpty() && port == e.byId))
        return true;
    const QString canonical = QFileInfo(port).canonicalFilePath();
    return !canonical.isEmpty() && canonical == QFileInfo(e.systemLocation).canonicalFilePath();
}

// The same adapter, whatever ttyUSB name it has now.
bool sameAdapter(const SerialPortEntry &a, const SerialPortEntry &b)
{
    if (!a.byId.isEmpty() && a.byId == b.byId)
        return true;
    return !a.serialNumber.isEmpty() && a.serialNumber == b.serialNumber &&
           a.vendorId == b.vendorId && a.productId == b.productId;
}

} // namespace

Reconnector::Reconnector(QObject *parent)
    : QObject(parent)
    , m_lister(&SerialPorts::systemPorts)
    , m_byIdDirectory(QStringLiteral("/dev/serial/by-id"))
{
    m_wait.setSingleShot(true);
    connect(&m_wait, &QTimer::timeout, this, &Reconnector::fire);
    m_tick.setInterval(1000);
    connect(&m_tick, &QTimer::timeout, this, [this] { Q_EMIT countdown(secondsLeft()); });
}

void Reconnector::setEnabled(bool enabled)
{
    m_enabled = enabled;
    if (!enabled)
        stop();
}

void Reconnector::setDelaysMs(const QList<int> &delays)
{
    if (!delays.isEmpty())
        m_delays = delays;
}

void Reconnector::setPortLister(SerialPorts::Lister lister)
{
    m_lister = std::move(lister);
}

void Reconnector::setByIdDirectory(const QString &directory)
{
    m_byIdDirectory = directory;
}

int Reconnector::secondsLeft() const
{
    if (m_state != State::Waiting)
        return 0;
    const qint64 left = std::max<qint64>(0, m_waitMs - m_waitClock.elapsed());
    return int((left + 999) / 1000);
}

QList<SerialPortEntry> Reconnector::listPorts() const
{
    SerialPorts ports;
    ports.setLister(m_lister);
    ports.setByIdDirectory(m_byIdDirectory);
    return ports.scan();
}

void Reconnector::linkOpened(const LinkSettings &settings)
{
    m_settings = settings;
    m_adapter = {};
    if (settings.transport != LinkSettings::Transport::Rtu)
        return;
    for (const SerialPortEntry &e : listPorts()) {
        if (names(e, settings.portName)) {
            m_adapter = e;
            break;
        }
    }
}

void Reconnector::linkLost(const LinkSettings &settings, const QString &reason)
{
    if (!m_enabled)
        return;
    m_settings = settings;
    m_attempt = 0;
    m_lastError = reason;
    arm();
}

LinkSettings Reconnector::locate() const
{
    LinkSettings s = m_settings;
    const bool known = !m_adapter.byId.isEmpty() || !m_adapter.serialNumber.isEmpty();
    if (s.transport != LinkSettings::Transport::Rtu || !known)
        return s;
    const QList<SerialPortEntry> ports = listPorts();
    for (const SerialPortEntry &e : ports) {
        if (names(e, s.portName) && sameAdapter(e, m_adapter))
            return s; // back under its old name
    }
    for (const SerialPortEntry &e : ports) {
        if (sameAdapter(e, m_adapter)) {
            s.portName = e.path();
            return s;
        }
    }
    return s; // not listed (yet): try the old name, the next attempt lists again
}

void Reconnector::setState(State state)
{
    if (state == m_state)
        return;
    m_state = state;
    Q_EMIT stateChanged(state);
}

void Reconnector::arm()
{
    const int delay = m_delays.at(std::min<qsizetype>(m_attempt, m_delays.size() - 1));
    m_waitMs = delay;
    m_waitClock.start();
    m_wait.start(delay);
    m_tick.start();
    setState(State::Waiting);
    Q_EMIT countdown(secondsLeft());
}

void Reconnector::fire()
{
    m_tick.stop();
    ++m_attempt;
    setState(State::Attempting);
    Q_EMIT reopen(locate());
}

void Reconnector::retryNow()
{
    if (m_state != State::Waiting)
        return;
    m_wait.stop();
    fire();
}

void Reconnector::attemptFinished(bool ok, const QString &reason)
{
    if (m_state != State::Attempting)
        return;
    if (!ok) {
        m_lastError = reason;
        arm();
        return;
    }
    setState(State::Idle);
    Q_EMIT restored(m_settings, m_attempt);
}

void Reconnector::cancel()
{
    if (m_state == State::Idle)
        return;
    stop();
    Q_EMIT cancelled();
}

void Reconnector::stop()
{
    m_wait.stop();
    m_tick.stop();
    setState(State::Idle);
}

} // namespace stepcom

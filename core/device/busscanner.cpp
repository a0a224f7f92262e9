#include "device/busscanner.h"

#include "bus/modbuslink.h"

namespace stepcom {

BusScanner::BusScanner(QObject *parent)
    : QObject(parent)
{}

BusScanner::~BusScanner()
{
    delete m_link;
}

void BusScanner::start(const LinkSettings &base, const QList<int> &bauds, int firstId, int lastId,
                       int probeTimeoutMs, bool stopAtFirst)
{
    cancel();
    m_base = base;
    m_bauds = base.isNetwork() ? QList<int>{base.baud} : bauds;
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
                Found f{
                    baud, id,
                    r.ok
                        ? tr("answered (register 40001 = %1)").arg(r.values.value(0))
                        : tr("answered with an exception: %1").arg(exceptionText(r.exceptionCode))};
                m_found << f;
                Q_EMIT foundDevice(f);
                if (m_stopAtFirst) {
                    finish(false, QString());
                    return;
                }
            }
            probeNext();
        },
        this);
}

} // namespace stepcom

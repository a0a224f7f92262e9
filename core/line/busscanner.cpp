#include "line/busscanner.h"

#include "bus/modbuslink.h"
#include "map/registermap.h"

#include <QCoreApplication>
#include <QPointer>
#include <QTimer>

#include <cmath>

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
    if (settings.isNetwork()) // the converter's baud is its own, not ours to name
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

int BusScanner::fittedProbeTimeoutMs(const LinkSettings &line)
{
    // Request: id, 03, address, count, CRC = 8 bytes; the longest answer to a one-register
    // read: id, 03, byte count, 2 bytes, CRC = 7 bytes (an exception answer is 5).
    const int bits = 1 + 8 + (line.parity == QSerialPort::NoParity ? 0 : 1) +
                     (line.stopBits == QSerialPort::TwoStop ? 2 : 1);
    const double charMs = line.baud > 0 ? 1000.0 * bits / line.baud : 0.0;
    const double wire = (8 + 7) * charMs + line.answerDelayMs;
    return int(std::ceil(wire)) + (line.isNetwork() ? kNetworkMarginMs : kUsbMarginMs);
}

int BusScanner::probeTimeoutMs(const LinkSettings &line, int askedMs)
{
    return std::max(askedMs, fittedProbeTimeoutMs(line));
}

int BusScanner::suggestedTimeoutMs(qint64 answerMs)
{
    const qint64 ms = qint64(std::ceil(double(answerMs) * 1.5 / 50.0)) * 50;
    return int(std::max<qint64>(LinkSettings().timeoutMs, ms));
}

int BusScanner::lateListenMs(int probeTimeoutMs, qint64 slowestAnswerMs)
{
    const qint64 slow = slowestAnswerMs > 0 ? qint64(std::ceil(1.5 * double(slowestAnswerMs))) : 0;
    return int(std::max<qint64>(2 * qint64(probeTimeoutMs), slow));
}

QList<LinkSettings> BusScanner::lines(const Plan &plan)
{
    if (plan.base.isNetwork())
        return {plan.base};
    const QList<QSerialPort::Parity> parities =
        plan.parities.isEmpty() ? QList<QSerialPort::Parity>{plan.base.parity} : plan.parities;
    QList<LinkSettings> out;
    for (const int baud : plan.bauds) {
        for (const QSerialPort::Parity parity : parities) {
            LinkSettings s = plan.base;
            s.baud = baud;
            s.parity = parity;
            out << s;
        }
    }
    return out;
}

qint64 BusScanner::worstCaseMs(const Plan &plan)
{
    qint64 ms = 0;
    for (const LinkSettings &line : lines(plan)) {
        // Opening waits for a quiet line; each probe is the request's frame and the timeout;
        // then the last probes' late answers are listened for (nobody answering: none seen).
        ms += kOpenQuietMs;
        const int timeoutMs = probeTimeoutMs(line, plan.probeTimeoutMs);
        ms += lateListenMs(timeoutMs, -1) - timeoutMs;
        const double frameMs = line.isNetwork() ? 0.0 : 8 * line.charTimeMs();
        ms += qint64(plan.ids.size()) * qint64(std::ceil(frameMs + timeoutMs));
    }
    return ms;
}

void BusScanner::start(const LinkSettings &base, const QList<int> &bauds, int firstId, int lastId,
                       int probeTimeoutMs, bool stopAtFirst)
{
    Plan plan;
    plan.base = base;
    plan.bauds = bauds;
    for (int id = std::clamp(firstId, 1, 255); id <= std::clamp(lastId, 1, 255); ++id)
        plan.ids << id;
    plan.probeTimeoutMs = probeTimeoutMs;
    plan.stopAtFirst = stopAtFirst;
    start(plan);
}

void BusScanner::start(const Plan &plan)
{
    cancel();
    m_plan = plan;
    m_lines = lines(plan);
    m_found.clear();
    m_late.clear();
    m_slowestMs = -1;
    m_done = 0;
    m_total = int(m_lines.size() * plan.ids.size());
    m_lineIndex = -1;
    m_running = true;
    m_clock.start();
    if (m_lines.isEmpty()) {
        finish(false, tr("no baud rate to try"));
        return;
    }
    if (plan.ids.isEmpty()) {
        finish(false, tr("no device id to try"));
        return;
    }
    openNextLine();
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

void BusScanner::openNextLine()
{
    if (!m_running)
        return;
    if (++m_lineIndex >= m_lines.size()) {
        finish(false, QString());
        return;
    }
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
        m_link->deleteLater();
    }
    m_link = new ModbusLink(this);
    LinkSettings s = m_lines.at(m_lineIndex);
    m_timeoutMs = probeTimeoutMs(s, m_plan.probeTimeoutMs);
    s.timeoutMs = m_timeoutMs;
    s.retries = 0;
    s.deviceId = m_plan.ids.first();
    m_probedAt.clear();
    m_waitedForLate = false;
    // Quiet only after bytes arrived (a late or garbled answer); a silent probe leaves none.
    m_link->setQuietTimeMs(kOpenQuietMs);
    m_link->setScanMode(true);
    connect(m_link, &ModbusLink::unitAnswered, this, &BusScanner::onLateAnswer);
    connect(m_link, &ModbusLink::opened, this, [this, s](bool ok, const QString &reason) {
        if (!ok) {
            finish(false, reason);
            return;
        }
        m_idIndex = 0;
        Q_EMIT lineStarted(where(s), m_timeoutMs);
        probeNext();
    });
    m_link->open(s);
}

BusScanner::Found BusScanner::foundAt(int id, int exceptionCode, const QList<quint16> &values,
                                      qint64 answerMs) const
{
    const LinkSettings &line = m_lines.at(m_lineIndex);
    Found f;
    f.baud = line.baud;
    f.parity = line.parity;
    f.deviceId = id;
    f.where = where(line);
    f.exceptionCode = exceptionCode;
    f.answerMs = answerMs;
    f.late = answerMs > m_timeoutMs;
    f.motorsInMap = m_map ? m_map->blockCount(QStringLiteral("motor")) : 0;
    if (exceptionCode == 0 && !values.isEmpty())
        f.stepAngles << values.first(); // 40001 is motor 1's step angle
    return f;
}

void BusScanner::onLateAnswer(int unit, int exceptionCode, const QList<quint16> &values)
{
    // Only an id this line has probed and that has not been found here yet: anything else
    // is no answer to a probe of ours (an identifying read's answer has many registers).
    if (!m_running || !m_probedAt.contains(unit) || (exceptionCode == 0 && values.size() != 1))
        return;
    const qint64 answerMs = m_clock.elapsed() - m_probedAt.take(unit);
    m_slowestMs = std::max(m_slowestMs, answerMs);
    m_late << foundAt(unit, exceptionCode, values, answerMs);
}

void BusScanner::probeNext()
{
    if (!m_running)
        return;
    if (!m_late.isEmpty()) {
        Found f = m_late.takeFirst();
        if (f.exceptionCode == 0 && f.motorsInMap > 1)
            identify(f);
        else
            report(f);
        return;
    }
    if (m_idIndex >= m_plan.ids.size()) {
        // The last probes' late answers may still come: listen for them as long as the probe
        // timeout or the slowest controller seen says (every answer frame names its id, so a
        // late one is found while this wait runs).
        if (!m_probedAt.isEmpty() && m_link && !m_waitedForLate) {
            m_waitedForLate = true;
            const qint64 sinceLastMs = m_clock.elapsed() - m_lastProbeAtMs;
            const int waitMs =
                int(std::max<qint64>(0, lateListenMs(m_timeoutMs, m_slowestMs) - sinceLastMs));
            QTimer::singleShot(waitMs, this, [this, link = QPointer<ModbusLink>(m_link)] {
                if (m_link == link)
                    probeNext();
            });
            return;
        }
        m_waitedForLate = false;
        openNextLine();
        return;
    }
    const int id = m_plan.ids.at(m_idIndex++);
    const int baud = m_lines.at(m_lineIndex).baud;
    Request probe = Request::read(0, 1, Priority::Read);
    probe.retryable = false;
    probe.unitId = id;
    probe.timeoutMs = m_timeoutMs;
    probe.what = tr("scan id %1 at %2").arg(id).arg(where(m_lines.at(m_lineIndex)));
    m_probedAt.insert(id, m_clock.elapsed());
    m_lastProbeAtMs = m_clock.elapsed();
    m_link->submit(
        probe,
        [this, id, baud](const Result &r) {
            if (!m_running)
                return;
            ++m_done;
            Q_EMIT progress(m_done, m_total, baud, id);
            if ((r.ok || r.exceptionCode != 0) && m_probedAt.contains(id)) {
                const qint64 answerMs = m_clock.elapsed() - m_probedAt.take(id);
                Found f = foundAt(id, r.ok ? 0 : r.exceptionCode, r.values, answerMs);
                f.answerMs = r.roundTripMs >= 0 ? r.roundTripMs : answerMs;
                f.late = false;
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
    read.unitId = found.deviceId;
    // It answers after its own delay (a late answer said how long) and sends more bytes.
    const LinkSettings &line = m_lines.at(m_lineIndex);
    read.timeoutMs = int(std::max<qint64>(
        {qint64(m_timeoutMs), 2 * found.answerMs,
         qint64(line.timeoutMs) + qint64(std::ceil(2 * read.count * line.charTimeMs()))}));
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
    if (m_plan.stopAtFirst) {
        finish(false, QString());
        return;
    }
    probeNext();
}

} // namespace stepcom

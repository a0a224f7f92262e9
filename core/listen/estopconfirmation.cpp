#include "listen/estopconfirmation.h"

#include "bus/rtuframe.h"
#include "listen/listendecoder.h"
#include "map/registermap.h"

#include <algorithm>

namespace stepcom {

namespace {

// The running registers are read in one request; a map that scatters them is not read back.
constexpr int kMaxReadSpan = 16;

} // namespace

EstopConfirmation::EstopConfirmation(const RegisterMap &map, int unit, bool echo)
    : m_stop(stopFrameFor(map, unit))
    , m_unit(unit)
    , m_echo(echo)
{
    const QString motor = QStringLiteral("motor");
    for (int n = 1; n <= map.blockCount(motor); ++n) {
        const Parameter *running = map.blockParameter(motor, n, QStringLiteral("running"));
        if (!running) {
            m_running.clear();
            break;
        }
        m_running << running->address;
    }
    if (m_running.isEmpty())
        return;
    const auto [low, high] = std::minmax_element(m_running.cbegin(), m_running.cend());
    const int span = *high - *low + 1;
    if (span > kMaxReadSpan) {
        m_running.clear();
        return;
    }
    m_readAddress = *low;
    m_read =
        RtuFrame::adu(unit, QModbusRequest(QModbusPdu::ReadHoldingRegisters, *low, quint16(span)));
}

QByteArray EstopConfirmation::stopFrameFor(const RegisterMap &map, int unit)
{
    // The system's E-STOP (all motors and outputs), as the connected window sends it; a motor's
    // own stop coil is an emergency command too, but stops that motor only.
    const Parameter *estop = map.find(QStringLiteral("estop"));
    if (!estop || !estop->isCoil())
        return {};
    QByteArray pdu;
    pdu.append(char(estop->address >> 8));
    pdu.append(char(estop->address & 0xFF));
    pdu.append(char(0xFF));
    pdu.append(char(0x00));
    return RtuFrame::adu(unit, QModbusRequest(QModbusPdu::WriteSingleCoil, pdu));
}

void EstopConfirmation::start()
{
    m_active = isValid();
    m_phase = Phase::Stop;
    m_stopTries = 0;
    m_readTries = 0;
    m_sentAtMs = -1;
    m_copies = 0;
    m_stopCopies = 0;
    m_echoHeard = false;
    m_readAnswered = false;
    m_moving.clear();
    m_verdict = Verdict::Pending;
    m_text.clear();
}

QByteArray EstopConfirmation::due(qint64 ms)
{
    if (!m_active || (m_sentAtMs >= 0 && ms - m_sentAtMs < kAnswerWaitMs))
        return {};
    if (m_phase == Phase::Stop && m_sentAtMs >= 0) {
        // A copy past the echo, or one copy while nobody knows yet whether the adapter echoes:
        // the read says which (and whether the axes stopped).
        if (stopCopied() || (m_stopCopies > 0 && !m_echoKnown)) {
            if (m_read.isEmpty()) {
                settle(Verdict::Acknowledged,
                       tr("E-STOP acknowledged by controller %1 (its answer heard; the register "
                          "map names no motion state to read back)")
                           .arg(m_unit));
                return {};
            }
            m_phase = Phase::Read;
        }
    } else if (m_phase == Phase::Read && m_sentAtMs >= 0 && !stopCopied()) {
        m_phase = Phase::Stop; // the copy heard was the adapter's echo: the E-STOP again
    }
    if (m_phase == Phase::Stop) {
        if (m_stopTries < kSendTries)
            return m_stop;
    } else if (m_readTries < kSendTries) {
        return m_read;
    }
    settle(Verdict::NotAcknowledged, failure());
    return {};
}

void EstopConfirmation::sent(qint64 ms)
{
    m_sentAtMs = ms;
    m_copies = 0;
    if (m_phase == Phase::Stop)
        ++m_stopTries;
    else
        ++m_readTries;
}

bool EstopConfirmation::heard(const HeardFrame &frame, const QByteArray &otherRequest)
{
    if (!m_active || m_sentAtMs < 0)
        return false;
    const QByteArray &b = frame.bytes;
    const QByteArray &last = m_phase == Phase::Stop ? m_stop : m_read;
    if (b == last) {
        ++m_copies;
        if (m_phase == Phase::Read) {
            // A read's copy is never its answer (that carries a byte count): the adapter echoes.
            m_echoHeard = true;
            learnEcho(true);
            return true;
        }
        m_stopCopies = std::max(m_stopCopies, m_copies);
        if (m_copies == 2 && !m_echo)
            learnEcho(true); // one E-STOP came back twice: the first was the adapter's
        if (m_echo && m_copies == 1)
            m_echoHeard = true;
        return true;
    }
    if (b == m_stop || b == m_read)
        return true; // a late copy of the frame sent before: StepCom's all the same
    // The read's answer, unless it fits the other master's waiting request as well (its own).
    if (m_phase != Phase::Read || !ListenDecoder::answers(m_read, b) ||
        (!otherRequest.isEmpty() && ListenDecoder::answers(otherRequest, b)))
        return false;
    if (quint8(b.at(1)) & 0x80)
        m_readAnswered = true; // refused: the controller is there; the read goes again
    else
        motionAnswered(b);
    return true;
}

void EstopConfirmation::motionAnswered(const QByteArray &frame)
{
    m_readAnswered = true;
    // The controller answered this read: had the adapter echoed, its copy came first.
    if (m_copies == 0)
        learnEcho(false);
    m_moving.clear();
    for (int axis = 0; axis < m_running.size(); ++axis) {
        const int at = 3 + 2 * (m_running.at(axis) - m_readAddress);
        if (((quint8(frame.at(at)) << 8) | quint8(frame.at(at + 1))) != 0)
            m_moving << axis + 1;
    }
    if (!stopCopied()) {
        // Only the echo of the E-STOP was heard: it goes again now.
        m_phase = Phase::Stop;
        m_sentAtMs = -1;
        return;
    }
    if (m_moving.isEmpty()) {
        settle(Verdict::Acknowledged,
               m_running.size() == 2
                   ? tr("E-STOP acknowledged by controller %1: both axes stopped").arg(m_unit)
                   : tr("E-STOP acknowledged by controller %1: %n axis(es) stopped", nullptr,
                        int(m_running.size()))
                         .arg(m_unit));
        return;
    }
    // Still running: the E-STOP again, and read back again.
    m_phase = Phase::Stop;
    m_stopCopies = 0;
    m_sentAtMs = -1;
}

void EstopConfirmation::learnEcho(bool echoes)
{
    if (echoes && !m_echo)
        m_echoNews = true;
    m_echo = echoes;
    m_echoKnown = true;
}

void EstopConfirmation::settle(Verdict verdict, const QString &text)
{
    m_verdict = verdict;
    m_text = text;
    m_active = false;
}

QString EstopConfirmation::failure() const
{
    const QString advice = tr("Stop the machine by its own E-STOP.");
    if (m_readAnswered && !m_moving.isEmpty()) {
        QStringList axes;
        for (const int axis : m_moving)
            axes << QString::number(axis);
        return tr("E-STOP not acknowledged by controller %1: motor %2 still running after %3 "
                  "E-STOPs. %4")
            .arg(m_unit)
            .arg(axes.join(QStringLiteral(", ")))
            .arg(m_stopTries)
            .arg(advice);
    }
    if (stopCopied())
        return tr("E-STOP not acknowledged by controller %1: a copy of it was heard, but the "
                  "controller never answered the read of its motion state. %2")
            .arg(m_unit)
            .arg(advice);
    if (m_echoHeard)
        return tr("E-STOP not acknowledged by controller %1: only our own echo heard (sent %2 "
                  "times). %3")
            .arg(m_unit)
            .arg(m_stopTries)
            .arg(advice);
    return tr("E-STOP sent %1 times into the other master's line, and controller %2 never "
              "answered it. %3")
        .arg(m_stopTries)
        .arg(m_unit)
        .arg(advice);
}

} // namespace stepcom

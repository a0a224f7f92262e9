#pragma once

#include "listen/heardframe.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>
#include <QString>

#include <utility>

namespace stepcom {

class RegisterMap;

// The E-STOP sent into another master's line, and how StepCom knows the controller took it.
// Through an adapter without echo suppression the E-STOP comes back as it was sent, and the
// controller's answer to an FC05 is those same bytes: a copy alone cannot tell them apart. So
// a copy of the E-STOP counts only past the echo (the first copy of each send when the line
// echoes: the line's echo option, or learnt when one send came back twice or the read below
// came back as sent; a read answered with no copy of it first shows there is none), and what
// acknowledges it is the controller's answer to an FC03 read of
// its motion state (the map's running registers): an answer carries fc 03 and a byte count,
// which no echo imitates, and says whether the axes stand. An axis still running sends the
// E-STOP again. A plain value: the listener hands it what it hears and sends what it asks for
// in the next silence.
class EstopConfirmation
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::EstopConfirmation)
public:
    static constexpr int kSendTries = 10;
    // How long a send waits for its copies and answer before the next goes out.
    static constexpr int kAnswerWaitMs = 300;

    enum class Verdict { Pending, Acknowledged, NotAcknowledged };

    EstopConfirmation() = default;
    // The E-STOP to `unit` on `map`; `echo`: the line's echo option (the adapter hears itself).
    EstopConfirmation(const RegisterMap &map, int unit, bool echo);
    // False when the map has no emergency coil: there is nothing to send.
    bool isValid() const { return !m_stop.isEmpty(); }
    bool isActive() const { return m_active; }
    // From the beginning: the E-STOP goes out at the next silence.
    void start();
    void cancel() { m_active = false; }

    // The line is quiet at `ms`: the frame to send now (the E-STOP or the read), empty while
    // a send may still be answered or once it is settled. When the tries ran out the verdict
    // is NotAcknowledged.
    QByteArray due(qint64 ms);
    // It went out at `ms`.
    void sent(qint64 ms);
    // A whole frame heard while active: true when it is StepCom's (its echo, the controller's
    // copy, the read's answer), not the other master's. `otherRequest`: the other master's
    // request waiting for its answer (empty when none): an answer that fits it is its.
    bool heard(const HeardFrame &frame, const QByteArray &otherRequest);

    Verdict verdict() const { return m_verdict; }
    // The verdict in words: "E-STOP acknowledged by controller 1: both axes stopped".
    QString text() const { return m_text; }
    // True once, when the copies showed the adapter echoes though the echo option is off.
    bool takeEchoLearned() { return std::exchange(m_echoNews, false); }
    bool echoes() const { return m_echo; }
    // The E-STOP request (the map's emergency coil set, FC05) to `unit`; empty when the map
    // has no emergency coil.
    static QByteArray stopFrameFor(const RegisterMap &map, int unit);
    // The frames, for the traffic view's words.
    const QByteArray &stopFrame() const { return m_stop; }
    const QByteArray &readFrame() const { return m_read; }
    int unit() const { return m_unit; }
    int stopTries() const { return m_stopTries; }
    int readTries() const { return m_readTries; }

private:
    enum class Phase { Stop, Read };
    // A copy of the E-STOP heard past the echo, as far as the line is known now.
    bool stopCopied() const { return m_stopCopies > (m_echo ? 1 : 0); }
    void learnEcho(bool echoes);
    QString failure() const;
    void settle(Verdict verdict, const QString &text);
    void motionAnswered(const QByteArray &frame);

    QByteArray m_stop; // FC05 on the emergency coil
    QByteArray m_read; // FC03 of the running registers; empty when the map has none
    quint16 m_readAddress = 0;
    QList<quint16> m_running; // each axis's running register, axis 1 first
    int m_unit = 0;
    bool m_echo = false;
    bool m_echoKnown = false; // learnt from the line, not only the option
    bool m_echoNews = false;
    bool m_active = false;
    Phase m_phase = Phase::Stop;
    int m_stopTries = 0;
    int m_readTries = 0;
    qint64 m_sentAtMs = -1; // the last send; -1: the next silence sends
    int m_copies = 0;       // copies of the last send heard
    int m_stopCopies = 0;   // the most copies one E-STOP send brought back
    bool m_echoHeard = false;
    bool m_readAnswered = false; // the controller answered a read (something not an echo)
    QList<int> m_moving;         // the axes the last read said were running
    Verdict m_verdict = Verdict::Pending;
    QString m_text;
};

} // namespace stepcom

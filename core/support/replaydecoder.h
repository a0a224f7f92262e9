#pragma once

#include "support/logline.h"
#include "support/replaystate.h"

#include <QCoreApplication>
#include <QList>

#include <functional>
#include <optional>

namespace stepcom {

class RegisterMap;

// Turns the lines of a session log, in order, into the state of every controller and the
// events worth a marker. Requests are paired with their answers as StepCom's link pairs them:
// by unit, function, address and count; an echo of a read is skipped; a request followed by
// another request (a retry, the next one) or by the link going down had no answer; an answer
// that fits a request already given up is a late (owed) answer and changes nothing, as StepCom
// discarded it. A plain value: copied as the snapshots of ReplayLog.
class ReplayDecoder
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ReplayDecoder)
public:
    enum class Framing { Auto, Rtu, Tcp };
    using Sink = std::function<void(const ReplayEvent &event)>;

    explicit ReplayDecoder(const RegisterMap *map = nullptr);
    void setFraming(Framing framing) { m_framing = framing; }
    // Logs with the session's own marks (linkup, linkdown, ...) need not have their translated
    // event texts guessed at; old logs are read by their English texts.
    void setMarked(bool marked) { m_marked = marked; }

    // One line at `ms` since the start; `line` is its number. `sink` may be empty.
    void feed(const LogLine &line, qint64 ms, qint64 lineNo, const Sink &sink);
    // The end of the log: a request still waiting had no answer.
    void finish(qint64 ms, const Sink &sink);
    const ReplayState &state() const { return m_state; }
    // The controller whose answer the line fed last was (0: that line answered nothing).
    int answeredUnit() const { return m_answeredUnit; }
    ReplayState &state() { return m_state; }

    // The unit and the PDU of a raw frame (RTU with a good CRC, or Modbus TCP's MBAP).
    static bool split(const QByteArray &raw, Framing framing, int *unit, QByteArray *pdu);

private:
    struct Pending
    {
        int unit = 0;
        QByteArray pdu;
        qint64 lineNo = 0;
    };
    void frame(const LogLine &line, qint64 ms, qint64 lineNo, const Sink &sink);
    void mark(const LogLine &line, qint64 ms, qint64 lineNo, const Sink &sink);
    void timedOut(const Pending &p, qint64 ms, qint64 lineNo, const Sink &sink);
    void answered(const Pending &p, const QByteArray &answer, qint64 ms, qint64 lineNo,
                  const Sink &sink);
    static bool fits(const Pending &p, int unit, const QByteArray &answer);
    // "read 40001-40002", "write motor1.speed", "command estop".
    QString describe(const QByteArray &request) const;
    void emitEvent(const Sink &sink, qint64 ms, int device, ReplayEvent::Kind kind,
                   const QString &text, qint64 lineNo) const;

    const RegisterMap *m_map;
    Framing m_framing = Framing::Auto;
    bool m_marked = false;
    int m_answeredUnit = 0;
    std::optional<Pending> m_pending;
    QList<Pending> m_owed; // the last requests given up, newest last
    ReplayState m_state;
};

} // namespace stepcom

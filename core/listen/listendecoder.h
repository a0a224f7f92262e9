#pragma once

#include "listen/heardevent.h"
#include "listen/heardframe.h"
#include "support/replaystate.h"

#include <QList>
#include <QMap>

#include <optional>

namespace stepcom {

class RegisterMap;

// Pairs the frames of a line another master drives -- each request with the next frame that
// can be its answer (unit, function, address or count) -- and decodes both with the register
// map into HeardEvents. A request followed by another request, or by a long silence, had no
// answer. What the answers and acknowledged writes said is kept per id as the heard state
// (the values as last seen, never read by StepCom). A plain value: feed it frames in order.
class ListenDecoder
{
public:
    struct DeviceStats
    {
        int requests = 0;
        int answered = 0;
        int exceptions = 0;
        int unanswered = 0;
        double answerMsMin = -1.0;
        double answerMsMax = -1.0;
        double answerMsSum = 0.0;
        double answerMsAverage() const { return answered ? answerMsSum / answered : -1.0; }
    };

    explicit ListenDecoder(const RegisterMap *map = nullptr, int baud = 9600);
    // A request unanswered this long after its end had no answer (the master's own timeout
    // is not known; a longer one only delays saying so).
    void setAnswerTimeoutMs(int ms) { m_answerTimeoutMs = ms; }

    QList<HeardEvent> frame(const HeardFrame &frame);
    // The line quiet until `ms`: a request waiting longer than the timeout had no answer.
    QList<HeardEvent> idle(qint64 ms);
    // The end: a request still waiting had no answer.
    QList<HeardEvent> finish();

    const ReplayState &state() const { return m_state; }
    // A request of the other master waits for its answer.
    bool waiting() const { return m_pending.has_value(); }
    // That request's bytes; empty when none waits.
    QByteArray waitingRequest() const { return m_pending ? m_pending->bytes : QByteArray(); }
    const QMap<int, DeviceStats> &deviceStats() const { return m_stats; }
    int pairs() const { return m_pairs; }
    int strayAnswers() const { return m_strays; }

    // Whether `answer` (unit, PDU) can answer `request`.
    static bool answers(const QByteArray &request, const QByteArray &answer);
    // Whether a frame can be a request by its shape.
    static bool canBeRequest(const QByteArray &frame);

private:
    struct Pending
    {
        HeardFrame frame;
    };
    HeardEvent decode(const HeardFrame &request, const HeardFrame *answer) const;
    // The parameters (and the loose registers) among `count` registers from `address`, the
    // words in `words` first, then the heard state of `unit` for a 2-word value's other half.
    void describeWords(HeardEvent *e, const QMap<quint16, quint16> &words) const;
    void noteAnswered(const HeardEvent &e);
    HeardEvent unanswered(const HeardFrame &request);

    const RegisterMap *m_map;
    int m_baud;
    int m_answerTimeoutMs = 1000;
    std::optional<HeardFrame> m_pending;
    ReplayState m_state;
    QMap<int, DeviceStats> m_stats;
    int m_pairs = 0;
    int m_strays = 0;
};

} // namespace stepcom

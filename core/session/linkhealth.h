#pragma once

#include <QObject>

namespace stepcom {

class ModbusLink;
struct Result;

// Whether the controller answers, in three steps: the port is closed; the port is open but
// the controller does not answer; the controller answers. A port that opens says nothing about
// the controller behind it, so "answering" needs an answer (an exception answer counts: the
// controller is there). Derived only from the results of the requests the session makes.
class LinkHealth : public QObject
{
    Q_OBJECT
public:
    enum class State {
        Closed,
        Opening,
        Asking,       // the port is open, no request has been answered or failed yet
        NotAnswering, // the port is open, requests go unanswered
        Answering,
    };
    Q_ENUM(State)

    explicit LinkHealth(ModbusLink *link, QObject *parent = nullptr);

    State state() const { return m_state; }
    bool isAnswering() const { return m_state == State::Answering; }
    // Requests in a row that went unanswered (after their retries) on this connection.
    int silentRequests() const { return m_silent; }
    // Failed requests in a row that make an answering controller "not answering" again.
    static constexpr int kSilentLimit = 3;

    // Short, in the installed language: "Connected", "Not answering", "Port closed" ...
    QString stateText() const;
    // Why a controller may not answer, in words, for the "not answering" state.
    static QString likelyCauses();

Q_SIGNALS:
    void stateChanged(stepcom::LinkHealth::State state);

private:
    void setState(State state);
    // The port's own state, in this class' terms (Closed, Opening or Asking).
    void onPortState(State state);
    void onFinished(const Result &result);

    ModbusLink *m_link;
    State m_state = State::Closed;
    int m_silent = 0;
};

} // namespace stepcom

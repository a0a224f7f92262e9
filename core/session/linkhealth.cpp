#include "session/linkhealth.h"

#include "bus/modbuslink.h"

namespace stepcom {

namespace {

// What the port's state alone says: an open port is only "asking" until something answers.
LinkHealth::State portState(ModbusLink::State state)
{
    switch (state) {
    case ModbusLink::State::Connecting:
        return LinkHealth::State::Opening;
    case ModbusLink::State::Connected:
        return LinkHealth::State::Asking;
    case ModbusLink::State::Disconnected:
        break;
    }
    return LinkHealth::State::Closed;
}

} // namespace

LinkHealth::LinkHealth(ModbusLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    connect(link, &ModbusLink::stateChanged, this,
            [this](ModbusLink::State s, const QString &) { onPortState(portState(s)); });
    connect(link, &ModbusLink::finished, this,
            [this](quint64, const Request &, const Result &r) { onFinished(r); });
    onPortState(portState(link->state()));
}

void LinkHealth::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    Q_EMIT stateChanged(state);
}

void LinkHealth::onPortState(State state)
{
    m_silent = 0;
    setState(state);
}

void LinkHealth::onFinished(const Result &result)
{
    if (m_state == State::Closed || m_state == State::Opening)
        return;
    // An exception answer is an answer: the controller is there and understood the frame.
    if (result.ok || result.exceptionCode != 0) {
        m_silent = 0;
        setState(State::Answering);
        return;
    }
    // Cancelled before it went out, or the link itself went away: says nothing about the device.
    if (result.attempts == 0 || result.error == QModbusDevice::ConnectionError)
        return;
    ++m_silent;
    if (m_state == State::Asking || m_silent >= kSilentLimit)
        setState(State::NotAnswering);
}

QString LinkHealth::stateText() const
{
    switch (m_state) {
    case State::Closed:
        return tr("Port closed");
    case State::Opening:
        return tr("Opening the port…");
    case State::Asking:
        return tr("Port open, waiting for the controller…");
    case State::NotAnswering:
        return tr("Not answering");
    case State::Answering:
        return tr("Connected");
    }
    return {};
}

QString LinkHealth::likelyCauses()
{
    return tr("The port is open but no controller answers. Likely causes: another device id "
              "(factory: 1), another baud rate (factory: 9600) or parity (factory: none), the "
              "RS-485 wires A and B swapped, or the controller has no power. A bus scan tries "
              "the ids and baud rates for you.");
}

} // namespace stepcom

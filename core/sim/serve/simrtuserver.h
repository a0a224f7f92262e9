#pragma once

#include <QModbusRtuSerialServer>

#include <functional>

namespace stepcom {

class SimResponder;

// The simulated controller on a serial line (the device side of a PtyBridge). Every request
// goes to SimResponder; the answer leaves after the controller's delay. Qt 6.4 drops frames of
// function codes it cannot size, so sizes are registered for every other code: those requests
// get exception 01 like the real controller's.
class SimRtuServer : public QModbusRtuSerialServer
{
    Q_OBJECT
public:
    // `clientBaud` returns the baud the client set on its end (0: unknown); when it differs
    // from register 40213 the device hears only framing errors and stays silent.
    SimRtuServer(SimResponder *responder, std::function<int()> clientBaud,
                 QObject *parent = nullptr);

    // True once: the answer just handed to the port must leave with a broken CRC.
    bool takeCorruptCrc();
    // The address of the frame arriving now (seen by the bridge before the server reads it):
    // Qt's server answers one address, so it is pointed at each request's controller in turn.
    void setRequestUnit(int unit);

Q_SIGNALS:
    // The fault plan says: hang up after this answer.
    void hangUpRequested();

protected:
    QModbusResponse processRequest(const QModbusPdu &request) override;
    QModbusResponse processPrivateRequest(const QModbusPdu &request) override;

private:
    static void registerUnknownFunctionCodes();

    SimResponder *m_responder;
    std::function<int()> m_clientBaud;
    bool m_corruptNext = false;
    int m_unit = -1; // -1: the server's own address
};

} // namespace stepcom

#pragma once

#include <QModbusDevice>
#include <QString>
#include <QVector>

#include <functional>

namespace stepcom {

// Order in which queued requests go out: a lower value always goes first.
enum class Priority { Emergency = 0, Command = 1, Read = 2, Poll = 3 };

struct Request
{
    enum class Type { ReadHolding, WriteHolding, WriteCoil };
    Type type = Type::ReadHolding;
    quint16 address = 0;
    quint16 count = 0;       // registers to read
    QVector<quint16> values; // registers to write (1 -> FC06, more -> FC10)
    bool coilOn = true;      // FC05: FF00 when true
    Priority priority = Priority::Read;
    // Retry after a timeout or a bad CRC? Never for commands that move: a lost answer may
    // mean the controller did act, and a second pulse would move the axis twice.
    bool retryable = true;
    QString what; // what the request is for, in words: "motor1.speed", "read-all block 2/5"
    // The controller it is addressed to on a line of several; 0: the link's device id.
    int unitId = 0;
    // This request's own answer timeout in ms; 0: the link's. A bus scan's probes wait only as
    // long as the wire needs, its identifying read as long as a slow controller needs.
    int timeoutMs = 0;

    static Request read(quint16 address, quint16 count, Priority p = Priority::Read);
    static Request write(quint16 address, QVector<quint16> values, Priority p = Priority::Command);
    static Request coil(quint16 address, bool on, Priority p = Priority::Command);
    int functionCode() const;
    int registerCount() const { return type == Type::ReadHolding ? count : int(values.size()); }
};

struct Result
{
    bool ok = false;
    QModbusDevice::Error error = QModbusDevice::NoError;
    int exceptionCode = 0;   // Modbus exception code when the device refused, else 0
    QString errorText;       // in words, names the request's `what` and address
    QVector<quint16> values; // registers read
    int attempts = 0;
    qint64 roundTripMs = -1;   // of the successful attempt
    bool mayHaveActed = false; // a command whose answer was lost: the device may have acted
};

using ResultCallback = std::function<void(const Result &)>;

// "illegal data address" etc.; codes from the Modbus specification.
QString exceptionText(int code);

} // namespace stepcom

#pragma once

#include <QList>
#include <QModbusPdu>

#include <QSet>

#include <functional>
#include <utility>

namespace stepcom {

class Parameter;
class SimRegisters;

// The controller's Modbus rules on one request PDU: only 03, 05, 06 and 10 (others: exception
// 01); quantities of 50 registers or more, malformed PDUs and coil values other than FF00/0000:
// exception 03; writes outside the map, to read-only registers or covering half of a 32-bit
// value: exception 02; values outside the map's range: exception 03, nothing written. Reads
// see one register array: gaps between parameters read as 0, past its end is exception 02
// (with strict reads every address must belong to a parameter; a lacking parameter, one a
// firmware variant does not have, is refused like a reserved register). A request is checked
// completely before anything is written.
class SimProtocol
{
public:
    using Write = std::pair<const Parameter *, qint64>;
    struct Hooks
    {
        std::function<void(const QList<Write> &)> write; // validated; the hook stores them
        // A coil switched ON; returns false when the device failed (answered with 04).
        std::function<bool(const Parameter &)> coil;
    };

    SimProtocol(const SimRegisters &registers, Hooks hooks, bool strictReads = false,
                QSet<QString> lacking = {});

    QModbusResponse process(const QModbusRequest &request) const;

private:
    QModbusResponse readHolding(const QModbusRequest &request) const;
    QModbusResponse writeSingle(const QModbusRequest &request) const;
    QModbusResponse writeMultiple(const QModbusRequest &request) const;
    QModbusResponse writeCoil(const QModbusRequest &request) const;

    const SimRegisters &m_regs;
    Hooks m_hooks;
    bool m_strictReads;
    QSet<QString> m_lacking; // keys of parameters this firmware does not have
};

} // namespace stepcom

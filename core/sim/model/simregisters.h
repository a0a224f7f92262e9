#pragma once

#include "map/registermap.h"

#include <QHash>
#include <QString>

namespace stepcom {

// The simulated controller's register contents, one raw value per holding parameter of the
// register map (the map decides which addresses exist), with the factory values.
class SimRegisters
{
public:
    explicit SimRegisters(const RegisterMap &map);

    const RegisterMap &map() const { return m_map; }

    qint64 raw(const Parameter *param) const { return param ? m_values.value(param->key) : 0; }
    // The value of `key`, or `fallback` when the map has no such register.
    qint64 raw(const QString &key, qint64 fallback = 0) const;
    void setRaw(const Parameter *param, qint64 raw);
    bool has(const QString &key) const { return m_map.find(key) != nullptr; }

    // Factory values: plausible for a 1.8° motor with an 8× driver on a 5 mm lead screw
    // (docs/simulator.md lists them).
    qint64 factoryValue(const Parameter &param) const;
    // Restores every writable parameter except the link settings (device id, baud).
    void resetToFactory();

    // Every writable parameter by key: what "save" writes to flash.
    QHash<QString, qint64> writableValues() const;
    // Takes the values of known writable keys that pass the map's range check; returns the
    // problems (unknown key, bad value) for the rest.
    QStringList applyValues(const QHash<QString, qint64> &values);

    // Number of inputs, outputs (io.inN / io.outN) and motors in the map.
    int inputCount() const { return m_inputs; }
    int outputCount() const { return m_outputs; }
    int motorCount() const { return m_motors; }
    // The highest protocol address a holding parameter covers: the end of the register array.
    int lastAddress() const { return m_lastAddress; }

private:
    RegisterMap m_map;
    QHash<QString, qint64> m_values;
    int m_inputs = 0;
    int m_outputs = 0;
    int m_motors = 0;
    int m_lastAddress = -1;
};

} // namespace stepcom

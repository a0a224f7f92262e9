#include "sim/model/simregisters.h"

#include "map/factoryvalues.h"

#include <QCoreApplication>

#include <algorithm>

namespace stepcom {

namespace {

int countNumbered(const RegisterMap &map, const QString &prefix)
{
    int n = 0;
    while (map.find(prefix + QString::number(n + 1)))
        ++n;
    return n;
}

} // namespace

SimRegisters::SimRegisters(const RegisterMap &map)
    : m_map(map)
{
    m_inputs = countNumbered(m_map, QStringLiteral("io.in"));
    m_outputs = countNumbered(m_map, QStringLiteral("io.out"));
    m_motors = m_map.blockCount(QStringLiteral("motor"));
    for (const Parameter &p : m_map.parameters()) {
        if (!p.isHolding())
            continue;
        m_values.insert(p.key, factoryValue(p));
        m_lastAddress = std::max(m_lastAddress, int(p.lastAddress()));
    }
}

qint64 SimRegisters::raw(const QString &key, qint64 fallback) const
{
    const auto it = m_values.constFind(key);
    return it == m_values.cend() ? fallback : *it;
}

void SimRegisters::setRaw(const Parameter *param, qint64 raw)
{
    if (param && param->isHolding())
        m_values.insert(param->key, raw);
}

qint64 SimRegisters::factoryValue(const Parameter &p) const
{
    // The simulated machine has its switches wired (the factory leaves the inputs unset):
    // motor n's positive end on IN(2n-1), its negative end and home on IN(2n).
    if (p.block == QLatin1String("motor")) {
        const int n = p.instance;
        std::optional<qint64> input;
        if (p.localKey == QLatin1String("limit_positive"))
            input = 2 * n - 1 <= m_inputs ? 2 * n - 1 : 0;
        else if (p.localKey == QLatin1String("limit_negative") ||
                 p.localKey == QLatin1String("home_input"))
            input = 2 * n <= m_inputs ? 2 * n : 0;
        if (input && p.checkRaw(*input).isEmpty())
            return *input;
    }
    return FactoryValues::value(p);
}

void SimRegisters::resetToFactory()
{
    for (const Parameter &p : m_map.parameters()) {
        if (!p.writable() || p.key == QLatin1String("device.id") ||
            p.key == QLatin1String("device.baud"))
            continue;
        m_values.insert(p.key, factoryValue(p));
    }
}

QHash<QString, qint64> SimRegisters::writableValues() const
{
    QHash<QString, qint64> out;
    for (const Parameter &p : m_map.parameters()) {
        if (p.writable())
            out.insert(p.key, m_values.value(p.key));
    }
    return out;
}

QStringList SimRegisters::applyValues(const QHash<QString, qint64> &values)
{
    QStringList problems;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        const Parameter *p = m_map.find(it.key());
        if (!p || !p->writable()) {
            problems << QCoreApplication::translate("stepcom::SimRegisters",
                                                    "%1: not a writable parameter of the map")
                            .arg(it.key());
            continue;
        }
        if (const QString why = p->checkRaw(it.value()); !why.isEmpty()) {
            problems << why;
            continue;
        }
        m_values.insert(p->key, it.value());
    }
    return problems;
}

} // namespace stepcom

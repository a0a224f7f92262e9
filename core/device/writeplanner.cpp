#include "device/writeplanner.h"

#include "map/parameter.h"

#include <algorithm>

namespace stepcom {

QList<Request> WritePlanner::plan(QList<ParameterWrite> writes, int maxRegisters, Priority priority)
{
    std::sort(writes.begin(), writes.end(), [](const ParameterWrite &a, const ParameterWrite &b) {
        return a.parameter->address < b.parameter->address;
    });
    QList<Request> requests;
    QStringList keys;
    auto flush = [&] {
        if (!requests.isEmpty() && requests.last().what.isEmpty())
            requests.last().what = keys.join(QLatin1String(", "));
        keys.clear();
    };
    for (const ParameterWrite &w : std::as_const(writes)) {
        const QVector<quint16> words = w.parameter->encode(w.raw);
        const bool continues =
            !requests.isEmpty() && requests.last().what.isEmpty() &&
            requests.last().address + requests.last().values.size() == w.parameter->address &&
            requests.last().values.size() + words.size() <= maxRegisters;
        if (!continues) {
            flush();
            requests << Request::write(w.parameter->address, {}, priority);
        }
        requests.last().values += words;
        keys << w.parameter->key;
    }
    flush();
    return requests;
}

} // namespace stepcom

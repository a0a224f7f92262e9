#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace stepcom {

struct Parameter;

// Why a typed value cannot be taken, said for the person at the field: the parameter's label,
// the allowed range and unit, in the installed language, never an internal key. The problem is
// kept as data, so the words can be made again after a language switch.
class ValueCheck
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ValueCheck)
public:
    enum class Problem { None, Empty, NotANumber, TooManyDecimals, OutOfRange, NotAChoice };

    // The raw value when `typed` is allowed for `p`; else nullopt and the problem in `problem`.
    static std::optional<qint64> check(const Parameter &p, const QString &typed, Problem *problem);
    // "Speed: 9999 is outside the allowed range 1 – 3000 rpm." and the like.
    static QString text(const Parameter &p, Problem problem, const QString &typed);
};

} // namespace stepcom

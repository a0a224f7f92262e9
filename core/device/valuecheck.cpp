#include "device/valuecheck.h"

#include "i18n/translators.h"
#include "map/parameter.h"

#include <QLocale>

#include <cmath>

namespace stepcom {

std::optional<qint64> ValueCheck::check(const Parameter &p, const QString &typed, Problem *problem)
{
    const auto set = [problem](Problem why) {
        if (problem)
            *problem = why;
    };
    set(Problem::None);
    if (const auto raw = p.parse(typed, nullptr)) {
        if (p.checkRaw(*raw).isEmpty())
            return raw;
        set(p.values.isEmpty() ? Problem::OutOfRange : Problem::NotAChoice);
        return std::nullopt;
    }
    const QString text = typed.trimmed();
    if (text.isEmpty()) {
        set(Problem::Empty);
        return std::nullopt;
    }
    bool number = false;
    const double value = QLocale::c().toDouble(text, &number);
    if (!number) {
        set(p.values.isEmpty() ? Problem::NotANumber : Problem::NotAChoice);
        return std::nullopt;
    }
    const double scaled = value * p.scale;
    if (std::abs(scaled - std::round(scaled)) > 1e-6) {
        set(Problem::TooManyDecimals);
        return std::nullopt;
    }
    set(p.values.isEmpty() ? Problem::OutOfRange : Problem::NotAChoice);
    return std::nullopt;
}

QString ValueCheck::text(const Parameter &p, Problem problem, const QString &typed)
{
    const QString lang = Translators::current();
    const QString label = p.label.text(lang);
    QString range = tr("%1 – %2").arg(p.formatRaw(p.rawMin), p.formatRaw(p.rawMax));
    if (!p.unit.isEmpty())
        range += QLatin1Char(' ') + p.unit;
    QStringList choices;
    for (const EnumValue &v : p.values)
        choices << v.label.text(lang);
    switch (problem) {
    case Problem::None:
        return {};
    case Problem::Empty:
        return tr("%1: enter a value (%2).").arg(label, range);
    case Problem::NotANumber:
        return tr("%1: “%2” is not a number. Allowed: %3.").arg(label, typed.trimmed(), range);
    case Problem::TooManyDecimals:
        return tr("%1: at most %n decimal(s). Allowed: %2.", nullptr, p.decimals())
            .arg(label, range);
    case Problem::OutOfRange:
        return tr("%1: %2 is outside the allowed range %3.").arg(label, typed.trimmed(), range);
    case Problem::NotAChoice:
        return tr("%1: “%2” is not one of %3.")
            .arg(label, typed.trimmed(), Translators::joinList(choices));
    }
    return {};
}

} // namespace stepcom

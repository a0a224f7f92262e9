#include "map/parameter.h"

#include <QCoreApplication>

#include <cmath>
#include <limits>

namespace stepcom {

QString LocalizedText::text(const QString &locale) const
{
    if (locale.startsWith(QLatin1String("zh")) && !zh.isEmpty())
        return zh;
    return en;
}

int Parameter::decimals() const
{
    int d = 0;
    for (int s = scale; s > 1; s /= 10)
        ++d;
    return d;
}

QString Parameter::registerName() const
{
    return QStringLiteral("%1 · 0x%2")
        .arg(plc, 5, 10, QLatin1Char('0'))
        .arg(QString::number(address, 16).rightJustified(4, QLatin1Char('0')).toUpper());
}

QString Parameter::formatRaw(qint64 raw) const
{
    if (scale == 1)
        return QString::number(raw);
    const bool negative = raw < 0;
    const quint64 magnitude = negative ? quint64(-(raw + 1)) + 1 : quint64(raw);
    const quint64 whole = magnitude / quint64(scale);
    const quint64 fraction = magnitude % quint64(scale);
    return QStringLiteral("%1%2.%3")
        .arg(negative ? QStringLiteral("-") : QString())
        .arg(whole)
        .arg(fraction, decimals(), 10, QLatin1Char('0'));
}

QString Parameter::displayRaw(qint64 raw, const QString &locale) const
{
    for (const EnumValue &v : values) {
        if (v.value == raw && !v.label.en.isEmpty() && v.label.en != QString::number(raw))
            return v.label.text(locale);
    }
    const QString number = formatRaw(raw);
    return unit.isEmpty() ? number : number + QLatin1Char(' ') + unit;
}

QString Parameter::rangeText() const
{
    if (!values.isEmpty()) {
        QStringList parts;
        for (const EnumValue &v : values) {
            const QString name = v.label.en;
            parts << (name == QString::number(v.value)
                          ? name
                          : QStringLiteral("%1 (%2)").arg(v.value).arg(name));
        }
        return parts.join(QLatin1String(", "));
    }
    QString text = formatRaw(rawMin) + QStringLiteral(" .. ") + formatRaw(rawMax);
    if (!unit.isEmpty())
        text += QLatin1Char(' ') + unit;
    return text;
}

QString Parameter::checkRaw(qint64 raw) const
{
    if (!values.isEmpty()) {
        for (const EnumValue &v : values) {
            if (v.value == raw)
                return {};
        }
        return QCoreApplication::translate("stepcom::Parameter", "%1: %2 is not one of %3")
            .arg(key, formatRaw(raw), rangeText());
    }
    if (raw < rawMin || raw > rawMax) {
        return QCoreApplication::translate("stepcom::Parameter", "%1: %2 is out of range (%3)")
            .arg(key, formatRaw(raw), rangeText());
    }
    return {};
}

std::optional<qint64> Parameter::parse(const QString &input, QString *error) const
{
    const QString text = input.trimmed();
    auto fail = [&](const QString &why) -> std::optional<qint64> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (text.isEmpty())
        return fail(
            QCoreApplication::translate("stepcom::Parameter", "%1: no value given").arg(key));

    // Enum labels are accepted in either language, case-insensitively ("in2", "Reverse").
    for (const EnumValue &v : values) {
        if (text.compare(v.label.en, Qt::CaseInsensitive) == 0 || text == v.label.zh) {
            if (const QString why = checkRaw(v.value); !why.isEmpty())
                return fail(why);
            return v.value;
        }
    }

    // Exact decimal: optional sign, digits, optional point and at most decimals() digits.
    qsizetype i = 0;
    bool negative = false;
    if (text.at(0) == QLatin1Char('-') || text.at(0) == QLatin1Char('+')) {
        negative = text.at(0) == QLatin1Char('-');
        ++i;
    }
    QString wholeDigits;
    QString fractionDigits;
    bool seenPoint = false;
    for (; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('.') && !seenPoint) {
            seenPoint = true;
        } else if (c.isDigit() && c.unicode() < 128) {
            (seenPoint ? fractionDigits : wholeDigits) += c;
        } else {
            // For a choice, name what it can be rather than asking for a number.
            if (!values.isEmpty())
                return fail(
                    QCoreApplication::translate("stepcom::Parameter", "%1: '%2' is not one of %3")
                        .arg(key, input, rangeText()));
            return fail(
                QCoreApplication::translate("stepcom::Parameter", "%1: '%2' is not a number")
                    .arg(key, input));
        }
    }
    if (wholeDigits.isEmpty() && fractionDigits.isEmpty())
        return fail(QCoreApplication::translate("stepcom::Parameter", "%1: '%2' is not a number")
                        .arg(key, input));
    while (fractionDigits.size() > decimals() && fractionDigits.endsWith(QLatin1Char('0')))
        fractionDigits.chop(1);
    if (fractionDigits.size() > decimals()) {
        return fail(QCoreApplication::translate("stepcom::Parameter",
                                                "%1: '%2' has more than %n decimal(s)", nullptr,
                                                decimals())
                        .arg(key, input));
    }
    fractionDigits = fractionDigits.leftJustified(decimals(), QLatin1Char('0'));
    if (wholeDigits.size() > 15)
        return fail(QCoreApplication::translate("stepcom::Parameter", "%1: '%2' is far too large")
                        .arg(key, input));
    const qint64 whole = wholeDigits.isEmpty() ? 0 : wholeDigits.toLongLong();
    const qint64 fraction = fractionDigits.isEmpty() ? 0 : fractionDigits.toLongLong();
    qint64 raw = whole * scale + fraction;
    if (negative)
        raw = -raw;
    if (const QString why = checkRaw(raw); !why.isEmpty())
        return fail(why);
    return raw;
}

std::optional<qint64> Parameter::fromEngineering(double value, QString *error) const
{
    auto fail = [&](const QString &why) -> std::optional<qint64> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (!std::isfinite(value))
        return fail(
            QCoreApplication::translate("stepcom::Parameter", "%1: not a finite number").arg(key));
    const double scaled = value * scale;
    if (std::fabs(scaled) > 9.0e15)
        return fail(QCoreApplication::translate("stepcom::Parameter", "%1: %2 is far too large")
                        .arg(key)
                        .arg(value, 0, 'g', 17));
    const double rounded = std::round(scaled);
    if (std::fabs(scaled - rounded) > 1e-6 * std::max(1.0, std::fabs(scaled))) {
        return fail(QCoreApplication::translate("stepcom::Parameter",
                                                "%1: %2 has more than %n decimal(s)", nullptr,
                                                decimals())
                        .arg(key)
                        .arg(value, 0, 'g', 17));
    }
    const auto raw = qint64(rounded);
    if (const QString why = checkRaw(raw); !why.isEmpty())
        return fail(why);
    return raw;
}

QVector<quint16> Parameter::encode(qint64 raw) const
{
    const auto bits = quint32(raw); // two's complement for negative values
    if (words == 2)
        return {quint16(bits & 0xFFFF), quint16(bits >> 16)};
    return {quint16(bits & 0xFFFF)};
}

qint64 Parameter::decode(const quint16 *wordsIn) const
{
    if (words == 2) {
        const quint32 bits = quint32(wordsIn[0]) | (quint32(wordsIn[1]) << 16);
        return isSigned ? qint64(qint32(bits)) : qint64(bits);
    }
    return isSigned ? qint64(qint16(wordsIn[0])) : qint64(wordsIn[0]);
}

} // namespace stepcom

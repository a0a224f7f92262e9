#include "listen/heardevent.h"

#include "bus/request.h" // exceptionText

#include <QJsonArray>
#include <QStringList>

namespace stepcom {

namespace {

int registerBase(int fc)
{
    return fc == 0x04 ? 30001 : 40001;
}

QString valuesText(const HeardEvent &e)
{
    QStringList parts;
    for (const HeardValue &v : e.values)
        parts << QStringLiteral("%1 = %2").arg(v.key, v.text);
    for (auto it = e.words.cbegin(); it != e.words.cend(); ++it)
        parts << QStringLiteral("%1 = %2").arg(registerBase(e.fc) + it.key()).arg(it.value());
    return parts.join(QStringLiteral(", "));
}

QString answerText(const HeardEvent &e)
{
    return e.answerMs < 0 ? QString()
                          : HeardEvent::tr(" (answered in %1 ms)").arg(e.answerMs, 0, 'f', 1);
}

bool isRegisterFunction(int fc)
{
    return fc == 0x03 || fc == 0x04 || fc == 0x06 || fc == 0x10;
}

} // namespace

QString HeardEvent::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Read:
        return QStringLiteral("read");
    case Kind::Write:
        return QStringLiteral("write");
    case Kind::Command:
        return QStringLiteral("command");
    case Kind::Exception:
        return QStringLiteral("exception");
    case Kind::NoAnswer:
        return QStringLiteral("no-answer");
    case Kind::Broadcast:
        return QStringLiteral("broadcast");
    case Kind::Stray:
        break;
    }
    return QStringLiteral("stray-answer");
}

QString HeardEvent::where() const
{
    if (!isRegisterFunction(fc)) {
        const QString first = QString::number(address + 1);
        return count > 1 ? tr("coils %1-%2").arg(first).arg(address + count)
                         : tr("coil %1").arg(first);
    }
    const int base = registerBase(fc);
    return count > 1 ? QStringLiteral("%1-%2").arg(base + address).arg(base + address + count - 1)
                     : QString::number(base + address);
}

QString HeardEvent::text() const
{
    const QString what = valuesText(*this);
    switch (kind) {
    case Kind::Read:
        return tr("PLC read %1 from id %2: %3%4")
            .arg(where())
            .arg(unit)
            .arg(what.isEmpty() ? tr("%n value(s)", nullptr, count) : what, answerText(*this));
    case Kind::Write:
        return tr("PLC wrote %1 to id %2%3").arg(what).arg(unit).arg(answerText(*this));
    case Kind::Command:
        return tr("PLC sent %1 to id %2%3").arg(what).arg(unit).arg(answerText(*this));
    case Kind::Exception:
        return tr("id %1 refused the PLC's FC%2 at %3: %4")
            .arg(unit)
            .arg(fc, 2, 10, QLatin1Char('0'))
            .arg(where(), exceptionText(exception));
    case Kind::NoAnswer:
        return tr("id %1 did not answer the PLC's FC%2 at %3%4")
            .arg(unit)
            .arg(fc, 2, 10, QLatin1Char('0'))
            .arg(where(), what.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(what));
    case Kind::Broadcast:
        return tr("PLC broadcast FC%1 at %2 to every id: %3")
            .arg(fc, 2, 10, QLatin1Char('0'))
            .arg(where(), what);
    case Kind::Stray:
        break;
    }
    return tr("an answer from id %1 (FC%2) whose request was not heard")
        .arg(unit)
        .arg(fc, 2, 10, QLatin1Char('0'));
}

QList<QJsonObject> HeardEvent::toJson(qint64 startMs) const
{
    QJsonObject base;
    base.insert(QStringLiteral("t"), double(ms - startMs) / 1000.0);
    base.insert(QStringLiteral("id"), unit);
    base.insert(QStringLiteral("fc"), fc);
    base.insert(QStringLiteral("kind"), kindName(kind));
    base.insert(QStringLiteral("address"),
                (isRegisterFunction(fc) ? registerBase(fc) : 1) + address);
    base.insert(QStringLiteral("count"), count);
    if (answerMs >= 0)
        base.insert(QStringLiteral("answer_ms"), qRound(answerMs * 10) / 10.0);
    if (exception)
        base.insert(QStringLiteral("exception"), exception);
    base.insert(QStringLiteral("from"), QStringLiteral("other master"));
    QJsonObject registers;
    for (auto it = words.cbegin(); it != words.cend(); ++it)
        registers.insert(QString::number(registerBase(fc) + it.key()), it.value());
    if (!registers.isEmpty())
        base.insert(QStringLiteral("registers"), registers);
    if (!coils.isEmpty() && values.isEmpty()) {
        QJsonArray bits;
        for (const bool bit : coils)
            bits.append(bit);
        base.insert(QStringLiteral("coils"), bits);
    }
    if (kind == Kind::Write || kind == Kind::Command || kind == Kind::Broadcast) {
        if (values.isEmpty())
            return {base};
        QList<QJsonObject> out;
        for (const HeardValue &v : values) {
            QJsonObject o = base;
            o.insert(QStringLiteral("key"), v.key);
            o.insert(QStringLiteral("value"), v.value);
            if (!v.unit.isEmpty())
                o.insert(QStringLiteral("unit"), v.unit);
            out << o;
        }
        return out;
    }
    QJsonArray keys;
    QJsonObject vals;
    QJsonObject units;
    for (const HeardValue &v : values) {
        keys.append(v.key);
        vals.insert(v.key, v.value);
        if (!v.unit.isEmpty())
            units.insert(v.key, v.unit);
    }
    if (!values.isEmpty()) {
        base.insert(QStringLiteral("keys"), keys);
        base.insert(QStringLiteral("values"), vals);
        base.insert(QStringLiteral("units"), units);
    }
    return {base};
}

} // namespace stepcom

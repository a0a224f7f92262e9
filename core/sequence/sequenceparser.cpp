#include "sequence/sequenceparser.h"

#include "map/registermap.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

#include <cmath>

namespace stepcom {

namespace {

using Kind = SequenceStep::Kind;

const QString kFormat = QStringLiteral("stepcom-sequence");

// The keys of each kind of step: its own word first.
const QList<std::pair<Kind, QStringList>> &stepKeys()
{
    static const QList<std::pair<Kind, QStringList>> keys{
        {Kind::Home, {QStringLiteral("home")}},
        {Kind::MoveTo, {QStringLiteral("move_to")}},
        {Kind::MoveBy, {QStringLiteral("move_by")}},
        {Kind::WaitInput,
         {QStringLiteral("wait_input"), QStringLiteral("on"), QStringLiteral("timeout_s")}},
        {Kind::Output, {QStringLiteral("output"), QStringLiteral("on")}},
        {Kind::Outputs, {QStringLiteral("outputs")}},
        {Kind::Dwell, {QStringLiteral("dwell_ms")}},
        {Kind::Repeat, {QStringLiteral("repeat"), QStringLiteral("steps")}},
        {Kind::Speed, {QStringLiteral("speed")}},
    };
    return keys;
}

QString typeName(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Bool:
        return SequenceParser::tr("a true/false");
    case QJsonValue::Double:
        return SequenceParser::tr("a number");
    case QJsonValue::String:
        return SequenceParser::tr("a text");
    case QJsonValue::Array:
        return SequenceParser::tr("a list");
    case QJsonValue::Object:
        return SequenceParser::tr("an object");
    case QJsonValue::Undefined:
        break;
    }
    return SequenceParser::tr("nothing");
}

// Reads one file, every problem said with where it is.
class Reader
{
public:
    Reader(const QString &fileName, const RegisterMap &map, QStringList *errors)
        : m_file(fileName)
        , m_map(map)
        , m_errors(errors)
    {}

    void error(const QString &where, const QString &what)
    {
        *m_errors << QStringLiteral("%1: %2: %3").arg(m_file, where, what);
    }
    bool ok() const { return m_errors->isEmpty(); }

    void unknownKeys(const QJsonObject &o, const QStringList &allowed, const QString &where)
    {
        for (auto it = o.begin(); it != o.end(); ++it) {
            if (!allowed.contains(it.key()))
                error(where, SequenceParser::tr("unknown key \"%1\" (allowed here: %2)")
                                 .arg(it.key(), allowed.join(QLatin1String(", "))));
        }
    }

    bool wrongType(const QJsonValue &v, QJsonValue::Type type, const QString &where,
                   const QString &wanted)
    {
        if (v.type() == type)
            return false;
        error(where, SequenceParser::tr("must be %1, not %2").arg(wanted, typeName(v)));
        return true;
    }

    // A whole number in [min, max], or nullopt (said).
    std::optional<int> integer(const QJsonValue &v, const QString &where, int min, int max)
    {
        if (wrongType(v, QJsonValue::Double, where, SequenceParser::tr("a whole number")))
            return std::nullopt;
        const double d = v.toDouble();
        if (d != std::floor(d) || d < min || d > max) {
            error(where, SequenceParser::tr("must be a whole number from %1 to %2, not %3")
                             .arg(min)
                             .arg(max)
                             .arg(d, 0, 'g', 17));
            return std::nullopt;
        }
        return int(d);
    }

    // "motor1" → 1 when this map has that motor (said otherwise).
    int motor(const QString &name, const QString &where)
    {
        static const QRegularExpression re(QStringLiteral("^motor([0-9]+)$"));
        const auto m = re.match(name);
        const int motors = m_map.blockCount(QStringLiteral("motor"));
        const int n = m.hasMatch() ? m.captured(1).toInt() : 0;
        if (n < 1 || n > motors) {
            error(where, SequenceParser::tr("unknown axis \"%1\" (this controller has motor1 .. "
                                            "motor%2)")
                             .arg(name)
                             .arg(motors));
            return 0;
        }
        return n;
    }

    // {"motor1": mm, ...}: each a value of the axis's `local` register (position or speed).
    QMap<int, double> axes(const QJsonValue &v, const QString &where, const QString &local,
                           bool relative)
    {
        QMap<int, double> out;
        if (wrongType(v, QJsonValue::Object, where,
                      SequenceParser::tr("an object {\"motor1\": …}")))
            return out;
        const QJsonObject o = v.toObject();
        if (o.isEmpty())
            error(where, SequenceParser::tr("names no axis"));
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString at = where + QLatin1Char('.') + it.key();
            const int n = motor(it.key(), at);
            if (n == 0)
                continue;
            if (wrongType(it.value(), QJsonValue::Double, at, SequenceParser::tr("a number")))
                continue;
            const double value = it.value().toDouble();
            const Parameter *p = m_map.blockParameter(QStringLiteral("motor"), n, local);
            QString why;
            // A distance may be negative and a position register's range is its own.
            if (p && !p->fromEngineering(relative ? std::abs(value) : value, &why)) {
                error(at, why);
                continue;
            }
            out.insert(n, value);
        }
        return out;
    }

    bool hasInput(int n) const { return n >= 1 && m_map.find(QStringLiteral("io.in%1").arg(n)); }
    int count(const char *pattern) const
    {
        int n = 0;
        while (m_map.find(QString::fromLatin1(pattern).arg(n + 1)))
            ++n;
        return n;
    }

    void readPoints(const QJsonValue &v, Sequence *s)
    {
        if (v.isUndefined())
            return;
        if (wrongType(v, QJsonValue::Object, QStringLiteral("points"),
                      SequenceParser::tr("an object of named points")))
            return;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            s->points.insert(it.key(), axes(it.value(), QStringLiteral("points.") + it.key(),
                                            QStringLiteral("position"), false));
    }

    void readLimits(const QJsonValue &v, Sequence *s)
    {
        if (v.isUndefined())
            return;
        const QString where = QStringLiteral("limits");
        if (wrongType(v, QJsonValue::Object, where,
                      SequenceParser::tr("an object {\"motor1\": {\"min\": …, \"max\": …}}")))
            return;
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it) {
            const QString at = where + QLatin1Char('.') + it.key();
            const int n = motor(it.key(), at);
            if (n == 0 || wrongType(it.value(), QJsonValue::Object, at,
                                    SequenceParser::tr("an object {\"min\": …, \"max\": …}")))
                continue;
            const QJsonObject axis = it.value().toObject();
            unknownKeys(axis, {QStringLiteral("min"), QStringLiteral("max")}, at);
            std::optional<double> ends[2];
            const char *names[2] = {"min", "max"};
            for (int i = 0; i < 2; ++i) {
                const QJsonValue e = axis.value(QLatin1String(names[i]));
                if (e.isUndefined())
                    continue;
                if (!wrongType(e, QJsonValue::Double,
                               at + QLatin1Char('.') + QLatin1String(names[i]),
                               SequenceParser::tr("a number")))
                    ends[i] = e.toDouble();
            }
            if (!ends[0] && !ends[1] && axis.isEmpty())
                error(at, SequenceParser::tr("sets neither min nor max"));
            else if (const QString why = s->limits.setAxis(m_map, n, ends[0], ends[1]);
                     !why.isEmpty())
                error(at, why);
        }
    }

    void readOnStop(const QJsonValue &v, Sequence *s)
    {
        if (v.isUndefined())
            return;
        const QString where = QStringLiteral("on_stop");
        if (wrongType(v, QJsonValue::Object, where, SequenceParser::tr("an object")))
            return;
        const QJsonObject o = v.toObject();
        unknownKeys(o, {QStringLiteral("outputs")}, where);
        const QJsonValue outputs = o.value(QStringLiteral("outputs"));
        if (outputs.isUndefined())
            return;
        if (outputs == QJsonValue(QStringLiteral("all_off")))
            s->outputsOffOnStop = true;
        else if (outputs != QJsonValue(QStringLiteral("leave")))
            error(where + QStringLiteral(".outputs"),
                  SequenceParser::tr("must be \"leave\" or \"all_off\""));
    }

    QList<SequenceStep> readSteps(const QJsonValue &v, const QString &where, const Sequence &s)
    {
        QList<SequenceStep> steps;
        if (wrongType(v, QJsonValue::Array, where, SequenceParser::tr("a list of steps")))
            return steps;
        const QJsonArray a = v.toArray();
        if (a.isEmpty())
            error(where, SequenceParser::tr("holds no step"));
        for (qsizetype i = 0; i < a.size(); ++i) {
            const QString at = QStringLiteral("%1[%2]").arg(where).arg(i);
            if (auto step = readStep(a.at(i), at, s))
                steps << *step;
        }
        return steps;
    }

    std::optional<SequenceStep> readStep(const QJsonValue &v, const QString &where,
                                         const Sequence &s)
    {
        if (wrongType(v, QJsonValue::Object, where, SequenceParser::tr("a step (an object)")))
            return std::nullopt;
        const QJsonObject o = v.toObject();
        QStringList kinds;
        QStringList words;
        const std::pair<Kind, QStringList> *chosen = nullptr;
        for (const auto &k : stepKeys()) {
            words << k.second.first();
            if (o.contains(k.second.first())) {
                kinds << k.second.first();
                chosen = &k;
            }
        }
        if (kinds.isEmpty()) {
            QStringList unknown = o.keys();
            if (!unknown.isEmpty()) {
                error(where, SequenceParser::tr("unknown key \"%1\": a step needs one of %2")
                                 .arg(unknown.join(QLatin1String("\", \"")),
                                      words.join(QLatin1String(", "))));
                return std::nullopt;
            }
        }
        if (kinds.size() != 1) {
            error(where, kinds.isEmpty() ? SequenceParser::tr("not a step: it needs one of %1")
                                               .arg(words.join(QLatin1String(", ")))
                                         : SequenceParser::tr("one step does one thing, not %1")
                                               .arg(kinds.join(QLatin1String(" and "))));
            return std::nullopt;
        }
        const int before = int(m_errors->size());
        unknownKeys(o, chosen->second, where);
        SequenceStep step;
        step.kind = chosen->first;
        step.path = where;
        const QString word = chosen->second.first();
        const QJsonValue value = o.value(word);
        const QString at = where + QLatin1Char('.') + word;
        switch (step.kind) {
        case Kind::Home:
            if (wrongType(value, QJsonValue::String, at,
                          SequenceParser::tr("\"order\" or a motor (\"motor1\")")))
                break;
            if (value.toString() == QLatin1String("order"))
                step.homeInOrder = true;
            else if (const int n = motor(value.toString(), at))
                step.homeMotors << n;
            break;
        case Kind::MoveTo:
            if (value.isString()) {
                step.point = value.toString();
                if (!s.points.contains(step.point)) {
                    const QStringList names = s.points.keys();
                    error(at,
                          SequenceParser::tr("unknown point \"%1\" (the file's points: %2)")
                              .arg(step.point, names.isEmpty() ? SequenceParser::tr("none")
                                                               : names.join(QLatin1String(", "))));
                }
                step.axes = s.points.value(step.point);
            } else {
                step.axes = axes(value, at, QStringLiteral("position"), false);
            }
            break;
        case Kind::MoveBy:
            step.axes = axes(value, at, QStringLiteral("move_distance"), true);
            break;
        case Kind::Speed:
            step.axes = axes(value, at, QStringLiteral("speed"), false);
            break;
        case Kind::WaitInput:
        case Kind::Output: {
            const bool input = step.kind == Kind::WaitInput;
            if (const auto n = integer(value, at, 1, 999)) {
                step.number = *n;
                const int have = count(input ? "io.in%1" : "io.out%1");
                if (*n > have)
                    error(at, (input ? SequenceParser::tr("the controller has no input %1 (it has "
                                                          "IN1 .. IN%2)")
                                     : SequenceParser::tr("the controller has no output %1 (it "
                                                          "has outputs 1 .. %2)"))
                                  .arg(*n)
                                  .arg(have));
                else if (!input && !m_map.find(QStringLiteral("output%1_on").arg(*n)))
                    error(at, SequenceParser::tr("the controller cannot switch output %1 alone "
                                                 "(only outputs with their own on/off command: "
                                                 "output 1); use \"outputs\": \"all_on\" or "
                                                 "\"all_off\"")
                                  .arg(*n));
            }
            const QJsonValue on = o.value(QStringLiteral("on"));
            if (on.isUndefined())
                error(where, SequenceParser::tr("needs \"on\": true or false"));
            else if (!wrongType(on, QJsonValue::Bool, where + QStringLiteral(".on"),
                                SequenceParser::tr("true or false")))
                step.on = on.toBool();
            const QJsonValue timeout = o.value(QStringLiteral("timeout_s"));
            if (input && !timeout.isUndefined() &&
                !wrongType(timeout, QJsonValue::Double, where + QStringLiteral(".timeout_s"),
                           SequenceParser::tr("a number of seconds"))) {
                const double t = timeout.toDouble();
                if (!(t > 0 && t <= 86400))
                    error(where + QStringLiteral(".timeout_s"),
                          SequenceParser::tr("must be more than 0 and at most 86400 s"));
                else
                    step.timeoutMs = int(std::llround(t * 1000));
            }
            break;
        }
        case Kind::Outputs:
            if (value == QJsonValue(QStringLiteral("all_on")))
                step.on = true;
            else if (value != QJsonValue(QStringLiteral("all_off")))
                error(at, SequenceParser::tr("must be \"all_on\" or \"all_off\""));
            break;
        case Kind::Dwell:
            if (const auto ms = integer(value, at, 0, 86400000))
                step.dwellMs = *ms;
            break;
        case Kind::Repeat:
            if (const auto n = integer(value, at, 1, 1000000))
                step.count = *n;
            if (!o.contains(QStringLiteral("steps")))
                error(where, SequenceParser::tr("a repeat needs \"steps\""));
            else
                step.steps = readSteps(o.value(QStringLiteral("steps")),
                                       where + QStringLiteral(".steps"), s);
            break;
        }
        if (m_errors->size() != before)
            return std::nullopt;
        return step;
    }

private:
    QString m_file;
    const RegisterMap &m_map;
    QStringList *m_errors;
};

} // namespace

QString SequenceParser::lineColumn(const QByteArray &json, int offset)
{
    const QByteArray before = json.left(offset);
    const int line = int(before.count('\n')) + 1;
    const int column = int(before.size() - (before.lastIndexOf('\n') + 1)) + 1;
    return tr("line %1, column %2").arg(line).arg(column);
}

std::optional<Sequence> SequenceParser::parse(const QByteArray &json, const QString &fileName,
                                              const RegisterMap &map, QStringList *errors)
{
    QStringList own;
    QStringList *out = errors ? errors : &own;
    const qsizetype already = out->size();
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *out << tr("%1: not valid JSON at %2: %3")
                    .arg(fileName, lineColumn(json, parseError.offset), parseError.errorString());
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *out << tr("%1: a sequence file is one JSON object").arg(fileName);
        return std::nullopt;
    }
    const QJsonObject o = doc.object();
    QStringList mine;
    Reader r(fileName, map, &mine);
    if (o.value(QStringLiteral("format")) != QJsonValue(kFormat))
        r.error(QStringLiteral("format"),
                tr("not a sequence file (\"format\" must be \"%1\")").arg(kFormat));
    else if (o.value(QStringLiteral("version")) != QJsonValue(kVersion))
        r.error(QStringLiteral("version"),
                tr("version %1 is not known (this StepCom reads version %2)")
                    .arg(o.value(QStringLiteral("version")).toVariant().toString())
                    .arg(kVersion));
    if (!r.ok()) {
        *out << mine;
        return std::nullopt;
    }
    r.unknownKeys(o,
                  {QStringLiteral("format"), QStringLiteral("version"), QStringLiteral("points"),
                   QStringLiteral("limits"), QStringLiteral("on_stop"), QStringLiteral("steps")},
                  QStringLiteral("file"));
    Sequence s;
    s.fileName = fileName;
    r.readPoints(o.value(QStringLiteral("points")), &s);
    r.readLimits(o.value(QStringLiteral("limits")), &s);
    r.readOnStop(o.value(QStringLiteral("on_stop")), &s);
    if (!o.contains(QStringLiteral("steps")))
        r.error(QStringLiteral("steps"), tr("the file has no \"steps\""));
    else
        s.steps = r.readSteps(o.value(QStringLiteral("steps")), QStringLiteral("steps"), s);
    *out << mine;
    if (out->size() != already)
        return std::nullopt;
    return s;
}

std::optional<Sequence> SequenceParser::load(const QString &path, const RegisterMap &map,
                                             QStringList *errors)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (errors)
            *errors << tr("%1: cannot be read: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return parse(file.readAll(), path, map, errors);
}

} // namespace stepcom

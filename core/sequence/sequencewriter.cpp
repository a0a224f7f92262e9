#include "sequence/sequencewriter.h"

#include "map/parameter.h"
#include "sequence/sequenceparser.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace stepcom {

namespace {

QString motorKey(int motor)
{
    return QStringLiteral("motor%1").arg(motor);
}

QJsonObject axesObject(const QMap<int, double> &axes)
{
    QJsonObject o;
    for (auto it = axes.begin(); it != axes.end(); ++it)
        o.insert(motorKey(it.key()), it.value());
    return o;
}

QJsonArray stepsArray(const QList<SequenceStep> &steps);

QJsonObject stepObject(const SequenceStep &step)
{
    using Kind = SequenceStep::Kind;
    QJsonObject o;
    const QString word = SequenceStep::kindWord(step.kind);
    switch (step.kind) {
    case Kind::Home:
        o.insert(word, step.homeInOrder || step.homeMotors.isEmpty()
                           ? QStringLiteral("order")
                           : motorKey(step.homeMotors.first()));
        break;
    case Kind::MoveTo:
        if (!step.point.isEmpty())
            o.insert(word, step.point);
        else
            o.insert(word, axesObject(step.axes));
        break;
    case Kind::MoveBy:
    case Kind::Speed:
        o.insert(word, axesObject(step.axes));
        break;
    case Kind::WaitInput:
        o.insert(word, step.number);
        o.insert(QStringLiteral("on"), step.on);
        if (step.timeoutMs > 0)
            o.insert(QStringLiteral("timeout_s"), step.timeoutMs / 1000.0);
        break;
    case Kind::Output:
        o.insert(word, step.number);
        o.insert(QStringLiteral("on"), step.on);
        break;
    case Kind::Outputs:
        o.insert(word, step.on ? QStringLiteral("all_on") : QStringLiteral("all_off"));
        break;
    case Kind::Dwell:
        o.insert(word, step.dwellMs);
        break;
    case Kind::Repeat:
        o.insert(word, step.count);
        o.insert(QStringLiteral("steps"), stepsArray(step.steps));
        break;
    }
    return o;
}

QJsonArray stepsArray(const QList<SequenceStep> &steps)
{
    QJsonArray a;
    for (const SequenceStep &step : steps)
        a.append(stepObject(step));
    return a;
}

} // namespace

QJsonObject SequenceWriter::toJson(const Sequence &sequence, const RegisterMap &map)
{
    QJsonObject o;
    o.insert(QStringLiteral("format"), QStringLiteral("stepcom-sequence"));
    o.insert(QStringLiteral("version"), SequenceParser::kVersion);
    QJsonObject points;
    for (auto it = sequence.points.begin(); it != sequence.points.end(); ++it)
        points.insert(it.key(), axesObject(it.value()));
    o.insert(QStringLiteral("points"), points);
    QJsonObject limits;
    const auto &axes = sequence.limits.axes();
    for (auto it = axes.begin(); it != axes.end(); ++it) {
        const Parameter *p = TravelLimits::positionParameter(map, it.key());
        if (!p || it.value().isEmpty())
            continue;
        QJsonObject ends;
        if (it.value().min)
            ends.insert(QStringLiteral("min"), p->toEngineering(*it.value().min));
        if (it.value().max)
            ends.insert(QStringLiteral("max"), p->toEngineering(*it.value().max));
        limits.insert(motorKey(it.key()), ends);
    }
    if (!limits.isEmpty())
        o.insert(QStringLiteral("limits"), limits);
    if (sequence.outputsOffOnStop)
        o.insert(QStringLiteral("on_stop"),
                 QJsonObject{{QStringLiteral("outputs"), QStringLiteral("all_off")}});
    o.insert(QStringLiteral("steps"), stepsArray(sequence.steps));
    return o;
}

QByteArray SequenceWriter::write(const Sequence &sequence, const RegisterMap &map)
{
    return QJsonDocument(toJson(sequence, map)).toJson(QJsonDocument::Indented);
}

} // namespace stepcom

#include "sequence/sequenceplan.h"

#include "map/parameter.h"
#include "map/registermap.h"

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");

} // namespace

QString SequencePlan::axesText(const RegisterMap &map, const QMap<int, double> &axes)
{
    QStringList parts;
    for (auto it = axes.begin(); it != axes.end(); ++it) {
        const Parameter *p = map.blockParameter(kMotor, it.key(), QStringLiteral("position"));
        parts << QStringLiteral("motor%1 %2 %3")
                     .arg(it.key())
                     .arg(it.value(), 0, 'f', p ? p->decimals() : 2)
                     .arg(p ? p->unit : QString());
    }
    return parts.join(QLatin1String(", "));
}

QList<int> SequencePlan::movedMotors(const Sequence &sequence)
{
    QList<int> motors;
    for (const SequenceStep *step : sequence.allSteps()) {
        if (step->kind != SequenceStep::Kind::MoveTo && step->kind != SequenceStep::Kind::MoveBy)
            continue;
        for (auto it = step->axes.begin(); it != step->axes.end(); ++it) {
            if (!motors.contains(it.key()))
                motors << it.key();
        }
    }
    std::sort(motors.begin(), motors.end());
    return motors;
}

QString SequencePlan::describe(const Sequence &s, const RegisterMap &map, int cycles,
                               bool checkSteps)
{
    QString text = tr("Sequence %1: %n step(s) in the file", nullptr, int(s.allSteps().size()))
                       .arg(s.fileName) +
                   QLatin1Char('\n');
    for (auto it = s.points.begin(); it != s.points.end(); ++it)
        text += tr("  point %1: %2").arg(it.key(), axesText(map, it.value())) + QLatin1Char('\n');
    for (auto it = s.limits.axes().begin(); it != s.limits.axes().end(); ++it) {
        const Parameter *p = map.blockParameter(kMotor, it.key(), QStringLiteral("position"));
        if (!p)
            continue;
        text += tr("  limits motor%1: %2 .. %3 %4")
                    .arg(it.key())
                    .arg(it->min ? p->formatRaw(*it->min) : QStringLiteral("−∞"),
                         it->max ? p->formatRaw(*it->max) : QStringLiteral("+∞"), p->unit) +
                QLatin1Char('\n');
    }
    text += (s.outputsOffOnStop ? tr("  on a stop: all outputs off")
                                : tr("  on a stop: the outputs are left as they are")) +
            QLatin1Char('\n');
    text += tr("  cycles: %1 (the whole step list each time)").arg(cycles) + QLatin1Char('\n');
    if (checkSteps) {
        QStringList motors;
        for (int m : movedMotors(s))
            motors << QStringLiteral("motor%1").arg(m);
        text += tr("  then the lost-step test (lost-steps) on %1, each referenced on its home "
                   "switch")
                    .arg(motors.join(QLatin1String(", "))) +
                QLatin1Char('\n');
    }
    return text;
}

} // namespace stepcom

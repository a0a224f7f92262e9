#include "sequence/sequencecheck.h"

#include "map/registermap.h"
#include "motion/travellimits.h"

#include <cmath>

namespace stepcom {

namespace {

using Kind = SequenceStep::Kind;

// A walk through the steps with the axes' positions as they would be.
class Walk
{
public:
    Walk(const Sequence &sequence, const RegisterMap &map, const TravelLimits &travel,
         const SequenceCheck::Start &start)
        : m_s(sequence)
        , m_map(map)
        , m_travel(travel)
        , m_start(start)
        , m_axes(start.axes)
    {}

    void cycles(int count)
    {
        for (int c = 0; c < count && m_budget > 0; ++c) {
            const auto before = m_axes;
            steps(m_s.steps);
            if (m_axes == before)
                break; // every further cycle walks the same positions
        }
        if (m_budget <= 0)
            m_errors << SequenceCheck::tr("%1: the run has too many steps to check its positions "
                                          "(more than %2): make it shorter or use fewer cycles")
                            .arg(m_s.fileName)
                            .arg(kBudget);
    }
    QStringList errors() const { return m_errors; }

private:
    static constexpr int kBudget = 2000000;

    void error(const SequenceStep &step, const QString &what)
    {
        const QString text = QStringLiteral("%1: %2: %3").arg(m_s.fileName, step.path, what);
        if (!m_errors.contains(text))
            m_errors << text;
    }

    void steps(const QList<SequenceStep> &list)
    {
        for (const SequenceStep &s : list) {
            if (--m_budget <= 0)
                return;
            step(s);
        }
    }

    void target(const SequenceStep &step, int motor, double to)
    {
        const Parameter *pos = TravelLimits::positionParameter(m_map, motor);
        SequenceCheck::Axis &a = m_axes[motor];
        if (pos) {
            const qint64 raw = std::llround(to * pos->scale);
            const AxisTravel own = m_s.limits.axis(motor);
            if ((own.max && raw > *own.max) || (own.min && raw < *own.min))
                error(step, SequenceCheck::tr("motor %1 would go to %2 %3, outside the file's "
                                              "limits (%4 .. %5 %3)")
                                .arg(motor)
                                .arg(pos->formatRaw(raw), pos->unit,
                                     own.min ? pos->formatRaw(*own.min) : QStringLiteral("−∞"),
                                     own.max ? pos->formatRaw(*own.max) : QStringLiteral("+∞")));
        }
        if (const QString why = m_travel.refuseTarget(m_map, motor, a.position.value_or(to), to);
            !why.isEmpty())
            error(step, why);
        a.position = to;
    }

    void step(const SequenceStep &s)
    {
        switch (s.kind) {
        case Kind::Home: {
            QList<int> motors = s.homeMotors;
            if (s.homeInOrder) {
                if (m_start.homingOrder) {
                    motors = *m_start.homingOrder;
                    if (motors.isEmpty())
                        error(s, SequenceCheck::tr("the controller's homing order (40177, 40178) "
                                                   "names no motor: \"home\": \"order\" homes "
                                                   "nothing"));
                } else {
                    motors.clear();
                    for (int m = 1; m <= m_map.blockCount(QStringLiteral("motor")); ++m)
                        motors << m;
                }
            }
            for (int m : motors)
                m_axes[m] = SequenceCheck::Axis{true, 0.0};
            break;
        }
        case Kind::MoveTo:
            for (auto it = s.axes.begin(); it != s.axes.end(); ++it) {
                if (!m_axes.value(it.key()).referenced)
                    error(s, SequenceCheck::tr("motor %1 is not referenced: a move_to needs a "
                                               "home step before it (or the axis referenced "
                                               "already)")
                                 .arg(it.key()));
                target(s, it.key(), it.value());
            }
            break;
        case Kind::MoveBy:
            for (auto it = s.axes.begin(); it != s.axes.end(); ++it) {
                SequenceCheck::Axis &a = m_axes[it.key()];
                if (a.position)
                    target(s, it.key(), *a.position + it.value());
            }
            break;
        case Kind::Repeat:
            for (int i = 0; i < s.count && m_budget > 0; ++i) {
                const auto before = m_axes;
                steps(s.steps);
                if (m_axes == before)
                    break;
            }
            break;
        case Kind::WaitInput:
        case Kind::Output:
        case Kind::Outputs:
        case Kind::Dwell:
        case Kind::Speed:
            break;
        }
    }

    const Sequence &m_s;
    const RegisterMap &m_map;
    const TravelLimits &m_travel;
    const SequenceCheck::Start &m_start;
    QHash<int, SequenceCheck::Axis> m_axes;
    QStringList m_errors;
    int m_budget = kBudget;
};

} // namespace

QStringList SequenceCheck::check(const Sequence &sequence, const RegisterMap &map,
                                 const TravelLimits &travel, const Start &start, int cycles)
{
    Walk walk(sequence, map, travel, start);
    walk.cycles(std::max(1, cycles));
    return walk.errors();
}

QList<int> SequenceCheck::homingOrder(qint64 first, qint64 second)
{
    QList<int> motors;
    for (qint64 m : {first, second}) {
        if (m > 0 && !motors.contains(int(m)))
            motors << int(m);
    }
    return motors;
}

} // namespace stepcom

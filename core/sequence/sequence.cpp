#include "sequence/sequence.h"

namespace stepcom {

namespace {

void collect(const QList<SequenceStep> &steps, QList<const SequenceStep *> *out)
{
    for (const SequenceStep &s : steps) {
        *out << &s;
        collect(s.steps, out);
    }
}

} // namespace

QList<const SequenceStep *> Sequence::allSteps() const
{
    QList<const SequenceStep *> out;
    collect(steps, &out);
    return out;
}

QList<int> Sequence::motors() const
{
    QList<int> motors;
    const auto add = [&motors](int m) {
        if (!motors.contains(m))
            motors << m;
    };
    for (const SequenceStep *s : allSteps()) {
        for (int m : s->homeMotors)
            add(m);
        for (auto it = s->axes.begin(); it != s->axes.end(); ++it)
            add(it.key());
    }
    std::sort(motors.begin(), motors.end());
    return motors;
}

} // namespace stepcom

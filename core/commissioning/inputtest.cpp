#include "commissioning/inputtest.h"

#include "map/registermap.h"

#include <algorithm>

namespace stepcom {

std::optional<QMap<int, bool>> InputObservation::inputs(const RegisterMap &map,
                                                        const QHash<QString, qint64> &values)
{
    QMap<int, bool> out;
    for (int n = 1;; ++n) {
        const QString key = QStringLiteral("io.in%1").arg(n);
        if (!map.find(key))
            break;
        const auto it = values.constFind(key);
        if (it == values.cend())
            return std::nullopt;
        out.insert(n, *it != 0);
    }
    return out;
}

void InputObservation::start(const QMap<int, bool> &baseline)
{
    m_baseline = baseline;
    m_changed.clear();
    m_started = true;
}

void InputObservation::add(const QMap<int, bool> &sample)
{
    if (!m_started)
        return;
    for (auto it = sample.cbegin(); it != sample.cend(); ++it) {
        if (m_baseline.contains(it.key()) && m_baseline.value(it.key()) != it.value())
            m_changed.insert(it.key(), true);
    }
}

QList<int> InputObservation::changed() const
{
    return m_changed.keys();
}

QString InputTest::localKey(Role role)
{
    switch (role) {
    case Role::PositiveLimit:
        return QStringLiteral("limit_positive");
    case Role::NegativeLimit:
        return QStringLiteral("limit_negative");
    case Role::Home:
        return QStringLiteral("home_input");
    }
    return {};
}

QString InputTest::roleName(Role role)
{
    switch (role) {
    case Role::PositiveLimit:
        return tr("positive limit");
    case Role::NegativeLimit:
        return tr("negative limit");
    case Role::Home:
        return tr("home switch");
    }
    return {};
}

namespace {

std::optional<int> configuredInput(const MotorWiring &w, InputTest::Role role)
{
    switch (role) {
    case InputTest::Role::PositiveLimit:
        return w.positive;
    case InputTest::Role::NegativeLimit:
        return w.negative;
    case InputTest::Role::Home:
        return w.home;
    }
    return std::nullopt;
}

} // namespace

InputJudgement InputTest::judge(const RegisterMap &map, int motor, Role role,
                                const QList<MotorWiring> &wiring, const QList<int> &changed)
{
    InputJudgement j;
    j.changed = changed;
    std::sort(j.changed.begin(), j.changed.end());
    j.changed.erase(std::unique(j.changed.begin(), j.changed.end()), j.changed.end());
    const auto own = std::find_if(wiring.cbegin(), wiring.cend(),
                                  [&](const MotorWiring &w) { return w.motor == motor; });
    if (own != wiring.cend())
        j.configured = configuredInput(*own, role).value_or(0);
    const QString what = tr("the %1 of motor %2").arg(roleName(role)).arg(motor);
    const QString configuredName = inputName(j.configured);

    if (j.changed.isEmpty()) {
        j.verdict = InputJudgement::Verdict::NoneAnswered;
        j.message = j.configured == 0
                        ? tr("No input changed while %1 was pressed, and none is configured for "
                             "it. If the machine has no such switch, skip this step; otherwise "
                             "check the switch, its wiring and its 24 V supply.")
                              .arg(what)
                        : tr("No input changed while %1 was pressed (configured: %2). Check the "
                             "switch, its wiring and its 24 V supply (the inputs are active on a "
                             "24 V negative signal), then try again.")
                              .arg(what, configuredName);
        return j;
    }
    if (j.changed.size() > 1) {
        QStringList names;
        for (int n : std::as_const(j.changed))
            names << inputName(n);
        j.verdict = InputJudgement::Verdict::Several;
        j.message = tr("Several inputs changed while %1 was pressed (%2): press only this switch "
                       "and try again.")
                        .arg(what, names.join(QLatin1String(", ")));
        return j;
    }
    j.answered = j.changed.first();
    const QString answeredName = inputName(j.answered);

    // The answered input may also serve another role or motor: say so, whatever the verdict.
    for (const MotorWiring &w : wiring) {
        for (Role r : {Role::PositiveLimit, Role::NegativeLimit, Role::Home}) {
            if ((w.motor == motor && r == role) || configuredInput(w, r).value_or(0) != j.answered)
                continue;
            // Home on the negative limit's switch is the usual wiring, not a conflict.
            const bool usualShare =
                w.motor == motor && ((role == Role::NegativeLimit && r == Role::Home) ||
                                     (role == Role::Home && r == Role::NegativeLimit));
            if (!usualShare)
                j.notes << tr("%1 is also configured as the %2 of motor %3")
                               .arg(answeredName, roleName(r))
                               .arg(w.motor);
        }
    }

    if (j.answered == j.configured) {
        j.verdict = InputJudgement::Verdict::Matches;
        j.message = tr("%1 answered for %2, as configured.").arg(answeredName, what);
        return j;
    }
    j.verdict = InputJudgement::Verdict::OtherInput;
    auto fix = [&](Role r) {
        if (const Parameter *p = map.blockParameter(QStringLiteral("motor"), motor, localKey(r));
            p && p->checkRaw(j.answered).isEmpty())
            j.fixes.append({p->key, j.answered});
    };
    fix(role);
    // The home input usually shares the negative limit's switch: when the limit's input was
    // wrong and home named the same input, home is wrong the same way.
    if (role == Role::NegativeLimit && own != wiring.cend() && j.configured != 0 &&
        own->home.value_or(0) == j.configured)
        fix(Role::Home);
    QStringList writes;
    for (const InputFix &f : std::as_const(j.fixes))
        writes << QStringLiteral("%1 = %2").arg(f.key, inputName(int(f.raw)));
    j.message =
        j.configured == 0
            ? tr("%1 answered for %2, which is not configured (none). Proposed: %3.")
                  .arg(answeredName, what, writes.join(QLatin1String(", ")))
            : tr("%1 answered for %2, but %3 is configured: the wiring and the "
                 "configuration disagree. Proposed: %4 (or rewire the switch to %3).")
                  .arg(answeredName, what, configuredName, writes.join(QLatin1String(", ")));
    if (j.fixes.isEmpty())
        j.message = tr("%1 answered for %2, and this register map cannot name %1 there.")
                        .arg(answeredName, what);
    return j;
}

} // namespace stepcom

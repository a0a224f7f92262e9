#include "widgets/checklist/checklistinputstep.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"

#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

namespace {

QHash<QString, qint64> deviceValues(const DeviceSession &session)
{
    QHash<QString, qint64> v;
    for (const Parameter *p : session.map().holdings()) {
        if (const auto raw = session.parameters()->store()->deviceValue(p->key))
            v.insert(p->key, *raw);
    }
    return v;
}

} // namespace

ChecklistInputStep::ChecklistInputStep(DeviceSession *session, WriteFlow *writes,
                                       const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_watch(new QPushButton(this))
    , m_done(new QPushButton(this))
    , m_fix(new QPushButton(this))
{
    m_watch->setObjectName(QStringLiteral("watchButton"));
    m_done->setObjectName(QStringLiteral("doneButton"));
    m_fix->setObjectName(QStringLiteral("fixButton"));
    auto *row = new QHBoxLayout;
    row->addWidget(m_watch);
    row->addWidget(m_done);
    row->addStretch(1);
    body()->addLayout(row);
    body()->addWidget(m_fix);
    for (QPushButton *b : {m_watch, m_done, m_fix})
        b->setAutoDefault(false);
    m_done->setEnabled(false);
    m_fix->hide();
    needsController(m_watch);
    connect(m_watch, &QPushButton::clicked, this, &ChecklistInputStep::startWatching);
    connect(m_done, &QPushButton::clicked, this, &ChecklistInputStep::judge);
    // Every poll after the baseline is a sample: a press that reaches one poll is seen.
    connect(session->status(), &SessionStatus::statusCycleFinished, this, [this](bool ok) {
        if (!ok || !m_observation.started())
            return;
        if (const auto in =
                InputObservation::inputs(this->session()->map(), deviceValues(*this->session())))
            m_observation.add(*in);
    });
    connect(m_fix, &QPushButton::clicked, this, [this] {
        QList<std::pair<QString, qint64>> values;
        for (const InputFix &f : std::as_const(m_fixes))
            values.append({f.key, f.raw});
        proposeWrite(values, [this](bool ok) {
            setStatus(ok ? tr("The input setting is written and verified. Repeat the step to "
                              "confirm.")
                         : tr("The input setting was not written."));
            if (ok)
                m_fix->hide();
        });
    });
    retranslate();
}

InputTest::Role ChecklistInputStep::role() const
{
    switch (step().kind) {
    case ChecklistStep::Kind::LimitPositive:
        return InputTest::Role::PositiveLimit;
    case ChecklistStep::Kind::LimitNegative:
        return InputTest::Role::NegativeLimit;
    default:
        break;
    }
    return InputTest::Role::Home;
}

QList<MotorWiring> ChecklistInputStep::wiring() const
{
    QList<MotorWiring> out;
    const RegisterMap &map = session()->map();
    const ParameterStore *store = session()->parameters()->store();
    for (int n = 1; n <= map.blockCount(QStringLiteral("motor")); ++n) {
        MotorWiring w;
        w.motor = n;
        const auto value = [&](const char *local) -> std::optional<int> {
            const Parameter *p =
                map.blockParameter(QStringLiteral("motor"), n, QLatin1String(local));
            const auto v = p ? store->deviceValue(p->key) : std::nullopt;
            return v ? std::optional<int>(int(*v)) : std::nullopt;
        };
        w.positive = value("limit_positive");
        w.negative = value("limit_negative");
        w.home = value("home_input");
        out << w;
    }
    return out;
}

void ChecklistInputStep::startWatching()
{
    const auto baseline = InputObservation::inputs(session()->map(), deviceValues(*session()));
    if (!session()->connection()->isConnected() || !baseline) {
        setStatus(tr("The inputs are not known yet: connect and wait for the status."));
        return;
    }
    m_observation.start(*baseline);
    m_fix->hide();
    m_done->setEnabled(true);
    setStatus(tr("Watching the inputs: press the %1 of motor %2 now, let go, then click Done.")
                  .arg(InputTest::roleName(role()))
                  .arg(step().motor));
}

void ChecklistInputStep::judge()
{
    if (!m_observation.started())
        return;
    const InputJudgement j =
        InputTest::judge(session()->map(), step().motor, role(), wiring(), m_observation.changed());
    m_observation = InputObservation();
    m_done->setEnabled(false);
    QList<ChecklistMeasurement> m{
        {QStringLiteral("input_configured"), inputName(j.configured), QString()},
        {QStringLiteral("input_answered"),
         j.answered ? inputName(j.answered)
                    : (j.changed.isEmpty() ? inputName(0) : QString::number(j.changed.size())),
         QString()}};
    m_fixes = j.fixes;
    QStringList fixes;
    for (const InputFix &f : j.fixes) {
        const Parameter *p = session()->map().find(f.key);
        fixes << QStringLiteral("%1 = %2").arg(f.key,
                                               p ? p->displayRaw(f.raw) : QString::number(f.raw));
    }
    if (!fixes.isEmpty())
        m << ChecklistMeasurement{QStringLiteral("fix"), fixes.join(QLatin1String(", ")),
                                  QString()};
    finishStep(j.passed() ? StepResult::Passed : StepResult::Failed, m);
    QString text = j.message;
    if (!j.notes.isEmpty())
        text += QLatin1Char('\n') + j.notes.join(QLatin1Char('\n'));
    setStatus(text);
    if (!m_fixes.isEmpty()) {
        m_fix->setText(tr("Write the fix (%1)…").arg(fixes.join(QLatin1String(", "))));
        m_fix->show();
    }
}

void ChecklistInputStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_watch->setText(tr("Press it now"));
    m_done->setText(tr("Done"));
}

} // namespace stepcom

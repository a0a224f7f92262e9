#include "widgets/checklist/checklistmotionstep.h"

#include "motion/motionjudge.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

ChecklistMotionStep::ChecklistMotionStep(DeviceSession *session, WriteFlow *writes,
                                         const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_run(new QPushButton(this))
{
    m_run->setObjectName(QStringLiteral("runButton"));
    m_run->setAutoDefault(false);
    auto *row = new QHBoxLayout;
    if (step.kind == ChecklistStep::Kind::Interpolation) {
        m_path = new QComboBox(this);
        m_path->addItems({QString(), QString()});
        row->addWidget(m_path);
    }
    row->addWidget(m_run);
    row->addStretch(1);
    body()->addLayout(row);
    needsController(m_run);
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (!this->session()->connection()->isConnected()) {
            setStatus(tr("Not connected: nothing was sent."));
            return;
        }
        const QString key = commandKey();
        StatusValues now;
        for (const Parameter *p : this->session()->map().holdings()) {
            if (const auto v = this->session()->parameters()->store()->deviceValue(p->key))
                now.insert(p->key, *v);
        }
        // Only what the supervisor will follow to its end is run: its verdict decides the step.
        if (!MotionJudge::plan(this->session()->map(), key, now)) {
            setStatus(tr("Nothing to run: the homing order is empty, every motor runs, or the "
                         "path's registers are not read yet."));
            return;
        }
        m_running = key;
        const QString warning = this->session()->motion()->startWarning(m_running);
        this->session()->command(m_running);
        setStatus(warning.isEmpty() ? tr("Running…") : warning);
    });
    connect(session, &DeviceSession::commandFinished, this, [this](const QString &key, bool ok) {
        if (key == m_running && !ok) {
            m_running.clear();
            setStatus(tr("The command was not acknowledged: nothing moved."));
        }
    });
    connect(session->motion(), &MotionSupervisor::finished, this, &ChecklistMotionStep::onFinished);
    retranslate();
}

QString ChecklistMotionStep::commandKey() const
{
    switch (step().kind) {
    case ChecklistStep::Kind::Homing: {
        const Parameter *p = motorParameter("home");
        return p ? p->key : QString();
    }
    case ChecklistStep::Kind::HomingOrder:
        return QStringLiteral("home_all");
    default:
        break;
    }
    return m_path && m_path->currentIndex() == 1 ? QStringLiteral("line.start")
                                                 : QStringLiteral("arc.start");
}

void ChecklistMotionStep::onFinished(const MotionOutcome &o)
{
    if (m_running.isEmpty() || o.start.command != m_running)
        return;
    m_running.clear();
    const RegisterMap &map = session()->map();
    QList<ChecklistMeasurement> m;
    for (const AxisEnd &a : o.axes) {
        const Parameter *pos =
            map.blockParameter(QStringLiteral("motor"), a.motor, QStringLiteral("position"));
        if (!pos)
            continue;
        const QString axis = QStringLiteral(".m%1").arg(a.motor);
        if (a.position)
            m << ChecklistMeasurement{QStringLiteral("position_end") + axis,
                                      pos->formatRaw(*a.position), pos->unit};
        if (a.target)
            m << ChecklistMeasurement{QStringLiteral("expected_end") + axis,
                                      pos->formatRaw(*a.target), pos->unit};
    }
    if (o.start.kind == MotionKind::HomeInOrder) {
        QStringList order;
        for (int n : o.start.motors)
            order << QString::number(n);
        m << ChecklistMeasurement{QStringLiteral("order"), order.join(QLatin1String(", ")),
                                  QString()};
    }
    m << ChecklistMeasurement{QStringLiteral("outcome"), o.verdictWord(), QString()};
    finishStep(o.ok() ? StepResult::Passed : StepResult::Failed, m);
    setStatus(session()->motion()->text(o));
}

void ChecklistMotionStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    switch (step().kind) {
    case ChecklistStep::Kind::Homing:
        m_run->setText(tr("Home motor %1").arg(step().motor));
        break;
    case ChecklistStep::Kind::HomingOrder:
        m_run->setText(tr("Home in order"));
        break;
    default:
        m_run->setText(tr("Run the test"));
        break;
    }
    if (m_path) {
        m_path->setItemText(0, tr("The configured arc"));
        m_path->setItemText(1, tr("The configured line"));
    }
}

} // namespace stepcom

#include "widgets/checklist/checklistcalibrationstep.h"

#include "commissioning/travelcalibration.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/stepmove.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

ChecklistCalibrationStep::ChecklistCalibrationStep(DeviceSession *session, WriteFlow *writes,
                                                   const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_commanded(new QDoubleSpinBox(this))
    , m_move(new QPushButton(this))
    , m_measured(new QDoubleSpinBox(this))
    , m_propose(new QPushButton(this))
    , m_write(new QPushButton(this))
{
    const Parameter *pitch = motorParameter("pitch");
    const QString unit = pitch ? QLatin1Char(' ') + pitch->unit : QString();
    for (QDoubleSpinBox *f : {m_commanded, m_measured}) {
        f->setDecimals(3);
        f->setRange(0.001, TravelCalibration::MaxDistance);
        f->setSuffix(unit);
    }
    m_commanded->setValue(10.0);
    m_measured->setValue(10.0);
    m_measured->setEnabled(false);
    m_propose->setEnabled(false);
    m_write->hide();
    m_move->setObjectName(QStringLiteral("moveButton"));
    m_propose->setObjectName(QStringLiteral("proposeButton"));
    m_write->setObjectName(QStringLiteral("writeButton"));
    for (QPushButton *b : {m_move, m_propose, m_write})
        b->setAutoDefault(false);
    auto *grid = new QGridLayout;
    grid->addWidget(m_commanded, 0, 0);
    grid->addWidget(m_move, 0, 1);
    grid->addWidget(m_measured, 1, 0);
    grid->addWidget(m_propose, 1, 1);
    grid->setColumnStretch(0, 1);
    body()->addLayout(grid);
    body()->addWidget(m_write);

    needsController(m_move);
    connect(m_move, &QPushButton::clicked, this, [this] {
        StepMoveRequest r{StepMoveRequest::Kind::By, this->step().motor, m_commanded->value(), 0};
        m_mine = true;
        if (const QString why = this->session()->stepMove()->start(r); !why.isEmpty()) {
            m_mine = false;
            setStatus(why);
            return;
        }
        m_write->hide();
        m_proposal.reset();
        setStatus(tr("Moving…"));
    });
    connect(session->stepMove(), &StepMove::finished, this, &ChecklistCalibrationStep::onMoved);
    connect(m_propose, &QPushButton::clicked, this, &ChecklistCalibrationStep::propose);
    connect(m_write, &QPushButton::clicked, this, [this] {
        const Parameter *p = motorParameter("pitch");
        if (!p || !m_proposal || !m_pitchNow)
            return;
        const qint64 before = *m_pitchNow;
        const qint64 after = *m_proposal;
        proposeWrite({{p->key, after}}, [this, before, after](bool ok) {
            if (!ok) {
                setStatus(tr("The pitch was not written."));
                return;
            }
            m_write->hide();
            finishStep(StepResult::Passed, measurements(before, after));
            setStatus(tr("Passed: the corrected pitch is written and verified."));
        });
    });
    retranslate();
}

QList<ChecklistMeasurement>
ChecklistCalibrationStep::measurements(qint64 before, std::optional<qint64> after) const
{
    const Parameter *p = motorParameter("pitch");
    QList<ChecklistMeasurement> m{
        {QStringLiteral("commanded"), QString::number(m_moved, 'f', 3), p->unit},
        {QStringLiteral("measured"), QString::number(m_measured->value(), 'f', 3), p->unit},
        {QStringLiteral("pitch_before"), p->formatRaw(before), p->unit}};
    if (after)
        m << ChecklistMeasurement{QStringLiteral("pitch_after"), p->formatRaw(*after), p->unit};
    return m;
}

void ChecklistCalibrationStep::onMoved(const StepMoveResult &r)
{
    if (!std::exchange(m_mine, false))
        return;
    setStatus(r.text);
    const Parameter *p = motorParameter("pitch");
    m_pitchNow = p ? session()->parameters()->store()->deviceValue(p->key) : std::nullopt;
    m_moved = r.request.value;
    // A measurement is asked for only when the axis arrived where it was sent.
    m_measured->setEnabled(r.arrived && m_pitchNow);
    m_propose->setEnabled(r.arrived && m_pitchNow);
    if (r.arrived)
        m_measured->setValue(m_moved);
}

void ChecklistCalibrationStep::propose()
{
    const Parameter *p = motorParameter("pitch");
    if (!p || !m_pitchNow)
        return;
    const CalibrationProposal c =
        TravelCalibration::propose(*p, *m_pitchNow, m_moved, m_measured->value());
    if (!c.ok()) {
        setStatus(c.error);
        return;
    }
    if (*c.raw == *m_pitchNow) {
        finishStep(StepResult::Passed, measurements(*m_pitchNow, std::nullopt));
        setStatus(tr("Passed: the axis moved what it was told; the pitch stays %1 %2.")
                      .arg(p->formatRaw(*m_pitchNow), p->unit));
        return;
    }
    m_proposal = c.raw;
    m_write->setText(tr("Write the corrected pitch %1 %2…").arg(p->formatRaw(*c.raw), p->unit));
    m_write->show();
    setStatus(tr("Measured ÷ commanded = %1: the pitch %2 %3 should be %4 %3.")
                  .arg(QString::number(c.factor, 'f', 4), p->formatRaw(*m_pitchNow), p->unit,
                       p->formatRaw(*c.raw)));
}

void ChecklistCalibrationStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_commanded->setPrefix(tr("Commanded: "));
    m_measured->setPrefix(tr("Measured: "));
    // The prefixes say it on screen; a screen reader needs the names.
    m_commanded->setAccessibleName(tr("Commanded distance"));
    m_measured->setAccessibleName(tr("Measured distance"));
    m_move->setText(tr("Move this distance"));
    m_propose->setText(tr("Propose the pitch"));
    if (m_proposal) {
        if (const Parameter *p = motorParameter("pitch"))
            m_write->setText(
                tr("Write the corrected pitch %1 %2…").arg(p->formatRaw(*m_proposal), p->unit));
    }
}

} // namespace stepcom

#include "widgets/checklist/checklistdirectionstep.h"

#include "commissioning/directioncheck.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/stepmove.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

ChecklistDirectionStep::ChecklistDirectionStep(DeviceSession *session, WriteFlow *writes,
                                               const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_distance(new QDoubleSpinBox(this))
    , m_move(new QPushButton(this))
    , m_yes(new QPushButton(this))
    , m_no(new QPushButton(this))
    , m_flip(new QPushButton(this))
{
    m_distance->setDecimals(2);
    m_distance->setRange(0.01, 1000);
    m_distance->setValue(1.0);
    if (const Parameter *d = motorParameter("move_distance"))
        m_distance->setSuffix(QLatin1Char(' ') + d->unit);
    m_move->setObjectName(QStringLiteral("moveButton"));
    m_yes->setObjectName(QStringLiteral("yesButton"));
    m_no->setObjectName(QStringLiteral("noButton"));
    m_flip->setObjectName(QStringLiteral("flipButton"));
    auto *row = new QHBoxLayout;
    row->addWidget(m_distance, 1);
    row->addWidget(m_move);
    auto *answers = new QHBoxLayout;
    answers->addWidget(m_yes);
    answers->addWidget(m_no);
    answers->addStretch(1);
    body()->addLayout(row);
    body()->addLayout(answers);
    body()->addWidget(m_flip);
    for (QPushButton *b : {m_move, m_yes, m_no, m_flip})
        b->setAutoDefault(false);
    m_yes->setEnabled(false);
    m_no->setEnabled(false);
    m_flip->hide();

    needsController(m_move);
    connect(m_move, &QPushButton::clicked, this, [this] {
        const Parameter *dir = motorParameter("direction");
        const auto current =
            dir ? this->session()->parameters()->store()->deviceValue(dir->key) : std::nullopt;
        if (!current) {
            setStatus(tr("The direction register is not read yet."));
            return;
        }
        m_directionUsed = *current;
        StepMoveRequest r{StepMoveRequest::Kind::Raw, this->step().motor, m_distance->value(),
                          *current};
        m_mine = true;
        if (const QString why = this->session()->stepMove()->start(r); !why.isEmpty()) {
            m_mine = false;
            setStatus(why);
            return;
        }
        m_yes->setEnabled(false);
        m_no->setEnabled(false);
        m_flip->hide();
        setStatus(tr("Moving…"));
    });
    connect(session->stepMove(), &StepMove::finished, this, &ChecklistDirectionStep::onMoved);
    connect(m_yes, &QPushButton::clicked, this, [this] { answer(true); });
    connect(m_no, &QPushButton::clicked, this, [this] { answer(false); });
    connect(m_flip, &QPushButton::clicked, this, [this] {
        const Parameter *dir = motorParameter("direction");
        if (!dir || !m_flipTo)
            return;
        proposeWrite({{dir->key, *m_flipTo}}, [this](bool ok) {
            setStatus(ok ? tr("The direction register is written and verified. Repeat the step to "
                              "confirm the axis now moves toward +.")
                         : tr("The direction register was not written."));
            if (ok)
                m_flip->hide();
        });
    });
    retranslate();
}

void ChecklistDirectionStep::onMoved(const StepMoveResult &r)
{
    if (!std::exchange(m_mine, false))
        return;
    setStatus(r.text);
    // Asked only when the controller showed the move ended where it should.
    m_yes->setEnabled(r.arrived);
    m_no->setEnabled(r.arrived);
}

void ChecklistDirectionStep::answer(bool towardPlus)
{
    const Parameter *dir = motorParameter("direction");
    const DirectionAnswer a =
        DirectionCheck::answer(session()->map(), step().motor, m_directionUsed, towardPlus);
    QList<ChecklistMeasurement> m{
        {QStringLiteral("commanded"), QString::number(m_distance->value(), 'f', 2),
         motorParameter("move_distance") ? motorParameter("move_distance")->unit : QString()},
        {QStringLiteral("moved_toward_plus"),
         towardPlus ? QStringLiteral("yes") : QStringLiteral("no"), QString()},
        {QStringLiteral("direction_before"), dir ? dir->displayRaw(m_directionUsed) : QString(),
         QString()}};
    m_yes->setEnabled(false);
    m_no->setEnabled(false);
    if (towardPlus) {
        finishStep(StepResult::Passed, m);
        setStatus(tr("Passed: the axis moves toward + with the direction as configured."));
        return;
    }
    if (!a.to) {
        finishStep(StepResult::Failed, m);
        setStatus(a.error);
        return;
    }
    m_flipTo = a.to;
    m << ChecklistMeasurement{QStringLiteral("direction_after"), dir->displayRaw(*a.to), QString()};
    finishStep(StepResult::Failed, m);
    m_flip->setText(tr("Flip the direction to %1…").arg(dir->displayRaw(*a.to)));
    m_flip->show();
    setStatus(tr("Failed: the axis moved toward −. Flip the direction register, then repeat the "
                 "step."));
}

void ChecklistDirectionStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_move->setText(tr("Move a small step"));
    m_distance->setAccessibleName(tr("Small step distance"));
    m_yes->setText(tr("Yes, toward +"));
    m_no->setText(tr("No, toward −"));
    if (m_flipTo) {
        if (const Parameter *dir = motorParameter("direction"))
            m_flip->setText(tr("Flip the direction to %1…").arg(dir->displayRaw(*m_flipTo)));
    }
}

} // namespace stepcom

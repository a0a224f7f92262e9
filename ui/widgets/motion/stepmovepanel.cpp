#include "widgets/motion/stepmovepanel.h"

#include "motion/travellimits.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

namespace stepcom {

namespace {

const double kSteps[] = {0.01, 0.1, 1, 10};

} // namespace

StepMovePanel::StepMovePanel(DeviceSession *session, int motor, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_motor(motor)
    , m_stepLabel(new QLabel(this))
    , m_step(new QComboBox(this))
    , m_custom(new QDoubleSpinBox(this))
    , m_minus(new QPushButton(this))
    , m_plus(new QPushButton(this))
    , m_targetLabel(new QLabel(this))
    , m_target(new QDoubleSpinBox(this))
    , m_moveTo(new QPushButton(this))
    , m_result(new QLabel(this))
{
    setObjectName(QStringLiteral("stepMovePanel%1").arg(motor));
    const Parameter *pos = TravelLimits::positionParameter(session->map(), motor);
    const double span = pos ? pos->toEngineering(pos->rawMax) : 1e6;
    for (int i = 0; i < 5; ++i)
        m_step->addItem(QString());
    m_step->setCurrentIndex(2);
    m_custom->setDecimals(2);
    m_custom->setRange(0.01, span);
    m_custom->setValue(0.5);
    m_target->setDecimals(2);
    m_target->setRange(-span, span);
    for (QPushButton *b : {m_minus, m_plus, m_moveTo})
        b->setAutoDefault(false);
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_stepLabel->setBuddy(m_step);
    m_targetLabel->setBuddy(m_target);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    // Three columns, so two motors' panels side by side still fit a 1024-pixel screen; the
    // spin boxes would ask for the width of their whole range (±21474836.48 mm) otherwise.
    const int fieldWidth = fontMetrics().horizontalAdvance(QStringLiteral("-00000.00 mm")) + 24;
    m_custom->setMinimumWidth(fieldWidth);
    m_target->setMinimumWidth(fieldWidth);
    m_step->setMinimumWidth(fieldWidth);
    grid->addWidget(m_stepLabel, 0, 0);
    grid->addWidget(m_step, 0, 1);
    grid->addWidget(m_custom, 0, 2);
    grid->addWidget(m_minus, 1, 1);
    grid->addWidget(m_plus, 1, 2);
    grid->addWidget(m_targetLabel, 2, 0);
    grid->addWidget(m_target, 2, 1);
    grid->addWidget(m_moveTo, 2, 2);
    grid->addWidget(m_result, 4, 0, 1, 3);
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(2, 1);

    connect(m_step, &QComboBox::currentIndexChanged, this, &StepMovePanel::refresh);
    connect(m_minus, &QPushButton::clicked, this,
            [this] { run(StepMoveRequest::Kind::By, -stepSize()); });
    connect(m_plus, &QPushButton::clicked, this,
            [this] { run(StepMoveRequest::Kind::By, stepSize()); });
    connect(m_moveTo, &QPushButton::clicked, this,
            [this] { run(StepMoveRequest::Kind::To, m_target->value()); });
    StepMove *step = session->stepMove();
    connect(step, &StepMove::started, this, &StepMovePanel::refresh);
    connect(step, &StepMove::finished, this, [this](const StepMoveResult &r) {
        if (r.request.motor == m_motor && std::exchange(m_mine, false))
            m_result->setText(r.text);
        refresh();
    });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &StepMovePanel::refresh);
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this,
            &StepMovePanel::refresh);
    connect(session->motion(), &MotionSupervisor::changed, this, &StepMovePanel::refresh);
    retranslate();
}

double StepMovePanel::stepSize() const
{
    const int i = m_step->currentIndex();
    return i >= 0 && i < 4 ? kSteps[i] : m_custom->value();
}

QString StepMovePanel::resultText() const
{
    return m_result->text();
}

void StepMovePanel::run(StepMoveRequest::Kind kind, double value)
{
    StepMoveRequest r;
    r.kind = kind;
    r.motor = m_motor;
    r.value = value;
    m_mine = true;
    if (const QString why = m_session->stepMove()->start(r); !why.isEmpty()) {
        m_mine = false;
        m_result->setText(why);
    }
    refresh();
}

void StepMovePanel::refresh()
{
    m_custom->setEnabled(m_step->currentIndex() == 4);
    const QString why = m_session->stepMove()->refusal({StepMoveRequest::Kind::By, m_motor, 1});
    for (QPushButton *b : {m_minus, m_plus, m_moveTo}) {
        b->setEnabled(why.isEmpty());
        // Why not, when refused; how it works otherwise (not a paragraph on the page).
        b->setToolTip(why.isEmpty() ? explanation() : why);
    }
}

QString StepMovePanel::explanation()
{
    return tr("Steps and move-to use this motor's single-move distance and direction "
              "registers, then write your own values back and verify them. They refuse "
              "while those fields hold unwritten edits, and any target beyond the "
              "software travel limits.");
}

void StepMovePanel::retranslate()
{
    const Parameter *pos = TravelLimits::positionParameter(m_session->map(), m_motor);
    const QString unit = pos ? pos->unit : QString();
    m_stepLabel->setText(tr("&Step:"));
    for (int i = 0; i < 4; ++i)
        m_step->setItemText(i, QStringLiteral("%1 %2").arg(QLocale().toString(kSteps[i]), unit));
    m_step->setItemText(4, tr("Custom"));
    m_custom->setAccessibleName(tr("Custom step"));
    m_custom->setSuffix(QLatin1Char(' ') + unit);
    m_target->setSuffix(QLatin1Char(' ') + unit);
    m_minus->setText(tr("− Step"));
    m_plus->setText(tr("+ Step"));
    m_targetLabel->setText(tr("Move &to:"));
    m_moveTo->setText(tr("Move to position"));
    for (QPushButton *b : {m_minus, m_plus, m_moveTo})
        b->setWhatsThis(explanation());
    refresh();
}

void StepMovePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace stepcom

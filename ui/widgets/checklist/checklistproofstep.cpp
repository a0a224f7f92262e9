#include "widgets/checklist/checklistproofstep.h"

#include "proof/axisproof.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/plots/marginplot.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>

namespace stepcom {

namespace {

QString mm(std::optional<double> v)
{
    return v ? QString::number(*v, 'f', 3) : QString();
}

} // namespace

ChecklistProofStep::ChecklistProofStep(DeviceSession *session, WriteFlow *writes,
                                       const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_proof(new AxisProof(session, this))
    , m_finder(new MarginFinder(session, this))
    , m_cycles(new QSpinBox(this))
    , m_distance(new QDoubleSpinBox(this))
    , m_from(new QSpinBox(this))
    , m_to(new QSpinBox(this))
    , m_step(new QSpinBox(this))
    , m_accel(new QCheckBox(this))
    , m_test(new QPushButton(this))
    , m_margin(new QPushButton(this))
    , m_stop(new QPushButton(this))
    , m_write(new QPushButton(this))
    , m_log(new QPlainTextEdit(this))
    , m_plot(new MarginPlot(this))
    , m_cyclesLabel(new QLabel(this))
    , m_distanceLabel(new QLabel(this))
    , m_rangeLabel(new QLabel(this))
{
    m_cycles->setRange(1, 1000);
    m_cycles->setValue(3);
    m_distance->setRange(0.1, 1000);
    m_distance->setDecimals(2);
    m_distance->setValue(10);
    const Parameter *position = motorParameter("position");
    if (position)
        m_distance->setSuffix(QLatin1Char(' ') + position->unit);
    // The margin's range: empty (0) means the test's own default.
    for (QSpinBox *f : {m_from, m_to, m_step}) {
        f->setRange(0, 65535);
        f->setSpecialValueText(tr("auto"));
    }
    m_test->setObjectName(QStringLiteral("lostStepTestButton"));
    m_margin->setObjectName(QStringLiteral("marginButton"));
    m_stop->setObjectName(QStringLiteral("proofStopButton"));
    m_write->setObjectName(QStringLiteral("writeRecommendedButton"));
    for (QPushButton *b : {m_test, m_margin, m_stop, m_write})
        b->setAutoDefault(false);
    m_stop->setEnabled(false);
    m_write->hide();
    m_log->setReadOnly(true);
    m_log->setObjectName(QStringLiteral("proofLog"));
    m_log->setMaximumBlockCount(500);
    // A few lines of the latest steps: the plot and the result matter more on a small screen.
    m_log->setMinimumHeight(60);
    m_log->setMaximumHeight(m_log->fontMetrics().lineSpacing() * 5 + 12);
    m_plot->hide();

    auto *form = new QFormLayout;
    m_cyclesLabel->setBuddy(m_cycles);
    m_distanceLabel->setBuddy(m_distance);
    m_rangeLabel->setBuddy(m_from);
    form->addRow(m_cyclesLabel, m_cycles);
    form->addRow(m_distanceLabel, m_distance);
    auto *range = new QHBoxLayout;
    range->addWidget(m_from);
    range->addWidget(m_to);
    range->addWidget(m_step);
    form->addRow(m_rangeLabel, range);
    form->addRow(QString(), m_accel);
    body()->addLayout(form);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_test);
    buttons->addWidget(m_margin);
    buttons->addWidget(m_stop);
    buttons->addStretch(1);
    body()->addLayout(buttons);
    body()->addWidget(m_write);
    body()->addWidget(m_plot);
    body()->addWidget(m_log);

    needsController(m_test);
    needsController(m_margin);
    connect(m_test, &QPushButton::clicked, this, &ChecklistProofStep::startTest);
    connect(m_margin, &QPushButton::clicked, this, &ChecklistProofStep::startMargin);
    connect(m_stop, &QPushButton::clicked, this, [this] {
        m_proof->stop();
        m_finder->stop();
    });
    // The E-STOP ends a test at once (the test sees it itself); Stop here is the soft way.
    connect(m_proof, &AxisProof::progress, this, &ChecklistProofStep::say);
    connect(m_finder, &MarginFinder::progress, this, &ChecklistProofStep::say);
    connect(m_proof, &AxisProof::ready, this, [this](const QString &plan) {
        confirmThen(
            plan, [this] { m_proof->proceed(); }, [this] { m_proof->stop(); });
    });
    connect(m_finder, &MarginFinder::ready, this, [this](const QString &plan) {
        confirmThen(
            plan, [this] { m_finder->proceed(); }, [this] { m_finder->stop(); });
    });
    connect(m_proof, &AxisProof::halfDone, this, [this](bool out, double lost) {
        say(out ? tr("After the moves out: %1 mm").arg(lost, 0, 'f', 3)
                : tr("After the moves back: %1 mm").arg(lost, 0, 'f', 3));
    });
    connect(m_finder, &MarginFinder::stepDone, m_plot, &MarginPlot::addStep);
    connect(m_proof, &AxisProof::finished, this, &ChecklistProofStep::onTested);
    connect(m_finder, &MarginFinder::finished, this, &ChecklistProofStep::onMargin);
    connect(m_write, &QPushButton::clicked, this, &ChecklistProofStep::writeRecommendation);
    retranslate();
}

bool ChecklistProofStep::isRunning() const
{
    return m_proof->isRunning() || m_finder->isRunning();
}

void ChecklistProofStep::say(const QString &text)
{
    m_log->appendPlainText(text);
    setStatus(text);
}

void ChecklistProofStep::setRunning(bool running)
{
    m_stop->setEnabled(running);
    for (QWidget *w : std::initializer_list<QWidget *>{m_test, m_margin, m_cycles, m_distance,
                                                       m_from, m_to, m_step, m_accel})
        w->setEnabled(!running &&
                      ((w != m_test && w != m_margin) || session()->connection()->isConnected()));
}

void ChecklistProofStep::confirmThen(const QString &plan, std::function<void()> yes,
                                     std::function<void()> no)
{
    const bool go =
        m_confirm
            ? m_confirm(plan)
            : QMessageBox::question(this, step().title(),
                                    plan + QLatin1Char('\n') + tr("Run it? The axis will move."),
                                    QMessageBox::Yes | QMessageBox::No,
                                    QMessageBox::No) == QMessageBox::Yes;
    (go ? yes : no)();
}

void ChecklistProofStep::startTest()
{
    AxisProof::Options o;
    o.motor = step().motor;
    o.cycles = m_cycles->value();
    o.distance = m_distance->value();
    o.askFirst = true;
    m_log->clear();
    m_plot->hide();
    setRunning(true);
    m_proof->start(o);
}

void ChecklistProofStep::startMargin()
{
    MarginFinder::Options o;
    o.motor = step().motor;
    o.accel = m_accel->isChecked();
    o.cycles = std::min(m_cycles->value(), 2);
    o.distance = m_distance->value();
    if (m_from->value() > 0)
        o.from = m_from->value();
    if (m_to->value() > 0)
        o.to = m_to->value();
    if (m_step->value() > 0)
        o.step = m_step->value();
    o.askFirst = true;
    m_log->clear();
    m_plot->clear(o.accel);
    m_plot->show();
    m_write->hide();
    setRunning(true);
    m_finder->start(o);
}

void ChecklistProofStep::onTested(const LostStepResult &r)
{
    setRunning(false);
    say(r.text);
    if (r.outcome != ProofOutcome::Done)
        return; // refused, stopped: nothing to record
    const QList<ChecklistMeasurement> m{
        {QStringLiteral("verdict"), r.verdictWord(), QString()},
        {QStringLiteral("speed_rpm"), QString::number(r.speedRpm), QStringLiteral("rpm")},
        {QStringLiteral("accel"), QString::number(r.accel), QStringLiteral("Hz/ms")},
        {QStringLiteral("cycles"), QString::number(r.cycles), QString()},
        {QStringLiteral("distance"), QString::number(r.distance, 'f', 2), QStringLiteral("mm")},
        {QStringLiteral("lost_out"), mm(r.lostOut), QStringLiteral("mm")},
        {QStringLiteral("lost_back"), mm(r.lostBack), QStringLiteral("mm")},
        {QStringLiteral("repeatability"), mm(r.repeatability), QStringLiteral("mm")},
        {QStringLiteral("simulator"),
         r.simulator ? QStringLiteral("simulator") : QStringLiteral("machine"), QString()}};
    using V = LostStepResult::Verdict;
    finishStep(r.verdict == V::Kept ? StepResult::Passed : StepResult::Failed, m);
    if (r.verdict == V::Lost)
        Q_EMIT stepsLost(step().motor, r.speedRpm,
                         m_recommendedAccel ? std::nullopt : m_recommended);
    else if (r.verdict == V::Kept)
        Q_EMIT stepsKept(step().motor);
}

void ChecklistProofStep::onMargin(const MarginResult &r)
{
    setRunning(false);
    say(r.text);
    m_plot->setRecommended(r.recommended);
    if (r.outcome != ProofOutcome::Done)
        return;
    m_recommended = r.recommended;
    m_recommendedAccel = r.accel;
    const QString unit = r.accel ? QStringLiteral("Hz/ms") : QStringLiteral("rpm");
    const QString suffix = r.accel ? QStringLiteral("_accel") : QStringLiteral("_rpm");
    const auto value = [](const std::optional<qint64> &v) {
        return v ? QString::number(*v) : QStringLiteral("—");
    };
    QList<ChecklistMeasurement> m{
        {QStringLiteral("kept") + suffix, value(r.kept), unit},
        {QStringLiteral("stall") + suffix, value(r.stall), unit},
        {QStringLiteral("recommended") + suffix, value(r.recommended), unit},
        {QStringLiteral("simulator"),
         r.simulator ? QStringLiteral("simulator") : QStringLiteral("machine"), QString()}};
    if (r.accel)
        m << ChecklistMeasurement{QStringLiteral("speed_rpm"), QString::number(r.speedRpm),
                                  QStringLiteral("rpm")};
    // Passed when the motor's own value kept its steps in the search.
    const Parameter *own = motorParameter(r.accel ? "accel_frequency" : "speed");
    const qint64 held =
        own ? session()->parameters()->store()->deviceValue(own->key).value_or(-1) : -1;
    const bool ownKept = held >= 0 && r.kept && held <= *r.kept;
    const bool ownLost = held >= 0 && r.stall && held >= *r.stall;
    finishStep(ownKept ? StepResult::Passed : StepResult::Failed, m);
    if (r.recommended && held >= 0 && *r.recommended != held) {
        m_write->setText(r.accel ? tr("Write the recommended acceleration %1…").arg(*r.recommended)
                                 : tr("Write the recommended speed %1 rpm…").arg(*r.recommended));
        m_write->show();
    }
    if (ownLost && !r.accel)
        Q_EMIT stepsLost(step().motor, held, r.recommended);
}

void ChecklistProofStep::writeRecommendation()
{
    const Parameter *p = motorParameter(m_recommendedAccel ? "accel_frequency" : "speed");
    if (!p || !m_recommended)
        return;
    proposeWrite({{p->key, *m_recommended}}, [this](bool ok) {
        if (!ok) {
            setStatus(tr("The recommendation was not written."));
            return;
        }
        m_write->hide();
        setStatus(tr("The recommendation is written and verified. Run the lost-step test again "
                     "to prove it."));
        Q_EMIT stepsKept(step().motor);
    });
}

void ChecklistProofStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_cyclesLabel->setText(tr("C&ycles:"));
    m_distanceLabel->setText(tr("&Distance of each move:"));
    m_rangeLabel->setText(tr("Margin: &from, to, step:"));
    m_cycles->setAccessibleName(tr("Cycles"));
    m_distance->setAccessibleName(tr("Distance of each move"));
    m_from->setAccessibleName(tr("Margin from"));
    m_to->setAccessibleName(tr("Margin to"));
    m_step->setAccessibleName(tr("Margin step"));
    for (QSpinBox *f : {m_from, m_to, m_step})
        f->setSpecialValueText(tr("auto"));
    m_accel->setText(tr("Search the &acceleration instead of the speed"));
    m_test->setText(tr("Run the &lost-step test"));
    m_margin->setText(tr("Find the &margin"));
    m_stop->setText(tr("&Stop"));
    m_log->setAccessibleName(tr("Test progress"));
    m_plot->setAccessibleName(tr("The margin search: lost mm at each value tested"));
    if (m_recommended && m_write->isVisible())
        m_write->setText(m_recommendedAccel
                             ? tr("Write the recommended acceleration %1…").arg(*m_recommended)
                             : tr("Write the recommended speed %1 rpm…").arg(*m_recommended));
}

} // namespace stepcom

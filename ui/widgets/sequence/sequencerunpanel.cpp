#include "widgets/sequence/sequencerunpanel.h"

#include "proof/axisproof.h"
#include "sequence/sequenceplan.h"
#include "sequence/sequencerunner.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "widgets/fields/wrappingrow.h"

#include <QCheckBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace stepcom {

namespace {

// The file's limits within the user's: the lost-step check after a run-in moves only where
// both allow.
TravelLimits narrowed(const TravelLimits &user, const TravelLimits &file, const RegisterMap &map)
{
    TravelLimits out = user;
    for (auto it = file.axes().begin(); it != file.axes().end(); ++it) {
        const Parameter *p = TravelLimits::positionParameter(map, it.key());
        if (!p)
            continue;
        AxisTravel t = user.axis(it.key());
        if (it->min)
            t.min = t.min ? std::max(*t.min, *it->min) : *it->min;
        if (it->max)
            t.max = t.max ? std::min(*t.max, *it->max) : *it->max;
        const auto eng = [p](const std::optional<qint64> &raw) -> std::optional<double> {
            return raw ? std::optional<double>(p->toEngineering(*raw)) : std::nullopt;
        };
        out.setAxis(map, it.key(), eng(t.min), eng(t.max));
    }
    return out;
}

QString seconds(double s)
{
    return QString::number(s, 'f', 3);
}

} // namespace

SequenceRunPanel::SequenceRunPanel(DeviceSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_runner(new SequenceRunner(session, this))
    , m_cycles(new QSpinBox(this))
    , m_single(new QCheckBox(this))
    , m_check(new QCheckBox(this))
    , m_run(new QPushButton(this))
    , m_pause(new QPushButton(this))
    , m_step(new QPushButton(this))
    , m_resume(new QPushButton(this))
    , m_stop(new QPushButton(this))
    , m_cycle(new QLabel(this))
    , m_status(new QLabel(this))
{
    m_cycles->setObjectName(QStringLiteral("sequenceCycles"));
    m_cycles->setRange(1, 1000000);
    m_single->setObjectName(QStringLiteral("sequenceSingleStep"));
    m_check->setObjectName(QStringLiteral("sequenceCheckSteps"));
    m_run->setObjectName(QStringLiteral("sequenceRun"));
    m_pause->setObjectName(QStringLiteral("sequencePause"));
    m_step->setObjectName(QStringLiteral("sequenceStep"));
    m_resume->setObjectName(QStringLiteral("sequenceResume"));
    m_stop->setObjectName(QStringLiteral("sequenceStop"));
    m_cycle->setObjectName(QStringLiteral("sequenceCycle"));
    m_status->setObjectName(QStringLiteral("sequenceStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    for (QPushButton *b : {m_run, m_pause, m_step, m_resume, m_stop})
        b->setAutoDefault(false);

    // Two rows each on a narrow page, rather than a page that scrolls sideways.
    auto *options = new WrappingRow(this);
    auto *cyclesLabel = new QLabel(this);
    cyclesLabel->setObjectName(QStringLiteral("cyclesLabel"));
    cyclesLabel->setBuddy(m_cycles);
    options->first()->addWidget(cyclesLabel);
    options->first()->addWidget(m_cycles);
    options->first()->addWidget(m_single);
    options->second()->addWidget(m_check);
    options->second()->addStretch(1);
    auto *buttons = new WrappingRow(this);
    for (QPushButton *b : {m_run, m_pause, m_step})
        buttons->first()->addWidget(b);
    buttons->second()->addWidget(m_resume);
    buttons->second()->addWidget(m_stop);
    buttons->second()->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(options);
    layout->addWidget(buttons);
    layout->addWidget(m_cycle);
    layout->addWidget(m_status);

    connect(m_run, &QPushButton::clicked, this, [this] { run(); });
    connect(m_stop, &QPushButton::clicked, this, &SequenceRunPanel::stop);
    connect(m_pause, &QPushButton::clicked, this, [this] {
        m_runner->setPauseAfterStep(true);
        m_status->setText(tr("Pausing after the current step…"));
        updateButtons();
    });
    connect(m_step, &QPushButton::clicked, this, [this] { m_runner->singleStep(); });
    connect(m_resume, &QPushButton::clicked, this, [this] {
        m_runner->setPauseAfterStep(m_single->isChecked());
        m_runner->resume();
    });
    connect(m_single, &QCheckBox::toggled, this, [this](bool on) {
        if (m_runner->isRunning())
            m_runner->setPauseAfterStep(on);
    });
    connect(m_runner, &SequenceRunner::started, this, [this] { updateButtons(); });
    connect(m_runner, &SequenceRunner::cycleStarted, this, [this](int) {
        m_cycle->setText(stripLine());
        Q_EMIT stripText(stripLine());
    });
    connect(m_runner, &SequenceRunner::stepStarted, this,
            [this](int cycle, const QString &path, const QString &text) {
                onStep(cycle, path);
                m_status->setText(tr("Step %1: %2").arg(path, text));
            });
    connect(m_runner, &SequenceRunner::cycleFinished, this, [this](int cycle, double s) {
        m_status->setText(tr("Cycle %1 done in %2 s.").arg(cycle).arg(seconds(s)));
    });
    connect(m_runner, &SequenceRunner::paused, this, [this](const QString &next) {
        m_status->setText(tr("Paused before %1: Step runs it, Resume goes on.").arg(next));
        Q_EMIT currentStepChanged(next);
        updateButtons();
    });
    connect(m_runner, &SequenceRunner::finished, this, &SequenceRunPanel::onFinished);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &SequenceRunPanel::updateButtons);
    retranslate();
    updateButtons();
}

SequenceRunPanel::~SequenceRunPanel()
{
    if (m_userLimits)
        m_session->setTravelLimits(*m_userLimits);
}

bool SequenceRunPanel::isBusy() const
{
    return m_runner->isRunning() || m_checking;
}

void SequenceRunPanel::setRunnable(bool runnable)
{
    m_runnable = runnable;
    updateButtons();
}

bool SequenceRunPanel::run()
{
    if (isBusy())
        return false;
    const std::optional<Sequence> sequence = m_source ? m_source() : std::nullopt;
    if (!sequence) {
        m_status->setText(tr("The sequence has problems (listed above): nothing was sent."));
        return false;
    }
    if (!m_session->connection()->isConnected()) {
        m_status->setText(tr("Not connected: nothing was sent."));
        return false;
    }
    const int cycles = m_cycles->value();
    const QString plan =
        SequencePlan::describe(*sequence, m_session->map(), cycles, m_check->isChecked());
    const bool go =
        m_confirm
            ? m_confirm(plan)
            : QMessageBox::question(this, tr("Run the sequence"),
                                    plan + QLatin1Char('\n') + tr("Run it? The machine will move."),
                                    QMessageBox::Yes | QMessageBox::No,
                                    QMessageBox::No) == QMessageBox::Yes;
    if (!go) {
        m_status->setText(tr("Not started: nothing was sent."));
        return false;
    }
    m_sequence = *sequence;
    m_cyclesWanted = cycles;
    m_stepNumber = 0;
    m_checks.clear();
    m_last.reset();
    m_runner->setPauseAfterStep(m_single->isChecked());
    if (!m_runner->start(m_sequence, cycles)) {
        m_status->setText(tr("The run could not start: not connected, or one is running."));
        return false;
    }
    m_status->setText(tr("Reading the positions and checking the run…"));
    m_cycle->setText(tr("Cycle — of %1").arg(cycles));
    Q_EMIT busyChanged(true);
    updateButtons();
    return true;
}

void SequenceRunPanel::stop()
{
    if (m_proof)
        m_proof->stop();
    m_runner->stop();
}

void SequenceRunPanel::onStep(int cycle, const QString &path)
{
    Q_UNUSED(cycle)
    const QList<const SequenceStep *> all = m_sequence.allSteps();
    m_stepNumber = 0;
    for (int i = 0; i < all.size(); ++i) {
        if (all[i]->path == path)
            m_stepNumber = i + 1;
    }
    m_cycle->setText(stripLine());
    Q_EMIT stripText(stripLine());
    Q_EMIT currentStepChanged(path);
    updateButtons();
}

QString SequenceRunPanel::stripLine() const
{
    if (m_stepNumber == 0)
        return tr("Running sequence: cycle %1 of %2").arg(m_runner->cycle()).arg(m_cyclesWanted);
    return tr("Running sequence: cycle %1 of %2, step %3")
        .arg(m_runner->cycle())
        .arg(m_cyclesWanted)
        .arg(m_stepNumber);
}

void SequenceRunPanel::onFinished(const SequenceResult &result)
{
    m_last = result;
    Q_EMIT currentStepChanged(QString());
    QString text =
        result.step.isEmpty() ? result.text : tr("%1 (at %2)").arg(result.text, result.step);
    for (const QString &p : result.problems)
        text += QLatin1Char('\n') + p;
    m_status->setText(text);
    if (!result.cycleSeconds.isEmpty())
        m_cycle->setText(tr("Cycles done: %1 of %2; cycle time min %3 s, median %4 s, max %5 s")
                             .arg(result.cyclesDone)
                             .arg(m_cyclesWanted)
                             .arg(seconds(result.minCycle()), seconds(result.medianCycle()),
                                  seconds(result.maxCycle())));
    else
        m_cycle->setText(tr("Cycles done: %1 of %2").arg(result.cyclesDone).arg(m_cyclesWanted));
    if (result.ok() && m_check->isChecked()) {
        m_checking = true;
        // The check moves only where the file and the user both allow.
        m_userLimits = m_session->travelLimits();
        m_session->setTravelLimits(narrowed(*m_userLimits, m_sequence.limits, m_session->map()));
        Q_EMIT stripText(tr("Running sequence: the lost-step check"));
        checkNext(SequencePlan::movedMotors(m_sequence));
        return;
    }
    finishAll();
}

void SequenceRunPanel::checkNext(QList<int> motors)
{
    if (motors.isEmpty()) {
        finishAll();
        return;
    }
    auto *proof = new AxisProof(m_session, this);
    m_proof = proof;
    connect(proof, &AxisProof::progress, this,
            [this](const QString &t) { m_status->setText(tr("Lost-step check: %1").arg(t)); });
    connect(proof, &AxisProof::finished, this, [this, proof, motors](const LostStepResult &r) {
        proof->deleteLater();
        m_checks << r;
        QList<int> rest = motors;
        rest.removeFirst();
        // A check that could not end (the link, an E-STOP) ends them all.
        if (r.outcome != ProofOutcome::Done)
            rest.clear();
        checkNext(rest);
    });
    AxisProof::Options o;
    o.motor = motors.first();
    if (!proof->start(o)) {
        proof->deleteLater();
        finishAll();
    }
}

void SequenceRunPanel::finishAll()
{
    const bool checked = m_checking;
    m_checking = false;
    if (m_userLimits) {
        m_session->setTravelLimits(*m_userLimits);
        m_userLimits.reset();
    }
    Q_EMIT stripText(QString());
    Q_EMIT busyChanged(false);
    updateButtons();
    if (!m_last)
        return;
    const SequenceResult &r = *m_last;
    // The worst verdict of the checks: lost over unknown over kept.
    QString verdict = checked ? QStringLiteral("kept") : QStringLiteral("not_checked");
    if (checked && m_checks.isEmpty())
        verdict = QStringLiteral("unknown");
    QStringList checkTexts;
    for (const LostStepResult &c : std::as_const(m_checks)) {
        checkTexts << c.text;
        if (c.verdict == LostStepResult::Verdict::Lost)
            verdict = QStringLiteral("lost");
        else if ((c.outcome != ProofOutcome::Done ||
                  c.verdict == LostStepResult::Verdict::Unknown) &&
                 verdict != QLatin1String("lost"))
            verdict = QStringLiteral("unknown");
    }
    if (checked)
        m_status->setText(m_status->text() + QLatin1Char('\n') +
                          tr("Lost-step check: %1").arg(checkTexts.join(QLatin1Char(' '))));
    using O = SequenceResult::Outcome;
    // A run the machine ended (a timeout, a limit, a move cut short) is a run-in's finding; a
    // run the user or the link ended says nothing about the machine's cycle.
    const bool finding = r.outcome == O::Done || r.outcome == O::Timeout || r.outcome == O::Limit ||
                         r.outcome == O::Stopped;
    if (m_cyclesWanted < 2 || !finding)
        return;
    const bool passed =
        r.ok() && verdict != QLatin1String("lost") && verdict != QLatin1String("unknown");
    QList<ChecklistMeasurement> m{
        {QStringLiteral("sequence"), m_sequence.fileName, QString()},
        {QStringLiteral("outcome"), r.word(), QString()},
        {QStringLiteral("cycles"), QString::number(m_cyclesWanted), QString()},
        {QStringLiteral("cycles_done"), QString::number(r.cyclesDone), QString()},
    };
    if (!r.cycleSeconds.isEmpty()) {
        m << ChecklistMeasurement{QStringLiteral("cycle_min"), seconds(r.minCycle()),
                                  QStringLiteral("s")}
          << ChecklistMeasurement{QStringLiteral("cycle_median"), seconds(r.medianCycle()),
                                  QStringLiteral("s")}
          << ChecklistMeasurement{QStringLiteral("cycle_max"), seconds(r.maxCycle()),
                                  QStringLiteral("s")};
    }
    m << ChecklistMeasurement{QStringLiteral("check_steps"), verdict, QString()};
    m << ChecklistMeasurement{QStringLiteral("simulator"),
                              m_session->connection()->isSimulator() ? QStringLiteral("simulator")
                                                                     : QStringLiteral("machine"),
                              QString()};
    Q_EMIT runInFinished(passed ? StepResult::Passed : StepResult::Failed, m, m_status->text());
}

void SequenceRunPanel::updateButtons()
{
    const bool running = m_runner->isRunning();
    const bool paused = m_runner->isPaused();
    const bool connected = m_session->connection()->isConnected();
    m_run->setEnabled(!isBusy() && m_runnable && connected);
    m_cycles->setEnabled(!isBusy());
    m_check->setEnabled(!isBusy());
    m_pause->setEnabled(running && !paused && !m_runner->pauseAfterStep());
    m_step->setEnabled(running && paused);
    m_resume->setEnabled(running && paused);
    m_stop->setEnabled(isBusy());
}

void SequenceRunPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SequenceRunPanel::retranslate()
{
    findChild<QLabel *>(QStringLiteral("cyclesLabel"))->setText(tr("C&ycles:"));
    m_single->setText(tr("S&ingle step"));
    m_single->setToolTip(tr("Pause after every step; Step runs the next one"));
    m_check->setText(tr("Lost-step &check at the end"));
    m_check->setToolTip(tr("After the last cycle, the lost-step test on every axis the "
                           "sequence moved, each referenced on its home switch"));
    m_run->setText(tr("&Run"));
    m_pause->setText(tr("&Pause"));
    m_pause->setToolTip(tr("Pause after the step running now"));
    m_step->setText(tr("S&tep"));
    m_resume->setText(tr("Resu&me"));
    m_stop->setText(tr("&Stop"));
    if (!isBusy() && !m_last)
        m_status->setText(tr("Not running."));
}

} // namespace stepcom

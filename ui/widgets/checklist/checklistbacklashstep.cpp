#include "widgets/checklist/checklistbacklashstep.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>

namespace stepcom {

ChecklistBacklashStep::ChecklistBacklashStep(DeviceSession *session, WriteFlow *writes,
                                             const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_test(new BacklashTest(session, this))
    , m_distance(new QDoubleSpinBox(this))
    , m_cycles(new QSpinBox(this))
    , m_start(new QPushButton(this))
    , m_stop(new QPushButton(this))
    , m_reading(new QDoubleSpinBox(this))
    , m_enter(new QPushButton(this))
    , m_distanceLabel(new QLabel(this))
    , m_cyclesLabel(new QLabel(this))
{
    const Parameter *position = motorParameter("position");
    const QString unit = position ? QLatin1Char(' ') + position->unit : QString();
    m_distance->setRange(0.01, 1000);
    m_distance->setDecimals(2);
    m_distance->setValue(1);
    m_distance->setSuffix(unit);
    m_cycles->setRange(1, 100);
    m_cycles->setValue(3);
    m_reading->setRange(-10000, 10000);
    m_reading->setDecimals(3);
    m_reading->setSuffix(unit);
    m_reading->setEnabled(false);
    m_enter->setEnabled(false);
    m_stop->setEnabled(false);
    m_start->setObjectName(QStringLiteral("backlashStartButton"));
    m_stop->setObjectName(QStringLiteral("backlashStopButton"));
    m_reading->setObjectName(QStringLiteral("gaugeReading"));
    m_enter->setObjectName(QStringLiteral("gaugeEnterButton"));
    for (QPushButton *b : {m_start, m_stop, m_enter})
        b->setAutoDefault(false);

    auto *form = new QFormLayout;
    m_distanceLabel->setBuddy(m_distance);
    m_cyclesLabel->setBuddy(m_cycles);
    form->addRow(m_distanceLabel, m_distance);
    form->addRow(m_cyclesLabel, m_cycles);
    body()->addLayout(form);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    buttons->addStretch(1);
    body()->addLayout(buttons);
    auto *gauge = new QHBoxLayout;
    gauge->addWidget(m_reading, 1);
    gauge->addWidget(m_enter);
    body()->addLayout(gauge);

    needsController(m_start);
    connect(m_start, &QPushButton::clicked, this, [this] {
        BacklashTest::Options o;
        o.motor = this->step().motor;
        o.distance = m_distance->value();
        o.cycles = m_cycles->value();
        o.askFirst = true;
        setRunning(true);
        m_test->start(o);
    });
    connect(m_stop, &QPushButton::clicked, m_test, &BacklashTest::stop);
    connect(m_test, &BacklashTest::progress, this, &ChecklistBacklashStep::setStatus);
    connect(m_test, &BacklashTest::ready, this, [this](const QString &plan) {
        const bool go =
            m_confirm ? m_confirm(plan)
                      : QMessageBox::question(this, this->step().title(),
                                              plan + QLatin1Char('\n') +
                                                  tr("Put the gauge on the carriage. Run it? The "
                                                     "axis will move."),
                                              QMessageBox::Yes | QMessageBox::No,
                                              QMessageBox::No) == QMessageBox::Yes;
        go ? m_test->proceed() : m_test->stop();
    });
    connect(m_test, &BacklashTest::readingWanted, this, [this](int index, const QString &where) {
        m_wanted = index;
        m_where = where;
        m_reading->setEnabled(true);
        m_enter->setEnabled(true);
        m_reading->setFocus();
        m_reading->selectAll();
        setStatus(tr("Reading %1 of %2, %3: type what the gauge shows and press Enter.")
                      .arg(index + 1)
                      .arg(m_test->readingsWanted())
                      .arg(where));
        Q_EMIT readingWanted(index);
    });
    const auto enter = [this] {
        if (m_wanted < 0)
            return;
        m_wanted = -1;
        m_reading->setEnabled(false);
        m_enter->setEnabled(false);
        m_test->giveReading(m_reading->value());
    };
    connect(m_enter, &QPushButton::clicked, this, enter);
    connect(m_reading, &QDoubleSpinBox::editingFinished, this, [this, enter] {
        if (m_reading->hasFocus())
            enter();
    });
    connect(m_test, &BacklashTest::finished, this, &ChecklistBacklashStep::onFinished);
    retranslate();
}

void ChecklistBacklashStep::setRunning(bool running)
{
    m_stop->setEnabled(running);
    m_distance->setEnabled(!running);
    m_cycles->setEnabled(!running);
    m_start->setEnabled(!running && session()->connection()->isConnected());
    if (!running) {
        m_wanted = -1;
        m_reading->setEnabled(false);
        m_enter->setEnabled(false);
    }
}

void ChecklistBacklashStep::onFinished(const BacklashResult &r)
{
    setRunning(false);
    setStatus(r.text);
    if (r.outcome != ProofOutcome::Done)
        return;
    QStringList readings;
    for (double v : r.readings)
        readings << QString::number(v, 'f', 3);
    const QString unit =
        motorParameter("position") ? motorParameter("position")->unit : QStringLiteral("mm");
    finishStep(
        StepResult::Passed,
        {{QStringLiteral("backlash"), QString::number(*r.backlash, 'f', 3), unit},
         {QStringLiteral("spread"), QString::number(*r.spread, 'f', 3), unit},
         {QStringLiteral("distance"), QString::number(r.distance, 'f', 2), unit},
         {QStringLiteral("cycles"), QString::number(r.cycles), QString()},
         {QStringLiteral("readings"), readings.join(QLatin1Char(' ')).left(200), unit},
         {QStringLiteral("simulator"),
          r.simulator ? QStringLiteral("simulator") : QStringLiteral("machine"), QString()}});
}

void ChecklistBacklashStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_distanceLabel->setText(tr("&Distance of each move:"));
    m_cyclesLabel->setText(tr("C&ycles:"));
    m_distance->setAccessibleName(tr("Distance of each move"));
    m_cycles->setAccessibleName(tr("Cycles"));
    m_reading->setPrefix(tr("Gauge: "));
    m_reading->setAccessibleName(tr("Gauge reading"));
    m_start->setText(tr("Start the &backlash test"));
    m_stop->setText(tr("&Stop"));
    m_enter->setText(tr("&Enter reading"));
}

} // namespace stepcom

#include "widgets/motion/jogpanel.h"

#include "base/language.h"
#include "base/writeflow.h"
#include "i18n/translators.h"
#include "motion/motionjudge.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/led.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/jogbutton.h"
#include "widgets/motion/stepmovepanel.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");
const char *const kWatched[] = {"speed",   "move_distance", "direction", "position",
                                "running", "home_input",    "stop"};

} // namespace

JogPanel::JogPanel(DeviceSession *session, JogController *jog, WriteFlow *writes, int motor,
                   QWidget *parent)
    : QGroupBox(parent)
    , m_session(session)
    , m_jog(jog)
    , m_writes(writes)
    , m_motor(motor)
{
    for (const char *local : kWatched) {
        if (const QString k = key(QLatin1String(local)); !k.isEmpty())
            m_keys << k;
    }
    auto *column = new QVBoxLayout(this);

    // Big targets: they are held, sometimes with gloves, and must be hit at 200% too.
    auto *buttons = new QHBoxLayout;
    m_reverse = new JogButton(this);
    m_stop = new QPushButton(this);
    m_forward = new JogButton(this);
    m_stop->setIcon(style()->standardIcon(QStyle::SP_MediaStop));
    m_stop->setAutoDefault(false);
    for (QPushButton *b :
         {static_cast<QPushButton *>(m_reverse), m_stop, static_cast<QPushButton *>(m_forward)}) {
        b->setMinimumHeight(b->fontMetrics().height() * 3);
        b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        buttons->addWidget(b);
    }
    column->addLayout(buttons);

    auto *state = new QHBoxLayout;
    m_led = new Led(this);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    // What the jog is doing; the position is the machine strip's, under every page.
    state->addWidget(m_led);
    state->addWidget(m_status, 1);
    column->addLayout(state);

    auto *grid = new QGridLayout;
    m_speedLabel = new QLabel(this);
    if (const Parameter *p = param(QStringLiteral("speed"))) {
        m_speed = new ParameterField(session->parameters()->store(), *p, this);
        m_speedLabel->setBuddy(m_speed->editor());
    }
    m_applySpeed = new QPushButton(this);
    m_applySpeed->setAutoDefault(false);
    m_speedNote = new QLabel(this);
    m_speedNote->setWordWrap(true);
    grid->addWidget(m_speedLabel, 0, 0);
    if (m_speed)
        grid->addWidget(m_speed, 0, 1);
    grid->addWidget(m_applySpeed, 0, 2);
    grid->addWidget(m_speedNote, 1, 1, 1, 2);

    m_moveLabel = new QLabel(this);
    m_moveInfo = new QLabel(this);
    m_moveInfo->setWordWrap(true);
    m_move = new QPushButton(this);
    m_move->setAutoDefault(false);
    grid->addWidget(m_moveLabel, 2, 0);
    grid->addWidget(m_moveInfo, 2, 1);
    grid->addWidget(m_move, 2, 2);

    m_homeLabel = new QLabel(this);
    m_homeInfo = new QLabel(this);
    m_homeInfo->setWordWrap(true);
    m_home = new QPushButton(this);
    m_home->setAutoDefault(false);
    grid->addWidget(m_homeLabel, 3, 0);
    grid->addWidget(m_homeInfo, 3, 1);
    grid->addWidget(m_home, 3, 2);
    m_reference = new QLabel(this);
    m_reference->setWordWrap(true);
    grid->addWidget(m_reference, 4, 1, 1, 2);
    grid->setColumnStretch(1, 1);
    column->addLayout(grid);
    m_steps = new StepMovePanel(session, motor, this); // step jog and move-to
    column->addWidget(m_steps);

    connect(m_reverse, &JogButton::jogPressed, this, [this] {
        if (!m_jog->press(m_motor, JogController::Direction::Reverse))
            m_reverse->letGo();
    });
    connect(m_forward, &JogButton::jogPressed, this, [this] {
        if (!m_jog->press(m_motor, JogController::Direction::Forward))
            m_forward->letGo();
    });
    connect(m_reverse, &JogButton::jogReleased, this, [this] { m_jog->release(m_motor); });
    connect(m_forward, &JogButton::jogReleased, this, [this] { m_jog->release(m_motor); });
    // On press, not click: a stop must not wait for the button to come up, nor be lost by
    // sliding off it.
    connect(m_stop, &QPushButton::pressed, this, [this] {
        m_jog->stop(m_motor, tr("stop button"));
        letGo();
    });
    connect(m_applySpeed, &QPushButton::clicked, this, &JogPanel::applySpeed);
    connect(m_move, &QPushButton::clicked, this, [this] { command(QStringLiteral("move")); });
    connect(m_home, &QPushButton::clicked, this, [this] { command(QStringLiteral("home")); });

    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &k) {
                if (m_keys.contains(k))
                    refresh();
            });
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this,
            &JogPanel::refresh);
    connect(session->connection(), &SessionConnection::linkStateChanged, this, &JogPanel::refresh);
    MotionSupervisor *motion = session->motion();
    connect(motion, &MotionSupervisor::changed, this, &JogPanel::refresh);
    connect(motion, &MotionSupervisor::finished, this, [this](const MotionOutcome &o) {
        if (o.axis(m_motor))
            m_hideOutcome = false;
    });
    connect(motion->references(), &ReferenceTracker::changed, this, &JogPanel::refresh);
    connect(jog, &JogController::stateChanged, this, [this](int n) {
        if (n != m_motor)
            return;
        if (m_jog->state(n) == JogController::State::Jogging)
            m_hideOutcome = true;
        refresh();
    });
    retranslate();
}

QString JogPanel::key(const QString &localKey) const
{
    const Parameter *p = param(localKey);
    return p ? p->key : QString();
}

const Parameter *JogPanel::param(const QString &localKey) const
{
    return m_session->map().blockParameter(kMotor, m_motor, localKey);
}

QList<QWidget *> JogPanel::tabChain() const
{
    QList<QWidget *> chain{m_stop};
    if (m_speed)
        chain << m_speed->editor();
    chain << m_applySpeed << m_move << m_home;
    return chain;
}

void JogPanel::letGo()
{
    m_reverse->letGo();
    m_forward->letGo();
    refresh();
}

void JogPanel::applySpeed()
{
    // The window's write dialog for this one key: reviewed, read back and logged as "Write
    // changes" is; the other edits stay held.
    if (const Parameter *p = param(QStringLiteral("speed")))
        m_writes->openFor({p->key});
}

void JogPanel::command(const QString &localKey)
{
    if (const QString k = key(localKey); !k.isEmpty() && m_session->connection()->isConnected()) {
        m_session->command(k);
    }
}

bool JogPanel::motorBusy() const
{
    return m_jog->state(m_motor) != JogController::State::Idle ||
           m_session->motion()->active(m_motor).has_value() ||
           m_session->parameters()
                   ->store()
                   ->deviceValue(key(QStringLiteral("running")))
                   .value_or(0) != 0;
}

QString JogPanel::moveBlocker() const
{
    if (!m_session->connection()->isConnected())
        return tr("Not connected.");
    const QString lang = Language::instance().current();
    QStringList unknown;
    QStringList edited;
    for (const char *local : {"move_distance", "direction", "speed"}) {
        const Parameter *p = param(QLatin1String(local));
        if (!p)
            continue;
        const ParameterStore::Entry e = m_session->parameters()->store()->entry(p->key);
        if (!e.device)
            unknown << p->label.text(lang);
        else if (e.edited)
            edited << p->label.text(lang);
    }
    if (!unknown.isEmpty())
        return tr("Not read yet: %1.").arg(Translators::joinList(unknown));
    if (!edited.isEmpty())
        return tr("%1 edited but not written: the controller moves by the values it holds. "
                  "Write or revert the edit first.")
            .arg(Translators::joinList(edited));
    if (motorBusy())
        return tr("The motor is moving.");
    return {};
}

QString JogPanel::moveText() const
{
    const ParameterStore *store = m_session->parameters()->store();
    const QString lang = Language::instance().current();
    const Parameter *distance = param(QStringLiteral("move_distance"));
    const Parameter *direction = param(QStringLiteral("direction"));
    const Parameter *speed = param(QStringLiteral("speed"));
    if (!distance || !direction || !speed)
        return tr("This controller has no single move.");
    const auto d = store->deviceValue(distance->key);
    const auto dir = store->deviceValue(direction->key);
    const auto s = store->deviceValue(speed->key);
    if (!d || !dir || !s)
        return QStringLiteral("—");
    return tr("%1, %2, at %3")
        .arg(distance->displayRaw(*d, lang), direction->displayRaw(*dir, lang),
             speed->displayRaw(*s, lang));
}

QString JogPanel::positionText() const
{
    const Parameter *p = param(QStringLiteral("position"));
    const auto raw = p ? m_session->parameters()->store()->deviceValue(p->key) : std::nullopt;
    return raw ? p->displayRaw(*raw, Language::instance().current()) : QStringLiteral("—");
}

QString JogPanel::statusText() const
{
    using State = JogController::State;
    const auto running =
        m_session->parameters()->store()->deviceValue(key(QStringLiteral("running")));
    switch (m_jog->state(m_motor)) {
    case State::Jogging:
        return m_jog->direction(m_motor) == JogController::Direction::Forward
                   ? tr("Jogging forward")
                   : tr("Jogging in reverse");
    case State::Stopping:
        return tr("Stopping…");
    case State::StillRunning:
        return tr("STILL RUNNING after its stop: use the E-STOP");
    case State::PossiblyRunning:
        return tr("Possibly still running: the link was lost; the stop goes out when it is back");
    case State::Idle:
        break;
    }
    const MotionSupervisor *motion = m_session->motion();
    if (const auto active = motion->active(m_motor))
        return running.value_or(0) ? tr("%1… running").arg(MotionJudge::name(*active))
                                   : tr("%1…").arg(MotionJudge::name(*active));
    if (!running)
        return tr("Unknown");
    if (*running)
        return tr("Running");
    // The last judged outcome, in words made now (a language switch retranslates it).
    const auto last = motion->lastOutcome(m_motor);
    return last && !m_hideOutcome ? tr("Idle — %1").arg(motion->text(*last)) : tr("Idle");
}

QString JogPanel::referenceText() const
{
    return m_session->motion()->references()->text(m_motor);
}

void JogPanel::refresh()
{
    const bool connected = m_session->connection()->isConnected();
    const ParameterStore *store = m_session->parameters()->store();
    const auto running = store->deviceValue(key(QStringLiteral("running")));
    m_led->setState(!running ? Led::State::Unknown : *running ? Led::State::On : Led::State::Off);
    m_status->setText(statusText());
    m_led->setToolTip(m_status->text());
    m_led->setAccessibleName(m_status->text());

    // The jog buttons depend on the link only: disabling one while held would end the jog.
    m_reverse->setEnabled(connected);
    m_forward->setEnabled(connected);
    const auto dir = m_jog->direction(m_motor);
    m_reverse->setDown(m_reverse->isHeld() || dir == JogController::Direction::Reverse);
    m_forward->setDown(m_forward->isHeld() || dir == JogController::Direction::Forward);
    m_stop->setEnabled(connected && !key(QStringLiteral("stop")).isEmpty());

    const Parameter *speed = param(QStringLiteral("speed"));
    const ParameterStore::Entry e = speed ? store->entry(speed->key) : ParameterStore::Entry{};
    m_applySpeed->setEnabled(connected && e.edited.has_value());
    const QString lang = Language::instance().current();
    if (speed && e.edited && e.device)
        m_speedNote->setText(
            tr("Jogs at %1, the controller's value, until you apply %2.")
                .arg(speed->displayRaw(*e.device, lang), speed->displayRaw(*e.edited, lang)));
    else
        m_speedNote->clear();
    m_speedNote->setVisible(!m_speedNote->text().isEmpty());

    const QString blocker = moveBlocker();
    // Said before the move, not found out after it: a limit already ON in its direction.
    const QString warning = m_session->motion()->startWarning(key(QStringLiteral("move")));
    m_moveInfo->setText(warning.isEmpty() ? moveText()
                                          : QStringLiteral("%1\n⚠ %2").arg(moveText(), warning));
    m_move->setEnabled(blocker.isEmpty() && !key(QStringLiteral("move")).isEmpty());
    m_move->setToolTip(blocker.isEmpty()
                           ? tr("Move once by the distance shown, in the direction and at the "
                                "speed shown (coil %1)")
                                 .arg(param(QStringLiteral("move"))
                                          ? param(QStringLiteral("move"))->registerName()
                                          : QString())
                           : blocker);
    const Parameter *home = param(QStringLiteral("home_input"));
    const auto input = home ? store->deviceValue(home->key) : std::nullopt;
    if (!input)
        m_homeInfo->setText(QStringLiteral("—"));
    else if (*input == 0)
        m_homeInfo->setText(tr("No home input: runs in reverse until a limit or a stop, "
                               "without zeroing."));
    else
        m_homeInfo->setText(
            tr("Reverse until %1, then position 0.").arg(home->displayRaw(*input, lang)));
    m_home->setEnabled(connected && !motorBusy() && !key(QStringLiteral("home")).isEmpty());
    m_reference->setText(tr("Reference: %1").arg(referenceText()));
}

void JogPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QGroupBox::changeEvent(event);
}

void JogPanel::retranslate()
{
    setTitle(tr("Motor %1").arg(m_motor));
    // No mnemonics on the hold buttons: a key would "click" them into a short jog.
    m_reverse->setText(tr("◀ Reverse"));
    m_forward->setText(tr("Forward ▶"));
    m_reverse->setToolTip(tr("Hold to run motor %1 in reverse; let go to stop").arg(m_motor));
    m_forward->setToolTip(tr("Hold to run motor %1 forward; let go to stop").arg(m_motor));
    m_stop->setText(tr("Stop motor &%1").arg(m_motor));
    m_stop->setToolTip(tr("Stop motor %1 at once, whatever started it").arg(m_motor));
    m_speedLabel->setText(tr("Jog speed:"));
    m_applySpeed->setText(tr("&Apply speed"));
    m_applySpeed->setToolTip(
        tr("Write just the jog speed to the controller: the write dialog shows it first, then "
           "it is written and read back. The controller takes a new speed even while the motor "
           "runs. Other edits wait for \"Write changes\"."));
    m_moveLabel->setText(tr("Single move:"));
    m_move->setText(tr("&Single move"));
    m_homeLabel->setText(tr("Home:"));
    m_home->setText(tr("Home &motor %1").arg(m_motor));
    m_home->setToolTip(
        tr("Run motor %1 in reverse to its home input and set its position to 0").arg(m_motor));
    refresh();
}

} // namespace stepcom

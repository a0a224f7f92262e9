#include "widgets/docks/machinestrip.h"

#include "base/emergencystop.h"
#include "base/language.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/elidedlabel.h"
#include "widgets/fields/led.h"
#include "widgets/fields/statetone.h"

#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");
const QString kUnknown = QStringLiteral("—");

// The state palette (statetone.h) against what the label is drawn on.
void setTone(QLabel *label, StateTone tone)
{
    const QWidget *under = label->parentWidget();
    QPalette pal = label->palette();
    pal.setColor(QPalette::WindowText,
                 stateColour(tone, under->palette(), under->backgroundRole()));
    label->setPalette(pal);
}

Led::State lampState(std::optional<qint64> value)
{
    if (!value)
        return Led::State::Unknown;
    return *value ? Led::State::On : Led::State::Off;
}

QFrame *separator(QWidget *parent)
{
    auto *line = new QFrame(parent);
    line->setFrameShape(QFrame::VLine);
    line->setFrameShadow(QFrame::Sunken);
    return line;
}

} // namespace

MachineStrip::MachineStrip(DeviceSession *session, EmergencyStop *estop, QWidget *parent)
    : QFrame(parent)
    , m_session(session)
    , m_inputsCaption(new QLabel(this))
    , m_outputsCaption(new QLabel(this))
    , m_link(new QLabel(this))
    , m_line(new ElidedLabel(this))
    , m_device(new ElidedLabel(this))
    , m_pendant(new QLabel(this))
    , m_sequence(new QLabel(this))
    , m_proofWarning(new QLabel(this))
    , m_proofAction(new QToolButton(this))
    , m_estopButton(estop->createButton(this))
{
    setObjectName(QStringLiteral("machineStrip"));
    setFrameShape(QFrame::StyledPanel);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    const RegisterMap &map = session->map();
    auto *row = new QHBoxLayout(this);
    for (int n = 1; n <= map.blockCount(kMotor); ++n) {
        const Parameter *pos = map.blockParameter(kMotor, n, QStringLiteral("position"));
        if (!pos)
            break;
        const Parameter *run = map.blockParameter(kMotor, n, QStringLiteral("running"));
        MotorView v;
        v.positionKey = pos->key;
        v.runningKey = run ? run->key : QString();
        v.caption = new QLabel(this);
        v.position = new QLabel(this);
        v.position->setObjectName(QStringLiteral("stripPosition%1").arg(n));
        v.position->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        v.position->setTextInteractionFlags(Qt::TextSelectableByMouse);
        v.motion = new QLabel(this);
        v.motion->setObjectName(QStringLiteral("stripMotion%1").arg(n));
        v.reference = new QLabel(this);
        v.reference->setObjectName(QStringLiteral("stripReference%1").arg(n));
        auto *grid = new QGridLayout;
        grid->setVerticalSpacing(0);
        grid->addWidget(v.caption, 0, 0, Qt::AlignLeft | Qt::AlignBottom);
        grid->addWidget(v.position, 1, 0, 2, 1);
        grid->addWidget(v.motion, 1, 1);
        grid->addWidget(v.reference, 2, 1);
        row->addLayout(grid);
        row->addWidget(separator(this));
        m_motors << v;
    }

    auto *io = new QGridLayout;
    io->setVerticalSpacing(2);
    io->addWidget(m_inputsCaption, 0, 0);
    io->addWidget(m_outputsCaption, 1, 0);
    for (int n = 1; map.find(QStringLiteral("io.in%1").arg(n)); ++n) {
        m_inputKeys << QStringLiteral("io.in%1").arg(n);
        auto *led = new Led(this);
        led->setObjectName(QStringLiteral("stripIn%1").arg(n));
        io->addWidget(led, 0, n);
        m_inputLeds << led;
    }
    for (int n = 1; map.find(QStringLiteral("io.out%1").arg(n)); ++n) {
        m_outputKeys << QStringLiteral("io.out%1").arg(n);
        auto *led = new Led(this);
        led->setObjectName(QStringLiteral("stripOut%1").arg(n));
        io->addWidget(led, 1, n);
        m_outputLeds << led;
    }
    row->addLayout(io);
    row->addWidget(separator(this));

    auto *linkColumn = new QVBoxLayout;
    linkColumn->setSpacing(0);
    auto *linkRow = new QHBoxLayout;
    m_device->setObjectName(QStringLiteral("stripDevice"));
    m_link->setObjectName(QStringLiteral("stripLink"));
    m_line->setObjectName(QStringLiteral("stripLine"));
    QFont bold = m_link->font();
    bold.setBold(true);
    m_link->setFont(bold);
    m_device->setFont(bold);
    m_device->setMinimumChars(8);
    linkRow->addWidget(m_device);
    linkRow->addSpacing(fontMetrics().averageCharWidth());
    linkRow->addWidget(m_link, 1);
    linkColumn->addLayout(linkRow);
    m_line->setMinimumChars(5);
    linkColumn->addWidget(m_line);
    m_pendant->setObjectName(QStringLiteral("stripPendant"));
    m_pendant->hide();
    linkColumn->addWidget(m_pendant);
    m_sequence->setObjectName(QStringLiteral("stripSequence"));
    m_sequence->hide();
    linkColumn->addWidget(m_sequence);
    m_proofWarning->setObjectName(QStringLiteral("stripProofWarning"));
    m_proofWarning->setStyleSheet(QStringLiteral("color: #c62828; font-weight: bold;"));
    m_proofAction->setObjectName(QStringLiteral("stripProofAction"));
    m_proofWarning->hide();
    m_proofAction->hide();
    connect(m_proofAction, &QToolButton::clicked, this, [this] {
        if (m_onProofAction)
            m_onProofAction();
    });
    auto *proof = new QHBoxLayout;
    proof->addWidget(m_proofWarning);
    proof->addWidget(m_proofAction);
    proof->addStretch(1);
    linkColumn->addLayout(proof);
    row->addLayout(linkColumn, 1);

    // The window's one E-STOP button, at the end: on every page, beside the machine's state.
    m_estopButton->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Expanding);
    row->addWidget(m_estopButton);

    m_refresh.setSingleShot(true);
    m_refresh.setInterval(0);
    connect(&m_refresh, &QTimer::timeout, this, &MachineStrip::refresh);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &key) {
                if (key.startsWith(QLatin1String("io.")) || key.startsWith(kMotor))
                    scheduleRefresh();
            });
    connect(session->parameters()->store(), &ParameterStore::originChanged, this,
            &MachineStrip::scheduleRefresh);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &MachineStrip::scheduleRefresh);
    connect(session->connection(), &SessionConnection::linkStatsChanged, this,
            &MachineStrip::scheduleRefresh);
    connect(session->line(), &SessionLine::deviceInViewChanged, this,
            &MachineStrip::scheduleRefresh);
    connect(session->line(), &SessionLine::deviceIdsChanged, this, &MachineStrip::scheduleRefresh);
    connect(session->connection()->health(), &LinkHealth::stateChanged, this,
            &MachineStrip::scheduleRefresh);
    connect(session->motion()->references(), &ReferenceTracker::changed, this,
            &MachineStrip::scheduleRefresh);
    applyFonts();
    retranslate();
}

QLabel *MachineStrip::positionLabel(int motor) const
{
    return motor >= 1 && motor <= m_motors.size() ? m_motors.at(motor - 1).position : nullptr;
}

QLabel *MachineStrip::motionLabel(int motor) const
{
    return motor >= 1 && motor <= m_motors.size() ? m_motors.at(motor - 1).motion : nullptr;
}

QLabel *MachineStrip::referenceLabel(int motor) const
{
    return motor >= 1 && motor <= m_motors.size() ? m_motors.at(motor - 1).reference : nullptr;
}

MachineStrip::Motion MachineStrip::motion(int motor) const
{
    return motor >= 1 && motor <= m_motors.size() ? m_motors.at(motor - 1).state : Motion::Unknown;
}

void MachineStrip::setCompact(bool compact)
{
    if (m_compact == compact)
        return;
    m_compact = compact;
    applyFonts();
}

void MachineStrip::setDeviceNamer(std::function<QString(int)> namer)
{
    m_namer = std::move(namer);
    scheduleRefresh();
}

void MachineStrip::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::FontChange || event->type() == QEvent::PaletteChange)
        applyFonts();
    QFrame::changeEvent(event);
}

void MachineStrip::applyFonts()
{
    // Fixed-width digits, as wide as the widest value the register holds ("-21474836.48 mm"):
    // a changing position never moves its neighbours and is never cut.
    QFont big = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    big.setPointSizeF(font().pointSizeF() * (m_compact ? 1.3 : 2.0));
    big.setBold(true);
    const QFontMetrics fm(big);
    const QString lang = Language::instance().current();
    const RegisterMap &map = m_session->map();
    for (const MotorView &v : std::as_const(m_motors)) {
        v.position->setFont(big);
        int widest = fm.horizontalAdvance(kUnknown);
        if (const Parameter *p = map.find(v.positionKey)) {
            for (qint64 raw : {p->rawMin, p->rawMax, std::max<qint64>(p->rawMin, -999999999)})
                widest = std::max(widest, fm.horizontalAdvance(p->displayRaw(raw, lang)));
        }
        v.position->setFixedWidth(widest + fm.horizontalAdvance(QLatin1Char(' ')));
    }
    layout()->setContentsMargins(m_compact ? QMargins(4, 1, 4, 1) : QMargins(6, 4, 6, 4));
    QFont estop = font();
    estop.setBold(true);
    estop.setPointSizeF(font().pointSizeF() * (m_compact ? 1.2 : 1.7));
    m_estopButton->setFont(estop);
    m_estopButton->setMinimumHeight(fm.height());
    updateGeometry();
}

void MachineStrip::scheduleRefresh()
{
    if (!m_refresh.isActive())
        m_refresh.start();
}

QStringList MachineStrip::inputRoles(int n) const
{
    QStringList roles;
    const RegisterMap &map = m_session->map();
    const ParameterStore *store = m_session->parameters()->store();
    const QString lang = Language::instance().current();
    for (int m = 1; m <= m_motors.size(); ++m) {
        for (const char *role : {"limit_positive", "limit_negative", "home_input"}) {
            const Parameter *p = map.blockParameter(kMotor, m, QLatin1String(role));
            if (p && store->deviceValue(p->key) == n)
                roles << p->label.text(lang);
        }
    }
    return roles;
}

MachineStrip::Motion MachineStrip::motionOf(int motor, std::optional<qint64> running) const
{
    // A replayed log's moment is known as a connected controller's is.
    if (!running ||
        !(m_session->connection()->isConnected() || m_session->parameters()->store()->isReplay()))
        return Motion::Unknown;
    if (*running)
        return Motion::Running;
    // Stopped with one of its limit inputs on: it stands at that limit.
    const RegisterMap &map = m_session->map();
    const ParameterStore *store = m_session->parameters()->store();
    for (const char *role : {"limit_positive", "limit_negative"}) {
        const Parameter *p = map.blockParameter(kMotor, motor, QLatin1String(role));
        const auto input = p ? store->deviceValue(p->key) : std::nullopt;
        if (input && *input > 0 &&
            store->deviceValue(QStringLiteral("io.in%1").arg(*input)).value_or(0) != 0)
            return Motion::AtLimit;
    }
    return Motion::Idle;
}

void MachineStrip::refresh()
{
    const ParameterStore *store = m_session->parameters()->store();
    const RegisterMap &map = m_session->map();
    const QString lang = Language::instance().current();
    const bool connected = m_session->connection()->isConnected() || store->isReplay();
    const ReferenceTracker *references = m_session->motion()->references();
    for (int m = 0; m < m_motors.size(); ++m) {
        MotorView &v = m_motors[m];
        const auto raw = connected ? store->deviceValue(v.positionKey) : std::nullopt;
        const Parameter *p = map.find(v.positionKey);
        v.position->setText(raw && p ? p->displayRaw(*raw, lang) : kUnknown);
        setTone(v.position, raw ? StateTone::Normal : StateTone::Unknown);
        const auto running =
            v.runningKey.isEmpty() ? std::nullopt : store->deviceValue(v.runningKey);
        v.state = motionOf(m + 1, running);
        switch (v.state) {
        case Motion::Unknown:
            v.motion->setText(kUnknown);
            setTone(v.motion, StateTone::Unknown);
            break;
        case Motion::Idle:
            v.motion->setText(tr("idle"));
            setTone(v.motion, StateTone::Normal);
            break;
        case Motion::Running:
            v.motion->setText(tr("running"));
            setTone(v.motion, StateTone::Running);
            break;
        case Motion::AtLimit:
            v.motion->setText(tr("at a limit"));
            setTone(v.motion, StateTone::Warning);
            break;
        }
        v.motion->setAccessibleName(tr("Motor %1: %2").arg(m + 1).arg(v.motion->text()));
        // Not known after a possible restart: said as unknown, as the status dock says it.
        const bool referenced = references->isReferenced(m + 1);
        const bool known = references->isKnown(m + 1);
        v.reference->setText(referenced
                                 ? tr("referenced")
                                 : (known ? tr("not referenced") : tr("reference not known")));
        v.reference->setToolTip(references->text(m + 1));
        setTone(v.reference,
                referenced ? StateTone::Good : (known ? StateTone::Warning : StateTone::Unknown));
        v.position->setAccessibleName(
            tr("Motor %1 position: %2").arg(m + 1).arg(v.position->text()));
    }
    const auto lamp = [&](Led *led, const QString &key, const QStringList &roles) {
        const auto value = connected ? store->deviceValue(key) : std::nullopt;
        led->setState(lampState(value));
        const Parameter *p = map.find(key);
        QString tip =
            QStringLiteral("%1: %2").arg(p ? p->label.text(lang) : key,
                                         !value ? tr("unknown") : (*value ? tr("on") : tr("off")));
        if (!roles.isEmpty())
            tip += QStringLiteral("\n") + roles.join(QLatin1Char('\n'));
        led->setToolTip(tip);
        led->setAccessibleName(tip);
    };
    for (int i = 0; i < m_inputLeds.size(); ++i)
        lamp(m_inputLeds.at(i), m_inputKeys.at(i), inputRoles(i + 1));
    for (int i = 0; i < m_outputLeds.size(); ++i)
        lamp(m_outputLeds.at(i), m_outputKeys.at(i), {});
    refreshLink();
}

void MachineStrip::showReplayLink(bool linkUp, bool answering, const QString &line)
{
    m_replay = ReplayLink{linkUp, answering, line};
    refreshLink();
}

void MachineStrip::setSequenceText(const QString &text)
{
    m_sequence->setText(text);
    m_sequence->setAccessibleName(text);
    m_sequence->setVisible(!text.isEmpty());
}

void MachineStrip::setPendantText(const QString &text)
{
    m_pendant->setText(text);
    m_pendant->setAccessibleName(text);
    m_pendant->setVisible(!text.isEmpty());
}

void MachineStrip::setProofWarning(const QString &text, const QString &action,
                                   std::function<void()> onAction)
{
    m_proofWarning->setText(text);
    m_proofWarning->setAccessibleName(text);
    m_proofWarning->setVisible(!text.isEmpty());
    m_proofAction->setText(action);
    m_proofAction->setVisible(!text.isEmpty() && !action.isEmpty());
    m_onProofAction = std::move(onAction);
}

void MachineStrip::endReplay()
{
    m_replay.reset();
    refreshLink();
}

void MachineStrip::refreshLink()
{
    StateTone tone = StateTone::Unknown;
    LinkHealth::State state = m_session->connection()->health()->state();
    if (m_replay)
        state = !m_replay->linkUp     ? LinkHealth::State::Closed
                : m_replay->answering ? LinkHealth::State::Answering
                                      : LinkHealth::State::NotAnswering;
    switch (state) {
    case LinkHealth::State::Closed:
        m_link->setText(tr("port closed"));
        break;
    case LinkHealth::State::Opening:
    case LinkHealth::State::Asking:
        m_link->setText(tr("asking…"));
        break;
    case LinkHealth::State::NotAnswering:
        m_link->setText(tr("not answering"));
        tone = StateTone::Warning;
        break;
    case LinkHealth::State::Answering:
        m_link->setText(tr("answering"));
        tone = StateTone::Good;
        break;
    }
    setTone(m_link, tone);
    m_link->setToolTip(state == LinkHealth::State::NotAnswering && !m_replay
                           ? LinkHealth::likelyCauses()
                           : QString());
    m_link->setAccessibleName(tr("Link: %1").arg(m_link->text()));
    const int id = m_session->line()->deviceInView();
    const LinkStats &stats = m_session->connection()->linkStats();
    ElidedLabel *line = m_line;
    const bool known = (m_session->connection()->isConnected() && stats.answers > 0) ||
                       (m_replay && !m_replay->line.isEmpty());
    line->setFullText(m_replay ? (known ? m_replay->line : kUnknown)
                      : known  ? stats.lineText(id)
                               : kUnknown);
    setTone(line, known ? StateTone::Normal : StateTone::Unknown);
    line->setAccessibleName(tr("Line: %1").arg(line->fullText()));
    const QList<int> ids = m_session->line()->deviceIds();
    m_device->setVisible(ids.size() > 1);
    const QString name = m_namer ? m_namer(id) : QString();
    m_device->setFullText(name.isEmpty() ? tr("Device %1").arg(id)
                                         : tr("%1 (id %2)").arg(name).arg(id));
}

void MachineStrip::retranslate()
{
    for (int m = 0; m < m_motors.size(); ++m) {
        m_motors.at(m).caption->setText(tr("Motor %1").arg(m + 1));
        m_motors.at(m).position->setToolTip(tr("Motor %1 position").arg(m + 1));
    }
    m_inputsCaption->setText(tr("IN 1-%1").arg(m_inputLeds.size()));
    m_outputsCaption->setText(tr("OUT 1-%1").arg(m_outputLeds.size()));
    applyFonts(); // the unit's words follow the language
    refresh();
}

} // namespace stepcom

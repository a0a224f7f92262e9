#include "pages/motionpage.h"

#include "base/language.h"
#include "base/writeflow.h"
#include "i18n/translators.h"
#include "motion/motionjudge.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/aboutbox.h"
#include "widgets/fields/led.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/gamepadpanel.h"
#include "widgets/motion/homingordereditor.h"
#include "widgets/motion/jogkeys.h"
#include "widgets/motion/jogpanel.h"
#include "widgets/motion/stepmovepanel.h"
#include "widgets/motion/travellimitseditor.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const char *const kOutputCommands[] = {"output1_on", "output1_off", "outputs_all_on",
                                       "outputs_all_off"};

QString outputKey(int n)
{
    return QStringLiteral("io.out%1").arg(n);
}

// A note that must be seen, in the palette's own tooltip colours (readable light and dark).
void makeProminent(QWidget *w, QPalette::ColorRole back, QPalette::ColorRole text)
{
    w->setAutoFillBackground(true);
    QPalette pal = w->palette();
    pal.setColor(QPalette::Window, pal.color(back));
    pal.setColor(QPalette::WindowText, pal.color(text));
    w->setPalette(pal);
}

} // namespace

MotionPage::MotionPage(DeviceSession *session, WriteFlow *writes, QWidget *parent)
    : Page(session, parent)
    , m_jog(session->jog())
    , m_writes(writes)
    , m_keys(new JogKeys(m_jog, this, this))
{
    // A scroll area keeps every control reachable at 200% scale on a small screen.
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);
    auto *content = new QWidget(scroll);
    scroll->setWidget(content);
    auto *rows = new QVBoxLayout(content);

    m_banner = new QFrame(content);
    m_banner->setFrameShape(QFrame::StyledPanel);
    auto *bannerLayout = new QHBoxLayout(m_banner);
    m_bannerIcon = new QLabel(m_banner);
    const int iconSize = style()->pixelMetric(QStyle::PM_MessageBoxIconSize);
    m_bannerIcon->setPixmap(
        style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(iconSize, iconSize));
    m_bannerText = new QLabel(m_banner);
    m_bannerText->setWordWrap(true);
    m_bannerText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont bold = m_bannerText->font();
    bold.setBold(true);
    m_bannerText->setFont(bold);
    m_bannerClear = new QPushButton(m_banner);
    m_bannerClear->setAutoDefault(false);
    bannerLayout->addWidget(m_bannerIcon, 0, Qt::AlignTop);
    bannerLayout->addWidget(m_bannerText, 1);
    bannerLayout->addWidget(m_bannerClear, 0, Qt::AlignTop);
    makeProminent(m_banner, QPalette::ToolTipBase, QPalette::ToolTipText);
    m_banner->hide();
    rows->addWidget(m_banner);
    m_about = new AboutBox(content); // Explanations on demand
    rows->addWidget(m_about);

    auto *keyboardRow = new QHBoxLayout;
    m_keyboard = new QCheckBox(content);
    m_keyboardIndicator = new QLabel(content);
    m_keyboardIndicator->setFont(bold);
    m_keyboardIndicator->setMargin(m_keyboardIndicator->fontMetrics().height() / 4);
    makeProminent(m_keyboardIndicator, QPalette::Highlight, QPalette::HighlightedText);
    m_keyboardIndicator->hide();
    m_keyboardHelp = new QLabel(content);
    m_keyboardHelp->setWordWrap(true);
    keyboardRow->addWidget(m_keyboard);
    keyboardRow->addWidget(m_keyboardIndicator);
    keyboardRow->addWidget(m_keyboardHelp, 1);
    rows->addLayout(keyboardRow);

    // Motors side by side, two to a row, so a 3-motor map still fits.
    auto *panels = new QGridLayout;
    for (int n = 1; n <= m_jog->motorCount(); ++n) {
        auto *p = new JogPanel(session, m_jog, m_writes, n, content);
        panels->addWidget(p, (n - 1) / 2, (n - 1) % 2, Qt::AlignTop);
        m_panels << p;
        if (ParameterField *f = p->speedField())
            connect(f, &ParameterField::rejected, this,
                    [this, f] { showBannerOf([f] { return f->rejectionText(); }); });
    }
    rows->addLayout(panels);
    m_limits = new TravelLimitsEditor(session, content);
    rows->addWidget(m_limits);
    m_gamepad = new GamepadPanel(session, content); // jogging at the machine, with a dead-man
    rows->addWidget(m_gamepad);

    auto *bottom = new QHBoxLayout;
    buildHoming(content);
    buildOutputs(content);
    bottom->addWidget(m_homingBox, 3, Qt::AlignTop);
    bottom->addWidget(m_outputsBox, 2, Qt::AlignTop);
    rows->addLayout(bottom);
    rows->addStretch(1);

    // Tab order: keyboard switch, each motor, homing, outputs, then the banner's button.
    QList<QWidget *> chain{m_keyboard};
    for (JogPanel *p : std::as_const(m_panels))
        chain << p->tabChain();
    chain << m_order->combo(0) << m_order->combo(1) << m_applyOrder << m_homeAll << m_zero
          << m_returnToZero;
    for (const char *k : kOutputCommands) {
        if (QPushButton *b = m_outputButtons.value(QLatin1String(k)))
            chain << b;
    }
    chain << m_bannerClear;
    for (int i = 1; i < chain.size(); ++i)
        setTabOrder(chain.at(i - 1), chain.at(i));

    connect(m_bannerClear, &QPushButton::clicked, m_banner, &QWidget::hide);
    connect(m_keyboard, &QCheckBox::toggled, m_jog, &JogController::setKeyboardEnabled);
    connect(m_jog, &JogController::keyboardEnabledChanged, this, &MotionPage::setKeyboard);
    connect(m_jog, &JogController::message, this,
            [this](DeviceSession::Severity s, const QString &text) {
                if (s != DeviceSession::Severity::Info)
                    showBanner(text);
            });
    connect(m_jog, &JogController::stateChanged, this, &MotionPage::refresh);
    // E-STOP: keys and buttons let go at once; a held key must be pressed again to jog.
    connect(m_jog, &JogController::heldControlsReset, this, [this] {
        m_keys->letGo();
        for (JogPanel *p : std::as_const(m_panels))
            p->letGo();
    });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &MotionPage::refresh);
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this,
            &MotionPage::refresh);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &k) {
                if (k.startsWith(QLatin1String("homing.")) ||
                    k.startsWith(QLatin1String("io.out")) || k.endsWith(QLatin1String(".running")))
                    refresh();
            });
    connect(session, &DeviceSession::commandFinished, this, [this](const QString &k, bool ok) {
        if (ok && k == QLatin1String("zero_coordinates"))
            m_shown = Shown::Zeroed;
        refresh();
    });
    connect(session->motion(), &MotionSupervisor::changed, this, &MotionPage::refresh);
    connect(session->motion(), &MotionSupervisor::finished, this, [this](const MotionOutcome &o) {
        if (o.start.kind == MotionKind::HomeInOrder)
            m_shown = Shown::HomeInOrder;
        else if (o.start.kind == MotionKind::ReturnToZero)
            m_shown = Shown::ReturnToZero;
    });
    retranslate();
}

MotionPage::~MotionPage() = default;

void MotionPage::buildHoming(QWidget *content)
{
    m_homingBox = new QGroupBox(content);
    auto *layout = new QVBoxLayout(m_homingBox);
    m_order = new HomingOrderEditor(session()->parameters()->store(), m_homingBox);
    layout->addWidget(m_order);
    auto *applyRow = new QHBoxLayout;
    m_applyOrder = new QPushButton(m_homingBox);
    m_orderNote = new QLabel(m_homingBox);
    m_orderNote->setWordWrap(true);
    applyRow->addWidget(m_applyOrder);
    applyRow->addWidget(m_orderNote, 1);
    layout->addLayout(applyRow);
    auto *commands = new QHBoxLayout;
    m_homeAll = new QPushButton(m_homingBox);
    m_zero = new QPushButton(m_homingBox);
    m_returnToZero = new QPushButton(m_homingBox);
    for (QPushButton *b : {m_applyOrder, m_homeAll, m_zero, m_returnToZero})
        b->setAutoDefault(false);
    commands->addWidget(m_homeAll);
    commands->addWidget(m_zero);
    commands->addWidget(m_returnToZero);
    commands->addStretch(1);
    layout->addLayout(commands);
    m_homingStatus = new QLabel(m_homingBox);
    m_homingStatus->setWordWrap(true);
    layout->addWidget(m_homingStatus);

    connect(m_order, &HomingOrderEditor::rejected, this, &MotionPage::showBanner);
    // The window's write dialog for the order alone: reviewed, read back and logged as "Write
    // changes" is.
    connect(m_applyOrder, &QPushButton::clicked, this, [this] {
        m_writes->openFor({m_order->key(0), m_order->key(1)});
    });
    connect(m_homeAll, &QPushButton::clicked, this,
            [this] { sessionCommand(QStringLiteral("home_all")); });
    connect(m_zero, &QPushButton::clicked, this,
            [this] { sessionCommand(QStringLiteral("zero_coordinates")); });
    connect(m_returnToZero, &QPushButton::clicked, this,
            [this] { sessionCommand(QStringLiteral("return_to_zero")); });
}

void MotionPage::buildOutputs(QWidget *content)
{
    m_outputsBox = new QGroupBox(content);
    auto *grid = new QGridLayout(m_outputsBox);
    int row = 0;
    for (int n = 1; session()->map().find(outputKey(n)); ++n, ++row) {
        auto *led = new Led(m_outputsBox);
        led->setOnColor(QColor(255, 170, 0)); // amber: an output, as on the inputs page
        auto *name = new QLabel(m_outputsBox);
        grid->addWidget(led, row, 0);
        grid->addWidget(name, row, 1, 1, 2);
        m_outputLeds << led;
        m_outputNames << name;
    }
    for (int i = 0; i < 4; ++i) {
        const QString k = QLatin1String(kOutputCommands[i]);
        if (!session()->map().find(k))
            continue;
        auto *b = new QPushButton(m_outputsBox);
        b->setAutoDefault(false);
        grid->addWidget(b, row + i / 2, 1 + i % 2);
        m_outputButtons.insert(k, b);
        connect(b, &QPushButton::clicked, this, [this, k] { sessionCommand(k); });
    }
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(2, 1);
}

QString MotionPage::title() const
{
    return tr("Jog and home");
}

QStringList MotionPage::keys() const
{
    QStringList k;
    for (JogPanel *p : m_panels) {
        if (p->speedField())
            k << p->speedField()->parameter().key;
    }
    k << m_order->key(0) << m_order->key(1);
    return k;
}

QPushButton *MotionPage::outputButton(const QString &commandKey) const
{
    return m_outputButtons.value(commandKey);
}

bool MotionPage::bannerShown() const
{
    return !m_banner->isHidden();
}

QString MotionPage::bannerText() const
{
    return m_bannerText->text();
}

void MotionPage::showBanner(const QString &text)
{
    m_bannerSource = {};
    m_bannerText->setText(text);
    m_banner->show();
}

void MotionPage::showBannerOf(std::function<QString()> text)
{
    m_bannerSource = std::move(text);
    m_bannerText->setText(m_bannerSource());
    m_banner->show();
}

void MotionPage::sessionCommand(const QString &key)
{
    if (!session()->connection()->isConnected())
        return;
    if (key == QLatin1String("home_all") || key == QLatin1String("return_to_zero"))
        m_shown = Shown::Nothing;
    session()->command(key);
}

QString MotionPage::homingStatus() const
{
    const MotionSupervisor *motion = session()->motion();
    for (MotionKind kind : {MotionKind::HomeInOrder, MotionKind::ReturnToZero}) {
        const auto active = motion->active(kind);
        if (!active)
            continue;
        QStringList motors;
        for (int n : motion->running(kind))
            motors << QString::number(n);
        const QString what = MotionJudge::name(*active);
        if (motors.isEmpty())
            return tr("%1…").arg(what);
        return tr("%1… motor %2 running").arg(what, Translators::joinList(motors));
    }
    // Made from state each time, so a language switch retranslates it.
    std::optional<MotionOutcome> last;
    switch (m_shown) {
    case Shown::Nothing:
        return {};
    case Shown::Zeroed:
        return tr("Coordinates zeroed");
    case Shown::HomeInOrder:
        last = motion->lastOutcome(MotionKind::HomeInOrder);
        break;
    case Shown::ReturnToZero:
        last = motion->lastOutcome(MotionKind::ReturnToZero);
        break;
    }
    return last ? motion->text(*last) : QString();
}

void MotionPage::refresh()
{
    const bool connected = session()->connection()->isConnected();
    const bool sequence = session()->motion()->active(MotionKind::HomeInOrder).has_value() ||
                          session()->motion()->active(MotionKind::ReturnToZero).has_value();
    const bool jogging = m_jog->isBusy();
    const bool orderEdited = m_order->isEdited();
    m_applyOrder->setEnabled(connected && orderEdited);
    m_homeAll->setEnabled(connected && m_order->isKnown() && !orderEdited && !sequence && !jogging);
    m_zero->setEnabled(connected && !sequence && !jogging);
    m_returnToZero->setEnabled(connected && !sequence && !jogging);
    if (orderEdited)
        m_orderNote->setText(tr("\"Home in order\" uses the order the controller holds (%1) "
                                "until you apply the edit.")
                                 .arg(m_order->deviceOrderText()));
    else if (m_order->isKnown())
        m_orderNote->setText(tr("Homes %1.").arg(m_order->deviceOrderText()));
    else
        m_orderNote->setText(QStringLiteral("—"));
    m_homeAll->setToolTip(m_orderNote->text());
    // Said before, not found out after: "return to data zero" into a limit already ON.
    const QString warning = session()->motion()->startWarning(QStringLiteral("return_to_zero"));
    m_returnToZero->setToolTip(warning.isEmpty() ? tr("Drive every idle motor back to position 0")
                                                 : tr("Drive every idle motor back to position 0") +
                                                       QStringLiteral("\n⚠ ") + warning);
    m_homingStatus->setText(homingStatus());
    m_homingStatus->setVisible(!m_homingStatus->text().isEmpty());

    for (QPushButton *b : std::as_const(m_outputButtons))
        b->setEnabled(connected);
    for (int i = 0; i < m_outputLeds.size(); ++i) {
        const auto v = session()->parameters()->store()->deviceValue(outputKey(i + 1));
        m_outputLeds.at(i)->setState(!v   ? Led::State::Unknown
                                     : *v ? Led::State::On
                                          : Led::State::Off);
        m_outputLeds.at(i)->setAccessibleName(m_outputNames.at(i)->text());
    }
}

void MotionPage::setKeyboard(bool on)
{
    const QSignalBlocker block(m_keyboard);
    m_keyboard->setChecked(on);
    m_keyboardIndicator->setVisible(on);
}

void MotionPage::hideEvent(QHideEvent *event)
{
    m_keys->letGo(); // the session stops the jogs themselves when the window changes page
    Page::hideEvent(event);
}

bool MotionPage::event(QEvent *event)
{
    // A page gets WindowDeactivate from its window (ActivationChange goes to windows only).
    if (event->type() == QEvent::WindowDeactivate ||
        (event->type() == QEvent::ActivationChange && !isActiveWindow())) {
        m_keys->letGo(); // the session stops the jogs on focus loss (MainWindow tells it)
    }
    return Page::event(event);
}

void MotionPage::retranslate()
{
    // A banner made from state is made again; one kept as text (a jog controller warning) was
    // written in the old language: the messages dock keeps it, the page lets it go.
    if (m_bannerSource) {
        m_bannerText->setText(m_bannerSource());
        m_banner->setHidden(m_banner->isHidden() || m_bannerText->text().isEmpty());
    } else if (!m_bannerText->text().isEmpty())
        m_banner->hide();
    m_bannerClear->setText(tr("&Clear"));
    m_bannerClear->setToolTip(tr("Hide this note; the messages dock keeps it"));
    m_keyboard->setText(tr("&Keyboard jogging"));
    m_keyboard->setToolTip(tr("Off by default. When on, the arrow keys jog while this page is "
                              "shown and the window has focus"));
    m_keyboardIndicator->setText(tr("⌨ KEYBOARD JOGGING ON"));
    m_keyboardHelp->setText(
        tr("Keys: ← → motor 1 reverse/forward, ↓ ↑ motor 2 reverse/forward, Home PgUp End PgDn "
           "the diagonals (both motors). Hold to move, let go to stop. Not while typing in a "
           "field; leaving the page or the window stops."));
    m_about->setText(StepMovePanel::explanation() + QStringLiteral("\n\n") +
                     m_limits->explanation());
    m_homingBox->setTitle(tr("Homing"));
    m_applyOrder->setText(tr("Apply o&rder"));
    m_applyOrder->setToolTip(
        tr("Write just the homing order to the controller: the write dialog shows it first, "
           "then it is written and read back"));
    m_homeAll->setText(tr("Home &in order"));
    m_zero->setText(tr("&Zero coordinates"));
    m_zero->setToolTip(tr("Make the present positions of all motors 0; nothing moves"));
    m_returnToZero->setText(tr("Re&turn to data zero"));
    m_outputsBox->setTitle(tr("Outputs"));
    const QString lang = Language::instance().current();
    for (int i = 0; i < m_outputNames.size(); ++i) {
        const Parameter *p = session()->map().find(outputKey(i + 1));
        m_outputNames.at(i)->setText(p ? p->label.text(lang) : outputKey(i + 1));
    }
    const QHash<QString, QString> texts{
        {QStringLiteral("output1_on"), tr("Output 1 o&n")},
        {QStringLiteral("output1_off"), tr("O&utput 1 off")},
        {QStringLiteral("outputs_all_on"), tr("All out&puts on")},
        {QStringLiteral("outputs_all_off"), tr("All &outputs off")}};
    for (auto it = m_outputButtons.cbegin(); it != m_outputButtons.cend(); ++it) {
        it.value()->setText(texts.value(it.key()));
        const Parameter *p = session()->map().find(it.key());
        it.value()->setToolTip(
            p ? QStringLiteral("%1 — %2").arg(p->label.text(lang), p->registerName()) : QString());
    }
    refresh();
}

} // namespace stepcom

#include "widgets/motion/gamepadpanel.h"

#include "gamepad/sdlgamepad.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kEnabled = QStringLiteral("enabled");
const QString kMapping = QStringLiteral("mapping");

const QList<int> kButtons{GamepadState::kRightTrigger,
                          GamepadState::kLeftTrigger,
                          GamepadState::RightShoulder,
                          GamepadState::LeftShoulder,
                          GamepadState::A,
                          GamepadState::B,
                          GamepadState::X,
                          GamepadState::Y,
                          GamepadState::Back,
                          GamepadState::Start};

} // namespace

GamepadPanel::GamepadPanel(DeviceSession *session, QWidget *parent)
    : QGroupBox(parent)
    , m_session(session)
    , m_reader(new SdlGamepad(this))
    , m_pad(new GamepadJog(session->jog(), this))
    , m_enable(new QCheckBox(this))
    , m_padLabel(new QLabel(this))
    , m_state(new QLabel(this))
    , m_deadman(new QComboBox(this))
    , m_stop(new QComboBox(this))
    , m_home(new QComboBox(this))
    , m_estopBox(new QComboBox(this))
    , m_deadzone(new QDoubleSpinBox(this))
{
    setObjectName(QStringLiteral("gamepadPanel"));
    m_enable->setObjectName(QStringLiteral("gamepadEnabled"));
    m_padLabel->setObjectName(QStringLiteral("gamepadName"));
    m_state->setObjectName(QStringLiteral("gamepadState"));
    m_state->setWordWrap(true);
    m_deadzone->setRange(0.05, 0.9);
    m_deadzone->setSingleStep(0.05);
    auto *form = new QFormLayout;
    for (QComboBox *box : {m_deadman, m_stop, m_home, m_estopBox}) {
        for (int b : kButtons)
            box->addItem(QString(), b);
        auto *caption = new QLabel(this);
        caption->setBuddy(box);
        m_captions << caption;
        form->addRow(caption, box);
        connect(box, &QComboBox::currentIndexChanged, this, &GamepadPanel::mappingEdited);
    }
    auto *zoneCaption = new QLabel(this);
    zoneCaption->setBuddy(m_deadzone);
    m_captions << zoneCaption;
    form->addRow(zoneCaption, m_deadzone);
    connect(m_deadzone, &QDoubleSpinBox::valueChanged, this, &GamepadPanel::mappingEdited);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_enable);
    layout->addWidget(m_padLabel);
    layout->addWidget(m_state);
    layout->addLayout(form);

    QSettings settings;
    settings.beginGroup(settingsGroup());
    QString why;
    const auto saved = GamepadMapping::fromJson(
        QJsonDocument::fromJson(settings.value(kMapping).toByteArray()).object(), &why);
    if (saved)
        m_pad->setMapping(*saved);
    showMapping();

    connect(m_enable, &QCheckBox::toggled, this, &GamepadPanel::setPadEnabled);
    connect(m_reader, &SdlGamepad::state, m_pad, &GamepadJog::update);
    connect(m_reader, &SdlGamepad::detached, m_pad, &GamepadJog::detached);
    connect(m_reader, &SdlGamepad::attached, this, &GamepadPanel::showPad);
    connect(m_reader, &SdlGamepad::detached, this, &GamepadPanel::showPad);
    connect(m_pad, &GamepadJog::homeRequested, this, &GamepadPanel::home);
    connect(m_pad, &GamepadJog::message, this, [this](const QString &t) { m_state->setText(t); });
    connect(m_pad, &GamepadJog::joggingChanged, this, &GamepadPanel::showPad);
    m_enable->setChecked(settings.value(kEnabled, false).toBool()); // off unless the user said
    retranslate();
    showPad();
}

GamepadPanel::~GamepadPanel()
{
    m_pad->setEnabled(false);
}

void GamepadPanel::setEmergencyStop(std::function<void()> estop)
{
    m_pad->setEmergencyStop(std::move(estop));
}

void GamepadPanel::setPadEnabled(bool enabled)
{
    QSettings settings;
    settings.beginGroup(settingsGroup());
    settings.setValue(kEnabled, enabled);
    m_sdlError.clear();
    if (enabled && !m_reader->start(&m_sdlError))
        enabled = false;
    if (!enabled)
        m_reader->stop();
    m_pad->setEnabled(enabled);
    showPad();
}

void GamepadPanel::mappingEdited()
{
    if (m_filling)
        return;
    GamepadMapping m = m_pad->mapping();
    m.deadman = m_deadman->currentData().toInt();
    m.stop = m_stop->currentData().toInt();
    m.home = m_home->currentData().toInt();
    m.emergencyStop = m_estopBox->currentData().toInt();
    m.deadzone = m_deadzone->value();
    QString why;
    // The same rules as a saved mapping: one button, one job.
    if (!GamepadMapping::fromJson(m.toJson(), &why)) {
        m_state->setText(tr("Not changed: %1.").arg(why));
        showMapping();
        return;
    }
    m_pad->setMapping(m);
    QSettings settings;
    settings.beginGroup(settingsGroup());
    settings.setValue(kMapping, QJsonDocument(m.toJson()).toJson(QJsonDocument::Compact));
    showPad();
}

void GamepadPanel::showMapping()
{
    m_filling = true;
    const GamepadMapping &m = m_pad->mapping();
    m_deadman->setCurrentIndex(m_deadman->findData(m.deadman));
    m_stop->setCurrentIndex(m_stop->findData(m.stop));
    m_home->setCurrentIndex(m_home->findData(m.home));
    m_estopBox->setCurrentIndex(m_estopBox->findData(m.emergencyStop));
    m_deadzone->setValue(m.deadzone);
    m_filling = false;
}

void GamepadPanel::showPad()
{
    if (!m_sdlError.isEmpty()) {
        m_padLabel->setText(tr("Game pads cannot be read: %1").arg(m_sdlError));
        m_state->clear();
        return;
    }
    if (!m_enable->isChecked()) {
        m_padLabel->setText(tr("Off: tick it to jog with a game pad."));
        m_state->clear();
        return;
    }
    const auto info = m_reader->info();
    if (!info) {
        m_padLabel->setText(tr("No pad connected: plug one in or pair it (Bluetooth)."));
        m_state->clear();
        return;
    }
    QString battery;
    if (info->wired)
        battery = tr(", wired");
    else if (info->batteryPercent)
        battery = tr(", battery about %1 %").arg(*info->batteryPercent);
    m_padLabel->setText(tr("Connected: %1%2").arg(info->name, battery));
    const QList<int> motors = m_pad->jogging();
    if (motors.isEmpty()) {
        m_state->setText(tr("Hold %1 (the dead-man) and move the left stick or the D-pad to "
                            "jog; %2 stops, %3 is the E-STOP.")
                             .arg(GamepadMapping::buttonName(m_pad->mapping().deadman),
                                  GamepadMapping::buttonName(m_pad->mapping().stop),
                                  GamepadMapping::buttonName(m_pad->mapping().emergencyStop)));
    } else {
        QStringList names;
        for (int m : motors)
            names << tr("motor %1").arg(m);
        m_state->setText(tr("Jogging %1 from the pad.").arg(names.join(QLatin1String(", "))));
    }
}

void GamepadPanel::home()
{
    const QString q = tr("Home the machine in its homing order? The axes will move to their "
                         "home switches.");
    const bool go = m_confirm ? m_confirm(q)
                              : QMessageBox::question(this, tr("Home from the pad"), q,
                                                      QMessageBox::Yes | QMessageBox::No,
                                                      QMessageBox::No) == QMessageBox::Yes;
    if (go)
        m_session->command(QStringLiteral("home_all"));
}

void GamepadPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QGroupBox::changeEvent(event);
}

void GamepadPanel::retranslate()
{
    setTitle(tr("Game pad"));
    m_enable->setText(tr("&Jog with a game pad"));
    m_enable->setToolTip(tr("The pad jogs only while its dead-man is held; unplugged or silent, "
                            "it stops what it jogs."));
    m_captions[0]->setText(tr("Dead-man (hold):"));
    m_captions[1]->setText(tr("Stop:"));
    m_captions[2]->setText(tr("Home:"));
    m_captions[3]->setText(tr("E-STOP:"));
    m_captions[4]->setText(tr("Dead zone:"));
    for (QComboBox *box : {m_deadman, m_stop, m_home, m_estopBox}) {
        for (int i = 0; i < box->count(); ++i)
            box->setItemText(i, GamepadMapping::buttonName(box->itemData(i).toInt()));
    }
    showPad();
}

} // namespace stepcom

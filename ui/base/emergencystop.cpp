#include "base/emergencystop.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QApplication>
#include <QKeyEvent>
#include <QToolButton>

namespace stepcom {

EmergencyStop::EmergencyStop(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    qApp->installEventFilter(this);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &EmergencyStop::refresh);
    connect(session->parameters()->store(), &ParameterStore::originChanged, this,
            &EmergencyStop::refresh);
    m_available = isAvailable();
}

EmergencyStop::~EmergencyStop()
{
    qApp->removeEventFilter(this);
}

bool EmergencyStop::isAvailable() const
{
    // Reconnecting keeps it: an E-STOP then is held and sent first when the link is back. A mode
    // that drives the E-STOP itself (listening beside another master) has a line to send it on.
    if (m_handler)
        return true;
    const ParameterStore *store = m_session->parameters()->store();
    return m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected ||
           !(store->isReplay() || store->isFile());
}

QString EmergencyStop::toolTip() const
{
    const QString key = shortcut().toString(QKeySequence::NativeText);
    const ParameterStore *store = m_session->parameters()->store();
    if (isAvailable())
        return tr("Emergency stop: all motors and outputs off (coil 00042). Key: %1").arg(key);
    return store->isReplay()
               ? tr("Nothing to stop: a session log is replayed and no controller is connected. "
                    "Connect to a controller to use the emergency stop.")
               : tr("Nothing to stop: a profile file is edited and no controller is connected. "
                    "Connect to a controller to use the emergency stop.");
}

void EmergencyStop::trigger()
{
    if (m_handler)
        m_handler();
    else
        m_session->emergencyStop();
    Q_EMIT triggered();
}

void EmergencyStop::refresh()
{
    const bool available = isAvailable();
    for (const QPointer<QToolButton> &button : std::as_const(m_buttons)) {
        if (!button)
            continue;
        button->setEnabled(available);
        button->setText(tr("E-STOP"));
        button->setToolTip(toolTip());
        button->setAccessibleName(button->text());
        button->setAccessibleDescription(toolTip());
    }
    if (available != m_available) {
        m_available = available;
        Q_EMIT availabilityChanged(available);
    }
}

bool EmergencyStop::eventFilter(QObject *watched, QEvent *event)
{
    // An application event filter sees the key before any widget or dialog can eat it;
    // consuming it ends the propagation, so one press is one stop.
    if (event->type() == QEvent::KeyPress) {
        auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_F12 && !key->isAutoRepeat() && watched->isWidgetType()) {
            trigger();
            return true;
        }
    }
    if (event->type() == QEvent::LanguageChange && watched == qApp)
        refresh();
    return QObject::eventFilter(watched, event);
}

QToolButton *EmergencyStop::createButton(QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setObjectName(QStringLiteral("emergencyStopButton"));
    button->setFocusPolicy(Qt::NoFocus); // a click must never be needed twice
    QFont font = button->font();
    font.setBold(true);
    font.setPointSizeF(font.pointSizeF() * 1.3);
    button->setFont(font);
    QPalette pal = button->palette();
    pal.setColor(QPalette::Button, QColor(200, 20, 20));
    pal.setColor(QPalette::ButtonText, Qt::white);
    button->setPalette(pal);
    button->setAutoFillBackground(true);
    // Style sheets are the only reliable way to get a red button in every style; greyed, it
    // must not look like a stop that works.
    button->setStyleSheet(
        QStringLiteral("QToolButton#emergencyStopButton { background: #c81414; color: white; "
                       "border: 2px solid #7a0000;"
                       " border-radius: 4px; padding: 0.3em 1.2em; }"
                       "QToolButton#emergencyStopButton:pressed { background: #8a0000; }"
                       "QToolButton#emergencyStopButton:disabled { background: #d4d4d4; "
                       "color: #606060; border: 2px dashed #909090; }"));
    connect(button, &QToolButton::clicked, this, &EmergencyStop::trigger);
    m_buttons << button;
    refresh();
    return button;
}

} // namespace stepcom

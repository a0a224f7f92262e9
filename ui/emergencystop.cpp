#include "emergencystop.h"

#include "session/devicesession.h"

#include <QApplication>
#include <QKeyEvent>
#include <QToolButton>

namespace stepcom {

EmergencyStop::EmergencyStop(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
{
    qApp->installEventFilter(this);
}

EmergencyStop::~EmergencyStop()
{
    qApp->removeEventFilter(this);
}

void EmergencyStop::trigger()
{
    if (m_handler)
        m_handler();
    else
        m_session->emergencyStop();
    Q_EMIT triggered();
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
    return QObject::eventFilter(watched, event);
}

QToolButton *EmergencyStop::createButton(QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setObjectName(QStringLiteral("emergencyStopButton"));
    button->setText(tr("E-STOP"));
    button->setToolTip(tr("Emergency stop: all motors and outputs off (coil 00042). Key: %1")
                           .arg(shortcut().toString(QKeySequence::NativeText)));
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
    // Style sheets are the only reliable way to get a red button in every style.
    button->setStyleSheet(
        QStringLiteral("QToolButton#emergencyStopButton { background: #c81414; color: white; "
                       "border: 2px solid #7a0000;"
                       " border-radius: 4px; padding: 0.3em 1.2em; }"
                       "QToolButton#emergencyStopButton:pressed { background: #8a0000; }"));
    connect(button, &QToolButton::clicked, this, &EmergencyStop::trigger);
    return button;
}

} // namespace stepcom

#include "widgets/motion/jogbutton.h"

#include <QEvent>
#include <QMouseEvent>

namespace stepcom {

JogButton::JogButton(QWidget *parent)
    : QPushButton(parent)
{
    setFocusPolicy(Qt::NoFocus);
    setAutoDefault(false);
}

void JogButton::letGo()
{
    if (!m_held)
        return;
    m_held = false;
    setDown(false);
    Q_EMIT jogReleased();
}

bool JogButton::event(QEvent *event)
{
    switch (event->type()) {
    case QEvent::Shortcut:
        return true; // a mnemonic would "click" it: a 100 ms jog from a key
    case QEvent::UngrabMouse:
    case QEvent::TouchCancel:
    case QEvent::WindowDeactivate: // children get this one, not ActivationChange
        letGo();
        break;
    default:
        break;
    }
    return QPushButton::event(event);
}

void JogButton::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || !isEnabled()) {
        event->ignore();
        return;
    }
    event->accept();
    if (m_held)
        return;
    m_held = true;
    setDown(true);
    Q_EMIT jogPressed();
}

void JogButton::mouseMoveEvent(QMouseEvent *event)
{
    event->accept();
    if (m_held && !rect().contains(event->position().toPoint()))
        letGo(); // dragged off: stop, and do not restart when it comes back
}

void JogButton::mouseReleaseEvent(QMouseEvent *event)
{
    event->accept();
    if (event->button() == Qt::LeftButton)
        letGo();
}

void JogButton::keyPressEvent(QKeyEvent *event)
{
    QWidget::keyPressEvent(event); // never QAbstractButton's: Space would press it
}

void JogButton::keyReleaseEvent(QKeyEvent *event)
{
    QWidget::keyReleaseEvent(event);
}

void JogButton::hideEvent(QHideEvent *event)
{
    letGo();
    QPushButton::hideEvent(event);
}

void JogButton::changeEvent(QEvent *event)
{
    if ((event->type() == QEvent::EnabledChange && !isEnabled()) ||
        (event->type() == QEvent::ActivationChange && !isActiveWindow()))
        letGo();
    QPushButton::changeEvent(event);
}

} // namespace stepcom

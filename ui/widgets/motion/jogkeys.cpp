#include "widgets/motion/jogkeys.h"

#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QWidget>

namespace stepcom {

JogKeys::JogKeys(JogController *jog, QWidget *scope, QObject *parent)
    : QObject(parent)
    , m_jog(jog)
    , m_scope(scope)
{
    connect(jog, &JogController::keyboardEnabledChanged, this, &JogKeys::follow);
    follow(jog->keyboardEnabled());
}

JogKeys::~JogKeys()
{
    qApp->removeEventFilter(this);
}

// Left/Right jog motor 1 (the x axis), Down/Up motor 2 (y), as on a plotter's keypad.
std::optional<JogKeys::Binding> JogKeys::bindingFor(int key)
{
    using D = JogController::Direction;
    switch (key) {
    case Qt::Key_Left:
        return Binding{1, D::Reverse};
    case Qt::Key_Right:
        return Binding{1, D::Forward};
    case Qt::Key_Down:
        return Binding{2, D::Reverse};
    case Qt::Key_Up:
        return Binding{2, D::Forward};
    default:
        return std::nullopt;
    }
}

void JogKeys::follow(bool enabled)
{
    letGo();
    qApp->removeEventFilter(this);
    if (enabled)
        qApp->installEventFilter(this);
}

void JogKeys::letGo()
{
    const QList<int> held = m_held.keys();
    m_held.clear();
    for (int key : held) {
        if (const auto b = bindingFor(key))
            m_jog->release(b->motor, JogController::Source::Keyboard);
    }
}

bool JogKeys::targetsScope(QObject *watched) const
{
    if (!m_scope || !m_scope->isVisible() || !m_scope->window()->isActiveWindow())
        return false;
    auto *w = qobject_cast<QWidget *>(watched);
    if (!w || w->window() != m_scope->window())
        return false;
    // Arrow keys keep their meaning where they edit or choose something.
    const QWidget *focus = QApplication::focusWidget();
    return !(qobject_cast<const QLineEdit *>(focus) ||
             qobject_cast<const QAbstractSpinBox *>(focus) ||
             qobject_cast<const QComboBox *>(focus) || qobject_cast<const QTextEdit *>(focus) ||
             qobject_cast<const QPlainTextEdit *>(focus) ||
             qobject_cast<const QAbstractItemView *>(focus));
}

bool JogKeys::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::KeyPress && event->type() != QEvent::KeyRelease)
        return false;
    auto *key = static_cast<QKeyEvent *>(event);
    const auto binding = bindingFor(key->key());
    if (!binding || binding->motor > m_jog->motorCount())
        return false;
    if (event->type() == QEvent::KeyRelease) {
        if (!m_held.contains(key->key()))
            return false;
        if (key->isAutoRepeat())
            return true; // X11 repeats come as release+press pairs: the key is still held
        if (m_held.take(key->key()))
            m_jog->release(binding->motor, JogController::Source::Keyboard);
        return true;
    }
    if (m_held.contains(key->key()))
        return true; // a repeat of a held key
    if (!targetsScope(watched))
        return false;
    if (key->isAutoRepeat())
        return true; // still held after a stop: press it again to move
    if (key->modifiers() & ~Qt::KeypadModifier)
        return false; // Shift/Ctrl/Alt+arrow keep their meaning
    m_held.insert(key->key(), m_jog->press(binding->motor, binding->direction,
                                           JogController::Source::Keyboard));
    return true;
}

} // namespace stepcom

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
QList<JogKeys::Binding> JogKeys::bindingsFor(int key)
{
    using D = JogController::Direction;
    switch (key) {
    case Qt::Key_Left:
        return {{1, D::Reverse}};
    case Qt::Key_Right:
        return {{1, D::Forward}};
    case Qt::Key_Down:
        return {{2, D::Reverse}};
    case Qt::Key_Up:
        return {{2, D::Forward}};
    // The diagonals, as on a numeric keypad (7 9 1 3 without Num Lock): both motors at once.
    case Qt::Key_Home:
        return {{1, D::Reverse}, {2, D::Forward}};
    case Qt::Key_PageUp:
        return {{1, D::Forward}, {2, D::Forward}};
    case Qt::Key_End:
        return {{1, D::Reverse}, {2, D::Reverse}};
    case Qt::Key_PageDown:
        return {{1, D::Forward}, {2, D::Reverse}};
    default:
        return {};
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
        for (const Binding &b : bindingsFor(key))
            m_jog->release(b.motor, JogController::Source::Keyboard);
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
    const QList<Binding> bindings = bindingsFor(key->key());
    if (bindings.isEmpty())
        return false;
    for (const Binding &b : bindings) {
        if (b.motor > m_jog->motorCount())
            return false;
    }
    if (event->type() == QEvent::KeyRelease) {
        if (!m_held.contains(key->key()))
            return false;
        if (key->isAutoRepeat())
            return true; // X11 repeats come as release+press pairs: the key is still held
        if (m_held.take(key->key())) {
            for (const Binding &b : bindings)
                m_jog->release(b.motor, JogController::Source::Keyboard);
        }
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
    // A diagonal jogs each motor it can; one at its limit (refused) leaves the other going.
    bool started = false;
    for (const Binding &b : bindings)
        started = m_jog->press(b.motor, b.direction, JogController::Source::Keyboard) || started;
    m_held.insert(key->key(), started);
    return true;
}

} // namespace stepcom

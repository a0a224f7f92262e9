#pragma once

#include "session/jogcontroller.h"

#include <QHash>
#include <QObject>
#include <QPointer>

#include <optional>

class QWidget;

namespace stepcom {

// Keyboard jogging: while the JogController's keyboard jogging is on, the arrow keys hold a jog
// (Left/Right motor 1 reverse/forward, Down/Up motor 2) when `scope` is shown in the active
// window and no text field or list has the focus. Releasing the key stops; auto-repeat never
// starts or stops anything. Keys are caught by an application event filter that exists only
// while keyboard jogging is on.
class JogKeys : public QObject
{
    Q_OBJECT
public:
    struct Binding
    {
        int motor;
        JogController::Direction direction;
    };

    JogKeys(JogController *jog, QWidget *scope, QObject *parent = nullptr);
    ~JogKeys() override;

    // What a key jogs: an arrow one motor, Home/PgUp/End/PgDn (the keypad's diagonals) both.
    static QList<Binding> bindingsFor(int key);
    // Forget the keys held (after a stop the same key must be pressed again).
    void letGo();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void follow(bool enabled);
    bool targetsScope(QObject *watched) const;

    JogController *m_jog;
    QPointer<QWidget> m_scope;
    QHash<int, bool> m_held; // key -> whether its press started a jog
};

} // namespace stepcom

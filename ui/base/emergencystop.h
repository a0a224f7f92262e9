#pragma once

#include <QKeySequence>
#include <QList>
#include <QObject>
#include <QPointer>

#include <functional>

class QToolButton;

namespace stepcom {

class DeviceSession;

// The stop that always works: a red button and a key (F12) caught by an application-wide event
// filter, so it fires from every page and from inside any dialog, modal or not. It never asks
// for confirmation. While a replay or a profile file stands where the controller's values
// would and no controller is connected there is nothing to stop: the button is greyed and its
// tooltip says why.
class EmergencyStop : public QObject
{
    Q_OBJECT
public:
    explicit EmergencyStop(DeviceSession *session, QObject *parent = nullptr);
    ~EmergencyStop() override;

    static QKeySequence shortcut() { return QKeySequence(Qt::Key_F12); }
    // A new red button wired to trigger(); the caller places it. Its text, tooltip and state
    // follow the session and the language.
    QToolButton *createButton(QWidget *parent);
    void trigger();
    // False while a replay or a profile file is shown without a controller connected.
    bool isAvailable() const;
    // What the button's tooltip says: what it does, or why there is nothing to stop.
    QString toolTip() const;
    // While a mode drives the E-STOP itself (listening beside another master: it asks, then
    // sends in the line's silence), it takes the trigger; empty: the session's E-STOP again.
    void setHandler(std::function<void()> handler)
    {
        m_handler = std::move(handler);
        refresh();
    }

Q_SIGNALS:
    void triggered();
    void availabilityChanged(bool available);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void refresh();

    DeviceSession *m_session;
    QList<QPointer<QToolButton>> m_buttons;
    bool m_available = true;
    std::function<void()> m_handler;
};

} // namespace stepcom

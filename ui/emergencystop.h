#pragma once

#include <QKeySequence>
#include <QObject>

#include <functional>

class QToolButton;

namespace stepcom {

class DeviceSession;

// The stop that always works: a red button for the toolbar and a key (F12) caught by an
// application-wide event filter, so it fires from every page and from inside any dialog,
// modal or not. It never asks for confirmation.
class EmergencyStop : public QObject
{
    Q_OBJECT
public:
    explicit EmergencyStop(DeviceSession *session, QObject *parent = nullptr);
    ~EmergencyStop() override;

    static QKeySequence shortcut() { return QKeySequence(Qt::Key_F12); }
    // A new red button wired to trigger(); the caller places it.
    QToolButton *createButton(QWidget *parent);
    void trigger();
    // While a mode drives the E-STOP itself (listening beside another master: it asks, then
    // sends in the line's silence), it takes the trigger; empty: the session's E-STOP again.
    void setHandler(std::function<void()> handler) { m_handler = std::move(handler); }

Q_SIGNALS:
    void triggered();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    DeviceSession *m_session;
    std::function<void()> m_handler;
};

} // namespace stepcom

#pragma once

#include <QList>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>
#include <vector>

namespace stepcom {

class DeviceSession;

// Who may move the machine from a phone, and the dead-man hold. Jogging is off until the window
// allows it (for this session only); then one phone at a time holds control. A jog from the
// holder goes through the session's JogController as its own source (Pendant), beside the
// pointer and the keys, so the window's rules (page change, focus loss, E-STOP) stop it too.
// While a finger is down the page sends a hold every 100 ms; when none has come for
// kHoldTimeoutMs the motor is stopped here, on the machine's side, whatever the phone does. So
// is it when the finger lifts, the phone goes away, another phone takes control, the window
// takes control back or jogging is no longer allowed. Clients are numbers given by the server.
class PendantControl : public QObject
{
    Q_OBJECT
public:
    static constexpr int kHoldTimeoutMs = 300;

    explicit PendantControl(DeviceSession *session, QObject *parent = nullptr);
    ~PendantControl() override;

    void setAllowed(bool allowed);
    bool isAllowed() const { return m_allowed; }
    int holder() const { return m_holder; } // 0: nobody
    // The motor a pendant jog runs on is held by `client`, or 0.
    int jogOwner(int motor) const;

    // Each returns why it was refused, or an empty text when it was done.
    QString take(int client);
    QString jog(int client, int motor, bool forward);
    QString step(int client, int motor, bool forward, double size);
    // A hold for the jog of `motor`: the watchdog starts again.
    void hold(int client, int motor);
    // The finger lifted, the page was hidden or lost focus (`why` says which).
    void stop(int client, int motor, const QString &why);
    void giveUp(int client);
    // The window takes control back: every pendant jog stops.
    void takeBack();
    // The phone went away (socket closed): its jogs stop, its control ends.
    void clientGone(int client);

Q_SIGNALS:
    void allowedChanged(bool allowed);
    void holderChanged(int client);
    // A pendant jog began or ended (and why), for the phone and the session log.
    void jogStarted(int client, int motor, bool forward);
    void jogEnded(int client, int motor, const QString &why);

private:
    struct Hold
    {
        int owner = 0;
        std::unique_ptr<QTimer> watchdog;
    };
    void stopJogsOf(int client, const QString &why);
    void stopMotor(int motor, const QString &why);
    void onJogState(int motor);
    void setHolder(int client);
    QString mayMove(int client) const;
    int motors() const { return int(m_holds.size()); }

    QPointer<DeviceSession> m_session;
    bool m_allowed = false;
    int m_holder = 0;
    std::vector<Hold> m_holds; // per motor, index motor - 1
};

} // namespace stepcom

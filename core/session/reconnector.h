#pragma once

#include "bus/linksettings.h"
#include "session/serialports.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QTimer>

namespace stepcom {

// After the link dropped on its own (a cable pulled, an adapter unplugged, a gateway gone), try
// to open it again with a growing pause between attempts until it is back or cancelled. A USB
// adapter that returns under another ttyUSB name is found again by its /dev/serial/by-id link
// or its serial number. It only decides when and where: the session opens the link
// (`reopen`), sends any pending stop first and re-reads.
class Reconnector : public QObject
{
    Q_OBJECT
public:
    enum class State {
        Idle,       // nothing to do (connected, never connected, given up or cancelled)
        Waiting,    // counting down to the next attempt
        Attempting, // an attempt is on its way
    };
    Q_ENUM(State)

    explicit Reconnector(QObject *parent = nullptr);

    // Off by default: a one-shot command ends on a loss; the window and `monitor` turn it on.
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    // The pauses before the attempts; the last one repeats (default 1, 2, 4, 8, 15 s).
    void setDelaysMs(const QList<int> &delays);
    QList<int> delaysMs() const { return m_delays; }
    // Where adapters are listed (tests hand in a fake listing and by-id directory).
    void setPortLister(SerialPorts::Lister lister);
    void setByIdDirectory(const QString &directory);

    State state() const { return m_state; }
    bool isActive() const { return m_state != State::Idle; }
    int attempt() const { return m_attempt; }
    // Whole seconds to the next attempt (rounded up; 0 while attempting or idle).
    int secondsLeft() const;
    // The last reason the link was lost or an attempt failed.
    QString lastError() const { return m_lastError; }

    // The link opened (by the user or by an attempt): remember the adapter it runs on.
    void linkOpened(const LinkSettings &settings);
    // The link dropped on its own: start counting down (when enabled).
    void linkLost(const LinkSettings &settings, const QString &reason);
    // The outcome of the attempt the session made for `reopen`.
    void attemptFinished(bool ok, const QString &reason);
    // The user gave up waiting.
    void cancel();
    // The user connected, disconnected or chose another line: stop without a word.
    void stop();
    // Try now instead of waiting out the pause.
    void retryNow();

    // The settings to open now: the ones lost, with the port found again by its adapter.
    LinkSettings locate() const;

Q_SIGNALS:
    void stateChanged(stepcom::Reconnector::State state);
    // Once a second while waiting, and when the wait starts.
    void countdown(int secondsLeft);
    // Open the link with these settings now and report with attemptFinished().
    void reopen(const stepcom::LinkSettings &settings);
    // The link is back (after `attempts` attempts) on these settings.
    void restored(const stepcom::LinkSettings &settings, int attempts);
    void cancelled();

private:
    void setState(State state);
    void arm();
    void fire();
    QList<SerialPortEntry> listPorts() const;

    bool m_enabled = false;
    QList<int> m_delays{1000, 2000, 4000, 8000, 15000};
    SerialPorts::Lister m_lister;
    QString m_byIdDirectory;
    State m_state = State::Idle;
    int m_attempt = 0;
    LinkSettings m_settings;   // what was lost
    SerialPortEntry m_adapter; // the adapter it ran on, when the listing knew it
    QString m_lastError;
    QTimer m_wait;
    QTimer m_tick;
    QElapsedTimer m_waitClock;
    int m_waitMs = 0;
};

} // namespace stepcom

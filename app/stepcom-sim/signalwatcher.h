#pragma once

#include <QObject>

QT_BEGIN_NAMESPACE
class QSocketNotifier;
class QTimer;
QT_END_NAMESPACE

namespace stepcom {

// Turns SIGINT/SIGTERM into a Qt signal in the main thread, so Ctrl-C ends the event loop and
// everything is torn down normally (pty links removed, state intact).
class SignalWatcher : public QObject
{
    Q_OBJECT
public:
    explicit SignalWatcher(QObject *parent = nullptr);
    ~SignalWatcher() override;

Q_SIGNALS:
    void terminationRequested();

private:
    QSocketNotifier *m_notifier = nullptr; // Unix: the read end of a socket pair
    QTimer *m_poll = nullptr;              // elsewhere: polls a flag set by a plain handler
};

} // namespace stepcom

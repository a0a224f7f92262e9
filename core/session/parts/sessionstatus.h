#pragma once

#include "device/poller.h" // what stats() hands out

#include <QObject>
#include <QStringList>

namespace stepcom {

class ParameterStore;
class RegisterMap;
class StatusRecorder;

// The session's live status poll of the device in view: started on connect while the session
// is live, its rate, how fast it is, and the samples recorded for the plots. Owned by the
// DeviceSession that hands it out (status()).
class SessionStatus : public QObject
{
    Q_OBJECT
public:
    SessionStatus(Poller *poller, ParameterStore *store, QObject *parent);

    void start();
    void stop();
    bool isActive() const;
    QStringList keys() const;
    void setIntervalMs(int ms);
    int intervalMs() const;
    double rate() const;
    bool isFast() const;
    QString error() const;
    const PollStats &stats() const;
    void resetStats();
    // The live status recorded for the plots; made on first use, recording from then on.
    StatusRecorder *recorder();

Q_SIGNALS:
    void statusCycleFinished(bool ok, qint64 ms);
    void statusFastChanged(bool fast);

private:
    Poller *m_poller;
    ParameterStore *m_store;
    StatusRecorder *m_recorder = nullptr;
};

} // namespace stepcom

#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QTimer>

namespace stepcom {

class DeviceClient;
class ParameterStore;

// Reads a set of parameters over and over into the store. A cycle starts only when the last
// one has finished (never a queue of polls behind a slow or silent device), at most every
// interval; polls go out at the lowest priority, behind anything the user asked for.
class Poller : public QObject
{
    Q_OBJECT
public:
    Poller(DeviceClient *client, ParameterStore *store, QObject *parent = nullptr);

    void setKeys(const QStringList &keys);
    QStringList keys() const { return m_keys; }
    void setIntervalMs(int ms) { m_intervalMs = std::max(0, ms); }
    int intervalMs() const { return m_intervalMs; }
    void start();
    void stop();
    bool isActive() const { return m_active; }
    // Cycles per second over the last few cycles.
    double rate() const { return m_rate; }

Q_SIGNALS:
    void cycleFinished(bool ok, qint64 ms);

private:
    void runCycle();

    DeviceClient *m_client;
    ParameterStore *m_store;
    QStringList m_keys;
    int m_intervalMs = 100;
    bool m_active = false;
    bool m_inCycle = false;
    quint64 m_generation = 0;
    QTimer m_timer;
    QElapsedTimer m_cycleClock;
    QElapsedTimer m_sinceLastStart;
    double m_rate = 0.0;
};

} // namespace stepcom

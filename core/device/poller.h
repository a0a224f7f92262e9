#pragma once

#include "device/readplanner.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QSet>
#include <QStringList>
#include <QTimer>

namespace stepcom {

class DeviceClient;
class ParameterStore;
class RegisterMap;
struct Parameter;
struct Request;
struct Result;

// What the poller achieved since start() or resetStats(): cycle times are from the start of a
// cycle to its last answer, queueing included.
struct PollStats
{
    int cycles = 0;
    int failed = 0;
    int fastCycles = 0; // cycles that read only the fast keys
    qint64 lastMs = -1;
    qint64 minMs = -1;
    qint64 maxMs = -1;
    qint64 totalMs = 0;
    double meanMs() const { return cycles > 0 ? double(totalMs) / cycles : 0.0; }
};

// Reads a set of parameters over and over into the store. A cycle starts only when the last
// one has finished (never a queue of polls behind a slow or silent device), at most every
// interval; polls go out at the lowest priority, behind anything the user asked for, and one
// request at a time, so at most one poll is ever waiting in the link's queue or on the wire.
//
// While a motor runs (any "motorN.running" in the store is 1, or a motion command was just
// acknowledged) it reads the fast keys (positions and running flags), and every fullEvery-th
// cycle the full list anyway, so inputs and outputs never go stale for long.
class Poller : public QObject
{
    Q_OBJECT
public:
    Poller(DeviceClient *client, ParameterStore *store, QObject *parent = nullptr);

    // The full list, read whenever no motor runs.
    void setKeys(const QStringList &keys);
    QStringList keys() const { return m_keys; }
    // Read while a motor runs; empty: always the full list.
    void setFastKeys(const QStringList &keys);
    QStringList fastKeys() const { return m_fastKeys; }
    // While fast, every n-th cycle reads the full list (n <= 1: every cycle is full).
    void setFullEvery(int n) { m_fullEvery = std::max(1, n); }
    int fullEvery() const { return m_fullEvery; }
    // The status group as the full list, positions and running flags as the fast one.
    void useStatusKeys();
    static QStringList statusKeys(const RegisterMap &map);
    static QStringList motionKeys(const RegisterMap &map);

    // Least time from one cycle's start to the next; 0: as fast as the link allows.
    void setIntervalMs(int ms) { m_intervalMs = std::max(0, ms); }
    int intervalMs() const { return m_intervalMs; }
    // STEPCOM_POLL_INTERVAL_MS when set to a number >= 0, else `fallback`.
    static int intervalFromEnvironment(int fallback);

    void start();
    void stop();
    bool isActive() const { return m_active; }
    // Cycles per second actually achieved over the last few cycles (start to start).
    double rate() const { return m_rate; }
    // A motor runs: the fast keys are being polled.
    bool isFast() const { return m_fast; }
    bool lastCycleWasFull() const { return m_cycleFull; }
    QString lastError() const { return m_lastError; }
    const PollStats &stats() const { return m_stats; }
    void resetStats() { m_stats = PollStats(); }

Q_SIGNALS:
    void cycleFinished(bool ok, qint64 ms);
    void fastChanged(bool fast);

private:
    void runCycle();
    void readBlock(int index);
    void onBlockRead(quint64 generation, int index, const Result &result);
    void finishCycle();
    bool anyRunning() const;
    void onLinkFinished(const Request &request, const Result &result);
    QList<const Parameter *> resolve(const QStringList &keys) const;

    DeviceClient *m_client;
    ParameterStore *m_store;
    QStringList m_keys;
    QStringList m_fastKeys;
    QStringList m_runningKeys; // motorN.running among both lists
    QSet<quint16> m_motionCoils;
    int m_fullEvery = 4;
    int m_intervalMs = 100;
    bool m_active = false;
    bool m_inCycle = false;
    bool m_outstanding = false; // a poll request is queued or on the wire
    bool m_fast = false;
    bool m_motionHint = false;
    bool m_cycleFull = true;
    bool m_cycleOk = true;
    int m_fastStreak = 0;
    quint64 m_generation = 0;
    QList<const Parameter *> m_cycleParams;
    QList<ReadBlock> m_cycleBlocks;
    QHash<QString, qint64> m_cycleValues;
    QString m_lastError;
    QTimer m_timer;
    QElapsedTimer m_cycleClock;
    QElapsedTimer m_sinceLastStart;
    double m_rate = 0.0;
    PollStats m_stats;
};

} // namespace stepcom

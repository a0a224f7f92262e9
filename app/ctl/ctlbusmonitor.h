#pragma once

#include <QElapsedTimer>
#include <QHash>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QTextStream>

#include <functional>

namespace stepcom {

class BusPoller;
class DeviceSession;
class SignalWatcher;
struct Parameter;
struct ReadOutcome;

// `stepcomctl monitor --id 1,2,3`: the status of several controllers of one line, fairly: one
// status read per device in turn, in the order given, a round at most every --interval. Each
// sample is one line keyed by its device id (JSON with --json, else text); --count N is N
// samples of each device. A restart of a device, certain or possible, is said as `monitor` of
// one says it (an event line with its id, or words on standard error). The exit code is the worst
// of the devices': 1 for a device one of whose reads failed (said on standard error with its id), 1
// when the link was lost. The turns are the window's background poll's (BusPoller, in rounds);
// each read goes through the session, the device shown for it.
class CtlBusMonitor : public QObject
{
    Q_OBJECT
public:
    CtlBusMonitor(DeviceSession *session, const QList<int> &ids, int count, int intervalMs,
                  bool json, QObject *parent = nullptr);
    void start();
    // --json's last line: samples printed and reads failed per id, events; the errors said
    // meanwhile.
    QJsonObject summary() const;
    QStringList errors() const { return m_errors; }
    // One sample's line for `id` from the values read.
    QString sampleLine(int id, qint64 tMs, const QHash<QString, qint64> &values) const;

Q_SIGNALS:
    void finished(int exitCode);

private:
    // The poller's turn: `id`'s status read through the session.
    void read(int id, const QList<const Parameter *> &params,
              const std::function<void(const ReadOutcome &)> &done);
    void onRead(int id, const ReadOutcome &outcome);
    bool countReached() const;
    bool anyFailed() const;
    void end(int exitCode);
    // `text` on standard error, kept among errors().
    void sayError(const QString &text);
    // One event: `text` on stderr, or with --json CtlMonitor::eventLine().
    void event(const QString &name, const QString &text, const QString &fields);

    DeviceSession *m_session;
    SignalWatcher *m_signals = nullptr;
    QList<int> m_ids;
    QList<const Parameter *> m_params;
    BusPoller *m_poller; // the turns, and each device's reads and failed ones
    int m_count;
    bool m_json;
    int m_events = 0;
    QStringList m_errors;
    bool m_ended = false; // an answer after end() is dropped
    QElapsedTimer m_clock;
    QTextStream m_out;
    QTextStream m_err;
};

} // namespace stepcom

#pragma once

#include "session/restartwatch.h"

#include <QElapsedTimer>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QTextStream>

#include <functional>
#include <optional>

namespace stepcom {

class DeviceSession;
class RegisterMap;
class SignalWatcher;
struct Parameter;

// `stepcomctl monitor`: polls the live status through the session, as the window does, and prints
// one compact JSON object per cycle -- {"time", "t_ms", then every status value in engineering
// units by map key} -- flushed line by line, until --count samples or SIGINT/SIGTERM. A lost
// link is tried again with a growing pause; "lost" and "back" are said as JSON lines
// ({"event":"lost"|"back", ...}) with --json, else as text on stderr, and the samples go on.
// So is a restart of the controller: "restarted" where it is proven, "possible_restart" where
// only moving axes went to 0 after a silence, each with what was seen (evidenceFields()).
class CtlMonitor : public QObject
{
    Q_OBJECT
public:
    // count < 1: until stopped; intervalMs 0: as fast as the link allows.
    CtlMonitor(DeviceSession *session, int count, int intervalMs, bool json,
               QObject *parent = nullptr);
    void start();
    // --json's last line: the samples printed and the events said; the errors said meanwhile.
    QJsonObject summary() const;
    QStringList errors() const { return m_errors; }
    // One line for the values known now (null for what was never read).
    QString sampleLine(qint64 tMs) const;
    // The status parameters in the order the lines give them: positions, running flags, rest.
    static QList<const Parameter *> statusParameters(const DeviceSession &session);
    // `"time":"…","t_ms":N` (no braces), the start of every line.
    static QString timeFields(qint64 tMs);
    // `,"key":value` for each parameter (null for what `raw` does not know).
    static QString valueFields(const QList<const Parameter *> &params,
                               const std::function<std::optional<qint64>(const QString &)> &raw);

    // Where an event goes: its name, its words, its JSON fields (`,"key":value` each).
    using EventSink =
        std::function<void(const QString &name, const QString &text, const QString &fields)>;
    // Every (possible) restart the session says of any device, as an event for `event` while
    // `context` lives: "restarted" and "possible_restart", each with evidenceFields(). Both
    // monitors, of one device and of several, say them so.
    static void sayRestarts(DeviceSession *session, QObject *context, const EventSink &event);
    // The JSON line of one event: {"event":name,"time","t_ms"`fields`}.
    static QString eventLine(const QString &name, qint64 tMs, const QString &fields);
    // `,"id","silent_ms","zeroed","stood_still","moving","before"` of a (possible) restart.
    static QString evidenceFields(const RegisterMap &map, int id,
                                  const RestartWatch::Evidence &seen);

Q_SIGNALS:
    // 0 after --count samples or a signal, 1 when the link was lost and trying again was
    // cancelled.
    void finished(int exitCode);

private:
    void onCycle(bool ok);
    void end(int exitCode);
    // `text` on standard error, kept among errors().
    void sayError(const QString &text);
    // One event: `text` on stderr, or with --json eventLine().
    void event(const QString &name, const QString &text, const QString &fields);

    DeviceSession *m_session;
    SignalWatcher *m_signals = nullptr;
    QList<const Parameter *> m_params; // positions, running flags, then the rest of the status
    int m_count;
    bool m_json;
    int m_printed = 0;
    int m_events = 0;
    QStringList m_errors;
    bool m_ended = false;
    QElapsedTimer m_clock;
    QTextStream m_out;
    QTextStream m_err;
};

} // namespace stepcom

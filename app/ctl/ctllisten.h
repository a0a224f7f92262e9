#pragma once

#include "session/parts/sessionconnection.h" // LinkSettings

#include <QElapsedTimer>
#include <QJsonObject>
#include <QObject>
#include <QTextStream>

#include <memory>

namespace stepcom {

class LineListener;
class ListenLog;
class RegisterMap;
class SignalWatcher;
struct HeardEvent;

// `stepcomctl listen`: hears a line another master drives (LineListener: the port read-only)
// and prints each paired request as it is decoded, flushed line by line -- a sentence, or with
// --json the lines of HeardEvent::toJson -- until Ctrl-C or --seconds; then a summary of
// frames, pairs, CRC errors and answer times on stderr. With --log FILE everything heard is
// kept as a session log (ListenLog) for `stepcomctl replay`.
class CtlListen : public QObject
{
    Q_OBJECT
public:
    CtlListen(const RegisterMap &map, const LinkSettings &line, bool json, int seconds,
              const QString &logFile, QObject *parent = nullptr);
    ~CtlListen() override;
    void start();
    // --json's last line: what summary() says in words (nothing heard when the port did not
    // open); the errors said meanwhile.
    QJsonObject summaryJson() const;
    QStringList errors() const { return m_errors; }

Q_SIGNALS:
    // 0 after --seconds or a signal; 1 when the port could not be opened or was lost; 2 when
    // the log cannot be written.
    void finished(int exitCode);

private:
    void onHeard(const HeardEvent &event);
    void end(int exitCode);
    QString summary() const;
    // `text` on standard error, kept among errors().
    void sayError(const QString &text);

    const RegisterMap &m_map;
    LinkSettings m_line;
    bool m_json;
    int m_seconds;
    QString m_logFile;
    LineListener *m_listener = nullptr;
    std::unique_ptr<ListenLog> m_log;
    SignalWatcher *m_signals = nullptr;
    bool m_listening = false;
    bool m_ended = false;
    QTextStream m_out;
    QTextStream m_err;
    int m_unanswered = 0;
    int m_exceptions = 0;
    QStringList m_errors;
};

} // namespace stepcom

#pragma once

#include "bus/trafficlog.h"
#include "session/restartwatch.h"

#include <QFile>
#include <QHash>
#include <QObject>
#include <QPointer>

namespace stepcom {

class DeviceSession;

// Every frame of every connection, with its date and time, in a file per connection under the
// application's data location: what a technician sends to support after a bad day. Files are
// rotated at a size and the oldest deleted beyond a total, so the log never fills a laptop.
// Fed by the session's TrafficLog (entryAdded); a new file begins each time the link starts
// connecting. Each file (or, with setFile, each connection appended to the one file) begins with
// '#' header lines that make it replayable on its own (core/support/ReplayLog): the program and
// Qt versions, the register map, the line and the ids. Beside the frames it notes, as lines of
// their own kind, what the session knows happened: the link up or lost, a controller restart,
// user actions (E-STOP pressed, the device in view, noteUserAction()).
class SessionLog : public QObject
{
    Q_OBJECT
public:
    explicit SessionLog(DeviceSession *session, QObject *parent = nullptr);
    ~SessionLog() override;

    // <AppDataLocation>/logs, e.g. ~/.local/share/StepCom/stepcom/logs.
    static QString defaultDirectory();
    void setDirectory(const QString &directory);
    QString directory() const { return m_directory; }
    // One file instead of the directory (stepcomctl --log FILE): appended to, never rotated or
    // pruned; every connection adds its header. Empty: back to the directory.
    void setFile(const QString &path);
    // A file is continued in a new part beyond `fileBytes`; the oldest files go beyond
    // `totalBytes` (the file being written is never deleted).
    void setLimits(qint64 fileBytes, qint64 totalBytes);
    qint64 fileLimit() const { return m_fileBytes; }
    qint64 totalLimit() const { return m_totalBytes; }

    // Ends the current file; the next entry starts a new one named after `description`
    // ("/dev/ttyUSB0 9600 8N1 id 1"). The session calls it when the link starts connecting.
    void beginConnection(const QString &description);
    QString currentFile() const;
    // The log files in the directory, newest first.
    QStringList files() const;
    // A user action the core cannot see (the window's page changes, a checklist result), as a
    // "user" line (while a log is being written: not before the first connection).
    void noteUserAction(const QString &text);
    // The names the user gave the ids of the line (the window's device list): the header of
    // the next file says them ("# names: {\"1\":\"X gantry\"}"), so a replay shows them too.
    void setDeviceNames(const QHash<int, QString> &names) { m_names = names; }
    // Why the last write failed (empty while writing works).
    QString error() const { return m_error; }

    // "2026-11-24 22:10:01.123  TX  poll   01 03 00 00 00 02 C4 0B  read 40001-40002"
    static QString formatLine(const TrafficEntry &entry);
    static QString kindName(TrafficEntry::Kind kind);
    // The kinds of the lines the session log adds beside the traffic: ReplayLog reads them.
    static constexpr const char *kLinkUp = "linkup";
    static constexpr const char *kLinkDown = "linkdown";
    static constexpr const char *kRestart = "restart";
    // The controller may have restarted: only moving axes went to 0 after a silence.
    static constexpr const char *kPossibleRestart = "possible-restart";
    static constexpr const char *kUser = "user";
    // "2026-11-24 22:10:01.123  --  user     E-STOP pressed"
    static QString formatMark(const QDateTime &time, const char *kind, const QString &text);
    // The text of a possible restart's mark, in English as every mark: "id 1 may have
    // restarted: silent 1.6 s; zeroed motor2; stood still motor1; moving motor2; before
    // motor1=0.00, motor2=12.34".
    static QString possibleRestartText(const RegisterMap &map, int id,
                                       const RestartWatch::Evidence &seen);
    // The link a file is about, in its header and link-up marks: "built-in simulator, not a
    // machine: /dev/pts/3 · 9600 8N1 · id 1" when it is the built-in simulator.
    static QString linkText(const DeviceSession *session);
    // The header lines of a file: "# StepCom 0.1.0 session log, part 1: <description>", then
    // "# key: value" lines (program, qt, map, line, ids, names) for what is known (session may
    // be null).
    static QString header(const DeviceSession *session, int part, const QString &description,
                          const QHash<int, QString> &names = {});

Q_SIGNALS:
    void fileStarted(const QString &path);
    // Writing stopped working (disk full, no permission): said once until it works again.
    void failed(const QString &reason);

private:
    void write(const TrafficEntry &entry);
    void writeLine(const QByteArray &line);
    void writeMark(const char *kind, const QString &text);
    bool openFile();
    void prune();
    void fail(const QString &reason);

    QPointer<DeviceSession> m_session;
    QString m_directory;
    QString m_fixedFile; // setFile(): one file, appended
    qint64 m_fileBytes = 4 * 1024 * 1024;
    qint64 m_totalBytes = 64 * 1024 * 1024;
    QString m_description;
    QString m_baseName; // file name without part number and suffix
    int m_part = 0;
    QFile m_file;
    QString m_error;
    QHash<int, QString> m_names;
};

} // namespace stepcom

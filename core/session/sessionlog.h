#pragma once

#include "bus/trafficlog.h"

#include <QFile>
#include <QObject>

namespace stepcom {

class DeviceSession;

// Every frame of every connection, with its date and time, in a file per connection under the
// application's data location: what a technician sends to support after a bad day. Files are
// rotated at a size and the oldest deleted beyond a total, so the log never fills a laptop.
// Fed by the session's TrafficLog (entryAdded); a new file begins each time the link starts
// connecting.
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
    // Why the last write failed (empty while writing works).
    QString error() const { return m_error; }

    // "2026-11-24 22:10:01.123  TX  poll   01 03 00 00 00 02 C4 0B  read 40001-40002"
    static QString formatLine(const TrafficEntry &entry);
    static QString kindName(TrafficEntry::Kind kind);

Q_SIGNALS:
    void fileStarted(const QString &path);
    // Writing stopped working (disk full, no permission): said once until it works again.
    void failed(const QString &reason);

private:
    void write(const TrafficEntry &entry);
    bool openFile();
    void prune();
    void fail(const QString &reason);

    QString m_directory;
    qint64 m_fileBytes = 4 * 1024 * 1024;
    qint64 m_totalBytes = 64 * 1024 * 1024;
    QString m_description;
    QString m_baseName; // file name without part number and suffix
    int m_part = 0;
    QFile m_file;
    QString m_error;
};

} // namespace stepcom

#pragma once

#include "bus/linksettings.h"
#include "listen/heardevent.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>

namespace stepcom {

class RegisterMap;

// What a listener heard, as a session log (SessionLog's format and header), so `stepcomctl
// replay` and the window's replay show a listened session like any other: each request of the
// other master as a TX line, its answer as an RX line, at the times they were heard. The
// header says StepCom only listened. One file, appended, flushed line by line.
class ListenLog
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ListenLog)
public:
    // `start` is the wall time at the listener's 0 ms.
    ListenLog(const RegisterMap &map, const LinkSettings &line, const QDateTime &start);
    // False and why when the file cannot be written.
    bool open(const QString &path, QString *error);
    // A name in `directory` as the session log's ("stepcom-<time>-listen-<port>.log").
    static QString fileIn(const QString &directory, const QString &portName);
    void write(const HeardEvent &event);
    // A line of its own kind: "E-STOP sent into a line driven by another master".
    void note(const char *kind, const QString &text, qint64 ms);
    QString fileName() const { return m_file.fileName(); }
    QString error() const { return m_error; }

private:
    void writeLine(const QString &line);

    const RegisterMap &m_map;
    LinkSettings m_line;
    QDateTime m_start;
    QFile m_file;
    QString m_error;
};

} // namespace stepcom

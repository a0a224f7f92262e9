#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

namespace stepcom {

// One line of a session log (SessionLog's format), taken apart without a regular expression:
// a replay reads millions of them.
//   "2026-11-24 22:10:01.123  TX  poll     01 03 00 00 00 02 C4 0B  read 40001-40002"
//   "2026-11-24 22:10:01.200  --  linkdown  the port vanished"
//   "# map: stepper2/1"
struct LogLine
{
    enum class Type { Blank, Header, Frame, Mark, Garbage };
    Type type = Type::Garbage;
    qint64 stamp = 0;  // ms since the start of the Julian calendar (local time as written)
    bool sent = false; // Frame: TX
    QByteArray kind;   // "poll", "write", "event", "error", "linkup", "user", ...
    QByteArray bytes;  // Frame: the raw frame
    QString text;      // the summary (Frame, Mark), or a header's value
    QByteArray key;    // Header: "map", "line", "ids" ... ("title" for the first line)

    // A log's stamps count days as this many ms (replays step over midnight with it).
    static constexpr qint64 kDayMs = 24 * 3600 * 1000;

    static LogLine parse(QByteArrayView line);
    // "2026-11-24 22:10:01.123" at the start of `text` as a stamp; false when it is not one.
    static bool parseStamp(QByteArrayView text, qint64 *stamp);
    // A stamp back as "2026-11-24 22:10:01.123".
    static QString stampText(qint64 stamp);
};

} // namespace stepcom

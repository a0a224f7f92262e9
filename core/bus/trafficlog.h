#pragma once

#include "bus/request.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QObject>

namespace stepcom {

class RegisterMap;

struct TrafficEntry
{
    enum class Direction { Sent, Received, Event };
    // What the frame was for, so a reader can hide the status polls and find the writes.
    enum class Kind { Event, Poll, Read, Write, Command, Error };
    QDateTime time;
    Direction direction = Direction::Event;
    Kind kind = Kind::Event;
    QByteArray bytes; // raw frame as on the wire, when known
    QString summary;  // one decoded line: "read 40001-40002", "= 180, 8", "timeout"
};

// A bounded log of what crossed the wire, for the traffic view and `--verbose`.
class TrafficLog : public QObject
{
    Q_OBJECT
public:
    explicit TrafficLog(QObject *parent = nullptr);

    void setCapacity(int entries);
    int capacity() const { return m_capacity; }
    // With a map the summaries name parameters ("motor1.speed = 300").
    void setMap(const RegisterMap *map) { m_map = map; }

    // A frame; `pduOffset` is where the function code starts (1 for RTU, 7 for TCP) and
    // `crcBytes` how many checksum bytes end it. `context` is the request the frame belongs to.
    void addFrame(TrafficEntry::Direction direction, const QByteArray &raw, int pduOffset,
                  int crcBytes, const Request *context);
    void addEvent(const QString &text, TrafficEntry::Kind kind = TrafficEntry::Kind::Event);
    // An entry made elsewhere, its time included (a replayed session log's line).
    void add(const TrafficEntry &entry) { append(entry); }
    const QList<TrafficEntry> &entries() const { return m_entries; }
    void clear();

    // "12:00:01.123  TX  01 03 00 00 00 02 C4 0B  read 40001-40002"
    static QString format(const TrafficEntry &entry);
    // What a frame of this request (or an exception answer) counts as.
    static TrafficEntry::Kind kindOf(const Request *context, const QByteArray &pdu);
    // Decode one PDU (function code first) into a line for people.
    static QString describePdu(TrafficEntry::Direction direction, const QByteArray &pdu,
                               const Request *context, const RegisterMap *map);

Q_SIGNALS:
    void entryAdded(const stepcom::TrafficEntry &entry);
    void cleared();

private:
    void append(TrafficEntry entry);

    QList<TrafficEntry> m_entries;
    int m_capacity = 5000;
    const RegisterMap *m_map = nullptr;
};

} // namespace stepcom

#pragma once

#include <QByteArray>
#include <QCoreApplication>
#include <QJsonObject>
#include <QList>
#include <QMap>
#include <QString>

namespace stepcom {

// One value a heard request or answer carried, named by the register map.
struct HeardValue
{
    QString key;        // "motor1.speed" (as `stepcomctl params --json` names it)
    qint64 raw = 0;     // as on the wire, scale applied
    double value = 0.0; // engineering value
    QString unit;
    QString text; // "777 rpm", or an enum's label
};

// What was heard of one request of another master, paired with its answer (or without one).
struct HeardEvent
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::HeardEvent)
public:
    enum class Kind {
        Read,      // a read and the values answered
        Write,     // a write the controller acknowledged (FC06/FC10)
        Command,   // a coil the controller acknowledged (FC05/FC0F)
        Exception, // the controller refused a request
        NoAnswer,  // a request nobody answered (the next request came, or a long silence)
        Broadcast, // a request to id 0: nobody answers it
        Stray,     // an answer whose request was not heard
    };
    Kind kind = Kind::Read;
    qint64 ms = 0;        // when its last frame ended
    qint64 requestMs = 0; // when the request ended
    int unit = 0;
    int fc = 0;
    quint16 address = 0;          // protocol address (40001 is 0)
    int count = 0;                // registers or coils
    QList<HeardValue> values;     // read: the values answered; write: the values written
    QMap<quint16, quint16> words; // registers no parameter of the map names whole
    QList<bool> coils;            // coils a command set or a coil read answered
    double answerMs = -1.0;       // request's end to the answer's start; < 0 none
    int exception = 0;
    QByteArray request; // the frames, CRC included
    QByteArray answer;

    static QString kindName(Kind kind); // "read", "write", ... (stable, for --json)
    // "PLC wrote motor1.speed = 777 rpm to id 1 (answered in 12.0 ms)": the other master is
    // called the PLC, as a technician at a machine calls it.
    QString text() const;
    // The lines of `stepcomctl listen --json`, `t` in seconds since the listening began: a
    // write one line per parameter ({"key", "value", "unit"}), anything else one line.
    QList<QJsonObject> toJson(qint64 startMs) const;
    // "40001-40002", "coil 3".
    QString where() const;
};

} // namespace stepcom

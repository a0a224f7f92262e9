#pragma once

#include <QCoreApplication>
#include <QHash>
#include <QJsonObject>
#include <QMap>
#include <QString>

namespace stepcom {

class RegisterMap;

// Something worth a marker on a replay's timeline.
struct ReplayEvent
{
    enum class Kind {
        Write,         // a verified write, with its values
        Command,       // a command coil acknowledged
        EmergencyStop, // the E-STOP coil sent (acknowledged or not)
        Exception,     // the controller refused a request
        Timeout,       // a request that got no answer
        LateAnswer,    // an answer to a request already given up (owed)
        LinkUp,
        LinkDown,
        Restart,         // the session saw the controller restart
        PossibleRestart, // it may have: only moving axes went to 0 after a silence
        User,            // a user action the session logged
    };
    qint64 ms = 0;  // since the start of the log
    int device = 0; // the controller's id; 0: the line
    Kind kind = Kind::Write;
    QString text;    // "motor1.speed 300 → 450 rpm"
    qint64 line = 0; // the line number in the log, for the traffic view

    static QString kindName(Kind kind); // "write", "estop", ... (stable, for --json)
};

// What the log says of one controller at a moment.
struct ReplayDevice
{
    QMap<quint16, quint16> words;   // holding registers by protocol address, last read or written
    QMap<quint16, quint16> written; // the last value written to each register and acknowledged
    bool answering = false;         // its last request was answered
    QString lastError;              // the last refusal or missing answer, and when
    qint64 lastErrorMs = -1;
    qint64 lastAnswerMs = -1;
    QString lastCommand;   // the last acknowledged command coil
    int requests = 0;      // requests to it that were answered or given up
    int errors = 0;        // of those, refused or not answered
    qint64 restartMs = -1; // the last restart the session saw, and what it said of it
    QString restartText;

    // Every holding parameter whose registers are all known, as raw values.
    QHash<QString, qint64> values(const RegisterMap &map) const;
    // The last value written to each parameter whose registers were all written.
    QHash<QString, qint64> writtenValues(const RegisterMap &map) const;
};

// Every controller of the line at a moment of the log.
struct ReplayState
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::ReplayState)
public:
    qint64 ms = 0; // since the start of the log
    bool linkUp = false;
    QMap<int, ReplayDevice> devices;

    // {"devices": {"1": {"answering", "last_error", "values": {key: engineering value},
    // "written": {key: value}, "requests", "errors", "restart_s", "restart"}}}; values in
    // engineering units as `stepcomctl read --json`.
    QJsonObject toJson(const RegisterMap &map) const;
    // What differs from `before`: one line per device and parameter,
    // "id 1  motor1.position  0.00 mm → 12.50 mm".
    QStringList diff(const ReplayState &before, const RegisterMap &map) const;
};

} // namespace stepcom

#pragma once

#include "session/parts/sessionconnection.h" // LinkSettings

#include <QCommandLineParser>
#include <QStringList>

namespace stepcom {

// The global options shared by every stepcomctl command, parsed and checked.
struct CtlOptions
{
    enum class Target { None, Port, Tcp, Sim };
    Target target = Target::None;
    LinkSettings link;
    // --id 1,2,3 or 1-3: the command runs for each in turn over one link (link.deviceId is the
    // first); one id: just that one.
    QList<int> ids;
    QString mapFile;
    bool json = false;
    bool verbose = false;
    bool yes = false;
    bool saveToFlash = false;
    bool simReset = false;    // --sim-reset: the built-in simulator's flash back to the factory
    bool wait = false;        // command: wait for a motion's end and judge it
    bool includeLink = false; // dump/apply: device.id and device.baud too
    bool noBackup = false;    // apply: no backup of the controller's settings first
    QString name;             // dump/report: the profile's or the machine's name
    QString notes;            // dump/report
    QString from;             // report --from PROFILE: from a file, no controller
    QString by;               // move --by D: a step of D axis units
    QString to;               // move --to X: to position X
    QString language = QStringLiteral("en"); // --lang or the environment: messages and the report
    int assignTo = 0;                        // assign-id --to N
    // scan: the bauds, parities and ids to try, and the probe timeout (0: fitted to the baud).
    QList<int> scanBauds;
    QList<QSerialPort::Parity> scanParities;
    QList<int> scanIds;
    int probeTimeoutMs = 0;
    QString logFile;          // --log FILE: the session log of this run, appended
    bool events = false;      // replay --events
    QString at;               // replay --at TIME
    QString diffFrom;         // replay --diff T1 (T2 is the next argument)
    QString entry;            // replay BUNDLE.zip --entry NAME: which log of the bundle
    int days = 7;             // bundle --days N
    QString profile;          // bundle --profile FILE
    int seconds = 0;          // listen --seconds N: stop after N s (0: until Ctrl-C)
    int cycles = 1;           // run --cycles N: how many times the whole step list runs
    bool cyclesGiven = false; // the proofs have defaults of their own
    QString distance;         // lost-steps, margin, backlash --distance D
    QString step;             // margin --step N
    bool accel = false;       // margin --accel: the acceleration register
    bool apply = false;       // margin --apply: write the recommendation (reviewed)
    bool checkSteps = false;  // run --check-steps: the lost-step test on the moved axes after
    int count = -1;
    int intervalMs = 0;
    QString command;
    QStringList arguments;

    // Sets up `parser` with every option; the caller processes it.
    static void addOptions(QCommandLineParser &parser);
    // Fills the options from a processed parser; on a usage error returns the message.
    static QString fromParser(const QCommandLineParser &parser, CtlOptions *out);
};

} // namespace stepcom

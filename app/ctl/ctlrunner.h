#pragma once

#include "ctloptions.h"
#include "map/registermap.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/simulatorstarter.h"

#include <QJsonObject>
#include <QObject>
#include <QPointer>
#include <QTextStream>

namespace stepcom {

struct BundleInput;
struct Profile;
class ProfileApply;
struct ProfileApplyResult;
struct ReportInput;
class CtlRunner;

// One stepcomctl command: its name, how it is called, its help (English source, translated in
// the "stepcomctl" context) and the runner's handler.
struct CtlCommand
{
    const char *name;
    const char *usage;
    const char *help;
    void (CtlRunner::*run)();
    // The option this row needs (command NAME --wait); a set one takes it over the plain row.
    bool CtlOptions::*when = nullptr;
};

// Runs one stepcomctl command against a controller and reports an exit code (Exit).
class CtlRunner : public QObject
{
    Q_OBJECT
public:
    // The exit codes, as exitCodesHelp() explains them: 1 is also a command's "no" (diff:
    // different, scan: none found, move and command --wait: not arrived), and diff and scan say
    // a link error with LinkError, their 1 being an answer.
    enum Exit { Ok = 0, DeviceError = 1, UsageError = 2, LinkError = 3 };

    CtlRunner(const CtlOptions &options, const RegisterMap &map, QObject *parent = nullptr);
    // Starts the command; `finished` follows once.
    void start();

    // Every command, in the order the help lists them.
    static const QList<CtlCommand> &commands();
    // The "Commands:" part of --help, built from the table (ctlhelp.cpp): the help column
    // starts after the longest usage, so the two never run together in any language.
    static QString commandsHelp();
    // The one table of exit codes, for every command (--help, `NAME --help`, man page, guide).
    static QString exitCodesHelp();
    // `stepcomctl NAME --help`: that command's usages, help and the exit codes; empty for a
    // name that is not a command.
    static QString commandHelp(const QString &name);
    // The message for a command that is not in the table.
    static QString unknownCommandMessage(const QString &name);
    // Every command's name, once, in the table's order: "params, read, ... and bundle".
    static QString commandNames();
    // A run that ends before a command is chosen (a bad option, no command, a bad --id list):
    // each message on standard error and, with --json, the envelope with them on standard
    // output; returns `code`.
    static int failEarly(int code, const QStringList &messages, bool json);
    // `--json` was given among `arguments` (before they could be parsed).
    static bool jsonAsked(const QStringList &arguments);

Q_SIGNALS:
    void finished(int exitCode);

private:
    void connectThen(std::function<void()> next);
    void runParams();
    void runRead();
    void runWrite();
    void writeThenReport(const QList<ParameterWrite> &writes);
    // Prints each value written and verified, and what was not, into the output and the JSON
    // result ("written", "not_written"); write and apply.
    void reportWritten(const QList<ParameterWrite> &writes, const WriteOutcome &w);
    // The window's review of `writes` (WriteReview), on what the controller holds: its
    // questions printed; without --yes nothing is written (exit 2), else `next`.
    void reviewThen(const QList<ParameterWrite> &writes, std::function<void()> next);
    void runCommand();
    // command NAME --wait: sends it and judges where the motion ended (CtlMotionWait).
    void runCommandWait();
    // The one coil `command` names, checked; nullptr after failing with the reason.
    const Parameter *commandArgument();
    void runMonitor();
    // listen (ctllisten.cpp): hears a line another master drives; nothing is sent.
    void runListen();
    // move MOTOR --by D | --to X: a step or move-to over the single move (ctlmove.cpp).
    void runMove();
    // The session's risk guard, as the window installs one: a backup of the controller's
    // settings before every risky operation (unless --no-backup), said where (ctlmove.cpp).
    void installRiskGuard();
    // Runs `next` once the guard let `risk` go on; fails (nothing done) when it did not.
    void guardThen(DeviceSession::Risk risk, std::function<void()> next);
    // assign-id --to N (ctlbus.cpp): the one controller at --id gets id N, verified there.
    void runAssignId();
    // scan (ctlbus.cpp): every controller on the line, at the bauds, parities and ids asked.
    void runScan();
    // ports (ctlports.cpp): every serial port, its stable name, adapter and who holds it.
    void runPorts();
    // Profiles and the report (ctlprofile.cpp).
    void runDump();
    void runDiff();
    void runApply();
    void runReport();
    bool loadProfileArgument(const QString &command, Profile *out);
    // Profiles of other maps are read too; problems go to standard error, false then.
    bool loadProfile(const QString &path, Profile *out);
    // What of a profile of another map is left out, under `heading` (nothing when all fits).
    // "not supported by this controller: ..." for what a read found the controller lacks;
    // returns how many keys of `profile` (when given) it takes out of it.
    int noteUnsupported(const ReadOutcome &read, Profile *profile = nullptr);
    void printLeftOut(const Profile &profile, const QString &heading);
    void runDiffFiles();
    void runReportFromFile(const QString &path);
    // report --id 1,2,3: every controller of the line in one document (ctlmachine.cpp).
    void runMachineReport();
    // Reads every controller of --id (one or several) completely, then `done` with their
    // sheets for a machine's report; fails with `failure` (and each one's errors) otherwise.
    void readMachine(const QString &failure, std::function<void(const QList<ReportInput> &)> done);
    // dump into a folder: one file per id, named by BusDump (ctlmachine.cpp).
    void dumpIntoFolder(const QString &folder, const QHash<QString, qint64> &values);
    // Support (ctlreplay.cpp): replay a session log or a bundle's; make a support bundle;
    // --log FILE for the session just made.
    void runReplay();
    void runBundle();
    // The bundle with the machine report of `sheets` (none: `input.noReport` says why).
    void writeBundle(BundleInput input, const QList<ReportInput> &sheets);
    void startLog();
    void confirmThenApply(const QList<ParameterWrite> &writes);
    void applyWrites(const QList<ParameterWrite> &writes);
    // Prints what ProfileApply came to: each value written and verified, what was not and why.
    void reportApplied(const ProfileApplyResult &result);
    void saveToFlashThenFinish();
    // --id with several ids (ctlbus.cpp): the command runs for each in turn over the one link;
    // the output is keyed by id and the exit code is the worst of them.
    bool isMulti() const { return m_options.ids.size() > 1; }
    // Several ids and a command run once per id (monitor watches them all in one run).
    bool isPerId() const
    {
        return isMulti() && m_chosen && QLatin1String(m_chosen->name) != QLatin1String("monitor") &&
               QLatin1String(m_chosen->name) != QLatin1String("listen");
    }
    void startMulti();
    // One id's run ended with `code`: true when the next one was started.
    bool nextId(int code);
    void runForCurrentId();
    void printMulti();
    int worstCode() const;
    // --json, for every command (ctlenvelope.cpp): what it prints is kept and one object ends
    // the run: exit, result (m_result, or the JSON the command printed), errors, messages; with
    // several ids one such object whose result holds each id's. monitor and listen print their
    // lines as they come and the object as the last line, its result a summary (m_result).
    bool isEnveloped() const { return m_options.json; }
    // monitor and listen: a line as it comes.
    bool isStreaming() const;
    // Output and messages into m_buffer and m_errBuffer, for the object at the end.
    void captureOutput();
    static QJsonObject envelope(int code, const QString &out, const QStringList &errors,
                                const QJsonObject &result);
    void printEnvelope(int code);
    // The errors of one read, each answer said once: on a dead line every block of the read
    // gets the same "no answer", which is said for the first with how many more had it.
    static QStringList condensed(const QStringList &errors);
    // A value in engineering units as JSON: a number.
    static QJsonValue jsonValue(const Parameter &p, qint64 raw);
    void fail(int code, const QString &message);
    void finish(int code);
    QString valueText(const Parameter &p, qint64 raw) const;

    CtlOptions m_options;
    RegisterMap m_map;
    DeviceSession *m_session = nullptr;
    QTextStream m_out;
    QTextStream m_err;
    // The exit code of a link that cannot be opened or read: DeviceError, except for diff,
    // where 1 already means "different".
    int m_linkError = DeviceError;
    QPointer<ProfileApply> m_applier;      // apply: the one ProfileApply of this id
    QList<ParameterWrite> m_appliedWrites; // apply: what was confirmed
    bool m_finished = false;
    const CtlCommand *m_chosen = nullptr;
    int m_idIndex = 0;
    QList<int> m_idCodes;    // exit code of each id run so far
    QStringList m_idOutputs; // what each id's run printed
    QString m_buffer;        // the current id's output
    QString m_errBuffer;     // the current id's messages, printed prefixed with its id
    QList<QStringList> m_idErrors;
    QJsonObject m_result;           // --json: what the current run came to
    QStringList m_liveErrors;       // monitor, listen: the errors already said as they came
    QList<QJsonObject> m_idResults; // each id's
    QString m_multiArgument;        // dump: the path asked for, suffixed per id
    QString m_dumpFolder;           // dump: the folder asked for, one file per id inside
    std::unique_ptr<SimulatorStarter> m_scanSim; // scan --sim: the simulator scanned
};

} // namespace stepcom

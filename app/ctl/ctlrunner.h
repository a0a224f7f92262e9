#pragma once

#include "ctloptions.h"
#include "map/registermap.h"
#include "session/devicesession.h"

#include <QObject>
#include <QTextStream>

namespace stepcom {

struct BundleInput;
struct Profile;
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

// Runs one stepcomctl command against a controller and reports an exit code:
// 0 success, 1 link or device error, 2 usage or validation error.
class CtlRunner : public QObject
{
    Q_OBJECT
public:
    enum Exit { Ok = 0, DeviceError = 1, UsageError = 2 };

    CtlRunner(const CtlOptions &options, const RegisterMap &map, QObject *parent = nullptr);
    // Starts the command; `finished` follows once.
    void start();

    // Every command, in the order the help lists them.
    static const QList<CtlCommand> &commands();
    // The "Commands:" part of --help, built from the table.
    static QString commandsHelp();
    // The message for a command that is not in the table.
    static QString unknownCommandMessage(const QString &name);

Q_SIGNALS:
    void finished(int exitCode);

private:
    void connectThen(std::function<void()> next);
    void runParams();
    void runRead();
    void runWrite();
    void writeThenReport(const QList<ParameterWrite> &writes);
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
    // Saves a backup of the controller's settings before `risk` (unless --no-backup), prints
    // where, then runs `next`; fails (nothing done) when it cannot be saved.
    void backupThen(DeviceSession::Risk risk, std::function<void()> next);
    // assign-id --to N (ctlbus.cpp): the one controller at --id gets id N, verified there.
    void runAssignId();
    // scan (ctlbus.cpp): every controller on the line, at the bauds, parities and ids asked.
    void runScan();
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
    // Saves the settings read before an apply as a backup (BackupStore), unless --no-backup;
    // false (and the command failed) when it could not be saved.
    bool backupBeforeApply();
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
    QHash<QString, qint64> m_beforeApply; // the settings read before apply: its backup
    bool m_finished = false;
    const CtlCommand *m_chosen = nullptr;
    int m_idIndex = 0;
    QList<int> m_idCodes;    // exit code of each id run so far
    QStringList m_idOutputs; // what each id's run printed
    QString m_buffer;        // the current id's output
    QString m_errBuffer;     // the current id's messages, printed prefixed with its id
    QList<QStringList> m_idErrors;
    QString m_multiArgument; // dump: the path asked for, suffixed per id
    QString m_dumpFolder;    // dump: the folder asked for, one file per id inside
};

} // namespace stepcom

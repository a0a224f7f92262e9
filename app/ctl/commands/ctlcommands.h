#pragma once

#include <QHash>
#include <QList>
#include <QString>

#include <functional>

namespace stepcom {

class CtlContext;
struct ParameterWrite;
struct Profile;
struct ReadOutcome;
struct ReportInput;

// stepcomctl's commands, each a function of the run's context (CtlRunner::commands() names
// them), one file per family.

// ctlread.cpp: the map and what the controller holds.
void runParams(CtlContext &ctx);
void runRead(CtlContext &ctx);
// ctlwrite.cpp: parsed and checked, reviewed as the window reviews it (WriteReview), then
// written and verified.
void runWrite(CtlContext &ctx);
// ctlcommand.cpp: a command coil pulsed; with --wait, where the motion ended (CtlMotionWait).
void runCommand(CtlContext &ctx);
void runCommandWait(CtlContext &ctx);
// ctlmove.cpp: move MOTOR --by D | --to X, a step or move-to over the single move.
void runMove(CtlContext &ctx);
// ctlwatch.cpp: monitor (the live status) and listen (a line another master drives; nothing
// is sent), their lines printed as they come.
void runMonitor(CtlContext &ctx);
void runListen(CtlContext &ctx);
// ctlline.cpp: assign-id --to N (the one controller at --id gets id N, verified there) and scan
// (every controller on the line, at the bauds, parities and ids asked).
void runAssignId(CtlContext &ctx);
void runScan(CtlContext &ctx);
// ctlports.cpp: every serial port, its stable name, adapter and who holds it.
void runPorts(CtlContext &ctx);
// ctlprofile.cpp: profiles and the report of one controller.
void runDump(CtlContext &ctx);
void runDiff(CtlContext &ctx);
void runReport(CtlContext &ctx);
// ctlapply.cpp: a profile's differing values written, after asking, and verified.
void runApply(CtlContext &ctx);
// ctlrun.cpp: a machine cycle (a .stepseq file) run, shown and asked about first.
void runRun(CtlContext &ctx);

// ctlproof.cpp: proving an axis (docs/proving.md), shown and asked about first.
void runLostSteps(CtlContext &ctx);
void runMargin(CtlContext &ctx);
void runBacklash(CtlContext &ctx);

// What write shares (ctlwrite.cpp).
// The window's review of `writes` (WriteReview) on what the controller holds: its questions
// printed; without --yes nothing is written (exit 2), else `next`.
void reviewThen(CtlContext &ctx, const QList<ParameterWrite> &writes, std::function<void()> next);
// Writes, verifies and prints each value (--save-to-flash after it), then ends the run.
void writeThenReport(CtlContext &ctx, const QList<ParameterWrite> &writes);

// What a question before a risky command says when it is not answered yes.
struct ConfirmRefusals
{
    QString notConfirmed; // answered anything but y/yes
    QString noAnswer;     // standard input ended
};
// Shows `shown` and asks `question` on the console (standard error with --json), reading the
// answer through the event loop: `yes` on y/yes, else the run fails (exit 2) with a refusal
// (ctlapply.cpp).
void confirmThen(CtlContext &ctx, const QString &shown, const QString &question,
                 const ConfirmRefusals &refusals, std::function<void()> yes);
// ctlmachine.cpp: report --id 1,2,3, every controller of the line in one document.
void runMachineReport(CtlContext &ctx);
// ctlreplay.cpp: replay a session log or a bundle's; make a support bundle.
void runReplay(CtlContext &ctx);
void runBundle(CtlContext &ctx);

// What the profile commands share (ctlprofile.cpp).
// Profiles of other maps are read too; problems go to standard error, false then.
bool loadProfile(CtlContext &ctx, const QString &path, Profile *out);
// The one profile file of `command`'s arguments; fails (nothing written) when it cannot be read.
bool loadProfileArgument(CtlContext &ctx, const QString &command, Profile *out);
// report's one file argument, a .pdf or .html; empty (and the run failed, saying why) otherwise.
QString reportPath(CtlContext &ctx);
// What of a profile of another map is left out, under `heading` (nothing when all fits).
void printLeftOut(CtlContext &ctx, const Profile &profile, const QString &heading);
// "not supported by this controller: ..." for what a read found the controller lacks;
// returns how many keys of `profile` (when given) it takes out of it.
int noteUnsupported(CtlContext &ctx, const ReadOutcome &read, Profile *profile = nullptr);

// What the machine's commands share (ctlmachine.cpp).
// Reads every controller of --id (one or several) completely, then `done` with their sheets
// for a machine's report; fails with `failure` (and each one's errors) otherwise.
void readMachine(CtlContext &ctx, const QString &failure,
                 std::function<void(const QList<ReportInput> &)> done);
// dump into a folder: one file per id, named by BusDump.
void dumpIntoFolder(CtlContext &ctx, const QString &folder, const QHash<QString, qint64> &values);

} // namespace stepcom

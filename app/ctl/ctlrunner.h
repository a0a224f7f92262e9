#pragma once

#include "ctloptions.h"
#include "map/registermap.h"

#include <QJsonObject>
#include <QObject>

#include <memory>

namespace stepcom {

class CtlContext;

// One stepcomctl command: its name, how it is called, its help (English source, translated in
// the "stepcomctl" context) and the function that runs it (app/ctl/commands/ctlcommands.h).
struct CtlCommand
{
    const char *name;
    const char *usage;
    const char *help;
    void (*run)(CtlContext &);
    // The option this row needs (command NAME --wait); a set one takes it over the plain row.
    bool CtlOptions::*when = nullptr;
};

// Runs one stepcomctl command against a controller and reports an exit code (Exit): chooses
// the command, runs it over the context (CtlContext) once or for each id, and ends the run.
class CtlRunner : public QObject
{
    Q_OBJECT
public:
    // The exit codes, as exitCodesHelp() explains them: 1 is also a command's "no" (diff:
    // different, scan: none found, move and command --wait: not arrived), and diff and scan say
    // a link error with LinkError, their 1 being an answer.
    enum Exit { Ok = 0, DeviceError = 1, UsageError = 2, LinkError = 3 };

    CtlRunner(const CtlOptions &options, const RegisterMap &map, QObject *parent = nullptr);
    ~CtlRunner() override;
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
    friend class CtlContext; // its finish() ends the command here
    void finish(int code);
    // Several ids and a command run once per id (monitor watches them all in one run).
    bool isPerId() const;
    // --id with several ids (ctlbus.cpp): the command runs for each in turn over the one link;
    // the output is keyed by id and the exit code is the worst of them.
    void startMulti();
    // One id's run ended with `code`: true when the next one was started.
    bool nextId(int code);
    void runForCurrentId();
    void printMulti();
    int worstCode() const;
    // --json, for every command (ctlenvelope.cpp): what it prints is kept and one object ends
    // the run: exit, result (the context's, or the JSON the command printed), errors, messages;
    // with several ids one such object whose result holds each id's. monitor and listen print
    // their lines as they come and the object as the last line, its result a summary.
    // Output and messages into the context's buffers, for the object at the end.
    void captureOutput();
    // monitor and listen: a line as it comes.
    bool isStreaming() const;
    static QJsonObject envelope(int code, const QString &out, const QStringList &errors,
                                const QJsonObject &result);
    void printEnvelope(int code);

    std::unique_ptr<CtlContext> m_ctx;
    bool m_finished = false;
    const CtlCommand *m_chosen = nullptr;
    QList<int> m_idCodes;    // exit code of each id run so far
    QStringList m_idOutputs; // what each id's run printed
    QList<QStringList> m_idErrors;
    QList<QJsonObject> m_idResults; // each id's
    QString m_multiArgument;        // dump: the path asked for, suffixed per id
};

} // namespace stepcom

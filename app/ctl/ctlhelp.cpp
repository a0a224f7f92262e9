// stepcomctl's help: the commands' table as text, the exit codes, one command's help.
#include "ctlrunner.h"

#include <QCoreApplication>

namespace stepcom {

namespace {

struct ExitCodeRow
{
    int code;
    const char *meaning;
};

// One table for every command; tst_ctlexit runs each command's failures against it.
const ExitCodeRow kExitCodes[] = {
    {CtlRunner::Ok,
     QT_TRANSLATE_NOOP("stepcomctl", "success: done, written and verified; diff: the same;\n"
                                     "scan: found; move, command --wait: arrived")},
    {CtlRunner::DeviceError,
     QT_TRANSLATE_NOOP("stepcomctl", "not done: a link or device error, a value not\n"
                                     "verified, a file or backup that could not be\n"
                                     "written; diff: different; scan: none found; move,\n"
                                     "command --wait: stopped elsewhere or not known;\n"
                                     "lost-steps: lost or not known; a proof stopped\n"
                                     "(Ctrl-C, E-STOP, end of input)")},
    {CtlRunner::UsageError,
     QT_TRANSLATE_NOOP("stepcomctl", "nothing was done: a usage or validation error, a bad\n"
                                     "file, a write the window asks about without --yes,\n"
                                     "an apply not confirmed, a proof refused")},
    {CtlRunner::LinkError,
     QT_TRANSLATE_NOOP("stepcomctl", "diff, scan: a link or device error (their 1 is an\n"
                                     "answer); run: the link lost, the controller\n"
                                     "restarted, a command not taken; lost-steps,\n"
                                     "margin, backlash: the link lost, a restart, a\n"
                                     "read or move that failed")},
};

// "  first<padded>help" with the help's further lines under its first one.
QString columns(const QList<std::pair<QString, QString>> &rows)
{
    qsizetype width = 0;
    for (const auto &row : rows)
        width = std::max(width, row.first.size());
    width += 2; // at least two spaces between the columns
    QString text;
    for (const auto &[first, help] : rows) {
        const QStringList lines = help.split(QLatin1Char('\n'));
        text +=
            QStringLiteral("  ") + first.leftJustified(width) + lines.first() + QLatin1Char('\n');
        for (qsizetype i = 1; i < lines.size(); ++i)
            text += QString(width + 2, QLatin1Char(' ')) + lines.at(i) + QLatin1Char('\n');
    }
    return text;
}

QString translated(const char *text)
{
    return QCoreApplication::translate("stepcomctl", text);
}

} // namespace

QString CtlRunner::commandsHelp()
{
    QList<std::pair<QString, QString>> rows;
    for (const CtlCommand &c : commands())
        rows.append({QLatin1String(c.usage), translated(c.help)});
    return translated(QT_TRANSLATE_NOOP("stepcomctl", "Commands:")) + QLatin1Char('\n') +
           columns(rows);
}

QString CtlRunner::exitCodesHelp()
{
    QList<std::pair<QString, QString>> rows;
    for (const ExitCodeRow &r : kExitCodes)
        rows.append({QString::number(r.code), translated(r.meaning)});
    return translated(QT_TRANSLATE_NOOP("stepcomctl", "Exit codes (every command):")) +
           QLatin1Char('\n') + columns(rows);
}

QString CtlRunner::commandHelp(const QString &name)
{
    QList<std::pair<QString, QString>> rows;
    for (const CtlCommand &c : commands()) {
        if (name == QLatin1String(c.name))
            rows.append(
                {QStringLiteral("stepcomctl ") + QLatin1String(c.usage), translated(c.help)});
    }
    if (rows.isEmpty())
        return {};
    QString text = translated(QT_TRANSLATE_NOOP("stepcomctl", "Usage:")) + QLatin1Char('\n') +
                   columns(rows) + QLatin1Char('\n');
    text += translated(QT_TRANSLATE_NOOP("stepcomctl",
                                         "The link and the other options: stepcomctl --help")) +
            QStringLiteral("\n\n");
    return text + exitCodesHelp();
}

} // namespace stepcom

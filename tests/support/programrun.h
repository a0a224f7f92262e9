#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace stepcom::test {

// What a finished program left behind.
struct ProgramRun
{
    int exitCode = -1; // -2: crashed; -1: did not start or did not end in time
    QString out;
    QString err;
};

struct ProgramOptions
{
    QByteArray input;         // written to its standard input, which is then closed
    QStringList environment;  // NAME=VALUE settings on top of the test's environment
    bool cleanLocale = false; // drop LANGUAGE, LC_ALL, LC_MESSAGES, LANG first
    QStringList unset;        // variables removed from the test's environment (e.g. DISPLAY)
    int timeoutMs = 20000;
};

// Runs a built program (programPath(name)) without blocking the event loop, so fake devices
// and simulators in the test process keep answering while it runs.
ProgramRun runProgram(const QString &name, const QStringList &args,
                      const ProgramOptions &options = {});

} // namespace stepcom::test

#pragma once

#include <QCoreApplication>
#include <QString>

namespace stepcom {

class SimHost;

// The simulator's console: one command line in, text out. Drives the inputs by hand, shows
// the state, writes parameters, runs commands, hangs up the port, switches the power off.
class SimConsole
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::SimConsole)
public:
    struct Result
    {
        QString text;
        bool ok = true;
        bool quit = false;
    };

    explicit SimConsole(SimHost *host);
    Result execute(const QString &line);
    static QString help();

private:
    Result input(const QStringList &args);
    Result set(const QStringList &args);
    Result get(const QStringList &args);
    Result run(const QStringList &args);
    Result place(const QStringList &args);
    Result powerCycle(const QStringList &args);
    Result status() const;

    SimHost *m_host;
};

} // namespace stepcom

#pragma once

#include "sim/host/simoptions.h"

#include <QCommandLineParser>
#include <QString>

#include <optional>
#include <utility>

namespace stepcom {

// The simulator's command-line options, shared by stepcom-sim and any program that embeds a
// SimHost (e.g. stepcomctl --sim), so they spell them the same way.
class SimCommandLine
{
public:
    static void addOptions(QCommandLineParser &parser);
    // Reads what addOptions() added; false and a message naming the option on bad input.
    static bool toOptions(const QCommandLineParser &parser, SimOptions *options, QString *error);

    // "IN3=on", "3=pulse", "in1=off"
    static std::optional<std::pair<int, SimMachine::InputForce>> parseInput(const QString &text,
                                                                            QString *error);
    // "3", "0.5": seconds as whole milliseconds from minMs to maxMs; nullopt when not.
    static std::optional<int> parseSeconds(const QString &text, int minMs, int maxMs);
    // "10:3" (--power-cycle): ms after start, ms off.
    static std::optional<std::pair<int, int>> parsePowerCycle(const QString &text, QString *error);
    // "96:800" (--slow-coil): a coil's PLC number in `map`, ms its answer is slower.
    static std::optional<std::pair<int, int>> parseSlowCoil(const RegisterMap &map,
                                                            const QString &text, QString *error);
    // "5020", "127.0.0.1:5020", "[::1]:502"
    static bool parseTcp(const QString &text, QHostAddress *address, quint16 *port, QString *error);
};

} // namespace stepcom

#pragma once

#include "sim/serve/faultoptions.h"

#include <QRandomGenerator>
#include <QString>

#include <optional>

namespace stepcom {

// Decides, reproducibly from the seed, which faults hit each request.
class FaultInjector
{
public:
    struct Decision
    {
        bool drop = false;
        bool corruptCrc = false;
        int extraDelayMs = 0;
        int exceptionCode = 0; // 0: none
        bool hangUp = false;   // after this answer
    };

    explicit FaultInjector(const FaultOptions &options = {});
    const FaultOptions &options() const { return m_options; }
    // One decision per request addressed to the device; draws the same amount of randomness
    // whatever the options, so a seed replays the same sequence.
    Decision next();

    // "0.1", "10%" -> 0.1
    static std::optional<double> parseShare(const QString &text, QString *error);
    // "0.2:500" -> share 0.2, value 500
    static bool parseShareAndValue(const QString &text, double *share, int *value, QString *error);

private:
    FaultOptions m_options;
    QRandomGenerator m_random;
    int m_answered = 0;
};

} // namespace stepcom

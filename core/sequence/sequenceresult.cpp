#include "sequence/sequenceresult.h"

#include <algorithm>

namespace stepcom {

QString SequenceResult::word(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Done:
        return QStringLiteral("done");
    case Outcome::Timeout:
        return QStringLiteral("timeout");
    case Outcome::Stopped:
        return QStringLiteral("stopped");
    case Outcome::EmergencyStop:
        return QStringLiteral("estop");
    case Outcome::Limit:
        return QStringLiteral("limit");
    case Outcome::LinkLost:
        return QStringLiteral("link-lost");
    case Outcome::Restarted:
        return QStringLiteral("restarted");
    case Outcome::Interrupted:
        return QStringLiteral("interrupted");
    case Outcome::DeviceError:
        return QStringLiteral("device-error");
    case Outcome::Refused:
        return QStringLiteral("refused");
    }
    return {};
}

double SequenceResult::minCycle() const
{
    return cycleSeconds.isEmpty() ? 0 : *std::min_element(cycleSeconds.begin(), cycleSeconds.end());
}

double SequenceResult::maxCycle() const
{
    return cycleSeconds.isEmpty() ? 0 : *std::max_element(cycleSeconds.begin(), cycleSeconds.end());
}

double SequenceResult::medianCycle() const
{
    if (cycleSeconds.isEmpty())
        return 0;
    QList<double> sorted = cycleSeconds;
    std::sort(sorted.begin(), sorted.end());
    const qsizetype n = sorted.size();
    return n % 2 ? sorted.at(n / 2) : (sorted.at(n / 2 - 1) + sorted.at(n / 2)) / 2;
}

} // namespace stepcom

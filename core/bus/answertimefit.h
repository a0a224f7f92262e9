#pragma once

#include <QList>
#include <QMap>

#include <optional>

namespace stepcom {

// The time one controller takes to answer, told apart from the bytes' time on the wire.
// A round trip is the request's and the answer's characters on the wire plus the controller's
// own answer time: round trips of frames of different lengths, fitted to a straight line
// (time = answer time + characters x time per character), give both. Only a fit whose time per
// character is that of the set baud rate is believed: on a pseudo-terminal, where bytes take no
// time, or behind a gateway, the line does not show the controller's own time, and the manual's
// answer time stays the one to plan with.
class AnswerTimeFit
{
public:
    // Lengths kept (the most recently seen), and round trips kept per length.
    static constexpr int kLengths = 12;
    static constexpr int kPerLength = 8;
    // The lengths must be this far apart on the wire for a fit (the time of a character times
    // their difference), so that a millisecond of jitter cannot tip the line.
    static constexpr double kMinSpreadMs = 10.0;

    // One answered request: `characters` on the wire (request, answer and the silence between
    // frames), `ms` from the request sent to the answer received.
    void add(int characters, double ms);
    void clear();

    struct Line
    {
        double answerMs = 0;  // the controller's own time (plus an adapter's latency)
        double msPerChar = 0; // the wire's time of one character
    };
    // The line through the lower quartile round trip of every length kept; nothing before two
    // lengths at least kMinSpreadMs apart at `expectedMsPerChar` were seen.
    std::optional<Line> fit(double expectedMsPerChar) const;
    // The controller's answer time when the fit shows a wire at `expectedMsPerChar` (its time
    // per character within 0.6-1.6x of it); nothing otherwise.
    std::optional<double> answerMs(double expectedMsPerChar) const;

private:
    QMap<int, QList<double>> m_byLength; // characters -> latest round trips
    QList<int> m_lengths;                // least recently seen first
};

} // namespace stepcom

#include "bus/answertimefit.h"

#include <algorithm>

namespace stepcom {

void AnswerTimeFit::add(int characters, double ms)
{
    if (characters <= 0 || ms < 0)
        return;
    m_lengths.removeOne(characters);
    m_lengths.append(characters);
    QList<double> &trips = m_byLength[characters];
    trips.append(ms);
    if (trips.size() > kPerLength)
        trips.removeFirst();
    while (m_lengths.size() > kLengths)
        m_byLength.remove(m_lengths.takeFirst());
}

void AnswerTimeFit::clear()
{
    m_byLength.clear();
    m_lengths.clear();
}

std::optional<AnswerTimeFit::Line> AnswerTimeFit::fit(double expectedMsPerChar) const
{
    if (m_byLength.size() < 2 || expectedMsPerChar <= 0)
        return std::nullopt;
    const int spread = m_byLength.lastKey() - m_byLength.firstKey();
    if (spread * expectedMsPerChar < kMinSpreadMs)
        return std::nullopt;
    // Least squares through one point per length: its lower quartile round trip. A busy
    // computer only ever adds to a round trip, so the quartile stays on the line while most of
    // a length's round trips were slowed.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (auto it = m_byLength.cbegin(); it != m_byLength.cend(); ++it) {
        QList<double> sorted = it.value();
        std::sort(sorted.begin(), sorted.end());
        const double x = it.key();
        const double y = sorted.at(sorted.size() / 4);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double n = double(m_byLength.size());
    const double denominator = n * sxx - sx * sx;
    if (denominator <= 0)
        return std::nullopt;
    Line line;
    line.msPerChar = (n * sxy - sx * sy) / denominator;
    line.answerMs = (sy - line.msPerChar * sx) / n;
    return line;
}

std::optional<double> AnswerTimeFit::answerMs(double expectedMsPerChar) const
{
    const std::optional<Line> line = fit(expectedMsPerChar);
    if (!line || line->msPerChar < 0.6 * expectedMsPerChar ||
        line->msPerChar > 1.6 * expectedMsPerChar)
        return std::nullopt;
    return std::max(0.0, line->answerMs);
}

} // namespace stepcom

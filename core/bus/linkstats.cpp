#include "bus/linkstats.h"

#include <QCoreApplication>

#include <algorithm>

namespace stepcom {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("stepcom::LinkStats", text);
}

} // namespace

void RoundTrips::add(qint64 ms)
{
    ++count;
    min = min < 0 ? ms : std::min(min, ms);
    max = std::max(max, ms);
    recent.append(ms);
    if (recent.size() > kWindow)
        recent.removeFirst();
}

qint64 RoundTrips::median() const
{
    if (recent.isEmpty())
        return -1;
    QList<qint64> sorted = recent;
    std::sort(sorted.begin(), sorted.end());
    return sorted.at(sorted.size() / 2);
}

QString RoundTrips::text() const
{
    if (count == 0)
        return {};
    return QCoreApplication::translate("stepcom::RoundTrips", "%1-%2 ms (median %3 ms)")
        .arg(min)
        .arg(max)
        .arg(median());
}

void LinkStats::addRoundTrip(qint64 ms, int unit, int characters)
{
    lastRoundTripMs = ms;
    minRoundTripMs = minRoundTripMs < 0 ? ms : std::min(minRoundTripMs, ms);
    maxRoundTripMs = std::max(maxRoundTripMs, ms);
    // answers has already been counted for this round trip
    const double n = double(std::max<quint64>(answers, 1));
    meanRoundTripMs += (double(ms) - meanRoundTripMs) / n;
    roundTrips.add(ms);
    if (unit > 0) {
        byUnit[unit].add(ms);
        if (characters > 0)
            answerTimes[unit].add(characters, double(ms));
    }
}

int LinkStats::suggestedTimeoutMs() const
{
    if (answers < 5 || maxRoundTripMs < 0)
        return -1;
    const qint64 raw = maxRoundTripMs * 3 / 2 + 50;
    return int(std::max<qint64>(100, (raw + 49) / 50 * 50));
}

QString LinkStats::lineText(int unit) const
{
    const RoundTrips &trips = unit > 0 ? byUnit.value(unit) : roundTrips;
    QStringList parts;
    if (!adapter.isEmpty())
        parts << adapter;
    parts << (trips.count == 0 ? tr("no answer timed yet") : tr("answers in %1").arg(trips.text()));
    parts << (echo < 0 ? tr("echo not known yet")
              : echo   ? tr("the adapter echoes")
                       : tr("no echo"));
    if (timeoutMs > 0)
        parts << tr("timeout %1 ms").arg(timeoutMs);
    return parts.join(QStringLiteral(", "));
}

QString LinkStats::summary(int setTimeoutMs) const
{
    QString text = tr("%1 requests, %2 answers; %3 timeouts, %4 CRC errors, %5 exceptions, "
                      "%6 stale or foreign answers discarded")
                       .arg(requests)
                       .arg(answers)
                       .arg(timeouts)
                       .arg(crcErrors)
                       .arg(exceptions)
                       .arg(stale);
    text += QStringLiteral("; ") + tr("line: %1").arg(lineText());
    if (const int suggested = suggestedTimeoutMs(); suggested > 0 && timeoutMs < 0)
        text += tr("; suggested timeout %1 ms (now %2 ms)").arg(suggested).arg(setTimeoutMs);
    return text;
}

} // namespace stepcom

#include "device/readplanner.h"

#include "map/parameter.h"

#include <algorithm>
#include <limits>

namespace stepcom {

ReadCostModel ReadCostModel::forBaud(int baud, double answerDelayMs)
{
    ReadCostModel m;
    m.charMs = baud > 0 ? 10000.0 / baud : 0.0;
    m.answerDelayMs = answerDelayMs;
    return m;
}

QList<ReadBlock> ReadPlanner::plan(const QList<const Parameter *> &params, int maxRegisters,
                                   const ReadCostModel &model, const MayRead &mayRead)
{
    struct Span
    {
        int first;
        int last;
    };
    QList<Span> spans;
    for (const Parameter *p : params) {
        if (p && p->readable())
            spans.append({p->address, p->lastAddress()});
    }
    std::sort(spans.begin(), spans.end(), [](Span a, Span b) { return a.first < b.first; });
    // Merge duplicates and overlaps so each span is a distinct stretch of registers.
    QList<Span> merged;
    for (const Span &s : std::as_const(spans)) {
        if (!merged.isEmpty() && s.first <= merged.last().last)
            merged.last().last = std::max(merged.last().last, s.last);
        else
            merged.append(s);
    }
    const int n = int(merged.size());
    if (n == 0)
        return {};
    // best[j]: cheapest plan covering spans 0..j-1; reads[j] its number of reads.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    QList<double> best(n + 1, kInf);
    QList<int> reads(n + 1, 0);
    QList<int> from(n + 1, -1);
    best[0] = 0.0;
    for (int j = 1; j <= n; ++j) {
        for (int i = j; i >= 1; --i) {
            const int length = merged[j - 1].last - merged[i - 1].first + 1;
            if (length > maxRegisters)
                break;
            // What a read may cover only shrinks as it widens: no wider block can be allowed.
            if (i < j && mayRead && !mayRead(merged[i - 1].first, merged[j - 1].last))
                break;
            if (best[i - 1] == kInf)
                continue;
            const double cost = best[i - 1] + model.readMs(length);
            const int count = reads[i - 1] + 1;
            constexpr double kEpsilon = 1e-9;
            if (cost < best[j] - kEpsilon || (cost <= best[j] + kEpsilon && count < reads[j])) {
                best[j] = cost;
                reads[j] = count;
                from[j] = i - 1;
            }
        }
    }
    QList<ReadBlock> blocks;
    for (int j = n; j > 0; j = from[j]) {
        const int i = from[j];
        if (i < 0)
            return {}; // a single value wider than the limit: cannot be read
        blocks.prepend(
            {quint16(merged[i].first), quint16(merged[j - 1].last - merged[i].first + 1)});
    }
    return blocks;
}

double ReadPlanner::costMs(const QList<ReadBlock> &blocks, const ReadCostModel &model)
{
    double total = 0.0;
    for (const ReadBlock &b : blocks)
        total += model.readMs(b.count);
    return total;
}

} // namespace stepcom

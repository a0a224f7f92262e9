#pragma once

#include <QList>

#include <functional>

namespace stepcom {

struct Parameter;

struct ReadBlock
{
    quint16 address = 0;
    quint16 count = 0;
    quint16 lastAddress() const { return quint16(address + count - 1); }
    bool operator==(const ReadBlock &o) const = default;
};

// Wire time of one FC03 read, in ms: the request (8 bytes), the answer (5 + 2 per register),
// two 3.5-character silences and the controller's answer delay. At 9600 baud a character
// (10 bits) takes 1.04 ms.
struct ReadCostModel
{
    double charMs = 10000.0 / 9600.0;
    double answerDelayMs = 35.0;
    double readMs(int registers) const
    {
        return (8 + 5 + 2 * registers + 7) * charMs + answerDelayMs;
    }
    static ReadCostModel forBaud(int baud, double answerDelayMs = 35.0);
};

// Plans the cheapest set of reads that covers the given parameters under the controller's
// limit of registers per request: it merges across gaps when reading the gap costs less than
// another request, and never splits a 32-bit value. Exact (dynamic programming over the sorted
// parameters), ties broken towards fewer reads. With `mayRead` a block may cover only what it
// allows (first and last 0-based address): a controller that refuses gaps gets the cheapest plan
// that never touches an unlisted register.
class ReadPlanner
{
public:
    using MayRead = std::function<bool(int first, int last)>;
    static QList<ReadBlock> plan(const QList<const Parameter *> &params, int maxRegisters,
                                 const ReadCostModel &model, const MayRead &mayRead = {});
    static double costMs(const QList<ReadBlock> &blocks, const ReadCostModel &model);
};

} // namespace stepcom

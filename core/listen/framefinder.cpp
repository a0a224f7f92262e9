#include "listen/framefinder.h"

#include "bus/bigendian.h"
#include "bus/rtuframe.h"

#include <algorithm>
#include <cmath>

namespace stepcom {

namespace {

constexpr int kMaxUnit = 247;

using bigendian::byteAt;
using bigendian::wordAt;

bool knownFunction(int fc)
{
    return (fc >= 0x01 && fc <= 0x06) || fc == 0x0F || fc == 0x10;
}

} // namespace

FrameFinder::FrameFinder(int baud, int minSilenceMs)
    : m_silenceMs(std::max(minSilenceMs, int(std::ceil(RtuFrame::charsMs(4, baud)))))
{}

QList<int> FrameFinder::candidateLengths(const QByteArray &b)
{
    if (b.isEmpty())
        return {0};
    if (byteAt(b, 0) > kMaxUnit)
        return {};
    if (b.size() < 2)
        return {0};
    const int fc = byteAt(b, 1);
    if (fc & 0x80)
        return knownFunction(fc & 0x7F) ? QList<int>{5} : QList<int>{};
    if (!knownFunction(fc))
        return {};
    QList<int> out;
    switch (fc) {
    case 0x01:
    case 0x02:
    case 0x03:
    case 0x04: {
        // The request: address and count (at most 2000 bits or 125 registers).
        const int most = fc <= 0x02 ? 2000 : 125;
        if (b.size() < 6)
            out << 8;
        else if (wordAt(b, 4) >= 1 && wordAt(b, 4) <= most)
            out << 8;
        // The answer: a byte count, even for registers.
        if (b.size() < 3) {
            out << 0;
        } else {
            const int n = byteAt(b, 2);
            if (n >= 1 && n <= 250 && (fc <= 0x02 || n % 2 == 0))
                out << 3 + n + 2;
        }
        break;
    }
    case 0x05:
    case 0x06:
        // Request and answer alike; a coil is set by FF00 or cleared by 0000 only.
        if (fc == 0x06 || b.size() < 6 || ((wordAt(b, 4) == 0xFF00 || wordAt(b, 4) == 0x0000)))
            out << 8;
        break;
    case 0x0F:
    case 0x10: {
        out << 8; // the answer: address and count
        if (b.size() < 7) {
            out << 0;
            break;
        }
        const int count = wordAt(b, 4);
        const int n = byteAt(b, 6);
        const bool fits = fc == 0x10 ? count >= 1 && count <= 123 && n == 2 * count
                                     : count >= 1 && count <= 1968 && n == (count + 7) / 8;
        if (fits)
            out << 7 + n + 2;
        break;
    }
    default:
        break;
    }
    std::sort(out.begin(), out.end());
    return out;
}

QList<HeardFrame> FrameFinder::feed(const QByteArray &bytes, qint64 ms)
{
    QList<HeardFrame> out;
    // Bytes after a silence begin a new frame: what waits from before cannot end in them.
    if (!m_buffer.isEmpty() && ms - m_lastMs >= m_silenceMs)
        scan(&out, true);
    m_stats.bytes += bytes.size();
    m_buffer.append(bytes);
    m_lastMs = ms;
    scan(&out, false);
    return out;
}

QList<HeardFrame> FrameFinder::idle(qint64 ms)
{
    QList<HeardFrame> out;
    if (!m_buffer.isEmpty() && ms - m_lastMs >= m_silenceMs)
        scan(&out, true);
    return out;
}

void FrameFinder::finish()
{
    QList<HeardFrame> ignored;
    scan(&ignored, true);
    skip(m_buffer.size());
    endJunk();
}

void FrameFinder::scan(QList<HeardFrame> *out, bool quiet)
{
    while (!m_buffer.isEmpty()) {
        const QList<int> lengths = candidateLengths(m_buffer);
        bool waiting = false;
        int found = 0;
        for (const int length : lengths) {
            if (length == 0 || length > m_buffer.size()) {
                waiting = true;
                continue;
            }
            if (RtuFrame::crcOk(m_buffer.left(length))) {
                found = length;
                break;
            }
        }
        if (found > 0) {
            endJunk();
            out->append(HeardFrame{m_buffer.left(found), m_lastMs});
            m_buffer.remove(0, found);
            ++m_stats.frames;
            continue;
        }
        if (waiting && !quiet)
            return;
        skip(1);
    }
    if (quiet)
        endJunk();
}

void FrameFinder::skip(qsizetype n)
{
    m_buffer.remove(0, n);
    m_junk += n;
}

void FrameFinder::endJunk()
{
    if (m_junk >= 4)
        ++m_stats.damaged;
    else
        m_stats.strayBytes += m_junk;
    m_junk = 0;
}

} // namespace stepcom

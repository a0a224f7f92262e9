#pragma once

#include "listen/heardframe.h"

#include <QList>

namespace stepcom {

// Finds Modbus RTU frames in the bytes of a line heard from the side. A USB adapter delivers
// bytes in packets, so the 3.5-character silence cannot mark a frame's end; a frame is where
// the unit, a function code StepCom knows and a length that request or answer of that code must
// have end in a good CRC. The silence is a hint only: bytes still waiting for a frame when the
// line has been quiet that long cannot be one. Whatever fits no frame is skipped a byte at a
// time, so a lost or damaged byte costs its one frame and the next one is found.
// A plain value: feed it bytes in order.
class FrameFinder
{
public:
    struct Stats
    {
        qint64 bytes = 0;   // every byte fed
        qint64 frames = 0;  // whole frames with a good CRC
        qint64 damaged = 0; // runs of 4 bytes or more that made no frame (a bad CRC, a lost byte)
        qint64 strayBytes = 0; // runs of 1-3 bytes that made no frame (a stray 0x00, noise)
    };

    // The baud sets how long a silence ends any frame (3.5 characters, at least `minSilenceMs`:
    // a USB adapter may hold bytes of one frame up to its latency timer).
    explicit FrameFinder(int baud = 9600, int minSilenceMs = 40);

    // Bytes that arrived at `ms`; the frames they completed, in order.
    QList<HeardFrame> feed(const QByteArray &bytes, qint64 ms);
    // The line was quiet until `ms`: after a silence, bytes still waiting are no frame.
    QList<HeardFrame> idle(qint64 ms);
    // The end of the stream: whatever is left is no frame.
    void finish();

    const Stats &stats() const { return m_stats; }
    int silenceMs() const { return m_silenceMs; }
    // Bytes held that are not a frame yet.
    qsizetype held() const { return m_buffer.size(); }

    // Candidate lengths of a frame starting `bytes` (CRC included): every length a request or
    // an answer of its function code may have, 0 for one not known until more bytes are in.
    // Empty: `bytes` cannot start a frame.
    static QList<int> candidateLengths(const QByteArray &bytes);

private:
    // Cuts frames from the front of the buffer; `quiet`: no more bytes are coming to it.
    void scan(QList<HeardFrame> *out, bool quiet);
    void skip(qsizetype n);
    void endJunk();

    QByteArray m_buffer;
    qint64 m_lastMs = 0;
    int m_silenceMs = 40;
    qsizetype m_junk = 0; // bytes skipped since the last frame
    Stats m_stats;
};

} // namespace stepcom

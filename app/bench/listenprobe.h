#pragma once

#include "benchreport.h"

#include <QList>
#include <QString>

namespace stepcom::bench {

// (n) listening beside a PLC: a recorded 38400 line (`seconds` of a PLC polling and writing,
// every byte as on the wire) cut into 16-byte USB packets and decoded by FrameFinder and
// ListenDecoder into the lines `stepcomctl listen` prints: frames decoded per second of CPU;
// and on a line of pseudo-terminals (LineHub) the delay from a frame's last byte written to its
// decoded line (LineListener::heard).
struct ListenResult
{
    QString error;
    int seconds = 0;
    qint64 frames = 0;
    qint64 bytes = 0;
    double decodeMs = 0;
    double framesPerSecond = 0;
    int delaySamples = 0;
    double delayMeanMs = 0;
    double delayMaxMs = 0;
};

ListenResult measureListen(int seconds, int delaySamples);
QList<Verdict> listenVerdicts(const ListenResult &r);

} // namespace stepcom::bench

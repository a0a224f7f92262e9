#include "listenprobe.h"

#include "bus/rtuframe.h"
#include "listen/framefinder.h"
#include "listen/linelistener.h"
#include "listen/listendecoder.h"
#include "map/registermap.h"
#include "sim/serve/linehub.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSerialPort>

#include <algorithm>

namespace stepcom::bench {

namespace {

constexpr int kBaud = 38400;

QByteArray frame(const QByteArray &hex)
{
    const QByteArray body = QByteArray::fromHex(hex);
    const quint16 crc = RtuFrame::crc(body);
    return body + char(crc & 0xFF) + char(crc >> 8);
}

// A PLC's cycle as the line carries it: read 40001-40010, write motor1.speed, read the
// positions, write a 32-bit pitch, each with its answer.
QByteArray plcCycle(int n)
{
    const QByteArray speed = QByteArray::number(100 + n % 2800, 16).rightJustified(4, '0');
    QByteArray out;
    out += frame("01030000000A");
    out += frame("01031400B40008019000500000012C01F4000000E80300");
    out += frame("01060005" + speed);
    out += frame("01060005" + speed);
    out += frame("0103006B0004");
    out += frame("0103080000000000000000");
    out += frame("0110001000020404D20000");
    out += frame("011000100002");
    return out;
}

} // namespace

ListenResult measureListen(int seconds, int delaySamples)
{
    ListenResult r;
    r.seconds = seconds;
    // The recorded line: as many cycles as `seconds` of wire time at 38400 hold.
    QByteArray line;
    const double bytesPerSecond = kBaud / 10.0;
    for (int n = 0; line.size() < bytesPerSecond * seconds; ++n)
        line += plcCycle(n);
    r.bytes = line.size();
    FrameFinder finder(kBaud);
    ListenDecoder decoder(&RegisterMap::builtin(), kBaud);
    qint64 events = 0;
    qint64 textChars = 0;
    QElapsedTimer clock;
    clock.start();
    for (qsizetype i = 0; i < line.size(); i += 16) {
        const qint64 ms = qint64(double(i) / bytesPerSecond * 1000.0);
        for (const HeardFrame &f : finder.feed(line.mid(i, 16), ms)) {
            for (const HeardEvent &e : decoder.frame(f)) {
                textChars += e.text().size(); // the line stepcomctl prints
                ++events;
            }
        }
    }
    r.decodeMs = double(clock.nsecsElapsed()) / 1e6;
    r.frames = finder.stats().frames;
    r.framesPerSecond = r.decodeMs > 0 ? double(r.frames) / (r.decodeMs / 1000.0) : 0;
    if (events == 0 || textChars == 0 || finder.stats().damaged != 0) {
        r.error = QStringLiteral("the recorded line did not decode (%1 events, %2 damaged)")
                      .arg(events)
                      .arg(finder.stats().damaged);
        return r;
    }

    // The delay on a line of ptys: a frame written by the PLC's end, heard on the other.
    LineHub hub;
    QString error;
    if (!hub.open(2, &error)) {
        r.error = error;
        return r;
    }
    LineListener listener(&RegisterMap::builtin());
    LinkSettings settings;
    settings.portName = hub.paths().at(1);
    settings.baud = kBaud;
    if (!listener.open(settings, &error)) {
        r.error = error;
        return r;
    }
    QSerialPort plc;
    plc.setPortName(hub.paths().at(0));
    if (!plc.open(QIODevice::ReadWrite)) {
        r.error = plc.errorString();
        return r;
    }
    qint64 heardAt = -1;
    QElapsedTimer wall;
    wall.start();
    QObject::connect(&listener, &LineListener::frameHeard, &listener,
                     [&] { heardAt = wall.nsecsElapsed(); });
    double sum = 0;
    const QByteArray request = frame("0103006B0004");
    for (int i = 0; i < delaySamples; ++i) {
        heardAt = -1;
        const qint64 sentAt = wall.nsecsElapsed();
        plc.write(request);
        plc.flush();
        QElapsedTimer wait;
        wait.start();
        while (heardAt < 0 && wait.elapsed() < 2000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        if (heardAt < 0) {
            r.error = QStringLiteral("a frame written was not heard within 2 s");
            return r;
        }
        const double ms = double(heardAt - sentAt) / 1e6;
        sum += ms;
        r.delayMaxMs = std::max(r.delayMaxMs, ms);
        ++r.delaySamples;
        // Past the answer timeout's silence: each request stands alone.
        QElapsedTimer gap;
        gap.start();
        while (gap.elapsed() < 60)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    r.delayMeanMs = r.delaySamples ? sum / r.delaySamples : 0;
    return r;
}

QList<Verdict> listenVerdicts(const ListenResult &r)
{
    if (!r.error.isEmpty())
        return {Verdict{QString::number(kBaud),
                        QStringLiteral("(o) listen beside a PLC"),
                        r.error,
                        {},
                        {},
                        Verdict::Result::Error}};
    // The line carries at most 3840 bytes a second: about 200 frames of a PLC's cycle.
    const double lineFrames = double(r.frames) / r.seconds;
    return {
        Verdict{QString::number(kBaud),
                QStringLiteral("(o) listen: frames decoded per second, a recorded line in "
                               "16-byte packets"),
                QStringLiteral("%1 frames/s (%2 frames, %3 s of the line in %4 ms)")
                    .arg(QString::number(r.framesPerSecond, 'f', 0))
                    .arg(r.frames)
                    .arg(r.seconds)
                    .arg(QString::number(r.decodeMs, 'f', 1)),
                QStringLiteral("> %1 frames/s (10x the line)")
                    .arg(QString::number(lineFrames * 10, 'f', 0)),
                QString::number(lineFrames * 10 / std::max(1.0, r.framesPerSecond), 'f', 3),
                r.framesPerSecond > lineFrames * 10 ? Verdict::Result::Pass
                                                    : Verdict::Result::Fail},
        Verdict{
            QString::number(kBaud),
            QStringLiteral("(o) listen: a frame's last byte to its decoded line (pty)"),
            QStringLiteral("mean %1 ms, max %2 ms (%3 frames)")
                .arg(QString::number(r.delayMeanMs, 'f', 2), QString::number(r.delayMaxMs, 'f', 2))
                .arg(r.delaySamples),
            // Said at the last byte, not at the next silence or tick (20 ms): the mean
            // tells it; the max is the busy machine's scheduling.
            QStringLiteral("mean < 10 ms"), QString::number(r.delayMeanMs / 10.0, 'f', 2),
            r.delayMeanMs < 10 ? Verdict::Result::Pass : Verdict::Result::Fail},
    };
}

} // namespace stepcom::bench

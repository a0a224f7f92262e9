#pragma once

// Session logs for the replay tests, written line by line in SessionLog's format.
#include "bus/rtuframe.h"
#include "map/registermap.h"
#include "session/sessionlog.h"

#include <QFile>
#include <QModbusPdu>
#include <QTemporaryDir>

namespace stepcom::test {

// Writes a session log as StepCom does, with a clock the test moves.
struct LogBuilder
{
    QDateTime time = QDateTime(QDate(2026, 11, 24), QTime(22, 10, 0));
    QString text;

    void header(const QString &map = RegisterMap::builtin().identity())
    {
        text += QStringLiteral("# StepCom 0.1.0 session log, part 1: test\n# program: StepCom "
                               "0.1.0\n# map: %1\n# line: transport=rtu port=/dev/null "
                               "baud=9600 parity=none stop=1 id=1\n# ids: 1\n")
                    .arg(map);
    }
    void frame(bool sent, const QByteArray &raw, int advanceMs = 10)
    {
        TrafficEntry e;
        e.time = time;
        e.direction = sent ? TrafficEntry::Direction::Sent : TrafficEntry::Direction::Received;
        e.kind = TrafficEntry::Kind::Read;
        e.bytes = raw;
        e.summary = QStringLiteral("test");
        text += SessionLog::formatLine(e);
        time = time.addMSecs(advanceMs);
    }
    static QByteArray words(const QList<quint16> &values)
    {
        QByteArray b;
        for (const quint16 v : values)
            b.append(char(v >> 8)).append(char(v & 0xFF));
        return b;
    }
    static QByteArray withCrc(QByteArray frame)
    {
        const quint16 crc = RtuFrame::crc(frame);
        return frame.append(char(crc & 0xFF)).append(char(crc >> 8));
    }
    static QByteArray readRequest(int unit, quint16 address, int count)
    {
        return RtuFrame::adu(unit, QModbusRequest(QModbusPdu::ReadHoldingRegisters,
                                                  words({address, quint16(count)})));
    }
    void read(int unit, quint16 address, const QList<quint16> &values)
    {
        frame(true, readRequest(unit, address, int(values.size())));
        frame(false, RtuFrame::adu(unit, QModbusResponse(QModbusPdu::ReadHoldingRegisters,
                                                         QByteArray(1, char(2 * values.size())) +
                                                             words(values))));
    }
    void write(int unit, quint16 address, const QList<quint16> &values)
    {
        const QByteArray head = words({address, quint16(values.size())});
        frame(true,
              RtuFrame::adu(unit, QModbusRequest(QModbusPdu::WriteMultipleRegisters,
                                                 head + char(2 * values.size()) + words(values))));
        frame(false,
              RtuFrame::adu(unit, QModbusResponse(QModbusPdu::WriteMultipleRegisters, head)));
    }
    void coil(int unit, quint16 address, bool answered = true)
    {
        const QByteArray raw = RtuFrame::adu(
            unit, QModbusRequest(QModbusPdu::WriteSingleCoil, words({address, 0xFF00})));
        frame(true, raw);
        if (answered)
            frame(false, raw);
    }
    void mark(const char *kind, const QString &what, int advanceMs = 10)
    {
        text += SessionLog::formatMark(time, kind, what);
        time = time.addMSecs(advanceMs);
    }
    QString save(const QTemporaryDir &dir, const QString &name = QStringLiteral("s.log")) const
    {
        const QString path = dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly))
            return {};
        f.write(text.toUtf8());
        return path;
    }
};

} // namespace stepcom::test

#pragma once

#include <QModbusPdu>
#include <QStringList>

namespace stepcom {

// How one attempt of a transaction ended on the line, as a transport saw it.
struct LinkAnswer
{
    enum class Kind {
        Answer,  // `response` is the answer (it may be an exception)
        Timeout, // nothing acceptable arrived in time
        Failed   // could not be sent (`errorText`)
    };
    Kind kind = Kind::Timeout;
    QModbusResponse response; // the answer's PDU (Qt drops the exception bit: see below)
    int exceptionCode = 0;    // an exception answer's code, else 0
    qint64 roundTripMs = -1;
    int crcErrors = 0;
    // Frames discarded while waiting (stale or foreign answers, garbage), each with why.
    QStringList discarded;
    // The adapter echoes (learnt or set), the request's bytes came back and nothing after.
    bool onlyEcho = false;
    QString errorText;
};

} // namespace stepcom

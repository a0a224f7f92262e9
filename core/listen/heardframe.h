#pragma once

#include <QByteArray>
#include <QtGlobal>

namespace stepcom {

// One whole RTU frame heard on a line StepCom does not drive: its bytes (CRC included) and when
// its last byte arrived (ms on the listener's clock). Whether it is a request or an answer is
// for the pairer to say: an FC05/FC06 answer is a copy of its request.
struct HeardFrame
{
    QByteArray bytes;
    qint64 ms = 0;
};

} // namespace stepcom

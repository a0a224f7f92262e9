#pragma once

#include <QModbusPdu>

namespace stepcom {

// What the device did with one request.
struct SimAnswer
{
    QModbusResponse response; // invalid: no answer at all
    // Device id or baud rate were written: the link follows once this answer is out.
    bool linkChanged = false;
};

} // namespace stepcom

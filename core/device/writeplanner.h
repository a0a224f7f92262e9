#pragma once

#include "bus/request.h"

#include <QList>

namespace stepcom {

struct Parameter;

struct ParameterWrite
{
    const Parameter *parameter = nullptr;
    qint64 raw = 0;
};

// Groups writes into as few requests as the map allows: one FC10 across registers that follow
// each other, split below the per-request limit but never through a 32-bit value; a lone
// 16-bit register goes out as FC06.
class WritePlanner
{
public:
    static QList<Request> plan(QList<ParameterWrite> writes, int maxRegisters,
                               Priority priority = Priority::Command);
};

} // namespace stepcom

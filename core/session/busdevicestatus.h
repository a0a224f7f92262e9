#pragma once

#include <QHash>
#include <QString>

namespace stepcom {

// What is known of one controller on the line that is not in view: its status from the slow
// background poll, and whether it answers.
struct BusDeviceStatus
{
    enum class State { Unknown, Answering, NotAnswering };
    int id = 0;
    State state = State::Unknown;
    QHash<QString, qint64> values; // raw status values by key, from the last good read
    int cycles = 0;                // status reads that went out
    int errors = 0;                // of those, how many failed
    QString lastError;

    static BusDeviceStatus of(int id)
    {
        BusDeviceStatus s;
        s.id = id;
        return s;
    }
};

} // namespace stepcom

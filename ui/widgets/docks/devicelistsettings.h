#pragma once

#include <QHash>
#include <QList>
#include <QString>

namespace stepcom {

class DeviceSession;

// The devices of a line and the names the user gave them, saved with the connection settings
// (QSettings group "connection") and restored when the same line is connected again.
class DeviceListSettings
{
public:
    QString line; // which line they belong to: lineKey() of the session
    QList<int> ids;
    QHash<int, QString> names;

    // "serial:/dev/ttyUSB0", "tcp:192.168.1.20:502": one per line, not per baud. Empty for the
    // built-in simulator, which starts afresh every time: nothing of it is kept.
    static QString lineKey(const DeviceSession &session);
    // What was saved last (empty ids when nothing or something unreadable was saved).
    static DeviceListSettings load();
    void save() const;
    static void clear();
};

} // namespace stepcom

#pragma once

#include <QDir>
#include <QFileInfo>
#include <QString>

namespace stepcom {

// Where the port layer reads the system: sysfs, /dev, /proc and the lock folders (/run/lock,
// /var/lock). "" (the default) is this computer; tests set a folder with sys/, dev/, proc/ and
// run/lock/ below it, and PortHolders, SerialAdapter and PortSurvey all read that fake system.
// Header only: the bus folder has its full count of sources.
class SystemRoot
{
public:
    static void set(const QString &root)
    {
        QString r = root.isEmpty() ? QString() : QDir::cleanPath(QDir(root).absolutePath());
        // Canonical, so a resolved link below it still starts with it.
        const QString canonical = QFileInfo(r).canonicalFilePath();
        if (!canonical.isEmpty())
            r = canonical;
        if (r == QLatin1String("/"))
            r.clear();
        storage() = r;
    }
    static QString root() { return storage(); }
    // `absolute` ("/sys/class/tty") as read here.
    static QString path(const QString &absolute) { return storage() + absolute; }
    // The device behind `port` as the system names it ("/dev/ttyUSB0"): a bare name is below
    // /dev (as Qt opens it), a /dev/serial/by-id link is followed; unchanged when it is not there.
    static QString device(const QString &port)
    {
        const bool bare = !port.startsWith(QLatin1Char('/')) &&
                          !port.startsWith(QLatin1String("./")) &&
                          !port.startsWith(QLatin1String("../"));
        const QString location = bare ? QStringLiteral("/dev/") + port : port;
        const QString &r = storage();
        const QString canonical =
            QFileInfo(location.startsWith(QLatin1Char('/')) ? path(location) : location)
                .canonicalFilePath();
        if (canonical.isEmpty())
            return location;
        if (r.isEmpty())
            return canonical;
        return canonical.startsWith(r + QLatin1Char('/')) ? canonical.mid(r.size()) : location;
    }

private:
    static QString &storage()
    {
        static QString r;
        return r;
    }
};

} // namespace stepcom

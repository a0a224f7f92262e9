#include "widgets/docks/devicelistsettings.h"

#include "session/devicesession.h"
#include "session/idlist.h"
#include "session/parts/sessionconnection.h"

#include <QSettings>

namespace stepcom {

namespace {
const QString kGroup = QStringLiteral("connection");
const QString kLine = QStringLiteral("deviceLine");
const QString kIds = QStringLiteral("deviceIds");
const QString kNames = QStringLiteral("deviceNames");
} // namespace

QString DeviceListSettings::lineKey(const DeviceSession &session)
{
    if (session.connection()->isSimulator())
        return QString();
    const LinkSettings s = session.connection()->settings();
    if (s.transport == LinkSettings::Transport::Rtu)
        return QStringLiteral("serial:%1").arg(s.portName);
    return QStringLiteral("tcp:%1:%2").arg(s.host).arg(s.tcpPort);
}

DeviceListSettings DeviceListSettings::load()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    DeviceListSettings saved;
    saved.line = settings.value(kLine).toString();
    QString error;
    // A list edited by hand into nonsense is ignored, not half-used.
    if (const auto ids = IdList::parse(settings.value(kIds).toString(), &error))
        saved.ids = *ids;
    const QVariantMap names = settings.value(kNames).toMap();
    for (auto it = names.cbegin(); it != names.cend(); ++it) {
        bool ok = false;
        const int id = it.key().toInt(&ok);
        if (ok && saved.ids.contains(id) && !it.value().toString().trimmed().isEmpty())
            saved.names.insert(id, it.value().toString().trimmed());
    }
    return saved;
}

void DeviceListSettings::save() const
{
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue(kLine, line);
    settings.setValue(kIds, IdList::format(ids));
    QVariantMap map;
    for (auto it = names.cbegin(); it != names.cend(); ++it)
        if (ids.contains(it.key()) && !it.value().isEmpty())
            map.insert(QString::number(it.key()), it.value());
    settings.setValue(kNames, map);
}

void DeviceListSettings::clear()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.remove(kLine);
    settings.remove(kIds);
    settings.remove(kNames);
}

} // namespace stepcom

#include "profile/settingsfingerprint.h"

#include "map/registermap.h"
#include "profile/profile.h"

#include <QCryptographicHash>

namespace stepcom {

namespace {

int countSettings(const RegisterMap &map, const QMap<QString, qint64> &values)
{
    int n = 0;
    for (const Parameter *p : Profile::profileParameters(map, false))
        n += values.contains(p->key) ? 1 : 0;
    return n;
}

} // namespace

QMap<QString, qint64> SettingsFingerprint::ordered(const QHash<QString, qint64> &values)
{
    QMap<QString, qint64> out;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        out.insert(it.key(), it.value());
    return out;
}

QString SettingsFingerprint::canonicalText(const RegisterMap &map,
                                           const QMap<QString, qint64> &values)
{
    QString text = QStringLiteral("stepcom-settings 1\nmap=%1\n").arg(map.identity());
    for (auto it = values.cbegin(); it != values.cend(); ++it) { // QMap: key order
        const Parameter *p = map.find(it.key());
        if (!p || !p->writable() || Profile::isLinkSetting(p->key))
            continue;
        text += it.key() + QLatin1Char('=') + p->formatRaw(it.value()) + QLatin1Char('\n');
    }
    return text;
}

QString SettingsFingerprint::hash(const RegisterMap &map, const QMap<QString, qint64> &values)
{
    return QString::fromLatin1(
        QCryptographicHash::hash(canonicalText(map, values).toUtf8(), QCryptographicHash::Sha256)
            .toHex());
}

QString SettingsFingerprint::shortHash(const RegisterMap &map, const QMap<QString, qint64> &values)
{
    const QString h = hash(map, values).left(16);
    return QStringLiteral("%1-%2-%3-%4").arg(h.mid(0, 4), h.mid(4, 4), h.mid(8, 4), h.mid(12, 4));
}

QString SettingsFingerprint::line(const RegisterMap &map, const QMap<QString, qint64> &values)
{
    // Numbers and the identity only: the same line in every language, comparable by eye.
    return QStringLiteral("%1 · %2 · %3")
        .arg(map.identity())
        .arg(countSettings(map, values))
        .arg(shortHash(map, values));
}

} // namespace stepcom

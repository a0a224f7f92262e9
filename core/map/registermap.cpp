#include "map/registermap.h"

#include "map/registermaploader.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace stepcom {

const RegisterMap &RegisterMap::builtin()
{
    static const RegisterMap map = [] {
        QFile file(QStringLiteral(":/maps/controller.json"));
        QStringList errors;
        std::optional<RegisterMap> loaded;
        if (file.open(QIODevice::ReadOnly))
            loaded = fromJson(file.readAll(), &errors);
        else
            errors << QStringLiteral("the built-in map resource is missing");
        // A broken built-in map is a build defect, never a user error.
        if (!loaded)
            qFatal("built-in register map invalid: %s", qPrintable(errors.join(QLatin1Char('\n'))));
        return *loaded;
    }();
    return map;
}

std::optional<RegisterMap> RegisterMap::loadFile(const QString &path, QStringList *errors)
{
    // Checked before reading: /dev/zero or a huge file would be read until memory runs out.
    const QFileInfo info(path);
    if (info.exists() && !info.isFile()) {
        if (errors)
            *errors << QCoreApplication::translate("stepcom::RegisterMap",
                                                   "%1: not a register map file (not a regular "
                                                   "file)")
                           .arg(path);
        return std::nullopt;
    }
    if (info.size() > kMaxFileBytes) {
        if (errors)
            *errors << QCoreApplication::translate("stepcom::RegisterMap",
                                                   "%1: %2 bytes is too large for a register map "
                                                   "(at most %3 MiB)")
                           .arg(path)
                           .arg(info.size())
                           .arg(kMaxFileBytes / (1024 * 1024));
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (errors)
            *errors << QStringLiteral("%1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    QStringList found;
    auto map = fromJson(file.read(kMaxFileBytes + 1), &found);
    if (errors) {
        for (const QString &e : std::as_const(found))
            *errors << QStringLiteral("%1: %2").arg(path, e);
    }
    return map;
}

std::optional<RegisterMap> RegisterMap::fromJson(const QByteArray &json, QStringList *errors)
{
    return RegisterMapLoader::load(json, errors);
}

const Parameter *RegisterMap::find(const QString &key) const
{
    const auto it = m_byKey.constFind(key);
    return it == m_byKey.cend() ? nullptr : &m_params.at(*it);
}

const Parameter *RegisterMap::holdingAt(quint16 address) const
{
    const auto it = m_holdingByAddress.constFind(address);
    return it == m_holdingByAddress.cend() ? nullptr : &m_params.at(*it);
}

const Parameter *RegisterMap::coilAt(quint16 address) const
{
    const auto it = m_coilByAddress.constFind(address);
    return it == m_coilByAddress.cend() ? nullptr : &m_params.at(*it);
}

QList<const Parameter *> RegisterMap::holdings() const
{
    QList<const Parameter *> out;
    for (const Parameter &p : m_params) {
        if (p.isHolding())
            out << &p;
    }
    return out;
}

QList<const Parameter *> RegisterMap::coils() const
{
    QList<const Parameter *> out;
    for (const Parameter &p : m_params) {
        if (p.isCoil())
            out << &p;
    }
    return out;
}

QList<const Parameter *> RegisterMap::inGroup(const QString &groupId) const
{
    QList<const Parameter *> out;
    for (const Parameter &p : m_params) {
        if (p.group == groupId)
            out << &p;
    }
    return out;
}

const Parameter *RegisterMap::blockParameter(const QString &prefix, int n,
                                             const QString &localKey) const
{
    return find(prefix + QString::number(n) + QLatin1Char('.') + localKey);
}

const ParameterGroup *RegisterMap::group(const QString &groupId) const
{
    for (const ParameterGroup &g : m_groups) {
        if (g.id == groupId)
            return &g;
    }
    return nullptr;
}

} // namespace stepcom

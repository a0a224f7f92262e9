#pragma once

#include "map/parameter.h"

#include <QHash>
#include <QStringList>

#include <optional>

namespace stepcom {

// The motors' block: its parameters are "motor1.speed", "motor2.speed", ...
inline const QString kMotorBlock = QStringLiteral("motor");

struct ParameterGroup
{
    QString id;
    LocalizedText label;
};

// The controller's registers and coils, loaded from JSON (see docs/register-map.md) and
// validated; immutable once loaded and cheap to copy.
class RegisterMap
{
public:
    RegisterMap() = default;

    // The map compiled into StepCom (resources/maps/controller.json).
    static const RegisterMap &builtin();
    // Load and validate; on failure nullopt and one message per problem, each naming the
    // entry and the field.
    // A map file larger than this is refused before it is read.
    static constexpr qint64 kMaxFileBytes = 4 * 1024 * 1024;
    static std::optional<RegisterMap> loadFile(const QString &path, QStringList *errors);
    static std::optional<RegisterMap> fromJson(const QByteArray &json, QStringList *errors);

    bool isValid() const { return !m_params.isEmpty(); }
    QString id() const { return m_id; }
    int version() const { return m_version; }
    // "id/version": what profiles record to tell maps apart.
    QString identity() const { return m_id + QLatin1Char('/') + QString::number(m_version); }
    LocalizedText name() const { return m_name; }
    int maxRegistersPerRequest() const { return m_maxRegisters; }
    int answerDelayMs() const { return m_answerDelayMs; }

    const QList<Parameter> &parameters() const { return m_params; }
    const QList<ParameterGroup> &groups() const { return m_groups; }
    const Parameter *find(const QString &key) const;
    // The holding parameter that covers a protocol address, or nullptr.
    const Parameter *holdingAt(quint16 address) const;
    const Parameter *coilAt(quint16 address) const;
    QList<const Parameter *> holdings() const;
    QList<const Parameter *> coils() const;
    QList<const Parameter *> inGroup(const QString &group) const;
    // Number of instances of a block ("motor" -> 2), 0 when there is none.
    int blockCount(const QString &prefix) const { return m_blockCounts.value(prefix); }
    // The parameter `localKey` of instance n of a block: ("motor", 2, "speed") -> motor2.speed.
    const Parameter *blockParameter(const QString &prefix, int n, const QString &localKey) const;
    const ParameterGroup *group(const QString &id) const;

private:
    QString m_id;
    int m_version = 0;
    LocalizedText m_name;
    int m_maxRegisters = 49;
    int m_answerDelayMs = 35;
    QList<Parameter> m_params;
    QList<ParameterGroup> m_groups;
    QHash<QString, int> m_byKey;
    QHash<quint16, int> m_holdingByAddress; // every covered address
    QHash<quint16, int> m_coilByAddress;
    QHash<QString, int> m_blockCounts;

    friend class RegisterMapLoader;
};

} // namespace stepcom

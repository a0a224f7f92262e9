#pragma once

#include "map/registermap.h"

#include <QJsonObject>

namespace stepcom {

// Turns map JSON into a RegisterMap, collecting every problem rather than stopping at the first,
// so whoever edits a map sees all mistakes at once.
class RegisterMapLoader
{
public:
    static std::optional<RegisterMap> load(const QByteArray &json, QStringList *errors);

private:
    explicit RegisterMapLoader(QStringList *errors)
        : m_errors(errors)
    {}

    bool loadTop(const QJsonObject &top);
    void loadGroups(const QJsonValue &value);
    void loadEnums(const QJsonValue &value);
    void loadBlock(const QJsonObject &block, int index);
    void loadEntry(const QJsonObject &entry, const QString &where, const QString &prefix, int n,
                   int count);
    void index();

    std::optional<LocalizedText> text(const QJsonObject &o, const QString &field,
                                      const QString &where, bool required, int n = 0);
    void unknownFields(const QJsonObject &o, const QStringList &allowed, const QString &where);
    void error(const QString &where, const QString &field, const QString &message);

    QStringList *m_errors;
    int m_errorCount = 0;
    RegisterMap m_map;
    QHash<QString, QList<EnumValue>> m_enums;
};

} // namespace stepcom

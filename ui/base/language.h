#pragma once

#include "i18n/translators.h"

#include <QObject>

namespace stepcom {

// Which language the window speaks, switchable at run time: installs StepCom's and Qt's own
// translators, and every widget retranslates on QEvent::LanguageChange.
class Language : public QObject
{
    Q_OBJECT
public:
    static Language &instance();
    // "en" or "zh_CN".
    QString current() const { return m_current; }
    static QStringList available() { return Translators::available(); }
    // The language's own name, for menus ("English", "简体中文").
    static QString nativeName(const QString &language);
    // Follow the system locale (Translators::systemLanguage()).
    static QString systemDefault();
    bool setLanguage(const QString &language);

Q_SIGNALS:
    void changed(const QString &language);

private:
    Language() = default;
    Translators m_translators;
    QString m_current = QStringLiteral("en");
};

} // namespace stepcom

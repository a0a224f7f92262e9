#pragma once

#include <QObject>
#include <QTranslator>

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
    static QStringList available() { return {QStringLiteral("en"), QStringLiteral("zh_CN")}; }
    // The language's own name, for menus ("English", "简体中文").
    static QString nativeName(const QString &language);
    // Follow the system locale (Chinese locales get Chinese, everything else English).
    static QString systemDefault();
    bool setLanguage(const QString &language);

Q_SIGNALS:
    void changed(const QString &language);

private:
    Language() = default;
    QTranslator m_app;
    QTranslator m_qt;
    QString m_current = QStringLiteral("en");
};

} // namespace stepcom

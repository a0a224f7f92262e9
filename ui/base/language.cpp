#include "base/language.h"

#include <QCoreApplication>
#include <QEvent>
#include <QLocale>

namespace stepcom {

Language &Language::instance()
{
    static Language language;
    return language;
}

QString Language::nativeName(const QString &language)
{
    return language == QLatin1String("zh_CN") ? QStringLiteral("简体中文")
                                              : QStringLiteral("English");
}

QString Language::systemDefault()
{
    return Translators::systemLanguage();
}

bool Language::setLanguage(const QString &language)
{
    if (!available().contains(language))
        return false;
    const bool loaded = m_translators.install(language);
    m_current = language;
    QLocale::setDefault(QLocale(language));
    // Qt posts LanguageChange; deliver it now so the whole window speaks the new language
    // as soon as this returns (and map texts, read from current(), agree with tr() texts).
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    Q_EMIT changed(language);
    return loaded;
}

} // namespace stepcom

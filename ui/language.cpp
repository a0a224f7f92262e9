#include "language.h"

#include <QCoreApplication>
#include <QEvent>
#include <QLibraryInfo>
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
    return QLocale::system().language() == QLocale::Chinese ? QStringLiteral("zh_CN")
                                                            : QStringLiteral("en");
}

bool Language::setLanguage(const QString &language)
{
    if (!available().contains(language))
        return false;
    QCoreApplication::removeTranslator(&m_app);
    QCoreApplication::removeTranslator(&m_qt);
    // The .qm files are compiled into the binary (qt_add_translations), under :/i18n.
    const bool loaded = m_app.load(QStringLiteral(":/i18n/stepcom_%1.qm").arg(language));
    if (loaded)
        QCoreApplication::installTranslator(&m_app);
    if (m_qt.load(QLocale(language), QStringLiteral("qtbase"), QStringLiteral("_"),
                  QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&m_qt);
    m_current = language;
    QLocale::setDefault(QLocale(language));
    // Qt posts LanguageChange; deliver it now so the whole window speaks the new language
    // as soon as this returns (and map texts, read from current(), agree with tr() texts).
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    Q_EMIT changed(language);
    return loaded || language == QLatin1String("en");
}

} // namespace stepcom

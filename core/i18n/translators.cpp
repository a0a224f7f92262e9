#include "translators.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>

namespace stepcom {

QString Translators::s_current = QStringLiteral("en");

Translators::~Translators()
{
    uninstall();
}

QStringList Translators::available()
{
    return {QStringLiteral("en"), QStringLiteral("zh_CN")};
}

QString Translators::systemLanguage()
{
    // uiLanguages() honours LANGUAGE (a list such as "zh_CN:en") before LC_ALL/LC_MESSAGES/LANG.
    const QStringList wanted = QLocale::system().uiLanguages();
    for (const QString &language : wanted) {
        if (language.startsWith(QLatin1String("zh")))
            return QStringLiteral("zh_CN");
        if (language.startsWith(QLatin1String("en")))
            return QStringLiteral("en");
    }
    return QLocale::system().language() == QLocale::Chinese ? QStringLiteral("zh_CN")
                                                            : QStringLiteral("en");
}

QCommandLineOption Translators::languageOption()
{
    return QCommandLineOption(
        QStringLiteral("lang"),
        QCoreApplication::translate("stepcom::Translators",
                                    "Language of the program: en or zh_CN (default: the "
                                    "system's, from LANGUAGE, LC_ALL, LC_MESSAGES or LANG)."),
        QCoreApplication::translate("stepcom::Translators", "language"));
}

QString Translators::languageFromArguments(const QStringList &arguments)
{
    // Only --lang is known here; the program's own parser reports every other option later.
    QCommandLineParser parser;
    const QCommandLineOption lang(QStringLiteral("lang"), QString(), QStringLiteral("language"));
    parser.addOption(lang);
    parser.parse(arguments);
    return parser.isSet(lang) ? parser.value(lang) : systemLanguage();
}

QString Translators::unknownLanguageMessage(const QString &language)
{
    return QCoreApplication::translate("stepcom::Translators", "unknown language '%1' (known: %2)")
        .arg(language, available().join(QLatin1String(", ")));
}

bool Translators::install(const QString &language)
{
    if (!available().contains(language))
        return false;
    uninstall();
    // StepCom's .qm files are compiled into the program (qt_add_translations), under :/i18n;
    // there is no English catalogue to miss: the sources are English.
    const bool loaded = m_app.load(QStringLiteral(":/i18n/stepcom_%1.qm").arg(language));
    if (loaded)
        QCoreApplication::installTranslator(&m_app);
    if (m_qt.load(QLocale(language), QStringLiteral("qtbase"), QStringLiteral("_"),
                  QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&m_qt);
    m_installed = true;
    s_current = language;
    return loaded || language == QLatin1String("en");
}

QString Translators::current()
{
    return s_current;
}

QString Translators::joinList(const QStringList &items)
{
    return items.join(
        QCoreApplication::translate("stepcom::Translators", ", ", "between the items of a list"));
}

void Translators::uninstall()
{
    m_installed = m_installed && QCoreApplication::instance(); // none left at static exit
    if (!m_installed)
        return;
    QCoreApplication::removeTranslator(&m_app);
    QCoreApplication::removeTranslator(&m_qt);
    m_installed = false;
    s_current = QStringLiteral("en");
}

} // namespace stepcom

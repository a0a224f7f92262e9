#pragma once

#include <QCommandLineOption>
#include <QStringList>
#include <QTranslator>

namespace stepcom {

// StepCom's own translator and Qt's (qtbase: QCommandLineParser's "Usage:", "Options:",
// "--help", standard dialogs) for one language. The window (Language) and the command-line
// programs all pick and install their language here, so they always speak the same one.
class Translators
{
public:
    Translators() = default;
    ~Translators();
    Translators(const Translators &) = delete;
    Translators &operator=(const Translators &) = delete;

    // "en" and "zh_CN".
    static QStringList available();
    // The language the environment asks for: the first of the user's UI languages
    // (LANGUAGE, then LC_ALL / LC_MESSAGES / LANG on Unix) that StepCom speaks; English when
    // none is Chinese or English.
    static QString systemLanguage();

    // --lang LANGUAGE, with its translated description (call after install()).
    static QCommandLineOption languageOption();
    // The value of --lang in arguments (a program's raw arguments, before its own parser
    // has run), else systemLanguage().
    static QString languageFromArguments(const QStringList &arguments);
    // "unknown language 'xx' (known: en, zh_CN)".
    static QString unknownLanguageMessage(const QString &language);

    // Replaces what this object installed before with the translators of language.
    // False for a language not in available() (nothing is changed then) or when StepCom's
    // compiled-in catalogue for it is missing. Qt's own catalogue is optional (it comes
    // from the Qt installation; without it Qt's few texts stay English).
    bool install(const QString &language);
    void uninstall();
    // The language installed last ("en" when none): for texts the map carries in both
    // languages (parameter labels), so they match the translated messages around them.
    static QString current();
    // Items of a list in the installed language: "a, b, c" in English, "a、b、c" in Chinese.
    static QString joinList(const QStringList &items);

private:
    QTranslator m_app;
    QTranslator m_qt;
    bool m_installed = false;
    static QString s_current;
};

} // namespace stepcom

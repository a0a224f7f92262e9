#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <functional>

namespace stepcom {

class DeviceSession;

// What the phone's page shows, built from the session: the status message (both motors'
// positions as the window writes them, the motion state, referenced or not, the inputs and
// outputs, the link, the device in view) and the page's own words in the browser's language
// (from StepCom's translations, so the .ts files hold them). A value not known is null, which
// the page shows as "—", never a guess.
class PendantPage
{
public:
    // "zh_CN" when the browser's Accept-Language (or navigator.language) asks for Chinese first,
    // else "en".
    static QString languageOf(const QByteArray &acceptLanguage);
    // {"t":"status", "link": ..., "device": {...}, "motors": [...], "inputs": [...], ...}
    static QJsonObject status(const DeviceSession &session, const QString &language,
                              const std::function<QString(int)> &namer);
    // The page's words, {"E-STOP": "急停", ...} keyed by a short name, in `language`.
    static QByteArray strings(const QString &language);
    // One of the page's words (the accessible names the browser test looks for, the dialog).
    static QString text(const char *source, const QString &language);
};

} // namespace stepcom

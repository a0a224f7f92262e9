#include "pendant/pendantpage.h"

#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTranslator>

#include <memory>

namespace stepcom {

namespace {

const char *const kContext = "stepcom::PendantPage";

// The page's words: the key the page's script uses, then the English source text.
struct Word
{
    const char *key;
    const char *source;
};

const Word kWords[] = {
    {"title", QT_TRANSLATE_NOOP("stepcom::PendantPage", "StepCom pendant")},
    {"m1pos", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 1 position")},
    {"m2pos", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 2 position")},
    {"m1fwd", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 1 forward")},
    {"m1rev", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 1 reverse")},
    {"m2fwd", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 2 forward")},
    {"m2rev", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 2 reverse")},
    {"motor1", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 1")},
    {"motor2", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor 2")},
    {"estop", QT_TRANSLATE_NOOP("stepcom::PendantPage", "E-STOP")},
    {"take", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Take control")},
    {"giveBack", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Give up control")},
    {"youHold",
     QT_TRANSLATE_NOOP("stepcom::PendantPage", "You hold control: hold a button to jog")},
    {"otherHolds", QT_TRANSLATE_NOOP("stepcom::PendantPage", "%1 holds control")},
    {"watchOnly", QT_TRANSLATE_NOOP("stepcom::PendantPage",
                                    "Watching only: jogging is not allowed in the window")},
    {"mayTake",
     QT_TRANSLATE_NOOP("stepcom::PendantPage", "Jogging is allowed: take control to jog")},
    {"idle", QT_TRANSLATE_NOOP("stepcom::PendantPage", "idle")},
    {"running", QT_TRANSLATE_NOOP("stepcom::PendantPage", "running")},
    {"atLimit", QT_TRANSLATE_NOOP("stepcom::PendantPage", "at a limit")},
    {"referenced", QT_TRANSLATE_NOOP("stepcom::PendantPage", "referenced")},
    {"notReferenced", QT_TRANSLATE_NOOP("stepcom::PendantPage", "not referenced")},
    {"inputs", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Inputs")},
    {"outputs", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Outputs")},
    {"link", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Link")},
    {"closed", QT_TRANSLATE_NOOP("stepcom::PendantPage", "port closed")},
    {"asking", QT_TRANSLATE_NOOP("stepcom::PendantPage", "asking…")},
    {"notAnswering", QT_TRANSLATE_NOOP("stepcom::PendantPage", "not answering")},
    {"answering", QT_TRANSLATE_NOOP("stepcom::PendantPage", "answering")},
    {"device", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Device %1")},
    {"deviceNamed", QT_TRANSLATE_NOOP("stepcom::PendantPage", "%1 (id %2)")},
    {"noData", QT_TRANSLATE_NOOP("stepcom::PendantPage", "no data")},
    {"age", QT_TRANSLATE_NOOP("stepcom::PendantPage", "updated %1 s ago")},
    {"step", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Step")},
    {"stepMinus", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor %1 step −")},
    {"stepPlus", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Motor %1 step +")},
    {"ended", QT_TRANSLATE_NOOP("stepcom::PendantPage", "The pendant was stopped in StepCom")},
    {"dropped", QT_TRANSLATE_NOOP("stepcom::PendantPage", "StepCom disconnected this phone")},
    {"lost", QT_TRANSLATE_NOOP("stepcom::PendantPage", "Connection lost: reload the page")},
    {"safety", QT_TRANSLATE_NOOP("stepcom::PendantPage",
                                 "This phone is no safety device: the machine's own E-STOP is.")},
};

// One translator per language for the life of the program (the page asks often).
QTranslator *translatorFor(const QString &language)
{
    static std::unique_ptr<QTranslator> zh;
    if (language != QLatin1String("zh_CN"))
        return nullptr;
    if (!zh) {
        zh = std::make_unique<QTranslator>();
        if (!zh->load(QStringLiteral(":/i18n/stepcom_zh_CN.qm")))
            return nullptr;
    }
    return zh.get();
}

QJsonValue optional(std::optional<qint64> v)
{
    return v ? QJsonValue(*v != 0) : QJsonValue(QJsonValue::Null);
}

QString linkCode(LinkHealth::State state)
{
    switch (state) {
    case LinkHealth::State::Closed:
        return QStringLiteral("closed");
    case LinkHealth::State::Opening:
    case LinkHealth::State::Asking:
        return QStringLiteral("asking");
    case LinkHealth::State::NotAnswering:
        return QStringLiteral("notAnswering");
    case LinkHealth::State::Answering:
        return QStringLiteral("answering");
    }
    return QStringLiteral("closed");
}

} // namespace

QString PendantPage::languageOf(const QByteArray &acceptLanguage)
{
    // The first language the browser names decides: "zh-CN,zh;q=0.9,en;q=0.8".
    const QByteArray first = acceptLanguage.split(',').value(0).trimmed().toLower();
    return first.startsWith("zh") ? QStringLiteral("zh_CN") : QStringLiteral("en");
}

QString PendantPage::text(const char *source, const QString &language)
{
    if (QTranslator *t = translatorFor(language)) {
        const QString s = t->translate(kContext, source);
        if (!s.isEmpty())
            return s;
    }
    return QString::fromUtf8(source);
}

QByteArray PendantPage::strings(const QString &language)
{
    QJsonObject o;
    for (const Word &w : kWords)
        o.insert(QLatin1String(w.key), text(w.source, language));
    o.insert(QStringLiteral("lang"),
             language == QLatin1String("zh_CN") ? QStringLiteral("zh-CN") : QStringLiteral("en"));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QJsonObject PendantPage::status(const DeviceSession &session, const QString &language,
                                const std::function<QString(int)> &namer)
{
    const RegisterMap &map = session.map();
    const ParameterStore *store = session.parameters()->store();
    const bool connected = session.connection()->isConnected();
    const ReferenceTracker *references = session.motion()->references();
    const auto value = [&](const QString &key) {
        return connected ? store->deviceValue(key) : std::nullopt;
    };
    QJsonArray motors;
    const int count = map.blockCount(QStringLiteral("motor"));
    for (int n = 1; n <= count; ++n) {
        const Parameter *pos =
            map.blockParameter(QStringLiteral("motor"), n, QStringLiteral("position"));
        const Parameter *run =
            map.blockParameter(QStringLiteral("motor"), n, QStringLiteral("running"));
        QJsonObject m;
        m.insert(QStringLiteral("n"), n);
        const auto raw = pos ? value(pos->key) : std::nullopt;
        m.insert(QStringLiteral("position"),
                 raw ? QJsonValue(pos->displayRaw(*raw, language)) : QJsonValue(QJsonValue::Null));
        const auto running = run ? value(run->key) : std::nullopt;
        QString state;
        if (running && *running) {
            state = QStringLiteral("running");
        } else if (running) {
            state = QStringLiteral("idle");
            // Stopped with one of its limit inputs on: it stands at that limit (as the strip).
            for (const char *role : {"limit_positive", "limit_negative"}) {
                const Parameter *p =
                    map.blockParameter(QStringLiteral("motor"), n, QLatin1String(role));
                const auto input = p ? value(p->key) : std::nullopt;
                if (input && *input > 0 &&
                    value(QStringLiteral("io.in%1").arg(*input)).value_or(0) != 0)
                    state = QStringLiteral("atLimit");
            }
        }
        m.insert(QStringLiteral("state"), state.isEmpty() ? QJsonValue(QJsonValue::Null) : state);
        m.insert(QStringLiteral("referenced"), references->isReferenced(n));
        motors.append(m);
    }
    const auto lamps = [&](const char *pattern) {
        QJsonArray a;
        for (int n = 1; map.find(QString::fromLatin1(pattern).arg(n)); ++n)
            a.append(optional(value(QString::fromLatin1(pattern).arg(n))));
        return a;
    };
    const int id = session.line()->deviceInView();
    QJsonObject device{{QStringLiteral("id"), id}};
    if (const QString name = namer ? namer(id) : QString(); !name.isEmpty())
        device.insert(QStringLiteral("name"), name);
    return QJsonObject{{QStringLiteral("t"), QStringLiteral("status")},
                       {QStringLiteral("link"), linkCode(session.connection()->health()->state())},
                       {QStringLiteral("device"), device},
                       {QStringLiteral("motors"), motors},
                       {QStringLiteral("inputs"), lamps("io.in%1")},
                       {QStringLiteral("outputs"), lamps("io.out%1")}};
}

} // namespace stepcom

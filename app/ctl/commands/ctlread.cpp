// stepcomctl params and read: the map's parameters, and what the controller holds.
#include "../ctlcontext.h"
#include "ctlcommands.h"
#include "session/parts/sessionparameters.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace stepcom {

namespace {

QString accessName(const Parameter &p)
{
    switch (p.access) {
    case Access::ReadOnly:
        return QStringLiteral("r");
    case Access::ReadWrite:
        return QStringLiteral("rw");
    case Access::Command:
        return QStringLiteral("w");
    }
    return {};
}

QString commandName(CommandClass c)
{
    switch (c) {
    case CommandClass::Emergency:
        return QStringLiteral("emergency");
    case CommandClass::Motion:
        return QStringLiteral("motion");
    case CommandClass::Output:
        return QStringLiteral("output");
    case CommandClass::Setting:
        return QStringLiteral("setting");
    case CommandClass::Destructive:
        return QStringLiteral("destructive");
    case CommandClass::None:
        break;
    }
    return {};
}

} // namespace

void runParams(CtlContext &ctx)
{
    if (ctx.options.json) {
        QJsonArray array;
        for (const Parameter &p : ctx.map.parameters()) {
            QJsonObject o{{QStringLiteral("key"), p.key},
                          {QStringLiteral("kind"),
                           p.isHolding() ? QStringLiteral("holding") : QStringLiteral("coil")},
                          {QStringLiteral("plc"), p.plc},
                          {QStringLiteral("address"), p.address},
                          {QStringLiteral("words"), p.isHolding() ? p.words : 1},
                          {QStringLiteral("signed"), p.isSigned},
                          {QStringLiteral("scale"), p.scale},
                          {QStringLiteral("unit"), p.unit},
                          {QStringLiteral("access"), accessName(p)},
                          {QStringLiteral("group"), p.group},
                          {QStringLiteral("label"), p.label.en},
                          {QStringLiteral("label_zh_CN"), p.label.zh},
                          {QStringLiteral("help"), p.help.en}};
            if (p.isHolding()) {
                o.insert(QStringLiteral("min"), CtlContext::jsonValue(p, p.rawMin));
                o.insert(QStringLiteral("max"), CtlContext::jsonValue(p, p.rawMax));
                if (!p.values.isEmpty()) {
                    QJsonArray values;
                    for (const EnumValue &v : p.values)
                        values.append(QJsonObject{{QStringLiteral("value"), double(v.value)},
                                                  {QStringLiteral("label"), v.label.en}});
                    o.insert(QStringLiteral("values"), values);
                }
            } else {
                o.insert(QStringLiteral("min"), QJsonValue());
                o.insert(QStringLiteral("max"), QJsonValue());
                o.insert(QStringLiteral("command"), commandName(p.command));
            }
            array.append(o);
        }
        ctx.out << QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Indented));
    } else {
        for (const Parameter &p : ctx.map.parameters()) {
            const QString range = p.isHolding() ? p.rangeText() : commandName(p.command);
            ctx.out << QStringLiteral("%1  %2  %3  %4  %5")
                           .arg(p.key, -26)
                           .arg(p.registerName(), -15)
                           .arg(accessName(p), -2)
                           .arg(p.label.en, -32)
                           .arg(range)
                    << Qt::endl;
        }
    }
    ctx.finish(CtlRunner::Ok);
}

void runRead(CtlContext &ctx)
{
    QList<const Parameter *> params;
    for (const QString &key : std::as_const(ctx.options.arguments)) {
        const Parameter *p = ctx.map.find(key);
        if (!p) {
            ctx.fail(CtlRunner::UsageError,
                     CtlRunner::tr("unknown parameter '%1' (see: stepcomctl params)").arg(key));
            return;
        }
        if (!p->readable()) {
            ctx.fail(CtlRunner::UsageError,
                     CtlRunner::tr("%1 is a command and cannot be read").arg(key));
            return;
        }
        params << p;
    }
    if (params.isEmpty())
        params = ctx.map.holdings();
    ctx.connectThen([&ctx, params] {
        ctx.session->parameters()->read(params, [&ctx, params](const ReadOutcome &r) {
            if (ctx.options.json) {
                QJsonObject o;
                for (const Parameter *p : params) {
                    if (r.values.contains(p->key))
                        o.insert(p->key, CtlContext::jsonValue(*p, r.values.value(p->key)));
                }
                ctx.out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Indented));
            } else {
                for (const Parameter *p : params) {
                    if (r.values.contains(p->key))
                        ctx.out << p->key << QStringLiteral(" = ")
                                << ctx.valueText(*p, r.values.value(p->key)) << Qt::endl;
                }
            }
            for (const QString &key : r.unsupported)
                ctx.err << QStringLiteral("stepcomctl: ")
                        << CtlRunner::tr("%1 is not supported by this controller").arg(key)
                        << Qt::endl;
            if (!r.ok) {
                for (const QString &e : CtlContext::condensed(r.errors))
                    ctx.err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
                ctx.finish(CtlRunner::DeviceError);
                return;
            }
            ctx.finish(CtlRunner::Ok);
        });
    });
}

} // namespace stepcom

// stepcomctl ports: the computer's serial ports, before any controller is reached.
#include "../ctlcontext.h"
#include "ctlcommands.h"

#include "line/portsurvey.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace stepcom {

void runPorts(CtlContext &ctx)
{
    if (!ctx.options.arguments.isEmpty()) {
        ctx.fail(
            CtlRunner::UsageError,
            CtlRunner::tr("ports takes no arguments ('%1')").arg(ctx.options.arguments.first()));
        return;
    }
    // Tests hand in a fake system (sys/, dev/, proc/, run/lock/ under one folder).
    PortSurvey::setSystemRoot(qEnvironmentVariable("STEPCOMCTL_SYSTEM_ROOT"));
    const QList<PortSurvey::Port> ports = PortSurvey::ports();
    const auto hex = [](quint16 id) {
        return QStringLiteral("%1").arg(id, 4, 16, QLatin1Char('0'));
    };
    if (ctx.options.json) {
        QJsonArray array;
        for (const PortSurvey::Port &p : ports) {
            QJsonArray holders;
            for (const PortSurvey::Holder &h : p.holders)
                holders.append(QJsonObject{{QStringLiteral("pid"), double(h.pid)},
                                           {QStringLiteral("program"), h.program},
                                           {QStringLiteral("how"), h.how}});
            const bool usb = p.entry.vendorId || p.entry.productId;
            array.append(QJsonObject{
                {QStringLiteral("path"), p.entry.systemLocation},
                {QStringLiteral("by_id"), p.entry.byId.isEmpty() ? QJsonValue() : p.entry.byId},
                {QStringLiteral("open_with"), p.entry.path()},
                {QStringLiteral("driver"), p.driver},
                {QStringLiteral("vendor_id"),
                 usb ? QJsonValue(hex(p.entry.vendorId)) : QJsonValue()},
                {QStringLiteral("product_id"),
                 usb ? QJsonValue(hex(p.entry.productId)) : QJsonValue()},
                {QStringLiteral("vendor"), p.entry.manufacturer},
                {QStringLiteral("product"), p.entry.description},
                {QStringLiteral("serial_number"), p.entry.serialNumber},
                {QStringLiteral("accessible"), p.accessible},
                {QStringLiteral("held"),
                 p.holdersKnown ? QJsonValue(!p.holders.isEmpty()) : QJsonValue()},
                {QStringLiteral("holders"), holders},
                // Another user's processes cannot be looked into: a holder may be missing.
                {QStringLiteral("holders_complete"), p.holdersKnown && !p.holdersIncomplete}});
        }
        ctx.out << QString::fromUtf8(QJsonDocument(array).toJson(QJsonDocument::Indented));
        ctx.finish(CtlRunner::Ok);
        return;
    }
    if (ports.isEmpty()) {
        ctx.out
            << CtlRunner::tr(
                   "no serial port found: is the USB adapter plugged in? (its driver's messages: "
                   "sudo dmesg | tail)")
            << Qt::endl;
        ctx.finish(CtlRunner::Ok);
        return;
    }
    for (const PortSurvey::Port &p : ports) {
        QStringList adapter;
        if (!p.entry.manufacturer.isEmpty())
            adapter << p.entry.manufacturer;
        if (!p.entry.description.isEmpty())
            adapter << p.entry.description;
        if (p.entry.vendorId || p.entry.productId)
            adapter << hex(p.entry.vendorId) + QLatin1Char(':') + hex(p.entry.productId);
        if (!p.entry.serialNumber.isEmpty())
            adapter << CtlRunner::tr("S/N %1").arg(p.entry.serialNumber);
        if (adapter.isEmpty() && !p.driver.isEmpty())
            adapter << p.driver;
        ctx.out << p.entry.systemLocation << QStringLiteral("  ")
                << adapter.join(QLatin1String(", ")) << QStringLiteral("  ")
                << PortSurvey::holdersText(p) << Qt::endl;
        if (!p.entry.byId.isEmpty())
            ctx.out << QStringLiteral("    ") << CtlRunner::tr("stable name: %1").arg(p.entry.byId)
                    << Qt::endl;
        if (!p.accessible)
            ctx.out << QStringLiteral("    ")
                    << CtlRunner::tr(
                           "no permission to open it: add yourself to its group (ls -l %1; "
                           "usually dialout), then log in again")
                           .arg(p.entry.systemLocation)
                    << Qt::endl;
        ctx.out << QStringLiteral("    ")
                << CtlRunner::tr("open it with: stepcomctl --port %1 read device.id")
                       .arg(p.entry.path())
                << Qt::endl;
    }
    ctx.finish(CtlRunner::Ok);
}

} // namespace stepcom

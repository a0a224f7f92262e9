#include "bus/wiretap.h"

#include <QHash>
#include <QLoggingCategory>
#include <QMutex>
#include <QPointer>
#include <QRegularExpression>

namespace stepcom {

namespace {

struct Registry
{
    QMutex mutex;
    QHash<QObject *, WireTap::Sink> sinks;
    QtMessageHandler previousHandler = nullptr;
    QLoggingCategory::CategoryFilter previousFilter = nullptr;
    bool installed = false;
    bool passThrough = false; // the user asked for qt.modbus output themselves
};

Registry &registry()
{
    static Registry r;
    return r;
}

bool isModbusCategory(const char *name)
{
    return name && qstrncmp(name, "qt.modbus", 9) == 0;
}

void categoryFilter(QLoggingCategory *category)
{
    Registry &r = registry();
    if (r.previousFilter)
        r.previousFilter(category);
    if (isModbusCategory(category->categoryName()))
        category->setEnabled(QtDebugMsg, true);
}

void messageHandler(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    Registry &r = registry();
    if (isModbusCategory(context.category)) {
        WireTap::Frame frame;
        QByteArray raw;
        if (WireTap::parse(message, &frame, &raw)) {
            QList<WireTap::Sink> sinks;
            {
                QMutexLocker lock(&r.mutex);
                sinks = r.sinks.values();
            }
            for (const auto &sink : std::as_const(sinks))
                sink(frame, raw);
        }
        // Qt's own modbus chatter (its warnings about frames on a bad line too) stays quiet
        // unless asked for: StepCom reports what went wrong in its own words.
        Q_UNUSED(type);
        if (!r.passThrough)
            return;
    }
    if (r.previousHandler)
        r.previousHandler(type, context, message);
}

} // namespace

bool WireTap::parse(const QString &message, Frame *frame, QByteArray *raw)
{
    static const QRegularExpression pattern(QStringLiteral(
        R"re(^\((RTU|TCP) [Cc]lient\) (Sent Serial ADU|Received ADU|Sent TCP ADU|Response buffer)[^:]*:\s*"?(?:0x)?([0-9a-fA-F]*)"?)re"));
    const QRegularExpressionMatch m = pattern.match(message);
    if (!m.hasMatch() || m.captured(3).isEmpty())
        return false;
    const bool rtu = m.captured(1) == QLatin1String("RTU");
    const QString what = m.captured(2);
    const bool sent = what.startsWith(QLatin1String("Sent"));
    if (rtu && what == QLatin1String("Response buffer"))
        return false; // partial reads; the complete ADU follows as "Received ADU"
    if (!rtu && !sent && what != QLatin1String("Response buffer"))
        return false; // the TCP client logs what it received as its response buffer
    *frame = rtu ? (sent ? Frame::RtuSent : Frame::RtuReceived)
                 : (sent ? Frame::TcpSent : Frame::TcpReceived);
    *raw = QByteArray::fromHex(m.captured(3).toLatin1());
    return true;
}

void WireTap::install()
{
    Registry &r = registry();
    {
        QMutexLocker lock(&r.mutex);
        if (!r.installed) {
            r.installed = true;
            r.passThrough =
                qEnvironmentVariable("QT_LOGGING_RULES").contains(QLatin1String("qt.modbus"));
            r.previousHandler = qInstallMessageHandler(messageHandler);
        }
    }
}

void WireTap::setPassThrough(bool passThrough)
{
    install();
    Registry &r = registry();
    QMutexLocker lock(&r.mutex);
    r.passThrough = passThrough ||
                    qEnvironmentVariable("QT_LOGGING_RULES").contains(QLatin1String("qt.modbus"));
}

void WireTap::attach(QObject *owner, Sink sink)
{
    install();
    Registry &r = registry();
    {
        QMutexLocker lock(&r.mutex);
        r.sinks.insert(owner, std::move(sink));
    }
    static bool filterInstalled = false;
    if (!filterInstalled) {
        filterInstalled = true;
        r.previousFilter = QLoggingCategory::installFilter(categoryFilter);
    }
}

void WireTap::detach(QObject *owner)
{
    Registry &r = registry();
    QMutexLocker lock(&r.mutex);
    r.sinks.remove(owner);
}

} // namespace stepcom

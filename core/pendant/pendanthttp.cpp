#include "pendant/pendanthttp.h"

#include "pendant/pendantgate.h"
#include "pendant/pendantpage.h"

#include <QFile>
#include <QHttpServerRequest>
#include <QHttpServerResponder>
#include <QTcpSocket>

namespace stepcom {

namespace {

const QByteArray kNoStore = QByteArrayLiteral("no-store");

} // namespace

PendantHttp::PendantHttp(PendantGate *gate, QObject *parent)
    : QAbstractHttpServer(parent)
    , m_gate(gate)
{}

bool PendantHttp::splitPath(const QString &path, QString *token, QString *file)
{
    const QStringList parts = path.split(QLatin1Char('/'));
    // "", "p", TOKEN[, file]
    if (parts.size() < 3 || parts.size() > 4 || !parts.at(0).isEmpty() ||
        parts.at(1) != QLatin1String("p") || parts.at(2).isEmpty())
        return false;
    *token = parts.at(2);
    *file = parts.value(3);
    return true;
}

QString PendantHttp::addressText(const QHostAddress &address)
{
    bool ok = false;
    const quint32 v4 = address.toIPv4Address(&ok);
    return ok ? QHostAddress(v4).toString() : address.toString();
}

bool PendantHttp::handleRequest(const QHttpServerRequest &request, QTcpSocket *socket)
{
    QString token;
    QString file;
    const QString address = addressText(request.remoteAddress());
    // Every request without the token counts as a wrong one, a path of another shape too.
    const bool split = splitPath(request.url().path(), &token, &file);
    const bool admitted = m_gate->admit(address, split ? token : QString());
    const bool upgrade =
        request.value(QByteArrayLiteral("upgrade")).compare("websocket", Qt::CaseInsensitive) == 0;
    if (upgrade) {
        // Qt 6.4 hands the socket to its WebSocket server only when this returns true having
        // written nothing; false makes it answer through missingHandler (403) and close.
        return admitted && file == QLatin1String("ws");
    }
    QHttpServerResponder responder = makeResponder(request, socket);
    if (!admitted || request.method() != QHttpServerRequest::Method::Get) {
        responder.write(QHttpServerResponder::StatusCode::Forbidden);
        return true;
    }
    static const QHash<QString, QPair<QString, QByteArray>> files = {
        {QString(), {QStringLiteral(":/pendant/index.html"), "text/html; charset=utf-8"}},
        {QStringLiteral("pendant.js"),
         {QStringLiteral(":/pendant/pendant.js"), "text/javascript; charset=utf-8"}},
        {QStringLiteral("pendant.css"),
         {QStringLiteral(":/pendant/pendant.css"), "text/css; charset=utf-8"}},
    };
    if (file == QLatin1String("strings.json")) {
        const QString lang =
            PendantPage::languageOf(request.value(QByteArrayLiteral("accept-language")));
        responder.write(
            PendantPage::strings(lang),
            {{"Content-Type", "application/json; charset=utf-8"}, {"Cache-Control", kNoStore}});
        return true;
    }
    const auto it = files.constFind(file);
    QFile f(it == files.cend() ? QString() : it->first);
    if (it == files.cend() || !f.open(QIODevice::ReadOnly)) {
        responder.write(QHttpServerResponder::StatusCode::NotFound);
        return true;
    }
    QByteArray body = f.readAll();
    if (file.isEmpty()) // the page's links carry the token: the page has no other way to know it
        body.replace("%BASE%", QByteArray("/p/") + token.toLatin1() + '/');
    responder.write(body, {{"Content-Type", it->second}, {"Cache-Control", kNoStore}});
    return true;
}

void PendantHttp::missingHandler(const QHttpServerRequest &request, QTcpSocket *socket)
{
    makeResponder(request, socket).write(QHttpServerResponder::StatusCode::Forbidden);
}

} // namespace stepcom

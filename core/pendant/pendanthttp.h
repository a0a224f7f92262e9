#pragma once

#include <QAbstractHttpServer>

namespace stepcom {

class PendantGate;

// The pendant's HTTP side (Qt HttpServer): the page, its script and style from the resources
// (:/pendant, nothing fetched from anywhere) and its words in the browser's language, all under
// /p/TOKEN/. Any request without the token, or from an address refused for guessing, gets 403
// and nothing else, a WebSocket upgrade too; the upgrade at /p/TOKEN/ws goes on to Qt's WebSocket
// server (newWebSocketConnection, PendantServer).
class PendantHttp : public QAbstractHttpServer
{
    Q_OBJECT
public:
    explicit PendantHttp(PendantGate *gate, QObject *parent = nullptr);

    // The token in a path "/p/TOKEN[/file]" and the file after it ("" for the page).
    static bool splitPath(const QString &path, QString *token, QString *file);
    // "::ffff:192.168.1.23" as "192.168.1.23": the address a technician recognises.
    static QString addressText(const QHostAddress &address);

protected:
    bool handleRequest(const QHttpServerRequest &request, QTcpSocket *socket) override;
    void missingHandler(const QHttpServerRequest &request, QTcpSocket *socket) override;

private:
    PendantGate *m_gate;
};

} // namespace stepcom

#pragma once

#include "pendant/pendantgate.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QHostAddress>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QUrl>

#include <functional>
#include <memory>

class QTcpServer;
class QWebSocket;

namespace stepcom {

class DeviceSession;
class PendantControl;
class PendantHttp;

// A phone as the pendant (off until started, never started by itself): one page and a
// WebSocket served from this process (Qt HttpServer, Qt WebSockets). Paired phones get the
// status pushed at the poll's rate (at most 10 a second) and may send the E-STOP; jogging is
// PendantControl's (allowed in the window, one holder, dead-man hold). Everything a phone does
// is said in userAction() for the session log. Headless: the window's dialog and `stepcom
// --pendant` drive it, the tests speak to it with Qt's own WebSocket client.
class PendantServer : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMinPushMs = 100; // at most 10 status updates a second

    struct Client
    {
        int id = 0;
        QString address;
        QString browser;
        QDateTime since;
    };

    explicit PendantServer(DeviceSession *session, QObject *parent = nullptr);
    ~PendantServer() override;

    // Listens on `address`:`port` (0: any free port) with a new token. False and error() when
    // the port cannot be had.
    bool start(const QHostAddress &address, quint16 port);
    // Tells every phone, closes every socket, stops any pendant jog.
    void stop(const QString &why = QString());
    bool isRunning() const { return m_http != nullptr; }
    QString error() const { return m_error; }
    quint16 port() const { return m_port; }
    QString token() const { return m_gate.token(); }
    // http://HOST:PORT/p/TOKEN -- HOST the bound address, or this machine's first network
    // address when bound to all of them.
    QUrl url() const;
    // Parses "[ADDRESS:]PORT" (IPv4, or [IPv6]); false with a message naming what was wrong.
    static bool parseListen(const QString &text, QHostAddress *address, quint16 *port,
                            QString *error);

    PendantControl *control() const { return m_control; }
    QList<Client> clients() const;
    void disconnectClient(int id);
    QString describe(int id) const; // the address of a client, for the window and the log
    // The name the user gave a device of the line, for the page.
    void setDeviceNamer(std::function<QString(int)> namer) { m_namer = std::move(namer); }

Q_SIGNALS:
    void runningChanged(bool running);
    void clientsChanged();
    // "pendant 192.168.1.23: took control" -- for SessionLog::noteUserAction.
    void userAction(const QString &text);

private:
    struct Connection
    {
        Client client;
        std::unique_ptr<QWebSocket> socket;
        QString language = QStringLiteral("en");
    };
    void onNewSocket();
    void onMessage(int id, const QString &text);
    void onClosed(int id);
    void send(int id, const QJsonObject &message);
    void sendControl();
    void schedulePush();
    void push();
    void say(int id, const QString &text);

    QPointer<DeviceSession> m_session;
    PendantControl *m_control;
    PendantGate m_gate;
    PendantHttp *m_http = nullptr;
    QHostAddress m_address;
    quint16 m_port = 0;
    QString m_error;
    std::map<int, Connection> m_connections;
    int m_nextId = 1;
    QTimer m_push;
    QElapsedTimer m_lastPush;
    std::function<QString(int)> m_namer;
};

} // namespace stepcom

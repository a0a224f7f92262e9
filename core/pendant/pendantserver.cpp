#include "pendant/pendantserver.h"

#include "motion/referencetracker.h"
#include "pendant/pendantcontrol.h"
#include "pendant/pendanthttp.h"
#include "pendant/pendantpage.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionstatus.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QNetworkInterface>
#include <QTcpServer>
#include <QWebSocket>

namespace stepcom {

namespace {

// "Chrome on Android": enough to tell two phones apart in the window.
QString browserOf(const QString &ua)
{
    QString browser = ua.contains(QLatin1String("Firefox"))  ? QStringLiteral("Firefox")
                      : ua.contains(QLatin1String("Edg/"))   ? QStringLiteral("Edge")
                      : ua.contains(QLatin1String("Chrom"))  ? QStringLiteral("Chrome")
                      : ua.contains(QLatin1String("Safari")) ? QStringLiteral("Safari")
                                                             : QString();
    const QString os = ua.contains(QLatin1String("Android"))   ? QStringLiteral("Android")
                       : ua.contains(QLatin1String("iPhone"))  ? QStringLiteral("iPhone")
                       : ua.contains(QLatin1String("iPad"))    ? QStringLiteral("iPad")
                       : ua.contains(QLatin1String("Windows")) ? QStringLiteral("Windows")
                       : ua.contains(QLatin1String("Mac OS"))  ? QStringLiteral("macOS")
                       : ua.contains(QLatin1String("Linux"))   ? QStringLiteral("Linux")
                                                               : QString();
    if (browser.isEmpty())
        return ua.left(40);
    return os.isEmpty() ? browser : QStringLiteral("%1, %2").arg(browser, os);
}

// What the page says about why it let go, in the log's words.
QString stopWhy(const QString &code)
{
    if (code == QLatin1String("hidden"))
        return QStringLiteral("page hidden");
    if (code == QLatin1String("blur"))
        return QStringLiteral("page lost focus");
    return QStringLiteral("finger lifted");
}

} // namespace

PendantServer::PendantServer(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_control(new PendantControl(session, this))
{
    m_push.setSingleShot(true);
    connect(&m_push, &QTimer::timeout, this, &PendantServer::push);
    connect(session->status(), &SessionStatus::statusCycleFinished, this,
            &PendantServer::schedulePush);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &PendantServer::schedulePush);
    connect(session->line(), &SessionLine::deviceInViewChanged, this, &PendantServer::schedulePush);
    connect(session->connection()->health(), &LinkHealth::stateChanged, this,
            &PendantServer::schedulePush);
    connect(session->motion()->references(), &ReferenceTracker::changed, this,
            &PendantServer::schedulePush);
    connect(m_control, &PendantControl::allowedChanged, this, [this](bool allowed) {
        Q_EMIT userAction(allowed ? QStringLiteral("pendant: jogging allowed in the window")
                                  : QStringLiteral("pendant: jogging not allowed"));
        sendControl();
    });
    connect(m_control, &PendantControl::holderChanged, this, [this](int client) {
        Q_EMIT userAction(client ? QStringLiteral("pendant %1: took control").arg(describe(client))
                                 : QStringLiteral("pendant: nobody holds control"));
        sendControl();
        Q_EMIT clientsChanged();
    });
    connect(m_control, &PendantControl::jogStarted, this, [this](int client, int motor, bool fwd) {
        Q_EMIT userAction(QStringLiteral("pendant %1: motor %2 jog %3 started")
                              .arg(describe(client))
                              .arg(motor)
                              .arg(fwd ? QStringLiteral("forward") : QStringLiteral("reverse")));
        for (const auto &[id, c] : m_connections)
            send(id, {{QStringLiteral("t"), QStringLiteral("jog")},
                      {QStringLiteral("motor"), motor},
                      {QStringLiteral("jogging"), true}});
    });
    connect(m_control, &PendantControl::jogEnded, this,
            [this](int client, int motor, const QString &why) {
                Q_EMIT userAction(QStringLiteral("pendant %1: motor %2 jog stopped (%3)")
                                      .arg(describe(client))
                                      .arg(motor)
                                      .arg(why));
                for (const auto &[id, c] : m_connections)
                    send(id, {{QStringLiteral("t"), QStringLiteral("jog")},
                              {QStringLiteral("motor"), motor},
                              {QStringLiteral("jogging"), false},
                              {QStringLiteral("why"), why}});
            });
}

PendantServer::~PendantServer()
{
    stop();
}

bool PendantServer::parseListen(const QString &text, QHostAddress *address, quint16 *port,
                                QString *error)
{
    QString host;
    QString portText = text.trimmed();
    const int colon = portText.lastIndexOf(QLatin1Char(':'));
    if (colon >= 0) {
        host = portText.left(colon);
        portText = portText.mid(colon + 1);
        if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
            host = host.mid(1, host.size() - 2);
    }
    bool ok = false;
    const uint p = portText.toUInt(&ok);
    if (!ok || p > 65535) {
        *error =
            tr("'%1' is not [ADDRESS:]PORT: the port must be a number from 0 to 65535").arg(text);
        return false;
    }
    QHostAddress a(QHostAddress::Any);
    if (!host.isEmpty() && !a.setAddress(host)) {
        *error = tr("'%1' is not [ADDRESS:]PORT: '%2' is not an IP address").arg(text, host);
        return false;
    }
    *address = a;
    *port = quint16(p);
    return true;
}

bool PendantServer::start(const QHostAddress &address, quint16 port)
{
    if (isRunning())
        stop();
    m_error.clear();
    auto *tcp = new QTcpServer;
    if (!tcp->listen(address, port)) {
        m_error = tr("The pendant cannot listen on %1 port %2: %3")
                      .arg(address.toString())
                      .arg(port)
                      .arg(tcp->errorString());
        delete tcp;
        return false;
    }
    m_gate.renew(); // a new token at every start: an old QR code pairs nothing
    m_http = new PendantHttp(&m_gate, this);
    tcp->setParent(m_http);
    m_http->bind(tcp);
    connect(m_http, &QAbstractHttpServer::newWebSocketConnection, this,
            &PendantServer::onNewSocket);
    m_address = address;
    m_port = tcp->serverPort();
    Q_EMIT userAction(QStringLiteral("pendant started on port %1").arg(m_port));
    Q_EMIT runningChanged(true);
    return true;
}

void PendantServer::stop(const QString &why)
{
    if (!isRunning())
        return;
    m_control->takeBack();
    m_control->setAllowed(false); // allowed for one run of the pendant only
    for (auto &[id, c] : m_connections) {
        send(id,
             {{QStringLiteral("t"), QStringLiteral("bye")},
              {QStringLiteral("text"),
               why.isEmpty() ? PendantPage::text("The pendant was stopped in StepCom", c.language)
                             : why}});
        c.socket->disconnect(this);
        c.socket->close(QWebSocketProtocol::CloseCodeGoingAway);
        c.socket.release()->deleteLater();
    }
    m_connections.clear();
    delete m_http;
    m_http = nullptr;
    m_push.stop();
    Q_EMIT userAction(QStringLiteral("pendant stopped"));
    Q_EMIT clientsChanged();
    Q_EMIT runningChanged(false);
}

QUrl PendantServer::url() const
{
    if (!isRunning())
        return {};
    QHostAddress host = m_address;
    if (host == QHostAddress(QHostAddress::Any) || host == QHostAddress(QHostAddress::AnyIPv4) ||
        host == QHostAddress(QHostAddress::AnyIPv6)) {
        host = QHostAddress(QHostAddress::LocalHost);
        // The address a phone on the same network reaches: the first that is not loopback.
        const auto all = QNetworkInterface::allAddresses();
        for (const QHostAddress &a : all) {
            if (a.protocol() == QAbstractSocket::IPv4Protocol && !a.isLoopback()) {
                host = a;
                break;
            }
        }
    }
    QUrl url;
    url.setScheme(QStringLiteral("http"));
    url.setHost(host.toString());
    url.setPort(m_port);
    url.setPath(QStringLiteral("/p/") + m_gate.token());
    return url;
}

QList<PendantServer::Client> PendantServer::clients() const
{
    QList<Client> list;
    for (const auto &[id, c] : m_connections)
        list << c.client;
    return list;
}

QString PendantServer::describe(int id) const
{
    const auto it = m_connections.find(id);
    return it == m_connections.end() ? QStringLiteral("(gone)") : it->second.client.address;
}

void PendantServer::disconnectClient(int id)
{
    const auto it = m_connections.find(id);
    if (it == m_connections.end())
        return;
    say(id, QStringLiteral("disconnected in the window"));
    send(id, {{QStringLiteral("t"), QStringLiteral("bye")},
              {QStringLiteral("text"),
               PendantPage::text("StepCom disconnected this phone", it->second.language)}});
    // close() may say `disconnected` at once, which ends the connection (onClosed): once only.
    QWebSocket *socket = it->second.socket.get();
    socket->close(QWebSocketProtocol::CloseCodeNormal);
    onClosed(id);
}

void PendantServer::onNewSocket()
{
    while (m_http && m_http->hasPendingWebSocketConnections()) {
        std::unique_ptr<QWebSocket> socket = m_http->nextPendingWebSocketConnection();
        if (!socket)
            continue;
        const QString address = PendantHttp::addressText(socket->peerAddress());
        QString token;
        QString file;
        // PendantHttp let only the token's upgrade through; checked again here all the same.
        if (!PendantHttp::splitPath(socket->requestUrl().path(), &token, &file) ||
            file != QLatin1String("ws") || !m_gate.admit(address, token)) {
            socket->close(QWebSocketProtocol::CloseCodePolicyViolated);
            socket.release()->deleteLater();
            continue;
        }
        const int id = m_nextId++;
        Connection c;
        c.client = {id, address, QString(), QDateTime::currentDateTime()};
        c.socket = std::move(socket);
        QWebSocket *s = c.socket.get();
        connect(s, &QWebSocket::textMessageReceived, this,
                [this, id](const QString &text) { onMessage(id, text); });
        connect(s, &QWebSocket::disconnected, this, [this, id] { onClosed(id); });
        m_connections.emplace(id, std::move(c));
        Q_EMIT clientsChanged();
    }
}

void PendantServer::onClosed(int id)
{
    const auto it = m_connections.find(id);
    if (it == m_connections.end())
        return;
    // First the stop, then the bookkeeping: a jog never outlives its phone's socket.
    m_control->clientGone(id);
    say(id, QStringLiteral("connection closed"));
    it->second.socket->disconnect(this);
    it->second.socket.release()->deleteLater();
    m_connections.erase(it);
    Q_EMIT clientsChanged();
}

void PendantServer::say(int id, const QString &text)
{
    Q_EMIT userAction(QStringLiteral("pendant %1: %2").arg(describe(id), text));
}

void PendantServer::onMessage(int id, const QString &text)
{
    const auto it = m_connections.find(id);
    if (it == m_connections.end())
        return;
    const QJsonObject m = QJsonDocument::fromJson(text.toUtf8()).object();
    const QString type = m.value(QStringLiteral("t")).toString();
    const int motor = m.value(QStringLiteral("motor")).toInt();
    const bool forward = m.value(QStringLiteral("dir")).toString() != QLatin1String("rev");
    QString refusal;
    if (type == QLatin1String("hold")) {
        m_control->hold(id, motor);
        return;
    } else if (type == QLatin1String("hello")) {
        Client &c = it->second.client;
        const bool first = c.browser.isEmpty();
        c.browser = browserOf(m.value(QStringLiteral("ua")).toString());
        it->second.language =
            PendantPage::languageOf(m.value(QStringLiteral("lang")).toString().toLatin1());
        if (first)
            say(id, QStringLiteral("paired (%1)").arg(c.browser));
        Q_EMIT clientsChanged();
        sendControl();
        send(id, PendantPage::status(*m_session, it->second.language, m_namer));
    } else if (type == QLatin1String("estop")) {
        say(id, QStringLiteral("E-STOP"));
        m_session->emergencyStop(); // as the window's button: every device, with priority
    } else if (type == QLatin1String("take")) {
        refusal = m_control->take(id);
    } else if (type == QLatin1String("give")) {
        m_control->giveUp(id);
    } else if (type == QLatin1String("jog")) {
        refusal = m_control->jog(id, motor, forward);
        if (!refusal.isEmpty())
            say(id, QStringLiteral("motor %1 jog refused: %2").arg(motor).arg(refusal));
    } else if (type == QLatin1String("stop")) {
        m_control->stop(id, motor, stopWhy(m.value(QStringLiteral("why")).toString()));
    } else if (type == QLatin1String("step")) {
        const double size = m.value(QStringLiteral("size")).toDouble();
        refusal = m_control->step(id, motor, forward, size);
        say(id, refusal.isEmpty()
                    ? QStringLiteral("motor %1 step %2%3")
                          .arg(motor)
                          .arg(forward ? QLatin1Char('+') : QLatin1Char('-'))
                          .arg(size)
                    : QStringLiteral("motor %1 step refused: %2").arg(motor).arg(refusal));
    }
    if (!refusal.isEmpty())
        send(id,
             {{QStringLiteral("t"), QStringLiteral("refused")}, {QStringLiteral("text"), refusal}});
}

void PendantServer::send(int id, const QJsonObject &message)
{
    const auto it = m_connections.find(id);
    if (it == m_connections.end() || !it->second.socket)
        return;
    it->second.socket->sendTextMessage(
        QString::fromUtf8(QJsonDocument(message).toJson(QJsonDocument::Compact)));
}

void PendantServer::sendControl()
{
    const int holder = m_control->holder();
    for (const auto &[id, c] : m_connections) {
        QJsonObject m{{QStringLiteral("t"), QStringLiteral("control")},
                      {QStringLiteral("allowed"), m_control->isAllowed()},
                      {QStringLiteral("you"), holder == id}};
        m.insert(QStringLiteral("holder"),
                 holder ? QJsonValue(describe(holder)) : QJsonValue(QJsonValue::Null));
        send(id, m);
    }
}

void PendantServer::schedulePush()
{
    if (m_connections.empty() || m_push.isActive())
        return;
    const qint64 since = m_lastPush.isValid() ? m_lastPush.elapsed() : kMinPushMs;
    m_push.start(int(std::max<qint64>(0, kMinPushMs - since)));
}

void PendantServer::push()
{
    m_lastPush.start();
    QHash<QString, QJsonObject> byLanguage;
    for (const auto &[id, c] : m_connections) {
        auto it = byLanguage.find(c.language);
        if (it == byLanguage.end())
            it =
                byLanguage.insert(c.language, PendantPage::status(*m_session, c.language, m_namer));
        send(id, *it);
    }
}

} // namespace stepcom

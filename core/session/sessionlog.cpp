#include "session/sessionlog.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include <QDateTime>
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QStandardPaths>

#include <algorithm>

namespace stepcom {

SessionLog::SessionLog(DeviceSession *session, QObject *parent)
    : QObject(parent)
    , m_session(session)
    , m_directory(defaultDirectory())
{
    if (!session)
        return;
    connect(session->connection()->traffic(), &TrafficLog::entryAdded, this, &SessionLog::write);
    connect(session->connection(), &SessionConnection::linkStateChanged, this, [this, session] {
        if (session->connection()->linkState() == SessionConnection::LinkState::Connecting)
            beginConnection(linkText(session));
    });
    // What happened beyond the frames, in kinds of their own so a replay need not read the
    // (translated) text.
    const auto mark = [this](const char *kind, const QString &text) { writeMark(kind, text); };
    connect(session->connection(), &SessionConnection::connected, this,
            [session, mark](bool ok, const QString &) {
                if (ok)
                    mark(kLinkUp, linkText(session));
            });
    // Closed on purpose or lost: the reason says which (linkLost follows this one).
    connect(session->connection(), &SessionConnection::disconnected, this,
            [mark](const QString &reason) { mark(kLinkDown, reason); });
    connect(session, &DeviceSession::controllerRestarted, this,
            [mark](int id, const QStringList &lost) {
                mark(kRestart,
                     QStringLiteral("id %1%2").arg(id).arg(
                         lost.isEmpty() ? QString()
                                        : QStringLiteral(": ") + lost.join(QStringLiteral("; "))));
            });
    // Not claimed, but kept with what was seen, so a replay shows it as the session said it.
    connect(session, &DeviceSession::controllerMayHaveRestarted, this,
            [mark, session](int id, const RestartWatch::Evidence &seen) {
                mark(kPossibleRestart, possibleRestartText(session->map(), id, seen));
            });
    connect(session, &DeviceSession::emergencyStopRequested, this,
            [mark] { mark(kUser, QStringLiteral("E-STOP pressed")); });
    connect(session->line(), &SessionLine::deviceInViewChanged, this,
            [mark](int id) { mark(kUser, QStringLiteral("device in view: id %1").arg(id)); });
}

SessionLog::~SessionLog() = default;

QString SessionLog::linkText(const DeviceSession *session)
{
    // A log of the built-in simulator must not pass for one of a machine.
    const QString link = session->connection()->settings().describe();
    return session->connection()->isSimulator()
               ? QStringLiteral("built-in simulator, not a machine: %1").arg(link)
               : link;
}

QString SessionLog::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/logs");
}

void SessionLog::setDirectory(const QString &directory)
{
    m_file.close();
    m_directory = directory;
}

void SessionLog::setFile(const QString &path)
{
    m_file.close();
    m_fixedFile = path;
}

void SessionLog::noteUserAction(const QString &text)
{
    writeMark(kUser, text);
}

void SessionLog::setLimits(qint64 fileBytes, qint64 totalBytes)
{
    m_fileBytes = std::max<qint64>(1024, fileBytes);
    m_totalBytes = std::max(m_fileBytes, totalBytes);
}

void SessionLog::beginConnection(const QString &description)
{
    m_file.close();
    m_description = description;
    m_baseName.clear();
    m_part = 0;
}

QString SessionLog::currentFile() const
{
    return m_file.isOpen() ? m_file.fileName() : QString();
}

QStringList SessionLog::files() const
{
    const QDir dir(m_directory);
    QStringList paths;
    for (const QFileInfo &info :
         dir.entryInfoList({QStringLiteral("stepcom-*.log")}, QDir::Files, QDir::Name))
        paths.prepend(info.absoluteFilePath()); // names begin with the time: newest last
    return paths;
}

QString SessionLog::kindName(TrafficEntry::Kind kind)
{
    switch (kind) {
    case TrafficEntry::Kind::Poll:
        return QStringLiteral("poll");
    case TrafficEntry::Kind::Read:
        return QStringLiteral("read");
    case TrafficEntry::Kind::Write:
        return QStringLiteral("write");
    case TrafficEntry::Kind::Command:
        return QStringLiteral("command");
    case TrafficEntry::Kind::Error:
        return QStringLiteral("error");
    case TrafficEntry::Kind::Event:
        break;
    }
    return QStringLiteral("event");
}

QString SessionLog::formatLine(const TrafficEntry &entry)
{
    const char *dir = entry.direction == TrafficEntry::Direction::Sent       ? "TX"
                      : entry.direction == TrafficEntry::Direction::Received ? "RX"
                                                                             : "--";
    const QString hex = QString::fromLatin1(entry.bytes.toHex(' ').toUpper());
    return QStringLiteral("%1  %2  %3  %4%5\n")
        .arg(entry.time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")), QLatin1String(dir),
             kindName(entry.kind).leftJustified(7),
             hex.isEmpty() ? QString() : hex + QStringLiteral("  "), entry.summary);
}

QString SessionLog::formatMark(const QDateTime &time, const char *kind, const QString &text)
{
    return QStringLiteral("%1  --  %2  %3\n")
        .arg(time.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")),
             QString::fromLatin1(kind).leftJustified(7), text);
}

QString SessionLog::possibleRestartText(const RegisterMap &map, int id,
                                        const RestartWatch::Evidence &seen)
{
    const auto position = [&map](int motor) {
        return map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("position"));
    };
    const auto name = [&position](int motor) {
        const Parameter *p = position(motor);
        return p ? p->key.section(QLatin1Char('.'), 0, 0) : QStringLiteral("motor%1").arg(motor);
    };
    const auto names = [&name](const QList<int> &motors) {
        QStringList out;
        for (const int motor : motors)
            out << name(motor);
        return out.isEmpty() ? QStringLiteral("none") : out.join(QLatin1String(", "));
    };
    QList<int> motors = seen.before.keys();
    std::sort(motors.begin(), motors.end());
    QStringList before;
    for (const int motor : std::as_const(motors)) {
        const Parameter *p = position(motor);
        const qint64 raw = seen.before.value(motor);
        before << QStringLiteral("%1=%2").arg(name(motor),
                                              p ? p->formatRaw(raw) : QString::number(raw));
    }
    return QStringLiteral("id %1 may have restarted: silent %2 s; zeroed %3; stood still %4; "
                          "moving %5; before %6")
        .arg(id)
        .arg(double(seen.silentMs) / 1000.0, 0, 'f', 1)
        .arg(names(seen.zeroed), names(seen.stoodStill), names(seen.moving),
             before.isEmpty() ? QStringLiteral("not known") : before.join(QLatin1String(", ")));
}

QString SessionLog::header(const DeviceSession *session, int part, const QString &description,
                           const QHash<int, QString> &names)
{
    QString text =
        QStringLiteral("# StepCom %1 session log, part %2: %3\n")
            .arg(QStringLiteral(STEPCOM_VERSION))
            .arg(part)
            .arg(description.isEmpty() ? QStringLiteral("(no connection)") : description);
    text += QStringLiteral("# program: StepCom %1\n# qt: %2\n")
                .arg(QStringLiteral(STEPCOM_VERSION), QLatin1String(qVersion()));
    if (!session)
        return text;
    text += QStringLiteral("# map: %1\n").arg(session->map().identity());
    const LinkSettings s = session->connection()->settings();
    const char *transport = s.transport == LinkSettings::Transport::Tcp      ? "tcp"
                            : s.transport == LinkSettings::Transport::RtuTcp ? "rtu-tcp"
                                                                             : "rtu";
    QString line = QStringLiteral("transport=%1").arg(QLatin1String(transport));
    if (s.isNetwork())
        line += QStringLiteral(" host=%1 port=%2").arg(s.host).arg(s.tcpPort);
    else
        line += QStringLiteral(" port=%1 baud=%2 parity=%3 stop=%4")
                    .arg(s.portName)
                    .arg(s.baud)
                    .arg(LinkSettings::parityName(s.parity))
                    .arg(s.stopBits == QSerialPort::TwoStop ? 2 : 1);
    line += QStringLiteral(" id=%1 timeout=%2 retries=%3")
                .arg(s.deviceId)
                .arg(s.timeoutMs)
                .arg(s.retries);
    if (session->connection()->isSimulator())
        line += QStringLiteral(" simulator=built-in (not a machine)");
    text += QStringLiteral("# line: %1\n").arg(line);
    QStringList ids;
    for (const int id : session->line()->deviceIds())
        ids << QString::number(id);
    if (ids.isEmpty())
        ids << QString::number(s.deviceId);
    text += QStringLiteral("# ids: %1\n").arg(ids.join(QLatin1Char(',')));
    QJsonObject named;
    for (auto it = names.cbegin(); it != names.cend(); ++it) {
        if (!it.value().trimmed().isEmpty())
            named.insert(QString::number(it.key()), it.value().trimmed());
    }
    if (!named.isEmpty())
        text += QStringLiteral("# names: %1\n")
                    .arg(QString::fromUtf8(QJsonDocument(named).toJson(QJsonDocument::Compact)));
    return text;
}

bool SessionLog::openFile()
{
    if (!m_fixedFile.isEmpty()) {
        ++m_part;
        m_file.setFileName(m_fixedFile);
        if (!m_file.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text)) {
            fail(tr("cannot write the session log %1: %2")
                     .arg(m_file.fileName(), m_file.errorString()));
            return false;
        }
        m_file.write(header(m_session, m_part, m_description, m_names).toUtf8());
        Q_EMIT fileStarted(m_file.fileName());
        return true;
    }
    if (!QDir().mkpath(m_directory)) {
        fail(tr("cannot create the log folder %1").arg(m_directory));
        return false;
    }
    if (m_baseName.isEmpty()) {
        // The time first, so names sort by age; then where the link went, readable and safe.
        static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9._-]+"));
        QString where = m_description;
        where.replace(unsafe, QStringLiteral("_"));
        where = where.left(60);
        m_baseName =
            QStringLiteral("stepcom-%1%2")
                .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")),
                     where.isEmpty() ? QString() : QLatin1Char('-') + where);
    }
    ++m_part;
    const QString name =
        m_part == 1
            ? m_baseName + QStringLiteral(".log")
            : QStringLiteral("%1.part%2.log").arg(m_baseName).arg(m_part, 3, 10, QLatin1Char('0'));
    m_file.setFileName(QDir(m_directory).filePath(name));
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text)) {
        fail(
            tr("cannot write the session log %1: %2").arg(m_file.fileName(), m_file.errorString()));
        return false;
    }
    m_file.write(header(m_session, m_part, m_description, m_names).toUtf8());
    Q_EMIT fileStarted(m_file.fileName());
    prune();
    return true;
}

void SessionLog::writeMark(const char *kind, const QString &text)
{
    // Not a file of its own: what happens with no link (a page shown before connecting) has no
    // frames to go with.
    if (!m_file.isOpen() && (!m_session || m_session->connection()->linkState() ==
                                               SessionConnection::LinkState::Disconnected))
        return;
    writeLine(formatMark(QDateTime::currentDateTime(), kind, text).toUtf8());
}

void SessionLog::write(const TrafficEntry &entry)
{
    writeLine(formatLine(entry).toUtf8());
}

void SessionLog::writeLine(const QByteArray &line)
{
    if (m_file.isOpen() && m_fixedFile.isEmpty() && m_file.size() + line.size() > m_fileBytes)
        m_file.close(); // continue in the next part
    if (!m_file.isOpen() && !openFile())
        return;
    // Flushed at once: after a crash or a pulled plug the last frames are what support needs.
    if (m_file.write(line) != line.size() || !m_file.flush()) {
        fail(
            tr("cannot write the session log %1: %2").arg(m_file.fileName(), m_file.errorString()));
        m_file.close();
        return;
    }
    m_error.clear();
}

void SessionLog::prune()
{
    // Oldest first (names begin with the time); the file being written always stays.
    QDir dir(m_directory);
    const QFileInfoList infos =
        dir.entryInfoList({QStringLiteral("stepcom-*.log")}, QDir::Files, QDir::Name);
    qint64 total = 0;
    for (const QFileInfo &info : infos)
        total += info.size();
    for (const QFileInfo &info : infos) {
        if (total <= m_totalBytes - m_fileBytes)
            break; // room for the current file to grow to its limit
        if (info.absoluteFilePath() == QFileInfo(m_file.fileName()).absoluteFilePath())
            continue;
        if (QFile::remove(info.absoluteFilePath()))
            total -= info.size();
    }
}

void SessionLog::fail(const QString &reason)
{
    if (m_error == reason)
        return;
    m_error = reason;
    Q_EMIT failed(reason);
}

} // namespace stepcom

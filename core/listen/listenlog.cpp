#include "listen/listenlog.h"

#include "map/registermap.h"
#include "session/sessionlog.h"

#include <QDir>
#include <QRegularExpression>

namespace stepcom {

namespace {

TrafficEntry::Kind kindOf(const HeardEvent &e)
{
    switch (e.fc) {
    case 0x05:
    case 0x0F:
        return TrafficEntry::Kind::Command;
    case 0x06:
    case 0x10:
        return TrafficEntry::Kind::Write;
    default:
        return TrafficEntry::Kind::Read;
    }
}

} // namespace

ListenLog::ListenLog(const RegisterMap &map, const LinkSettings &line, const QDateTime &start)
    : m_map(map)
    , m_line(line)
    , m_start(start)
{}

QString ListenLog::fileIn(const QString &directory, const QString &portName)
{
    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9._-]+"));
    QString where = portName;
    where.replace(unsafe, QStringLiteral("_"));
    return QDir(directory).filePath(
        QStringLiteral("stepcom-%1-listen%2.log")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")),
                 where.isEmpty() ? QString() : QLatin1Char('-') + where.left(60)));
}

bool ListenLog::open(const QString &path, QString *error)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Append | QIODevice::Text)) {
        *error = tr("cannot write the session log %1: %2").arg(path, m_file.errorString());
        return false;
    }
    const QString description = tr("%1 %2 baud, listening (another master drives the line)")
                                    .arg(m_line.portName)
                                    .arg(m_line.baud);
    QString header = SessionLog::header(nullptr, 1, description);
    header += QStringLiteral("# map: %1\n").arg(m_map.identity());
    header += QStringLiteral("# line: transport=rtu port=%1 baud=%2 parity=%3 stop=%4 id=0\n")
                  .arg(m_line.portName)
                  .arg(m_line.baud)
                  .arg(LinkSettings::parityName(m_line.parity))
                  .arg(m_line.stopBits == QSerialPort::TwoStop ? 2 : 1);
    header +=
        QStringLiteral("# listen: StepCom only listened; the requests are another master's\n");
    writeLine(header);
    return m_error.isEmpty();
}

void ListenLog::write(const HeardEvent &e)
{
    if (!m_file.isOpen())
        return;
    const QString text = e.text();
    if (!e.request.isEmpty()) {
        writeLine(SessionLog::formatLine(
            TrafficEntry{m_start.addMSecs(e.requestMs), TrafficEntry::Direction::Sent, kindOf(e),
                         e.request, e.answer.isEmpty() ? text : QString()}));
    }
    if (!e.answer.isEmpty())
        writeLine(SessionLog::formatLine(TrafficEntry{
            m_start.addMSecs(e.ms), TrafficEntry::Direction::Received, kindOf(e), e.answer, text}));
}

void ListenLog::note(const char *kind, const QString &text, qint64 ms)
{
    if (m_file.isOpen())
        writeLine(SessionLog::formatMark(m_start.addMSecs(ms), kind, text));
}

void ListenLog::writeLine(const QString &line)
{
    const QByteArray bytes = line.toUtf8();
    // Flushed at once: after a pulled plug the last frames are what support needs.
    if (m_file.write(bytes) != bytes.size() || !m_file.flush()) {
        m_error =
            tr("cannot write the session log %1: %2").arg(m_file.fileName(), m_file.errorString());
        m_file.close();
    }
}

} // namespace stepcom

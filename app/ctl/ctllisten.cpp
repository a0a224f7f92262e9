#include "ctllisten.h"

#include "ctlrunner.h"
#include "listen/linelistener.h"
#include "listen/listenlog.h"
#include "signalwatcher.h"

#include <QDateTime>
#include <QJsonDocument>
#include <QTimer>

#include <cstdio>

namespace stepcom {

CtlListen::CtlListen(const RegisterMap &map, const LinkSettings &line, bool json, int seconds,
                     const QString &logFile, QObject *parent)
    : QObject(parent)
    , m_map(map)
    , m_line(line)
    , m_json(json)
    , m_seconds(seconds)
    , m_logFile(logFile)
    , m_out(stdout)
    , m_err(stderr)
{}

CtlListen::~CtlListen() = default;

void CtlListen::start()
{
    m_signals = new SignalWatcher(this);
    connect(m_signals, &SignalWatcher::terminationRequested, this, [this] { end(0); });
    m_listener = new LineListener(&m_map, this);
    connect(m_listener, &LineListener::heard, this, &CtlListen::onHeard);
    connect(m_listener, &LineListener::lost, this, [this](const QString &reason) {
        sayError(tr("stepcomctl: the port %1 was lost: %2").arg(m_line.portName, reason));
        end(CtlRunner::DeviceError);
    });
    QString error;
    if (!m_listener->open(m_line, &error)) {
        sayError(tr("stepcomctl: cannot open %1 to listen: %2").arg(m_line.portName, error));
        end(CtlRunner::DeviceError);
        return;
    }
    if (!m_logFile.isEmpty()) {
        m_log = std::make_unique<ListenLog>(m_map, m_line, QDateTime::currentDateTime());
        if (!m_log->open(m_logFile, &error)) {
            sayError(QStringLiteral("stepcomctl: ") + error);
            end(CtlRunner::UsageError);
            return;
        }
    }
    m_listening = true;
    m_err << tr("listening on %1 at %2 baud; nothing is sent (Ctrl-C ends)")
                 .arg(m_line.portName)
                 .arg(m_line.baud)
          << Qt::endl;
    if (const QString adapter = m_listener->adapterText(); !adapter.isEmpty())
        m_err << tr("adapter: %1").arg(adapter) << Qt::endl;
    if (m_seconds > 0)
        QTimer::singleShot(m_seconds * 1000, this, [this] { end(0); });
}

void CtlListen::onHeard(const HeardEvent &e)
{
    if (e.kind == HeardEvent::Kind::NoAnswer)
        ++m_unanswered;
    if (e.kind == HeardEvent::Kind::Exception)
        ++m_exceptions;
    if (m_log)
        m_log->write(e);
    if (m_json) {
        for (const QJsonObject &o : e.toJson(0))
            m_out << QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)) << '\n';
    } else {
        m_out << QStringLiteral("%1  ").arg(double(e.ms) / 1000.0, 8, 'f', 3) << e.text() << '\n';
    }
    // Flushed line by line: a technician watches it, a script reads it as it comes.
    m_out.flush();
}

QString CtlListen::summary() const
{
    const FrameFinder::Stats &f = m_listener->finder().stats();
    const ListenDecoder &d = m_listener->decoder();
    QString text =
        tr("heard %1 frames (%2 bytes): %3 pairs, %4 unanswered, %5 exceptions, %6 CRC errors "
           "(frames skipped), %7 stray bytes, %8 answers without their request")
            .arg(f.frames)
            .arg(f.bytes)
            .arg(d.pairs())
            .arg(m_unanswered)
            .arg(m_exceptions)
            .arg(f.damaged)
            .arg(f.strayBytes)
            .arg(d.strayAnswers());
    const auto &stats = d.deviceStats();
    for (auto it = stats.cbegin(); it != stats.cend(); ++it) {
        const ListenDecoder::DeviceStats &s = it.value();
        text += QLatin1Char('\n');
        if (s.answered > 0)
            text += tr("id %1: %2 requests, %3 answered in %4-%5 ms (%6 ms on average), %7 "
                       "unanswered")
                        .arg(it.key())
                        .arg(s.requests)
                        .arg(s.answered)
                        .arg(s.answerMsMin, 0, 'f', 1)
                        .arg(s.answerMsMax, 0, 'f', 1)
                        .arg(s.answerMsAverage(), 0, 'f', 1)
                        .arg(s.unanswered);
        else
            text += tr("id %1: %2 requests, none answered").arg(it.key()).arg(s.requests);
    }
    return text;
}

void CtlListen::sayError(const QString &text)
{
    m_err << text << Qt::endl;
    // The JSON's errors say what went wrong, as every command's do, without the program's name.
    const QString prefix = QStringLiteral("stepcomctl: ");
    m_errors << (text.startsWith(prefix) ? text.mid(prefix.size()) : text);
}

QJsonObject CtlListen::summaryJson() const
{
    if (!m_listening)
        return {};
    const FrameFinder::Stats &f = m_listener->finder().stats();
    const ListenDecoder &d = m_listener->decoder();
    QJsonObject devices;
    const auto &stats = d.deviceStats();
    for (auto it = stats.cbegin(); it != stats.cend(); ++it) {
        const ListenDecoder::DeviceStats &s = it.value();
        const auto ms = [&s](double v) { return s.answered > 0 ? QJsonValue(v) : QJsonValue(); };
        devices.insert(QString::number(it.key()),
                       QJsonObject{{QStringLiteral("requests"), s.requests},
                                   {QStringLiteral("answered"), s.answered},
                                   {QStringLiteral("unanswered"), s.unanswered},
                                   {QStringLiteral("answer_ms_min"), ms(s.answerMsMin)},
                                   {QStringLiteral("answer_ms_max"), ms(s.answerMsMax)},
                                   {QStringLiteral("answer_ms_average"), ms(s.answerMsAverage())}});
    }
    return {{QStringLiteral("frames"), double(f.frames)},
            {QStringLiteral("bytes"), double(f.bytes)},
            {QStringLiteral("pairs"), d.pairs()},
            {QStringLiteral("unanswered"), m_unanswered},
            {QStringLiteral("exceptions"), m_exceptions},
            {QStringLiteral("crc_errors"), double(f.damaged)},
            {QStringLiteral("stray_bytes"), double(f.strayBytes)},
            {QStringLiteral("stray_answers"), d.strayAnswers()},
            {QStringLiteral("devices"), devices}};
}

void CtlListen::end(int exitCode)
{
    if (m_ended)
        return;
    m_ended = true;
    if (m_listener) {
        m_listener->finish();
        m_listener->close();
        if (m_listening)
            m_err << summary() << Qt::endl;
    }
    m_out.flush();
    Q_EMIT finished(exitCode);
}

} // namespace stepcom

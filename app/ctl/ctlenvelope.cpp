// stepcomctl --json: one object for every command, `exit`, `result` and `errors`, so a script
// reads the same three members whatever it ran (guide: "--json for every command").
#include "ctlcontext.h"
#include "ctlrunner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace stepcom {

namespace {

const QString kPrefix = QStringLiteral("stepcomctl: ");

} // namespace

bool CtlRunner::jsonAsked(const QStringList &arguments)
{
    // Up to a "--" that ends the options, as QCommandLineParser reads them.
    for (const QString &a : arguments.mid(1)) {
        if (a == QLatin1String("--"))
            return false;
        if (a == QLatin1String("--json"))
            return true;
    }
    return false;
}

int CtlRunner::failEarly(int code, const QStringList &messages, bool json)
{
    QTextStream err(stderr);
    for (const QString &m : messages)
        err << kPrefix << m << Qt::endl;
    if (json)
        QTextStream(stdout) << QString::fromUtf8(
            QJsonDocument(envelope(code, QString(), messages, QJsonObject()))
                .toJson(QJsonDocument::Indented));
    return code;
}

bool CtlRunner::isStreaming() const
{
    return m_chosen && (QLatin1String(m_chosen->name) == QLatin1String("monitor") ||
                        QLatin1String(m_chosen->name) == QLatin1String("listen"));
}

void CtlRunner::captureOutput()
{
    m_ctx->outBuffer.clear();
    m_ctx->out.setString(&m_ctx->outBuffer);
    m_ctx->errBuffer.clear();
    m_ctx->err.setString(&m_ctx->errBuffer);
}

QJsonObject CtlRunner::envelope(int code, const QString &out, const QStringList &errors,
                                const QJsonObject &result)
{
    QJsonObject one{{QStringLiteral("exit"), code},
                    {QStringLiteral("errors"), QJsonArray::fromStringList(errors)}};
    // A command with JSON of its own printed it: that is the result.
    const QJsonDocument doc = QJsonDocument::fromJson(out.toUtf8());
    if (result.isEmpty() && doc.isObject()) {
        one.insert(QStringLiteral("result"), doc.object());
    } else if (result.isEmpty() && doc.isArray()) {
        one.insert(QStringLiteral("result"), doc.array());
    } else {
        one.insert(QStringLiteral("result"), result);
        const QStringList lines = out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        if (!lines.isEmpty())
            one.insert(QStringLiteral("messages"), QJsonArray::fromStringList(lines));
    }
    return one;
}

void CtlRunner::printEnvelope(int code)
{
    m_ctx->out.flush();
    m_ctx->err.flush();
    QStringList errors;
    QTextStream err(stderr);
    for (QString line : m_ctx->errBuffer.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        err << line << Qt::endl; // still said where a person reads it
        if (line.startsWith(kPrefix))
            line = line.mid(kPrefix.size());
        errors << line;
    }
    errors << m_ctx->liveErrors; // said on standard error as they came
    // A stream's last line is one line too, so a script reading line by line reads it whole.
    QTextStream(stdout) << QString::fromUtf8(QJsonDocument(envelope(code, m_ctx->outBuffer, errors,
                                                                    m_ctx->result))
                                                 .toJson(isStreaming() ? QJsonDocument::Compact
                                                                       : QJsonDocument::Indented))
                        << (isStreaming() ? "\n" : "");
    m_ctx->outBuffer.clear();
    m_ctx->errBuffer.clear();
}

void CtlRunner::printMulti()
{
    QTextStream out(stdout);
    if (m_ctx->options.json) {
        QJsonObject all;
        QStringList errors;
        for (qsizetype i = 0; i < m_idOutputs.size(); ++i) {
            const int id = m_ctx->options.ids.at(i);
            all.insert(QString::number(id), envelope(m_idCodes.at(i), m_idOutputs.at(i),
                                                     m_idErrors.at(i), m_idResults.at(i)));
            for (const QString &e : m_idErrors.at(i))
                errors << tr("id %1: %2").arg(id).arg(e);
        }
        // The same three members as one id's: the worst exit, each id's object, every error.
        const QJsonObject top{{QStringLiteral("exit"), worstCode()},
                              {QStringLiteral("result"), all},
                              {QStringLiteral("errors"), QJsonArray::fromStringList(errors)}};
        out << QString::fromUtf8(QJsonDocument(top).toJson(QJsonDocument::Indented));
    } else {
        for (qsizetype i = 0; i < m_idOutputs.size(); ++i) {
            out << tr("== device id %1 ==").arg(m_ctx->options.ids.at(i)) << Qt::endl;
            const QString text = m_idOutputs.at(i);
            out << text;
            if (!text.isEmpty() && !text.endsWith(QLatin1Char('\n')))
                out << Qt::endl;
        }
    }
    out.flush();
    m_ctx->out.setDevice(nullptr);
    m_ctx->err.setDevice(nullptr);
}

} // namespace stepcom

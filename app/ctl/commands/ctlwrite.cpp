// stepcomctl write: parsed and checked, reviewed as the window reviews it (WriteReview), then
// written and verified: a part of CtlRunner.
#include "../ctlrunner.h"
#include "session/parts/sessionparameters.h"

#include "../ctllinkadvice.h"

#include "device/writereview.h"

#include <QJsonArray>

namespace stepcom {

void CtlRunner::runWrite()
{
    if (m_options.arguments.isEmpty()) {
        fail(UsageError, tr("write needs KEY=VALUE arguments"));
        return;
    }
    QList<ParameterWrite> writes;
    QStringList problems;
    for (const QString &arg : std::as_const(m_options.arguments)) {
        const qsizetype eq = arg.indexOf(QLatin1Char('='));
        if (eq <= 0) {
            problems << tr("'%1' is not KEY=VALUE").arg(arg);
            continue;
        }
        const QString key = arg.left(eq).trimmed();
        const Parameter *p = m_map.find(key);
        if (!p) {
            problems << tr("unknown parameter '%1' (see: stepcomctl params)").arg(key);
            continue;
        }
        if (!p->writable()) {
            problems << (p->isCoil() ? tr("%1 is a command: use 'stepcomctl command %1'").arg(key)
                                     : tr("%1 is read-only").arg(key));
            continue;
        }
        QString error;
        const auto raw = p->parse(arg.mid(eq + 1), &error);
        if (!raw) {
            problems << error;
            continue;
        }
        writes.append({p, *raw});
    }
    if (problems.isEmpty())
        problems = DeviceClient::validate(writes); // duplicates, as the device client checks
    if (!problems.isEmpty()) {
        for (const QString &p : std::as_const(problems))
            m_err << QStringLiteral("stepcomctl: ") << p << Qt::endl;
        m_err << QStringLiteral("stepcomctl: ") << tr("nothing was written") << Qt::endl;
        finish(UsageError);
        return;
    }
    // A new id or baud, or a save to flash after the write: the settings before it are backed up.
    std::optional<DeviceSession::Risk> risk;
    for (const ParameterWrite &w : std::as_const(writes)) {
        if (w.parameter->key == QLatin1String("device.id"))
            risk = DeviceSession::Risk::DeviceId;
        else if (w.parameter->key == QLatin1String("device.baud") && !risk)
            risk = DeviceSession::Risk::Baud;
    }
    if (!risk && m_options.saveToFlash)
        risk = DeviceSession::Risk::SaveToFlash;
    connectThen([this, writes, risk] {
        reviewThen(writes, [this, writes, risk] {
            if (risk) {
                guardThen(*risk, [this, writes] { writeThenReport(writes); });
                return;
            }
            writeThenReport(writes);
        });
    });
}

void CtlRunner::reviewThen(const QList<ParameterWrite> &writes, std::function<void()> next)
{
    const auto judge = [this, writes, next](const QHash<QString, qint64> &held) {
        const QStringList problems = WriteReview::problems(
            m_map,
            [&held](const QString &key) {
                const auto it = held.constFind(key);
                return it == held.cend() ? std::nullopt : std::optional<qint64>(*it);
            },
            writes);
        for (const QString &p : problems)
            m_err << QStringLiteral("stepcomctl: ") << tr("check: %1").arg(p) << Qt::endl;
        if (!problems.isEmpty())
            m_result.insert(QStringLiteral("questions"), QJsonArray::fromStringList(problems));
        if (!problems.isEmpty() && !m_options.yes) {
            fail(UsageError, tr("nothing was written: the window asks before writing these "
                                "values; add --yes to write them anyway"));
            return;
        }
        next();
    };
    // What the review judges besides the values written: the wiring, the mode, the path.
    QList<const Parameter *> params;
    for (const QString &k : WriteReview::keysRead(m_map, writes))
        params << m_map.find(k);
    if (params.isEmpty()) {
        judge({});
        return;
    }
    m_session->parameters()->read(params, [this, judge](const ReadOutcome &r) {
        if (!r.ok) {
            for (const QString &e : condensed(r.errors))
                m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
            fail(DeviceError, tr("what the values are checked against could not be read: "
                                 "nothing was written"));
            return;
        }
        judge(r.values);
    });
}

void CtlRunner::writeThenReport(const QList<ParameterWrite> &writes)
{
    m_session->parameters()->write(writes, [this, writes](const WriteOutcome &w) {
        reportWritten(writes, w);
        if (!w.ok) {
            finish(DeviceError);
            return;
        }
        for (const QString &note : CtlLinkAdvice::notes(m_options, writes, m_options.saveToFlash))
            m_out << note << Qt::endl;
        if (!m_options.saveToFlash) {
            finish(Ok);
            return;
        }
        saveToFlashThenFinish();
    });
}

void CtlRunner::reportWritten(const QList<ParameterWrite> &writes, const WriteOutcome &w)
{
    QJsonObject written;
    for (const ParameterWrite &pw : writes) {
        if (!w.verified(pw.parameter->key))
            continue;
        written.insert(pw.parameter->key, jsonValue(*pw.parameter, pw.raw));
        m_out << pw.parameter->key << QStringLiteral(" = ") << valueText(*pw.parameter, pw.raw)
              << QStringLiteral("  ") << tr("(written, verified)") << Qt::endl;
    }
    m_result.insert(QStringLiteral("written"), written);
    m_result.insert(QStringLiteral("not_written"), QJsonArray::fromStringList(w.notWritten));
    for (const QString &e : w.errors)
        m_err << QStringLiteral("stepcomctl: ") << e << Qt::endl;
    if (!w.notWritten.isEmpty())
        m_err << QStringLiteral("stepcomctl: ")
              << tr("not written: %1").arg(w.notWritten.join(QLatin1String(", "))) << Qt::endl;
}

} // namespace stepcom

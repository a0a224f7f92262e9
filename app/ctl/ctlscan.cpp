#include "ctlscan.h"

#include "map/registermap.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace stepcom {

CtlScan::CtlScan(const BusScanner::Plan &plan, const RegisterMap &map, bool json, QTextStream &out,
                 QTextStream &problems, QObject *parent)
    : QObject(parent)
    , m_plan(plan)
    , m_json(json)
    , m_network(plan.base.isNetwork())
    , m_out(out)
    , m_problems(problems)
    , m_err(stderr)
{
    m_scanner.setMap(&map);
    connect(&m_scanner, &BusScanner::progress, this, &CtlScan::onProgress);
    connect(&m_scanner, &BusScanner::finished, this, &CtlScan::onFinished);
    connect(&m_scanner, &BusScanner::lineStarted, this, [this](const QString &line, int timeoutMs) {
        m_err << tr("scanning %1: %n id(s), %2 ms a probe", nullptr, int(m_plan.ids.size()))
                     .arg(line)
                     .arg(timeoutMs)
              << Qt::endl;
    });
    connect(&m_scanner, &BusScanner::foundDevice, this, [this](const BusScanner::Found &f) {
        m_err << tr("found %1").arg(f.summary()) << Qt::endl;
    });
}

void CtlScan::start()
{
    m_clock.start();
    if (m_network)
        m_err << tr("over a network the converter's or gateway's serial line has its own baud "
                    "and parity: only the ids are scanned")
              << Qt::endl;
    m_err << tr("at most about %1 s when nobody answers; a scan only reads")
                 .arg((BusScanner::worstCaseMs(m_plan) + 999) / 1000)
          << Qt::endl;
    m_scanner.start(m_plan);
}

void CtlScan::onProgress(int done, int total, int baud, int deviceId)
{
    Q_UNUSED(baud);
    // A line every 25 probes and at the end: enough to see it move, not a flood in a log.
    if (done % 25 == 0 || done == total)
        m_err << tr("%1 of %2 probed (id %3)").arg(done).arg(total).arg(deviceId) << Qt::endl;
}

void CtlScan::onFinished(bool cancelled, const QString &error)
{
    Q_UNUSED(cancelled);
    if (!error.isEmpty()) {
        m_problems << QStringLiteral("stepcomctl: ") << tr("scan stopped: %1").arg(error)
                   << Qt::endl;
        if (m_json)
            printJson();
        m_out.flush();
        Q_EMIT finished(LinkError);
        return;
    }
    m_err << tr("%n controller(s) found in %1 s", nullptr, int(m_scanner.found().size()))
                 .arg(double(m_clock.elapsed()) / 1000.0, 0, 'f', 1)
          << Qt::endl;
    if (m_json)
        printJson();
    else
        printTable();
    // Exit 1 says it; the JSON's errors name it, as the table's line does.
    if (m_json && m_scanner.found().isEmpty())
        m_problems << QStringLiteral("stepcomctl: ")
                   << tr("No controller answered. Check the power, the wiring (A and B swapped?), "
                         "the port, and for a controller that answers slowly give "
                         "--probe-timeout.")
                   << Qt::endl;
    m_out.flush();
    Q_EMIT finished(m_scanner.found().isEmpty() ? NoneFound : Found);
}

void CtlScan::printTable() const
{
    const QList<BusScanner::Found> &found = m_scanner.found();
    if (found.isEmpty()) {
        m_out << tr("No controller answered. Check the power, the wiring (A and B swapped?), "
                    "the port, and for a controller that answers slowly give --probe-timeout.")
              << Qt::endl;
        return;
    }
    const QString dash = QStringLiteral("-");
    m_out << QStringLiteral("%1  %2  %3  %4  %5")
                 .arg(tr("id"), -4)
                 .arg(tr("baud"), -6)
                 .arg(tr("parity"), -6)
                 .arg(tr("answer"), -7)
                 .arg(tr("controller"))
          << Qt::endl;
    for (const BusScanner::Found &f : found) {
        m_out << QStringLiteral("%1  %2  %3  %4  %5")
                     .arg(f.deviceId, -4)
                     .arg(m_network ? dash : QString::number(f.baud), -6)
                     .arg(m_network ? dash : LinkSettings::parityName(f.parity), -6)
                     .arg(tr("%1 ms").arg(f.answerMs), -7)
                     .arg(f.detail)
              << Qt::endl;
    }
    for (const BusScanner::Found &f : found) {
        if (f.late)
            m_out << tr("id %1 answered after %2 ms, later than the probe waited: connect with "
                        "--timeout %3")
                         .arg(f.deviceId)
                         .arg(f.answerMs)
                         .arg(BusScanner::suggestedTimeoutMs(f.answerMs))
                  << Qt::endl;
    }
}

void CtlScan::printJson() const
{
    QJsonArray list;
    for (const BusScanner::Found &f : m_scanner.found()) {
        QJsonObject o{
            {QStringLiteral("id"), f.deviceId},
            {QStringLiteral("where"), f.where},
            {QStringLiteral("answer_ms"), double(f.answerMs)},
            {QStringLiteral("late"), f.late},
            {QStringLiteral("suggested_timeout_ms"), BusScanner::suggestedTimeoutMs(f.answerMs)},
            {QStringLiteral("controller"), f.detail}};
        o.insert(QStringLiteral("baud"), m_network ? QJsonValue() : QJsonValue(f.baud));
        o.insert(QStringLiteral("parity"),
                 m_network ? QJsonValue() : QJsonValue(LinkSettings::parityName(f.parity)));
        if (f.exceptionCode != 0)
            o.insert(QStringLiteral("exception"), f.exceptionCode);
        QJsonArray angles;
        for (const qint64 raw : f.stepAngles)
            angles << double(raw);
        o.insert(QStringLiteral("step_angles_raw"), angles);
        list << o;
    }
    m_out << QString::fromUtf8(QJsonDocument(list).toJson(QJsonDocument::Indented));
}

} // namespace stepcom

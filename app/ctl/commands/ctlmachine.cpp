// stepcomctl for a whole machine: every controller of the line in one report, every one saved
// into one folder.
#include "../ctlrunner.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include "line/bussweep.h"
#include "profile/busdump.h"
#include "report/machinereport.h"

#include <QDate>
#include <QFileInfo>

namespace stepcom {

void CtlRunner::dumpIntoFolder(const QString &folder, const QHash<QString, qint64> &values)
{
    const int id = m_session->line()->deviceInView();
    const BusDump::Saved saved =
        BusDump::save(folder, m_map, id, m_options.name, m_options.notes, values,
                      QDate::currentDate(), m_session->connection()->isSimulator());
    if (!saved.ok()) {
        fail(UsageError, saved.error);
        return;
    }
    m_out << tr("saved the settings of %1 to %2")
                 .arg(m_session->line()->describeDevice(id), saved.path)
          << Qt::endl;
    finish(Ok);
}

void CtlRunner::runMachineReport()
{
    if (m_options.arguments.size() != 1) {
        fail(UsageError, tr("report needs exactly one file (.pdf or .html)"));
        return;
    }
    const QString path = m_options.arguments.first();
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QLatin1String("pdf") && suffix != QLatin1String("html") &&
        suffix != QLatin1String("htm")) {
        fail(UsageError, tr("%1: the report is written as .pdf or .html").arg(path));
        return;
    }
    if (!m_options.from.isEmpty()) {
        fail(UsageError, tr("report --from makes the report of one profile file: give one --id"));
        return;
    }
    connectThen([this, path] {
        readMachine(tr("no report: not every controller could be read completely"),
                    [this, path](const QList<ReportInput> &inputs) {
                        const MachineReport report(inputs, m_options.name, m_options.notes,
                                                   m_options.language);
                        if (const QString e = report.write(path); !e.isEmpty()) {
                            fail(UsageError, e);
                            return;
                        }
                        m_result = QJsonObject{{QStringLiteral("file"), path},
                                               {QStringLiteral("controllers"), int(inputs.size())}};
                        m_out << tr("report of %n controller(s) written to %1", nullptr,
                                    int(inputs.size()))
                                     .arg(path)
                              << Qt::endl;
                        finish(Ok);
                    });
    });
}

void CtlRunner::readMachine(const QString &failure,
                            std::function<void(const QList<ReportInput> &)> done)
{
    auto *sweep = new BusSweep(m_session, this);
    connect(sweep, &BusSweep::finished, this, [this, sweep, failure, done](bool ok) {
        sweep->deleteLater();
        if (!ok) {
            // A machine's report never leaves a controller out silently: none then.
            for (int id : m_options.ids) {
                for (const QString &e : sweep->outcome(id).errors)
                    m_err << QStringLiteral("stepcomctl: ") << tr("id %1: %2").arg(id).arg(e)
                          << Qt::endl;
            }
            fail(DeviceError, failure);
            return;
        }
        QList<ReportInput> inputs;
        const QDateTime now = QDateTime::currentDateTime();
        for (int id : m_options.ids) {
            ReportInput input;
            input.map = m_map;
            input.values = sweep->outcome(id).values;
            input.link = m_session->line()->describeDevice(id);
            input.simulator = m_session->connection()->isSimulator();
            input.line = m_session->connection()->linkStats().lineText(id);
            input.deviceId = id;
            input.date = now;
            input.lastRead = now; // one-shot: the flash state is not known
            inputs << input;
        }
        done(inputs);
    });
    sweep->start(m_options.ids, m_map.holdings());
}

} // namespace stepcom

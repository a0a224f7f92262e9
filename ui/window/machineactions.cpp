#include "window/machineactions.h"

#include "base/language.h"
#include "dialogs/applytodevicesdialog.h"
#include "line/bussweep.h"
#include "profile/busdump.h"
#include "profile/profilefile.h"
#include "report/machinereport.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "widgets/docks/devicelistdock.h"

#include <QAction>
#include <QDate>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>

namespace stepcom {

MachineActions::MachineActions(DeviceSession *session, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_window(window)
    , m_apply(new QAction(this))
    , m_dump(new QAction(this))
    , m_report(new QAction(this))
{
    m_apply->setObjectName(QStringLiteral("applyProfileToDevices"));
    m_dump->setObjectName(QStringLiteral("saveAllDevices"));
    m_report->setObjectName(QStringLiteral("machineReport"));
    connect(m_apply, &QAction::triggered, this, &MachineActions::chooseApply);
    connect(m_dump, &QAction::triggered, this, &MachineActions::chooseDump);
    connect(m_report, &QAction::triggered, this, &MachineActions::chooseReport);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &MachineActions::updateActions);
    connect(session->line(), &SessionLine::deviceInViewChanged, this,
            &MachineActions::updateActions);
    connect(session->line(), &SessionLine::deviceStatusChanged, this,
            &MachineActions::updateActions);
    connect(&Language::instance(), &Language::changed, this, &MachineActions::retranslate);
    retranslate();
    updateActions();
}

void MachineActions::addTo(QMenu *menu, std::function<DeviceListDock *()> list)
{
    m_list = std::move(list);
    menu->addAction(m_apply);
    menu->addAction(m_dump);
    menu->addAction(m_report);
}

void MachineActions::retranslate()
{
    m_apply->setText(tr("Apply profile to &several devices…"));
    m_apply->setToolTip(tr("Compare one profile file with several devices of the line, then "
                           "write the checked differences to each and verify them"));
    m_dump->setText(tr("Save &all devices as profiles…"));
    m_dump->setToolTip(tr("Read every device of the line and save each as a profile file into "
                          "one folder"));
    m_report->setText(tr("Commissioning report of the &machine…"));
    m_report->setToolTip(tr("Read every device of the line, then write one commissioning report "
                            "of them all"));
}

void MachineActions::updateActions()
{
    const bool several =
        m_session->connection()->isConnected() && m_session->line()->deviceIds().size() > 1;
    m_apply->setEnabled(several);
    m_dump->setEnabled(several && !isBusy());
    m_report->setEnabled(several && !isBusy());
}

ApplyToDevicesDialog *MachineActions::applyDialog() const
{
    return m_applyDialog;
}

bool MachineActions::isBusy() const
{
    return m_sweep && m_sweep->isBusy();
}

QHash<int, QString> MachineActions::names() const
{
    QHash<int, QString> out;
    DeviceListDock *dock = m_list ? m_list() : nullptr;
    for (int id : m_session->line()->deviceIds()) {
        if (dock)
            out.insert(id, dock->nameOf(id));
    }
    return out;
}

void MachineActions::chooseApply()
{
    auto *dialog =
        new QFileDialog(m_window, tr("Apply a profile to several devices"), QDir::homePath(),
                        tr("StepCom profiles (*.json);;All files (*)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::ExistingFile);
    connect(dialog, &QFileDialog::fileSelected, this, &MachineActions::applyProfileFile);
    dialog->open();
}

bool MachineActions::applyProfileFile(const QString &path)
{
    const ProfileParseResult r =
        ProfileFile::load(path, m_session->map(), ProfileFile::OtherMaps::Accept);
    if (!r.ok()) {
        for (const QString &e : r.errors)
            Q_EMIT finished(false, e);
        Q_EMIT finished(false, tr("The profile cannot be used: nothing was written"));
        return false;
    }
    if (m_applyDialog)
        m_applyDialog->close();
    m_applyDialog = new ApplyToDevicesDialog(m_session, *r.profile, QFileInfo(path).fileName(),
                                             names(), {}, m_window);
    m_applyDialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_applyDialog, &ApplyToDevicesDialog::message, this, &MachineActions::finished);
    m_applyDialog->show(); // not modal: the window's E-STOP stays at hand
    return true;
}

void MachineActions::sweep(const QString &what, const QList<const Parameter *> &params,
                           std::function<void(BusSweep *)> done)
{
    if (!m_session->connection()->isConnected() || isBusy()) {
        Q_EMIT finished(false,
                        tr("%1: connect to the line first, and wait for what runs").arg(what));
        return;
    }
    m_sweep = new BusSweep(m_session, this);
    BusSweep *s = m_sweep;
    connect(s, &BusSweep::finished, this, [this, s, what, done](bool ok) {
        s->deleteLater();
        if (!ok) {
            for (int id : s->ids()) {
                for (const QString &e : s->outcome(id).errors)
                    Q_EMIT finished(false, tr("id %1: %2").arg(id).arg(e));
            }
        }
        done(s);
        updateActions();
    });
    Q_EMIT finished(
        true, tr("%1: reading %n device(s)", nullptr, int(m_session->line()->deviceIds().size()))
                  .arg(what));
    s->start(m_session->line()->deviceIds(), params);
    updateActions();
}

void MachineActions::chooseDump()
{
    auto *dialog =
        new QFileDialog(m_window, tr("Folder for the profiles of every device"), QDir::homePath());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::Directory);
    dialog->setOption(QFileDialog::ShowDirsOnly);
    connect(dialog, &QFileDialog::fileSelected, this, &MachineActions::dumpIntoFolder);
    dialog->open();
}

void MachineActions::dumpIntoFolder(const QString &folder)
{
    if (const QString problem = BusDump::checkDirectory(folder); !problem.isEmpty()) {
        Q_EMIT finished(false, tr("Nothing was saved: %1").arg(problem));
        return;
    }
    const QHash<int, QString> names = this->names();
    const auto params = Profile::profileParameters(m_session->map(), true);
    sweep(tr("Save all devices"), params, [this, folder, names](BusSweep *s) {
        const QDate today = QDate::currentDate();
        for (int id : s->ids()) {
            const ReadOutcome r = s->outcome(id);
            if (!r.ok) {
                Q_EMIT finished(false,
                                tr("id %1 was not saved: it could not be read completely").arg(id));
                continue;
            }
            const BusDump::Saved saved =
                BusDump::save(folder, m_session->map(), id, names.value(id), QString(), r.values,
                              today, m_session->connection()->isSimulator());
            Q_EMIT finished(saved.ok(),
                            saved.ok() ? tr("id %1 saved to %2").arg(id).arg(saved.path)
                                       : tr("id %1 was not saved: %2").arg(id).arg(saved.error));
        }
    });
}

void MachineActions::chooseReport()
{
    auto *notes = new QInputDialog(m_window);
    notes->setAttribute(Qt::WA_DeleteOnClose);
    notes->setWindowTitle(tr("Commissioning report of the machine"));
    notes->setLabelText(tr("Notes for the report (machine, place, who commissioned it):"));
    notes->setOption(QInputDialog::UsePlainTextEditForTextInput);
    connect(notes, &QInputDialog::textValueSelected, this, [this](const QString &text) {
        auto *dialog = new QFileDialog(m_window, tr("Save the commissioning report of the machine"),
                                       QDir::homePath(), tr("PDF (*.pdf);;HTML (*.html)"));
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setAcceptMode(QFileDialog::AcceptSave);
        dialog->setDefaultSuffix(QStringLiteral("pdf"));
        connect(dialog, &QFileDialog::fileSelected, this,
                [this, text](const QString &path) { reportFile(path, QString(), text); });
        dialog->open();
    });
    notes->open();
}

void MachineActions::reportFile(const QString &path, const QString &title, const QString &notes)
{
    const QHash<int, QString> names = this->names();
    sweep(tr("Commissioning report"), m_session->map().holdings(),
          [this, path, title, notes, names](BusSweep *s) {
              if (!s->allOk()) {
                  Q_EMIT finished(false,
                                  tr("No report: not every device could be read completely"));
                  return;
              }
              QList<ReportInput> inputs;
              const QDateTime now = QDateTime::currentDateTime();
              for (int id : s->ids())
                  inputs << sheet(id, s->outcome(id).values, names.value(id), now);
              const MachineReport report(inputs, title, notes, Language::instance().current());
              if (const QString e = report.write(path); !e.isEmpty()) {
                  Q_EMIT finished(false, e);
                  return;
              }
              Q_EMIT finished(true, tr("Commissioning report of %n device(s) written to %1",
                                       nullptr, int(inputs.size()))
                                        .arg(path));
          });
}

ReportInput MachineActions::sheet(int id, const QHash<QString, qint64> &values, const QString &name,
                                  const QDateTime &read) const
{
    ReportInput input = ReportInput::fromSession(*m_session, id, values, read);
    input.title = name;
    return input;
}

QList<ReportInput> MachineActions::knownSheets() const
{
    QList<int> ids = m_session->line()->deviceIds();
    if (ids.isEmpty())
        ids << m_session->line()->deviceInView();
    const QHash<int, QString> names = this->names();
    QList<ReportInput> sheets;
    for (int id : std::as_const(ids)) {
        const QHash<QString, qint64> values = m_session->line()->knownValues(id);
        // Only the live status seen (never in view): no sheet to speak of.
        const bool settings =
            std::any_of(values.keyBegin(), values.keyEnd(), [this](const QString &key) {
                const Parameter *p = m_session->map().find(key);
                return p && p->writable();
            });
        if (settings)
            sheets << sheet(id, values, names.value(id), {});
    }
    return sheets;
}

std::optional<ReportInput> MachineActions::profileSheet(const QString &path,
                                                        QStringList *problems) const
{
    return ReportInput::fromProfileFile(m_session->map(), path, Language::instance().current(),
                                        problems);
}

ReportSheets MachineActions::reportSheets()
{
    const QPointer<MachineActions> self(this);
    return {[self] { return self ? self->knownSheets() : QList<ReportInput>{}; },
            [self](const QString &path, QStringList *problems) {
                return self ? self->profileSheet(path, problems) : std::nullopt;
            }};
}

} // namespace stepcom

#include "pages/checklistpage.h"

#include "commissioning/checklistfile.h"
#include "profile/profile.h"
#include "profile/settingsfingerprint.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "widgets/checklist/checklistbacklashstep.h"
#include "widgets/checklist/checklistcalibrationstep.h"
#include "widgets/checklist/checklistdirectionstep.h"
#include "widgets/checklist/checklistflashstep.h"
#include "widgets/checklist/checklistinputstep.h"
#include "widgets/checklist/checklistmotionstep.h"
#include "widgets/checklist/checklistproofstep.h"
#include "widgets/checklist/checklistruninstep.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kGroup = QStringLiteral("checklist");
const QString kProfile = QStringLiteral("profile");

ChecklistStepWidget *makeStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &s,
                              QWidget *parent)
{
    using Kind = ChecklistStep::Kind;
    switch (s.kind) {
    case Kind::Direction:
        return new ChecklistDirectionStep(session, writes, s, parent);
    case Kind::Calibration:
        return new ChecklistCalibrationStep(session, writes, s, parent);
    case Kind::LimitPositive:
    case Kind::LimitNegative:
    case Kind::HomeInput:
        return new ChecklistInputStep(session, writes, s, parent);
    case Kind::KeepsSteps:
        return new ChecklistProofStep(session, writes, s, parent);
    case Kind::Backlash:
        return new ChecklistBacklashStep(session, writes, s, parent);
    case Kind::Homing:
    case Kind::HomingOrder:
    case Kind::Interpolation:
        return new ChecklistMotionStep(session, writes, s, parent);
    case Kind::RunIn:
        return new ChecklistRunInStep(session, writes, s, parent);
    case Kind::SaveToFlash:
        break;
    }
    return new ChecklistFlashStep(session, writes, s, parent);
}

} // namespace

ChecklistPage::ChecklistPage(DeviceSession *session, WriteFlow *writes, QWidget *parent)
    : Page(session, parent)
    , m_writes(writes)
    , m_profileLabel(new QLabel(this))
    , m_chooseProfile(new QPushButton(this))
    , m_summary(new QLabel(this))
    , m_problem(new QLabel(this))
    , m_list(new QListWidget(this))
    , m_stack(new QStackedWidget(this))
{
    setObjectName(QStringLiteral("checklistPage"));
    m_checklist = Checklist::forMap(session->map());
    m_profileLabel->setWordWrap(true);
    m_profileLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setWordWrap(true);
    m_problem->setWordWrap(true);
    m_problem->setObjectName(QStringLiteral("checklistProblem"));
    m_chooseProfile->setObjectName(QStringLiteral("chooseChecklistProfile"));
    m_chooseProfile->setAutoDefault(false);
    // Long step titles wrap instead of widening the list past a small screen.
    m_list->setWordWrap(true);
    m_list->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_list->setResizeMode(QListView::Adjust);
    auto *top = new QHBoxLayout;
    top->addWidget(m_profileLabel, 1);
    top->addWidget(m_chooseProfile, 0, Qt::AlignTop);

    // The whole page scrolls: every control stays reachable at 1024×600 and at 200%.
    QWidget *content = scrollableContent();
    for (QWidget *w : std::initializer_list<QWidget *>{m_profileLabel, m_chooseProfile, m_summary,
                                                       m_problem, m_list, m_stack})
        w->setParent(content);
    auto *splitter = new QSplitter(content);
    splitter->addWidget(m_list);
    splitter->addWidget(m_stack);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(content);
    layout->addLayout(top);
    layout->addWidget(m_summary);
    layout->addWidget(m_problem);
    layout->addWidget(splitter, 1);

    for (const ChecklistStep &s : m_checklist.steps()) {
        ChecklistStepWidget *w = makeStep(session, writes, s, m_stack);
        m_widgets.insert(s.id, w);
        m_stack->addWidget(w);
        auto *item = new QListWidgetItem(m_list);
        item->setData(Qt::UserRole, s.id);
        connect(w, &ChecklistStepWidget::recorded, this, &ChecklistPage::onRecorded);
        if (auto *proof = qobject_cast<ChecklistProofStep *>(w)) {
            connect(proof, &ChecklistProofStep::stepsLost, this, &ChecklistPage::stepsLost);
            connect(proof, &ChecklistProofStep::stepsKept, this, &ChecklistPage::stepsKept);
        }
        if (auto *runIn = qobject_cast<ChecklistRunInStep *>(w))
            connect(runIn, &ChecklistRunInStep::sequencePageWanted, this,
                    &ChecklistPage::sequencePageWanted);
    }
    connect(m_list, &QListWidget::currentRowChanged, m_stack, &QStackedWidget::setCurrentIndex);
    connect(m_chooseProfile, &QPushButton::clicked, this, &ChecklistPage::chooseProfile);

    QSettings settings;
    settings.beginGroup(kGroup);
    m_profile = settings.value(kProfile).toString();
    load();
    retranslate();
}

void ChecklistPage::writeRecommendation(int motor)
{
    const QString id = Checklist::stepId(ChecklistStep::Kind::KeepsSteps, motor);
    selectStep(id);
    if (auto *proof = qobject_cast<ChecklistProofStep *>(m_widgets.value(id)))
        proof->writeRecommendation();
}

void ChecklistPage::recordRunIn(StepResult result, const QList<ChecklistMeasurement> &measurements,
                                const QString &summary)
{
    const QString id = Checklist::stepId(ChecklistStep::Kind::RunIn);
    if (auto *runIn = qobject_cast<ChecklistRunInStep *>(m_widgets.value(id)))
        runIn->record(result, measurements, summary);
}

QString ChecklistPage::defaultFile()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("machine.checklist.json"));
}

QString ChecklistPage::title() const
{
    return tr("Commissioning checklist");
}

void ChecklistPage::setProfilePath(const QString &path)
{
    m_profile = path;
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue(kProfile, path);
    load();
    retranslate();
}

void ChecklistPage::load()
{
    m_file = m_profile.isEmpty() ? defaultFile() : ChecklistFile::pathFor(m_profile);
    m_checklist = Checklist::forMap(session()->map());
    m_fileUsable = true;
    m_problem->clear();
    if (QFileInfo::exists(m_file)) {
        const ChecklistParseResult r = ChecklistFile::load(m_file, session()->map());
        if (r.ok()) {
            m_checklist = *r.checklist;
        } else {
            m_fileUsable = false; // its results are not lost by saving over it
            m_problem->setText(tr("The checklist file %1 cannot be used, and nothing is saved "
                                  "over it: %2")
                                   .arg(m_file, r.errors.join(QLatin1String("; "))));
        }
    }
    if (m_checklist.machine.isEmpty() && !m_profile.isEmpty())
        m_checklist.machine = QFileInfo(m_profile).completeBaseName();
    refreshList();
    // Resume where it stopped: the first step not run.
    const ChecklistStep *next = m_checklist.nextPending();
    selectStep(next ? next->id : m_checklist.steps().constFirst().id);
}

void ChecklistPage::onRecorded(const QString &id, StepResult result,
                               const QList<ChecklistMeasurement> &measurements, const QString &note)
{
    if (const QString e = m_checklist.record(id, result, measurements, note); !e.isEmpty()) {
        m_problem->setText(e);
        return;
    }
    Q_EMIT resultRecorded(
        QStringLiteral("checklist %1: %2").arg(id, ChecklistStep::resultWord(result)));
    // The settings this result was had with: the report warns when the machine's differ now.
    QHash<QString, qint64> values;
    for (const Parameter *p : Profile::profileParameters(session()->map(), false)) {
        if (const auto v = session()->parameters()->store()->deviceValue(p->key))
            values.insert(p->key, *v);
    }
    if (values.size() == Profile::profileParameters(session()->map(), false).size())
        m_checklist.settingsFingerprint =
            SettingsFingerprint::shortHash(session()->map(), SettingsFingerprint::ordered(values));
    if (m_fileUsable) {
        QDir().mkpath(QFileInfo(m_file).absolutePath());
        if (const QString e = ChecklistFile::save(m_file, m_checklist); !e.isEmpty())
            m_problem->setText(tr("The result is not saved: %1").arg(e));
        else
            m_problem->clear();
    }
    refreshList();
}

void ChecklistPage::refreshList()
{
    for (int i = 0; i < m_list->count(); ++i) {
        QListWidgetItem *item = m_list->item(i);
        const ChecklistStep *s = m_checklist.step(item->data(Qt::UserRole).toString());
        if (!s)
            continue;
        item->setText(
            QStringLiteral("%1 — %2").arg(s->title(), ChecklistStep::resultLabel(s->result())));
        const ChecklistAttempt *a = s->latest();
        item->setToolTip(a ? QLocale().toString(a->time.toLocalTime(), QLocale::ShortFormat) +
                                 (a->note.isEmpty() ? QString() : QStringLiteral(": ") + a->note)
                           : QString());
    }
    m_summary->setText(QStringLiteral("%1 — %2").arg(Checklist::verdictText(m_checklist.verdict()),
                                                     m_checklist.summary()));
    Q_EMIT progressChanged();
}

Page::Progress ChecklistPage::progress() const
{
    // An unreadable file: what was passed before is not known, so no count is shown.
    return {m_checklist.count(StepResult::Passed), int(m_checklist.steps().size()), m_fileUsable};
}

std::optional<std::pair<Checklist, QString>> ChecklistPage::reportChecklist() const
{
    if (m_checklist.verdict() == Checklist::Verdict::NotStarted)
        return std::nullopt;
    return std::make_pair(m_checklist, QFileInfo(m_file).fileName());
}

QString ChecklistPage::currentStepId() const
{
    const QListWidgetItem *item = m_list->currentItem();
    return item ? item->data(Qt::UserRole).toString() : QString();
}

void ChecklistPage::selectStep(const QString &id)
{
    for (int i = 0; i < m_list->count(); ++i) {
        if (m_list->item(i)->data(Qt::UserRole).toString() == id)
            m_list->setCurrentRow(i);
    }
}

QString ChecklistPage::summaryText() const
{
    return m_summary->text();
}

QString ChecklistPage::problemText() const
{
    return m_problem->text();
}

void ChecklistPage::chooseProfile()
{
    auto *dialog = new QFileDialog(this, tr("The machine's profile"),
                                   m_profile.isEmpty() ? QDir::homePath()
                                                       : QFileInfo(m_profile).absolutePath(),
                                   tr("StepCom profiles (*.json)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setFileMode(QFileDialog::AnyFile);
    connect(dialog, &QFileDialog::fileSelected, this, &ChecklistPage::setProfilePath);
    dialog->open();
}

void ChecklistPage::retranslate()
{
    // File names on the page, the whole paths in the tooltip (no path in /tmp/...
    // between the technician and the steps).
    m_profileLabel->setText(
        m_profile.isEmpty()
            ? tr("No profile chosen: the progress is kept in %1. Choose the machine's profile to "
                 "keep it beside it.")
                  .arg(QFileInfo(m_file).fileName())
            : tr("Profile %1 — the progress is kept in %2")
                  .arg(QFileInfo(m_profile).fileName(), QFileInfo(m_file).fileName()));
    m_profileLabel->setToolTip(m_profile.isEmpty() ? m_file
                                                   : m_profile + QLatin1Char('\n') + m_file);
    m_chooseProfile->setText(tr("Choose &profile…"));
    for (ChecklistStepWidget *w : std::as_const(m_widgets))
        w->retranslate();
    refreshList();
}

} // namespace stepcom

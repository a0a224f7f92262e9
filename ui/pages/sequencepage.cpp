#include "pages/sequencepage.h"

#include "base/errorbox.h"
#include "map/parameter.h"
#include "sequence/sequenceparser.h"
#include "sequence/sequencerunner.h"
#include "sequence/sequencewriter.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/plots/movehere.h"
#include "widgets/plots/xyplot.h"
#include "widgets/sequence/sequenceeditor.h"
#include "widgets/sequence/sequencepoints.h"
#include "widgets/sequence/sequencerunpanel.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

namespace stepcom {

namespace {

using StepKind = SequenceStep::Kind;

// The path the steps take in the XY plane (motor 1 across, motor 2 up), each loop walked once,
// from `start` where the poll knows it; an axis whose position is not known yet draws nothing
// until a step sets it. A homing ends at 0, where the controller counts from.
QList<QPointF> walk(const Sequence &s, QMap<int, double> at)
{
    QList<QPointF> out;
    const auto add = [&] {
        if (at.contains(1) && at.contains(2)) {
            const QPointF p(at.value(1), at.value(2));
            if (out.isEmpty() || out.last() != p)
                out << p;
        }
    };
    add();
    for (const SequenceStep *step : s.allSteps()) {
        switch (step->kind) {
        case StepKind::Home:
            for (int m : step->homeInOrder ? QList<int>{1, 2} : step->homeMotors)
                at[m] = 0;
            break;
        case StepKind::MoveTo:
            for (auto it = step->axes.begin(); it != step->axes.end(); ++it)
                at[it.key()] = it.value();
            break;
        case StepKind::MoveBy:
            for (auto it = step->axes.begin(); it != step->axes.end(); ++it) {
                if (at.contains(it.key()))
                    at[it.key()] += it.value();
            }
            break;
        default:
            continue;
        }
        add();
    }
    return out;
}

QGroupBox *group(QWidget *parent, const char *name, QWidget *content)
{
    auto *box = new QGroupBox(parent);
    box->setObjectName(QLatin1String(name));
    auto *l = new QVBoxLayout(box);
    l->addWidget(content);
    return box;
}

} // namespace

SequencePage::SequencePage(DeviceSession *session, QWidget *parent)
    : Page(session, parent)
    , m_points(new SequencePoints(session, this))
    , m_editor(new SequenceEditor(session->map(), this))
    , m_run(new SequenceRunPanel(session, this))
    , m_preview(new XYPlot(this))
    , m_file(new QLabel(this))
    , m_limits(new QLabel(this))
    , m_problemLabel(new QLabel(this))
    , m_hint(new QLabel(this))
    , m_outputsOff(new QCheckBox(this))
    , m_new(new QPushButton(this))
    , m_open(new QPushButton(this))
    , m_save(new QPushButton(this))
    , m_saveAs(new QPushButton(this))
{
    m_file->setObjectName(QStringLiteral("sequenceFile"));
    m_limits->setObjectName(QStringLiteral("sequenceLimits"));
    m_limits->setWordWrap(true);
    m_problemLabel->setObjectName(QStringLiteral("sequenceProblems"));
    m_problemLabel->setWordWrap(true);
    m_problemLabel->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_problemLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_hint->setObjectName(QStringLiteral("sequenceHint"));
    m_hint->setWordWrap(true);
    m_outputsOff->setObjectName(QStringLiteral("sequenceOutputsOff"));
    m_new->setObjectName(QStringLiteral("sequenceNew"));
    m_open->setObjectName(QStringLiteral("sequenceOpen"));
    m_save->setObjectName(QStringLiteral("sequenceSave"));
    m_saveAs->setObjectName(QStringLiteral("sequenceSaveAs"));
    for (QPushButton *b : {m_new, m_open, m_save, m_saveAs})
        b->setAutoDefault(false);
    m_preview->setObjectName(QStringLiteral("sequencePreview"));
    m_preview->setMinimumSize(220, 180);

    QWidget *content = scrollableContent();
    m_file->setWordWrap(true);
    auto *files = new QHBoxLayout;
    files->addWidget(m_new);
    files->addWidget(m_open);
    files->addWidget(m_save);
    files->addWidget(m_saveAs);
    files->addStretch(1);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(group(this, "pointsGroup", m_points), 1);
    leftLayout->addWidget(group(this, "previewGroup", m_preview), 1);
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    auto *steps = new QWidget(this);
    auto *stepsLayout = new QVBoxLayout(steps);
    stepsLayout->setContentsMargins(0, 0, 0, 0);
    stepsLayout->addWidget(m_editor, 1);
    stepsLayout->addWidget(m_outputsOff);
    stepsLayout->addWidget(m_limits);
    // Run above the steps: while the cycle runs its controls and counters stay in view.
    rightLayout->addWidget(group(this, "runGroup", m_run));
    rightLayout->addWidget(group(this, "stepsGroup", steps), 1);
    m_groups = {findChild<QGroupBox *>(QStringLiteral("pointsGroup")),
                findChild<QGroupBox *>(QStringLiteral("previewGroup")),
                findChild<QGroupBox *>(QStringLiteral("stepsGroup")),
                findChild<QGroupBox *>(QStringLiteral("runGroup"))};
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(left);
    split->addWidget(right);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    split->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(content);
    layout->addLayout(files);
    layout->addWidget(m_file);
    layout->addWidget(m_problemLabel);
    layout->addWidget(m_hint);
    layout->addWidget(split, 1);

    m_run->setSource([this] { return m_problems.isEmpty() ? m_valid : std::nullopt; });
    // A right-click on the preview: move there, or take the point clicked as a taught one.
    m_moveHere = new MoveHere(session, m_preview, this);
    m_moveHere->setExtra([this](QMenu *menu, const QPointF &at) {
        QAction *teach = menu->addAction(
            tr("Teach this point (%1, %2)").arg(at.x(), 0, 'f', 2).arg(at.y(), 0, 'f', 2));
        teach->setObjectName(QStringLiteral("teachClicked"));
        teach->setEnabled(!m_run->isBusy());
        connect(teach, &QAction::triggered, this, [this, at] {
            const QString name = m_points->addPoint({{1, at.x()}, {2, at.y()}});
            m_points->say(tr("Point %1 taught at the place clicked.").arg(name), false);
            edited();
        });
    });
    connect(m_moveHere, &MoveHere::said, this,
            [this](const QString &t) { m_points->say(t, false); });
    connect(m_points, &SequencePoints::changed, this, &SequencePage::edited);
    connect(m_points, &SequencePoints::renamed, m_editor, &SequenceEditor::renamePoint);
    connect(m_editor, &SequenceEditor::changed, this, &SequencePage::edited);
    connect(m_outputsOff, &QCheckBox::toggled, this, &SequencePage::edited);
    connect(m_run->cyclesBox(), &QSpinBox::valueChanged, this, &SequencePage::judge);
    connect(m_run, &SequenceRunPanel::currentStepChanged, m_editor, &SequenceEditor::setCurrent);
    connect(m_run, &SequenceRunPanel::busyChanged, this, [this](bool busy) {
        m_points->setEditable(!busy);
        m_editor->setEditable(!busy);
        for (QWidget *w : std::initializer_list<QWidget *>{m_new, m_open, m_outputsOff})
            w->setEnabled(!busy);
        if (!busy)
            judge(); // what the run changed (references) judged again
    });
    connect(m_run, &SequenceRunPanel::stripText, this, &SequencePage::runText);
    connect(m_new, &QPushButton::clicked, this, [this] {
        if (mayDiscard())
            newSequence();
    });
    connect(m_open, &QPushButton::clicked, this, &SequencePage::chooseOpen);
    connect(m_save, &QPushButton::clicked, this, [this] { chooseSave(false); });
    connect(m_saveAs, &QPushButton::clicked, this, [this] { chooseSave(true); });
    // A reference gained or lost, a limit changed: what may run changes with them.
    connect(session, &DeviceSession::travelLimitsChanged, this, [this] {
        if (!m_run->isBusy())
            judge();
    });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &SequencePage::judge);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &key) {
                if (key.endsWith(QLatin1String(".position")))
                    updateMarker();
            });
    retranslate();
    judge();
}

QString SequencePage::title() const
{
    return tr("Sequence");
}

void SequencePage::setConfirmer(std::function<bool(const QString &)> confirm)
{
    m_confirm = confirm;
    m_run->setConfirmer(std::move(confirm));
}

Sequence SequencePage::edit() const
{
    Sequence s;
    s.fileName = m_path.isEmpty() ? tr("(new sequence)") : QFileInfo(m_path).fileName();
    s.points = m_points->points();
    s.limits = m_fileLimits;
    s.outputsOffOnStop = m_outputsOff->isChecked();
    s.steps = m_editor->steps();
    return s;
}

void SequencePage::edited()
{
    m_modified = true;
    showFileName();
    judge();
}

void SequencePage::judge()
{
    const Sequence s = edit();
    if (s.steps.isEmpty()) {
        // Nothing built yet is no problem to show in red: what to do first, and Run waits.
        m_valid.reset();
        m_problems.clear();
        m_editor->setPointNames(m_points->points().keys());
        m_editor->setProblems({});
        m_problemLabel->hide();
        m_hint->setText(tr("No steps yet: jog to each point and teach it, then Add step "
                           "(or open a .stepseq file)."));
        m_hint->show();
        m_run->setRunnable(false);
        redrawPreview();
        return;
    }
    m_hint->hide();
    QStringList problems;
    // Written out and read back as a file: the parser's judgement, word for word.
    m_valid = SequenceParser::parse(SequenceWriter::write(s, session()->map()), s.fileName,
                                    session()->map(), &problems);
    if (m_valid) {
        m_valid->fileName = s.fileName;
        problems << m_run->runner()->check(*m_valid, m_run->cyclesBox()->value());
        m_editor->setSteps(m_valid->steps);
    }
    m_problems = problems;
    m_editor->setPointNames(m_points->points().keys());
    m_editor->setProblems(problems);
    m_problemLabel->setText(problems.join(QLatin1Char('\n')));
    m_problemLabel->setVisible(!problems.isEmpty());
    m_run->setRunnable(m_valid && problems.isEmpty());
    redrawPreview();
}

void SequencePage::redrawPreview()
{
    QList<QPointF> dots;
    for (const auto &p : m_points->points()) {
        if (p.contains(1) && p.contains(2))
            dots << QPointF(p.value(1), p.value(2));
    }
    m_preview->setPoints(QStringLiteral("points"), dots, tr("Points"));
    QMap<int, double> start;
    const ParameterStore *store = session()->parameters()->store();
    for (int m = 1; m <= 2; ++m) {
        const Parameter *p = TravelLimits::positionParameter(session()->map(), m);
        const auto raw =
            p && session()->connection()->isConnected() ? store->deviceValue(p->key) : std::nullopt;
        if (raw)
            start.insert(m, p->toEngineering(*raw));
    }
    m_preview->setPath(QStringLiteral("path"), m_valid ? walk(*m_valid, start) : QList<QPointF>(),
                       tr("Path"));
    updateMarker();
}

void SequencePage::updateMarker()
{
    const ParameterStore *store = session()->parameters()->store();
    const Parameter *x = TravelLimits::positionParameter(session()->map(), 1);
    const Parameter *y = TravelLimits::positionParameter(session()->map(), 2);
    const bool connected = session()->connection()->isConnected();
    const auto rx = x && connected ? store->deviceValue(x->key) : std::nullopt;
    const auto ry = y && connected ? store->deviceValue(y->key) : std::nullopt;
    if (rx && ry)
        m_preview->setMarker(QPointF(x->toEngineering(*rx), y->toEngineering(*ry)));
    else
        m_preview->clearMarker(); // not known: no marker, never a guess
}

bool SequencePage::mayDiscard()
{
    if (!m_modified)
        return true;
    const QString q = tr("The sequence has changes that are not saved. Discard them?");
    return m_confirm
               ? m_confirm(q)
               : QMessageBox::question(this, title(), q, QMessageBox::Discard | QMessageBox::Cancel,
                                       QMessageBox::Cancel) == QMessageBox::Discard;
}

void SequencePage::newSequence()
{
    m_path.clear();
    m_fileLimits = {};
    m_points->setPoints({});
    m_outputsOff->setChecked(false);
    m_editor->setSteps({});
    m_modified = false;
    showFileName();
    judge();
}

bool SequencePage::openFile(const QString &path)
{
    if (m_run->isBusy())
        return false;
    QStringList errors;
    const std::optional<Sequence> s = SequenceParser::load(path, session()->map(), &errors);
    if (!s) {
        showErrorBox(m_errorBox, this, QStringLiteral("sequenceError"), tr("Open a sequence"),
                     errors, tr("%1 was not opened: the sequence is as it was.").arg(path));
        return false;
    }
    m_path = path;
    m_fileLimits = s->limits;
    const QSignalBlocker blockOutputs(m_outputsOff);
    m_outputsOff->setChecked(s->outputsOffOnStop);
    m_points->setPoints(s->points);
    m_editor->setSteps(s->steps);
    m_modified = false;
    showFileName();
    judge();
    return true;
}

bool SequencePage::saveFile(const QString &path)
{
    if (!m_valid) {
        showErrorBox(m_errorBox, this, QStringLiteral("sequenceError"), tr("Save the sequence"),
                     m_problems, tr("Not saved: the sequence could not be read back as a file."));
        return false;
    }
    Sequence s = *m_valid;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(SequenceWriter::write(s, session()->map())) < 0 || !file.commit()) {
        showErrorBox(m_errorBox, this, QStringLiteral("sequenceError"), tr("Save the sequence"),
                     {tr("%1 was not saved: %2").arg(path, file.errorString())},
                     tr("Any earlier file there is as it was."));
        return false;
    }
    m_path = path;
    m_modified = false;
    showFileName();
    judge(); // the file's name is in the messages
    return true;
}

void SequencePage::chooseOpen()
{
    if (!mayDiscard())
        return;
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open a sequence"), QFileInfo(m_path).absolutePath(),
                                     tr("StepCom sequences (*.stepseq);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

void SequencePage::chooseSave(bool as)
{
    QString path = m_path;
    if (as || path.isEmpty()) {
        path = QFileDialog::getSaveFileName(this, tr("Save the sequence"),
                                            path.isEmpty() ? QStringLiteral("cycle.stepseq") : path,
                                            tr("StepCom sequences (*.stepseq)"));
        if (path.isEmpty())
            return;
        if (QFileInfo(path).suffix().isEmpty())
            path += QStringLiteral(".stepseq");
    }
    saveFile(path);
}

void SequencePage::showFileName()
{
    const QString name =
        m_path.isEmpty() ? tr("a new sequence, not saved") : QDir::toNativeSeparators(m_path);
    m_file->setText(tr("Sequence: %1%2").arg(name, m_modified ? tr(" (changed)") : QString()));
    QStringList limits;
    for (auto it = m_fileLimits.axes().begin(); it != m_fileLimits.axes().end(); ++it) {
        const Parameter *p = TravelLimits::positionParameter(session()->map(), it.key());
        if (p)
            limits << tr("motor %1 %2 .. %3 %4")
                          .arg(it.key())
                          .arg(it->min ? p->formatRaw(*it->min) : QStringLiteral("−∞"),
                               it->max ? p->formatRaw(*it->max) : QStringLiteral("+∞"), p->unit);
    }
    m_limits->setText(limits.isEmpty()
                          ? tr("The file sets no limits of its own; StepCom's travel limits "
                               "(Jog page) apply.")
                          : tr("The file's limits: %1; StepCom's travel limits apply too.")
                                .arg(limits.join(QLatin1String("; "))));
}

void SequencePage::retranslate()
{
    static_cast<QGroupBox *>(m_groups[0])->setTitle(tr("Points"));
    static_cast<QGroupBox *>(m_groups[1])->setTitle(tr("Path (motor 1 across, motor 2 up)"));
    static_cast<QGroupBox *>(m_groups[2])->setTitle(tr("Steps"));
    static_cast<QGroupBox *>(m_groups[3])->setTitle(tr("Run"));
    m_outputsOff->setText(tr("All outputs &off when the run stops"));
    m_new->setText(tr("&New"));
    m_open->setText(tr("&Open…"));
    m_save->setText(tr("Sa&ve"));
    m_saveAs->setText(tr("Save &as…"));
    m_preview->setAxisTitles(tr("motor 1"), tr("motor 2"));
    showFileName();
    judge(); // the problems in the new language
}

} // namespace stepcom

#include "pages/plotpage.h"

#include "device/statusrecorder.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionstatus.h"
#include "widgets/fields/wrappingrow.h"
#include "widgets/plots/movehere.h"
#include "widgets/plots/positionplot.h"
#include "widgets/plots/xyplot.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <cmath>

namespace stepcom {

namespace {

const QString kSettingsGroup = QStringLiteral("plots");
const QString kLastDir = QStringLiteral("lastDirectory");

QString nativePath(const QString &path)
{
    return QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath());
}

} // namespace

PlotPage::PlotPage(DeviceSession *session, QWidget *parent)
    : Page(session, parent)
    , m_recorder(session->status()->recorder()) // the session records; this page shows and saves it
{
    m_positions = new PositionPlot(m_recorder, this);
    m_xy = new XYPlot(this);

    auto *layout = new QVBoxLayout(this);
    // The plot's controls, then the files': in two rows on a narrow page (1366×768 at ×1.5).
    auto *controls = new WrappingRow(this);
    QHBoxLayout *bar = controls->first();
    const auto button = [this, &bar](const char *name) {
        auto *b = new QPushButton(this);
        b->setObjectName(QLatin1String(name));
        bar->addWidget(b);
        return b;
    };
    m_pause = button("pauseButton");
    m_pause->setCheckable(true);
    m_fit = button("fitButton");
    m_clear = button("clearTraceButton");
    m_windowLabel = new QLabel(this);
    m_window = new QSpinBox(this);
    m_window->setRange(5, int(m_recorder->maxAgeMs() / 1000));
    m_window->setValue(m_positions->windowSeconds());
    m_windowLabel->setBuddy(m_window);
    bar->addWidget(m_windowLabel);
    bar->addWidget(m_window);
    bar->addStretch(1);
    bar = controls->second();
    bar->addStretch(1);
    m_exportPng = button("exportPngButton");
    m_exportCsv = button("exportCsvButton");
    m_record = button("recordButton");
    m_record->setCheckable(true);
    layout->addWidget(controls);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("recordingStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->addWidget(m_positions);
    m_splitter->addWidget(m_xy);
    // A right-click on the XY view: move both axes there (referenced, inside the limits).
    m_moveHere = new MoveHere(session, m_xy, this);
    connect(m_moveHere, &MoveHere::said, m_status, &QLabel::setText);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);
    // Never so low that the charts cut their axes' numbers and titles to "…" (1366×768 at ×1.5
    // did): a low window scrolls the page instead. Scaled up, the charts need more lines for
    // the same text (measured: 13 lines whole at ×1, 17 at ×1.5).
    m_splitter->setMinimumHeight(fontMetrics().height() * (devicePixelRatioF() > 1.2 ? 17 : 13));
    layout->addWidget(m_splitter, 1);
    // Without a second motor there is no plane to draw.
    m_xy->setVisible(m_recorder->motorCount() >= 2);
    m_clear->setVisible(m_recorder->motorCount() >= 2);

    connect(m_pause, &QPushButton::toggled, this, &PlotPage::setPaused);
    connect(m_positions, &PositionPlot::pausedChanged, this, [this](bool paused) {
        m_pause->setChecked(paused);
        retranslate();
        if (!paused)
            updateXY(); // catch up with what was sampled meanwhile
    });
    connect(m_fit, &QPushButton::clicked, this, &PlotPage::fit);
    connect(m_clear, &QPushButton::clicked, this, &PlotPage::clearTrace);
    connect(m_window, &QSpinBox::valueChanged, m_positions, &PositionPlot::setWindowSeconds);
    connect(m_exportPng, &QPushButton::clicked, this, [this] { askForFile(FileAction::Png); });
    connect(m_exportCsv, &QPushButton::clicked, this, [this] { askForFile(FileAction::Csv); });
    connect(m_record, &QPushButton::clicked, this, [this] {
        if (m_recorder->isRecording())
            stopRecording();
        else
            askForFile(FileAction::Record);
        m_record->setChecked(m_recorder->isRecording());
    });
    connect(m_recorder, &StatusRecorder::recordingChanged, this, [this](bool recording) {
        m_record->setChecked(recording);
        if (recording)
            m_statusTimer.start();
        else
            m_statusTimer.stop();
        retranslate();
    });
    connect(m_recorder, &StatusRecorder::recordingFailed, this, &PlotPage::showError);
    m_statusTimer.setInterval(1000);
    connect(&m_statusTimer, &QTimer::timeout, this, &PlotPage::updateRecordingStatus);

    m_xyTimer.setSingleShot(true);
    m_xyTimer.setInterval(200);
    connect(&m_xyTimer, &QTimer::timeout, this, &PlotPage::updateXY);
    connect(m_recorder, &StatusRecorder::sampleAdded, this, &PlotPage::scheduleXY);
    // Cleared (a replay shows another moment): the trace starts again with it.
    connect(m_recorder, &StatusRecorder::cleared, this, [this] {
        m_xy->clearTrace();
        m_xy->clearMarker();
        m_fedUntilMs = -1;
    });
    connect(session->connection(), &SessionConnection::disconnected, m_xy, &XYPlot::clearMarker);
    retranslate();
}

PlotPage::~PlotPage() = default;

QString PlotPage::title() const
{
    return tr("Plots");
}

void PlotPage::setPaused(bool paused)
{
    m_positions->setPaused(paused);
}

bool PlotPage::isPaused() const
{
    return m_positions->isPaused();
}

void PlotPage::fit()
{
    m_positions->fit();
    m_xy->fit();
}

void PlotPage::clearTrace()
{
    m_xy->clearTrace();
}

void PlotPage::showTrace(const QList<QPointF> &path)
{
    m_xy->clearTrace();
    m_xy->appendTrace(path);
    if (path.isEmpty())
        m_xy->clearMarker();
    else
        m_xy->setMarker(path.last());
    m_fedUntilMs = m_recorder->isEmpty() ? -1 : m_recorder->last().elapsedMs;
}

void PlotPage::scheduleXY()
{
    if (!m_xyTimer.isActive())
        m_xyTimer.start();
}

void PlotPage::updateXY()
{
    if (isPaused() || m_recorder->isEmpty() || m_recorder->motorCount() < 2)
        return;
    QList<QPointF> points;
    for (int i = m_recorder->indexAtOrAfter(m_fedUntilMs + 1); i < m_recorder->size(); ++i) {
        const StatusSample &s = m_recorder->at(i);
        const double x = s.positions.value(0, qQNaN());
        const double y = s.positions.value(1, qQNaN());
        if (!std::isnan(x) && !std::isnan(y))
            points << QPointF(x, y);
    }
    m_fedUntilMs = m_recorder->last().elapsedMs;
    m_xy->appendTrace(points);
    if (!points.isEmpty())
        m_xy->setMarker(points.last());
}

bool PlotPage::exportPng(const QString &path, QString *error)
{
    m_xy->flush();
    const QPixmap picture = m_splitter->grab();
    if (picture.isNull() || !picture.save(path, "PNG")) {
        if (error)
            *error = tr("Cannot write the picture “%1”.").arg(nativePath(path));
        return false;
    }
    return true;
}

bool PlotPage::exportCsv(const QString &path, QString *error)
{
    return m_positions->exportCsv(path, error);
}

bool PlotPage::startRecording(const QString &path, QString *error)
{
    m_error.clear();
    const bool ok = m_recorder->startRecording(path, error);
    updateRecordingStatus();
    return ok;
}

void PlotPage::stopRecording()
{
    m_recorder->stopRecording();
    updateRecordingStatus();
}

QString PlotPage::recordingStatus() const
{
    return m_status->text();
}

void PlotPage::askForFile(FileAction action)
{
    if (m_dialog)
        m_dialog->close();
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    QString dir = settings.value(kLastDir).toString();
    if (dir.isEmpty() || !QFileInfo(dir).isDir())
        dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString stamp = QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"));
    const bool png = action == FileAction::Png;
    auto *dialog = new QFileDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setFileMode(QFileDialog::AnyFile);
    dialog->setWindowTitle(action == FileAction::Record ? tr("Record status to CSV")
                           : png                        ? tr("Export plots as PNG")
                                                        : tr("Export visible samples as CSV"));
    dialog->setNameFilter(png ? tr("PNG images (*.png)") : tr("CSV files (*.csv)"));
    dialog->setDefaultSuffix(png ? QStringLiteral("png") : QStringLiteral("csv"));
    dialog->setDirectory(dir);
    dialog->selectFile((action == FileAction::Record ? QStringLiteral("stepcom-recording-")
                        : png                        ? QStringLiteral("stepcom-plots-")
                                                     : QStringLiteral("stepcom-status-")) +
                       stamp + (png ? QStringLiteral(".png") : QStringLiteral(".csv")));
    connect(dialog, &QFileDialog::fileSelected, this,
            [this, action](const QString &path) { fileChosen(action, path); });
    m_dialog = dialog;
    dialog->open();
}

void PlotPage::fileChosen(FileAction action, const QString &path)
{
    QSettings settings;
    settings.beginGroup(kSettingsGroup);
    settings.setValue(kLastDir, QFileInfo(path).absolutePath());
    QString error;
    bool ok = false;
    switch (action) {
    case FileAction::Png:
        ok = exportPng(path, &error);
        break;
    case FileAction::Csv:
        ok = exportCsv(path, &error);
        break;
    case FileAction::Record:
        ok = startRecording(path, &error);
        break;
    }
    if (!ok) {
        showError(error);
    } else if (action != FileAction::Record) {
        m_error.clear();
        m_status->setText(tr("Saved “%1”.").arg(nativePath(path)));
    }
}

void PlotPage::showError(const QString &error)
{
    m_error = error;
    updateRecordingStatus();
}

void PlotPage::updateRecordingStatus()
{
    if (!m_error.isEmpty())
        m_status->setText(m_error);
    else if (m_recorder->isRecording())
        m_status->setText(tr("Recording to “%1”: %n sample(s)", nullptr, m_recorder->recordedRows())
                              .arg(nativePath(m_recorder->recordingPath())));
    else
        m_status->setText(tr("Not recording. Samples of the last %n minute(s) are kept for the "
                             "plots and exports.",
                             nullptr, int(m_recorder->maxAgeMs() / 60000)));
}

void PlotPage::retranslate()
{
    m_pause->setText(isPaused() ? tr("&Resume") : tr("&Pause"));
    m_pause->setToolTip(tr("Freeze the plots; samples are still taken and recorded"));
    m_fit->setText(tr("&Fit"));
    m_fit->setToolTip(tr("Show all of the data (or double-click a plot). Drag to zoom into a "
                         "region, wheel to zoom, middle button to pan."));
    m_clear->setText(tr("&Clear path"));
    m_clear->setToolTip(tr("Start the tool path trace again from here"));
    m_windowLabel->setText(tr("&Window:"));
    m_window->setSuffix(tr(" s"));
    m_window->setToolTip(tr("How many seconds the position plot shows"));
    m_exportPng->setText(tr("Export P&NG…"));
    m_exportPng->setToolTip(tr("Save both plots as they are shown as a PNG picture"));
    m_exportCsv->setText(tr("Export CS&V…"));
    m_exportCsv->setToolTip(tr("Save the samples in the visible time range as CSV"));
    m_record->setText(m_recorder->isRecording() ? tr("&Stop recording") : tr("&Record CSV…"));
    m_record->setToolTip(tr("Write every status sample to a CSV file as it arrives"));
    const QString unit = m_recorder->positionUnit();
    const auto axis = [&unit](int motor) {
        return unit.isEmpty() ? tr("Motor %1").arg(motor)
                              : tr("Motor %1 (%2)").arg(motor).arg(unit);
    };
    m_xy->setAxisTitles(axis(1), axis(2));
    m_xy->setTraceName(tr("Tool path"));
    updateRecordingStatus();
}

} // namespace stepcom

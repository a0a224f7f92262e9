#include "widgets/docks/trafficview.h"

#include "widgets/docks/trafficmodel.h"
#include "widgets/fields/wrappingrow.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QDesktopServices>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollBar>
#include <QTableView>
#include <QTimer>
#include <QUrl>

namespace stepcom {

TrafficView::TrafficView(QWidget *parent)
    : QWidget(parent)
    , m_model(new TrafficModel(this))
    , m_table(new QTableView(this))
    , m_pause(new QCheckBox(this))
    , m_search(new QLineEdit(this))
    , m_clear(new QPushButton(this))
    , m_copy(new QPushButton(this))
    , m_save(new QPushButton(this))
    , m_openFolder(new QPushButton(this))
    , m_earlierButton(new QPushButton(this))
{
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    // Uniform rows: the view never measures 250 000 rows one by one.
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 4);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // Fixed column widths from the font: sizing to contents would read every row.
    const QFontMetrics fm(m_table->font());
    const int digit = fm.horizontalAdvance(QLatin1Char('0'));
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->setColumnWidth(0, digit * 14);
    m_table->setColumnWidth(1, digit * 4);
    // A read-all answer is over 100 bytes: room for a request (8 bytes) and a short answer; the
    // user can widen it, and the tooltip has the whole frame.
    m_table->setColumnWidth(2, digit * 3 * 20);
    connect(m_model, &TrafficModel::appended, m_table, [this] {
        if (!m_pause->isChecked())
            m_table->scrollToBottom();
    });

    m_pause->setObjectName(QStringLiteral("pause"));
    m_search->setObjectName(QStringLiteral("search"));
    m_search->setClearButtonEnabled(true);
    m_openFolder->setObjectName(QStringLiteral("openLogFolder"));
    m_save->setObjectName(QStringLiteral("saveLog"));
    // The filters and the actions side by side where the dock is wide enough (a low screen
    // keeps the line for the page), one above the other where not.
    auto *controls = new WrappingRow(this);
    QHBoxLayout *filters = controls->first();
    filters->addWidget(m_pause);
    for (const TrafficEntry::Kind kind :
         {TrafficEntry::Kind::Poll, TrafficEntry::Kind::Read, TrafficEntry::Kind::Write,
          TrafficEntry::Kind::Command, TrafficEntry::Kind::Error}) {
        auto *box = new QCheckBox(this);
        box->setChecked(m_model->isKindShown(kind));
        connect(box, &QCheckBox::toggled, m_model,
                [this, kind](bool on) { m_model->setKindShown(kind, on); });
        m_kinds.insert(kind, box);
        filters->addWidget(box);
    }
    filters->addStretch();
    QHBoxLayout *actions = controls->second();
    actions->addWidget(m_earlierButton);
    actions->addWidget(m_search, 1);
    actions->addWidget(m_clear);
    actions->addWidget(m_copy);
    actions->addWidget(m_save);
    actions->addWidget(m_openFolder);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addWidget(controls);
    layout->addWidget(m_table);
    // A few rows are enough to see frames go by; the page needs the height more (1024×600).
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height() +
                              2 * m_table->verticalHeader()->defaultSectionSize() +
                              2 * m_table->frameWidth());
    connect(m_pause, &QCheckBox::toggled, m_model, &TrafficModel::setPaused);
    connect(m_search, &QLineEdit::textChanged, m_model, &TrafficModel::setSearch);
    connect(m_clear, &QPushButton::clicked, m_model, &TrafficModel::clear);
    connect(m_copy, &QPushButton::clicked, this, &TrafficView::copySelection);
    connect(m_save, &QPushButton::clicked, this, &TrafficView::saveAs);
    connect(m_openFolder, &QPushButton::clicked, this, [this] {
        QString error;
        if (openLogFolder(&error))
            return;
        auto *box = new QMessageBox(QMessageBox::Warning, tr("Open log folder"), error,
                                    QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    m_openFolder->hide();
    // A replay's earlier lines: on the button, or when the rows are scrolled to the top.
    m_earlierButton->setObjectName(QStringLiteral("earlierLines"));
    m_earlierButton->hide();
    connect(m_earlierButton, &QPushButton::clicked, this, &TrafficView::showEarlier);
    QScrollBar *bar = m_table->verticalScrollBar();
    connect(bar, &QScrollBar::valueChanged, this, [this, bar](int value) {
        if (m_earlier && value == bar->minimum() && bar->maximum() > 0)
            QTimer::singleShot(0, this, [this, bar] {
                if (m_earlier && bar->value() == bar->minimum() && bar->maximum() > 0)
                    showEarlier();
            });
    });
    retranslate();
}

void TrafficView::setEarlier(const Earlier &earlier)
{
    m_earlier = earlier;
    m_earlierButton->setVisible(bool(earlier));
    m_earlierButton->setEnabled(bool(earlier));
}

int TrafficView::showEarlier()
{
    if (!m_earlier)
        return 0;
    int added = 0;
    while (added < kEarlierRows &&
           m_model->storedCount() + m_model->pendingCount() < m_model->capacity()) {
        const QList<TrafficEntry> more = m_earlier();
        if (more.isEmpty()) {
            m_earlierButton->setEnabled(false); // the start of the log
            break;
        }
        added += m_model->prepend(more);
    }
    if (added > 0 && added < m_model->rowCount()) // the rows that were first, still in sight
        m_table->scrollTo(m_model->index(added, 0), QAbstractItemView::PositionAtTop);
    return added;
}

void TrafficView::setLog(TrafficLog *log)
{
    m_model->setLog(log);
}

void TrafficView::setLogFolder(const QString &folder)
{
    m_logFolder = folder;
    m_openFolder->setVisible(!folder.isEmpty());
    retranslate();
}

void TrafficView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void TrafficView::retranslate()
{
    m_pause->setText(tr("&Pause"));
    m_pause->setToolTip(tr("Hold the rows still to read them; frames are still kept"));
    m_kinds.value(TrafficEntry::Kind::Poll)->setText(tr("Polls"));
    m_kinds.value(TrafficEntry::Kind::Poll)
        ->setToolTip(tr("The live status poll: several frames a second"));
    m_kinds.value(TrafficEntry::Kind::Read)->setText(tr("Reads"));
    m_kinds.value(TrafficEntry::Kind::Write)->setText(tr("Writes"));
    m_kinds.value(TrafficEntry::Kind::Command)->setText(tr("Commands"));
    m_kinds.value(TrafficEntry::Kind::Error)->setText(tr("Errors"));
    m_search->setPlaceholderText(tr("Search (text, key or bytes)"));
    m_search->setAccessibleName(tr("Search"));
    m_clear->setText(tr("C&lear"));
    m_copy->setText(tr("&Copy"));
    m_copy->setToolTip(tr("Copy the selected rows (all rows shown when none are selected)"));
    m_save->setText(tr("&Save log…"));
    m_earlierButton->setText(tr("Earlier lines"));
    m_earlierButton->setToolTip(
        tr("Show the lines of the replayed log before the first one here (scrolling to the top "
           "does it too)"));
    m_save->setToolTip(tr("Save the rows shown to a file"));
    m_openFolder->setText(tr("Open log &folder"));
    m_openFolder->setToolTip(
        tr("The session log files: every frame of every connection, with date and time (%1)")
            .arg(QDir::toNativeSeparators(m_logFolder)));
}

QString TrafficView::text() const
{
    QStringList lines;
    lines.reserve(m_model->rowCount());
    for (int row = 0; row < m_model->rowCount(); ++row)
        lines << TrafficLog::format(m_model->entryAt(row));
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

void TrafficView::copySelection()
{
    const QModelIndexList rows = m_table->selectionModel()->selectedRows();
    if (rows.isEmpty()) {
        QApplication::clipboard()->setText(text());
        return;
    }
    QStringList lines;
    for (const QModelIndex &index : rows)
        lines << TrafficLog::format(m_model->entryAt(index.row()));
    QApplication::clipboard()->setText(lines.join(QLatin1Char('\n')));
}

bool TrafficView::saveTo(const QString &path, QString *error) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text) || file.write(text().toUtf8()) < 0 ||
        !file.commit()) {
        if (error)
            *error = file.errorString();
        return false;
    }
    return true;
}

bool TrafficView::openLogFolder(QString *error) const
{
    if (m_logFolder.isEmpty() || !QDir().mkpath(m_logFolder)) {
        if (error)
            *error = tr("Cannot create the log folder %1.").arg(m_logFolder);
        return false;
    }
    if (!QDesktopServices::openUrl(QUrl::fromLocalFile(m_logFolder))) {
        if (error)
            *error = tr("No file manager opened %1. The session log files are there.")
                         .arg(QDir::toNativeSeparators(m_logFolder));
        return false;
    }
    return true;
}

void TrafficView::saveAs()
{
    auto *dialog =
        new QFileDialog(this, tr("Save traffic log"), QString(), tr("Text files (*.txt *.log)"));
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("log"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QFileDialog::fileSelected, this, [this](const QString &path) {
        QString error;
        if (saveTo(path, &error))
            return;
        auto *box =
            new QMessageBox(QMessageBox::Warning, tr("Save traffic log"),
                            tr("Could not save %1: %2").arg(path, error), QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
    dialog->open();
}

} // namespace stepcom

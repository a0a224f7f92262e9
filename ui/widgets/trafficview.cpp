#include "widgets/trafficview.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QEvent>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QTableView>

namespace stepcom {

TrafficModel::TrafficModel(QObject *parent)
    : QAbstractTableModel(parent)
{}

void TrafficModel::setLog(TrafficLog *log)
{
    if (m_log)
        m_log->disconnect(this);
    m_log = log;
    if (m_log)
        connect(m_log, &TrafficLog::entryAdded, this, &TrafficModel::append);
}

void TrafficModel::setPaused(bool paused)
{
    m_paused = paused;
}

void TrafficModel::clear()
{
    beginResetModel();
    m_entries.clear();
    endResetModel();
}

void TrafficModel::append(const TrafficEntry &entry)
{
    if (m_paused)
        return;
    if (m_entries.size() >= m_capacity) {
        beginRemoveRows({}, 0, 0);
        m_entries.removeFirst();
        endRemoveRows();
    }
    const int row = int(m_entries.size());
    beginInsertRows({}, row, row);
    m_entries.append(entry);
    endInsertRows();
}

int TrafficModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_entries.size());
}

int TrafficModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : 4;
}

QVariant TrafficModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_entries.size())
        return {};
    const TrafficEntry &e = m_entries.at(index.row());
    // Long frames are cut in the table (the meaning must stay in view): the whole text on hover.
    if (role == Qt::ToolTipRole && index.column() >= 2)
        return data(index, Qt::DisplayRole);
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case 0:
            return e.time.toString(QStringLiteral("HH:mm:ss.zzz"));
        case 1:
            return e.direction == TrafficEntry::Direction::Sent       ? QStringLiteral("TX")
                   : e.direction == TrafficEntry::Direction::Received ? QStringLiteral("RX")
                                                                      : QStringLiteral("—");
        case 2:
            return QString::fromLatin1(e.bytes.toHex(' ').toUpper());
        case 3:
            return e.summary;
        }
    }
    return {};
}

QVariant TrafficModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case 0:
        return tr("Time");
    case 1:
        return tr("Dir");
    case 2:
        return tr("Bytes (hex)");
    case 3:
        return tr("Meaning");
    }
    return {};
}

TrafficView::TrafficView(QWidget *parent)
    : QWidget(parent)
    , m_model(new TrafficModel(this))
    , m_table(new QTableView(this))
    , m_pause(new QCheckBox(this))
    , m_clear(new QPushButton(this))
    , m_copy(new QPushButton(this))
    , m_save(new QPushButton(this))
{
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // A read-all answer is over 100 bytes: sized to its contents, the bytes column would push
    // the decoded meaning out of view. Room for a request (8 bytes) and a short answer; the
    // user can widen it, and the tooltip has the whole frame.
    m_table->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Interactive);
    m_table->setColumnWidth(2, QFontMetrics(m_table->font()).horizontalAdvance(QLatin1Char('0')) *
                                   3 * 20);
    connect(m_model, &QAbstractItemModel::rowsInserted, m_table, [this] {
        if (!m_pause->isChecked())
            m_table->scrollToBottom();
    });
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_pause);
    buttons->addStretch();
    buttons->addWidget(m_clear);
    buttons->addWidget(m_copy);
    buttons->addWidget(m_save);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(buttons);
    layout->addWidget(m_table);
    connect(m_pause, &QCheckBox::toggled, m_model, &TrafficModel::setPaused);
    connect(m_clear, &QPushButton::clicked, m_model, &TrafficModel::clear);
    connect(m_copy, &QPushButton::clicked, this, &TrafficView::copySelection);
    connect(m_save, &QPushButton::clicked, this, &TrafficView::saveAs);
    retranslate();
}

void TrafficView::setLog(TrafficLog *log)
{
    m_model->setLog(log);
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
    m_clear->setText(tr("C&lear"));
    m_copy->setText(tr("&Copy"));
    m_save->setText(tr("&Save…"));
    m_copy->setToolTip(tr("Copy the selected rows (all rows when none are selected)"));
}

QString TrafficView::text() const
{
    QStringList lines;
    for (const TrafficEntry &e : m_model->entries())
        lines << TrafficLog::format(e);
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
        lines << TrafficLog::format(m_model->entries().at(index.row()));
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

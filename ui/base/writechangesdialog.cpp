#include "base/writechangesdialog.h"

#include "base/fittoscreen.h"
#include "base/language.h"
#include "device/parameterstore.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {

QList<ParameterWrite> writesOf(const ParameterStore &store, const QStringList &keys)
{
    QList<ParameterWrite> writes = store.pendingWrites();
    if (!keys.isEmpty())
        writes.removeIf(
            [&keys](const ParameterWrite &w) { return !keys.contains(w.parameter->key); });
    return writes;
}

} // namespace

WriteChangesDialog::WriteChangesDialog(const ParameterStore &store, QWidget *parent)
    : WriteChangesDialog(store, QStringList(), parent)
{}

WriteChangesDialog::WriteChangesDialog(const ParameterStore &store, const QStringList &keys,
                                       QWidget *parent)
    : QDialog(parent)
    , m_writes(writesOf(store, keys))
    , m_table(new QTableWidget(int(m_writes.size()), 4, this))
    , m_summary(new QLabel(this))
    , m_problemsLabel(new QLabel(this))
{
    setWindowTitle(tr("Write changes to the controller"));
    const QString lang = Language::instance().current();
    m_table->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Register"), tr("Controller holds"), tr("New value")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    for (int row = 0; row < m_writes.size(); ++row) {
        const Parameter &p = *m_writes.at(row).parameter;
        const std::optional<qint64> device = store.deviceValue(p.key);
        // The key tells motor 1's speed from motor 2's where the label alone cannot.
        auto *name =
            new QTableWidgetItem(QStringLiteral("%1  (%2)").arg(p.label.text(lang), p.key));
        name->setToolTip(p.help.text(lang));
        m_table->setItem(row, 0, name);
        m_table->setItem(row, 1, new QTableWidgetItem(p.registerName()));
        m_table->setItem(
            row, 2, new QTableWidgetItem(device ? p.displayRaw(*device, lang) : tr("unknown")));
        auto *value = new QTableWidgetItem(p.displayRaw(m_writes.at(row).raw, lang));
        QFont bold = value->font();
        bold.setBold(true);
        value->setFont(bold);
        m_table->setItem(row, 3, value);
    }
    // The parameter's name takes the room the numbers leave and wraps in it: no sideways
    // scrolling on a small screen, nothing cut.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->setWordWrap(true);
    m_table->setTextElideMode(Qt::ElideNone);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_summary->setWordWrap(true);
    m_summary->setText(tr("%n parameter(s) will be written and then read back to verify. "
                          "They stay in the controller's RAM until you save to flash.",
                          nullptr, int(m_writes.size())));
    auto *buttons = new QDialogButtonBox(this);
    m_write = buttons->addButton(tr("&Write"), QDialogButtonBox::AcceptRole);
    m_write->setObjectName(QStringLiteral("writeButton"));
    m_cancel = buttons->addButton(QDialogButtonBox::Cancel);
    m_problemsLabel->setObjectName(QStringLiteral("problems"));
    m_problemsLabel->setWordWrap(true);
    m_problemsLabel->setTextFormat(Qt::PlainText);
    QPalette pal = m_problemsLabel->palette();
    pal.setColor(QPalette::WindowText, QColor(200, 30, 30));
    m_problemsLabel->setPalette(pal);
    m_problemsLabel->hide();
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_problemsLabel);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(fitToScreen(this, sizeHint().expandedTo(QSize(fontMetrics().averageCharWidth() * 110,
                                                         fontMetrics().height() * 24))));
}

void WriteChangesDialog::setProblems(const QStringList &problems)
{
    m_problems = problems;
    m_problemsLabel->setVisible(!problems.isEmpty());
    if (problems.isEmpty()) {
        m_problemsLabel->clear();
        m_write->setText(tr("&Write"));
        m_write->setAutoDefault(true);
        m_write->setDefault(true);
        return;
    }
    // Say what the pages already know, and make writing it anyway a deliberate choice.
    QStringList lines{tr("The pages flag problems in these values:")};
    for (const QString &p : problems)
        lines << QStringLiteral("• ") + p;
    m_problemsLabel->setText(lines.join(QLatin1Char('\n')));
    m_write->setText(tr("&Write anyway"));
    m_write->setAutoDefault(false);
    m_write->setDefault(false);
    m_cancel->setDefault(true);
}

} // namespace stepcom

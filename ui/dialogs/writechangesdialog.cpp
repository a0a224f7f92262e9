#include "dialogs/writechangesdialog.h"

#include "device/parameterstore.h"
#include "device/writereview.h"
#include "language.h"

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
    , m_problems(WriteReview::problems(store, m_writes))
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
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_summary->setWordWrap(true);
    m_summary->setText(tr("%n parameter(s) will be written and then read back to verify. "
                          "They stay in the controller's RAM until you save to flash.",
                          nullptr, int(m_writes.size())));
    auto *buttons = new QDialogButtonBox(this);
    QPushButton *write = buttons->addButton(tr("&Write"), QDialogButtonBox::AcceptRole);
    write->setObjectName(QStringLiteral("writeButton"));
    QPushButton *cancel = buttons->addButton(QDialogButtonBox::Cancel);
    auto *problems = new QLabel(this);
    problems->setObjectName(QStringLiteral("problems"));
    problems->setWordWrap(true);
    problems->setTextFormat(Qt::PlainText);
    if (!m_problems.isEmpty()) {
        // Say what the pages already know, and make writing it anyway a deliberate choice.
        QStringList lines{tr("The pages flag problems in these values:")};
        for (const QString &p : std::as_const(m_problems))
            lines << QStringLiteral("• ") + p;
        problems->setText(lines.join(QLatin1Char('\n')));
        QPalette pal = problems->palette();
        pal.setColor(QPalette::WindowText, QColor(200, 30, 30));
        problems->setPalette(pal);
        write->setText(tr("&Write anyway"));
        write->setAutoDefault(false);
        cancel->setDefault(true);
    }
    problems->setVisible(!m_problems.isEmpty());
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(problems);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(sizeHint().expandedTo(QSize(fontMetrics().horizontalAdvance(QLatin1Char('x')) * 80,
                                       fontMetrics().height() * 16)));
}

} // namespace stepcom

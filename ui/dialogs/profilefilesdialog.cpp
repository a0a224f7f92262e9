#include "dialogs/profilefilesdialog.h"

#include "base/fittoscreen.h"
#include "base/language.h"
#include "map/registermap.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {
// The compare dialog's highlight: readable in the light and the dark palette alike.
const QColor kHighlight(255, 214, 140);
} // namespace

ProfileFilesDialog::ProfileFilesDialog(const RegisterMap &map, const Profile &a,
                                       const QString &nameA, const Profile &b, const QString &nameB,
                                       QWidget *parent)
    : QDialog(parent)
    , m_map(map)
    , m_a(a)
    , m_b(b)
    , m_nameA(nameA)
    , m_nameB(nameB)
    , m_comparison(ProfileComparison::compare(m_map, m_a, m_b))
    , m_header(new QLabel(this))
    , m_summary(new QLabel(this))
    , m_table(new QTableWidget(this))
    , m_differencesOnly(new QCheckBox(this))
{
    setObjectName(QStringLiteral("profileFilesDialog"));
    m_differencesOnly->setObjectName(QStringLiteral("differencesOnly"));
    m_header->setWordWrap(true);
    m_header->setTextFormat(Qt::PlainText);
    m_summary->setWordWrap(true);
    m_table->setColumnCount(Columns);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(ParameterColumn, QHeaderView::Stretch);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_header);
    layout->addWidget(m_differencesOnly);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    connect(m_differencesOnly, &QCheckBox::toggled, this, &ProfileFilesDialog::updateFilter);
    retranslate();
    resize(fitToScreen(this, QSize(fontMetrics().horizontalAdvance(QLatin1Char('x')) * 120,
                                   fontMetrics().height() * 40)));
}

QString ProfileFilesDialog::groupName(Group group) const
{
    switch (group) {
    case Group::Differ:
        return tr("differ");
    case Group::Same:
        return tr("the same");
    case Group::OnlyInA:
        return tr("only in A");
    case Group::OnlyInB:
        return tr("only in B");
    case Group::Outside:
        return tr("outside this map");
    }
    return {};
}

int ProfileFilesDialog::rowOf(const QString &key) const
{
    return int(m_keys.indexOf(key));
}

bool ProfileFilesDialog::isHighlighted(int row) const
{
    const QTableWidgetItem *item = m_table->item(row, KeyColumn);
    return item && item->background().color() == kHighlight;
}

void ProfileFilesDialog::rebuild()
{
    const QString lang = Language::instance().current();
    m_groups.clear();
    m_keys.clear();
    m_table->setRowCount(0);
    const auto addRow = [this](Group group, bool differs, const QStringList &cells,
                               const QString &tip) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_groups << group;
        m_keys << cells.at(KeyColumn);
        for (int c = 0; c < Columns; ++c) {
            auto *item = new QTableWidgetItem(c == GroupColumn ? groupName(group) : cells.at(c));
            item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
            item->setToolTip(tip);
            if (differs) {
                item->setBackground(kHighlight);
                item->setForeground(QColor(Qt::black));
                QFont f = item->font();
                f.setBold(c == AColumn || c == BColumn);
                item->setFont(f);
            }
            m_table->setItem(row, c, item);
        }
    };
    for (const ProfileDifference &r : std::as_const(m_comparison.rows)) {
        const Parameter &p = *r.parameter;
        if (!r.device && !r.profile)
            continue; // neither file holds it (the link settings, usually)
        const Group group = !r.profile    ? Group::OnlyInA
                            : !r.device   ? Group::OnlyInB
                            : r.differs() ? Group::Differ
                                          : Group::Same;
        const auto shown = [&](const std::optional<qint64> &raw) {
            if (!raw)
                return QStringLiteral("—");
            const QString n = p.formatRaw(*raw);
            const QString text = p.displayRaw(*raw, lang);
            return (!p.values.isEmpty() && text != n) ? QStringLiteral("%1 (%2)").arg(n, text) : n;
        };
        // "Speed" is in every motor block: say which motor, as the device comparison does.
        QString label = p.label.text(lang);
        if (p.instance > 0 && p.block == QLatin1String("motor") &&
            !label.contains(QString::number(p.instance)))
            label = tr("Motor %1 · %2").arg(p.instance).arg(label);
        addRow(group, group != Group::Same,
               {QString(), label, shown(r.device), shown(r.profile), p.unit, p.key},
               p.registerName());
    }
    for (const ProfileForeignRow &f : std::as_const(m_comparison.foreign)) {
        const auto number = [](const std::optional<double> &v) {
            return v ? QString::number(*v, 'g', QLocale::FloatingPointShortest)
                     : QStringLiteral("—");
        };
        addRow(Group::Outside, f.differs(),
               {QString(), tr("(not a setting of this map)"), number(f.a), number(f.b), QString(),
                f.key},
               f.reason);
    }
    for (int c : {GroupColumn, AColumn, BColumn, UnitColumn, KeyColumn})
        m_table->resizeColumnToContents(c);
    m_summary->setText(
        tr("%1 differ, %2 only in A, %3 only in B, %4 outside this map (%5 of them differ).")
            .arg(m_comparison.differing().size())
            .arg(m_comparison.onlyInA().size())
            .arg(m_comparison.onlyInB().size())
            .arg(m_comparison.foreign.size())
            .arg(m_comparison.foreignDiffering().size()) +
        QLatin1Char(' ') +
        (m_comparison.identical() ? tr("The files hold the same values.")
                                  : tr("The files differ.")));
    updateFilter();
}

void ProfileFilesDialog::updateFilter()
{
    const bool only = m_differencesOnly->isChecked();
    for (int row = 0; row < m_groups.size(); ++row)
        m_table->setRowHidden(row, only && m_groups.at(row) == Group::Same);
}

void ProfileFilesDialog::retranslate()
{
    setWindowTitle(tr("Compare profiles: %1 and %2").arg(m_nameA, m_nameB));
    const auto describe = [](const QString &letter, const QString &file, const Profile &p) {
        QString line = tr("%1 = %2").arg(letter, file);
        if (!p.name.isEmpty())
            line += QStringLiteral(": \"%1\"").arg(p.name);
        if (p.variance.isVariant())
            line += QStringLiteral(", ") + tr("register map %1").arg(p.variance.fileMap);
        return line;
    };
    m_header->setText(describe(QStringLiteral("A"), m_nameA, m_a) + QLatin1Char('\n') +
                      describe(QStringLiteral("B"), m_nameB, m_b) + QLatin1Char('\n') +
                      tr("Two files compared against register map %1/%2; no controller is read "
                         "or written.")
                          .arg(m_map.id())
                          .arg(m_map.version()));
    m_table->setHorizontalHeaderLabels(
        {tr("Group"), tr("Parameter"), tr("A"), tr("B"), tr("Unit"), tr("Key")});
    m_differencesOnly->setText(tr("Differences only"));
    rebuild();
}

void ProfileFilesDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

} // namespace stepcom

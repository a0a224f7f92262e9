#include "dialogs/profilecomparedialog.h"

#include "base/language.h"
#include "profile/profileapply.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace stepcom {

namespace {
const QString kSaveToFlash = QStringLiteral("save_to_flash");
}

ProfileCompareDialog::ProfileCompareDialog(DeviceSession *session, const Profile &profile,
                                           const QString &fileName, QWidget *parent)
    : QDialog(parent)
    , m_session(session)
    , m_profile(profile)
    , m_fileName(fileName)
    , m_header(new QLabel(this))
    , m_summary(new QLabel(this))
    , m_table(new QTableWidget(this))
    , m_differencesOnly(new QCheckBox(this))
    , m_includeLink(new QCheckBox(this))
    , m_checkDiffering(new QPushButton(this))
    , m_checkNone(new QPushButton(this))
    , m_apply(new QPushButton(this))
    , m_saveToFlash(new QPushButton(this))
    , m_close(new QPushButton(this))
    , m_progress(new QProgressBar(this))
    , m_result(new QLabel(this))
{
    setObjectName(QStringLiteral("profileCompareDialog"));
    m_apply->setObjectName(QStringLiteral("applyButton"));
    m_saveToFlash->setObjectName(QStringLiteral("saveToFlashButton"));
    m_differencesOnly->setObjectName(QStringLiteral("differencesOnly"));
    m_includeLink->setObjectName(QStringLiteral("includeLink"));
    m_header->setWordWrap(true);
    m_header->setTextFormat(Qt::PlainText);
    m_result->setWordWrap(true);
    m_result->setTextFormat(Qt::PlainText);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_progress->setRange(0, 0); // busy: the write and the read-back take their time
    m_progress->hide();
    m_saveToFlash->hide();

    m_table->setColumnCount(ColumnCount);
    // Opens on what matters: the values the controller and the profile disagree on.
    m_differencesOnly->setChecked(true);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(ParameterColumn, QHeaderView::Stretch);

    auto *filters = new QHBoxLayout;
    filters->addWidget(m_differencesOnly);
    filters->addWidget(m_includeLink);
    filters->addStretch();
    filters->addWidget(m_checkDiffering);
    filters->addWidget(m_checkNone);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_progress, 1);
    buttons->addStretch();
    buttons->addWidget(m_apply);
    buttons->addWidget(m_saveToFlash);
    buttons->addWidget(m_close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_header);
    layout->addLayout(filters);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_summary);
    layout->addWidget(m_result);
    layout->addLayout(buttons);

    connect(m_table, &QTableWidget::cellChanged, this, &ProfileCompareDialog::onItemChanged);
    connect(m_differencesOnly, &QCheckBox::toggled, this, &ProfileCompareDialog::updateFilter);
    connect(m_includeLink, &QCheckBox::toggled, this, [this](bool on) {
        for (const ProfileDifference &r : std::as_const(m_rows)) {
            if (r.linkSetting)
                m_checked[r.parameter->key] = on && r.differs();
        }
        rebuild();
    });
    connect(m_checkDiffering, &QPushButton::clicked, this, [this] {
        for (const ProfileDifference &r : std::as_const(m_rows))
            m_checked[r.parameter->key] =
                r.differs() && (!r.linkSetting || m_includeLink->isChecked());
        rebuild();
    });
    connect(m_checkNone, &QPushButton::clicked, this, [this] {
        for (const ProfileDifference &r : std::as_const(m_rows)) {
            m_checked[r.parameter->key] = false;
            m_touched.insert(r.parameter->key);
        }
        rebuild();
    });
    connect(m_apply, &QPushButton::clicked, this, &ProfileCompareDialog::apply);
    connect(m_saveToFlash, &QPushButton::clicked, this, [this] {
        m_saveToFlash->setEnabled(false);
        m_session->saveToFlash();
    });
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(session, &DeviceSession::commandFinished, this, [this](const QString &key, bool ok) {
        if (key != kSaveToFlash || m_saveToFlash->isHidden())
            return;
        QString text = m_result->text();
        if (ok) // the warning about power-off no longer holds
            text.remove(QLatin1Char('\n') + forgetWarning());
        m_result->setText(text + QLatin1Char('\n') +
                          (ok ? tr("Saved to flash: the controller keeps these values after "
                                   "power-off.")
                              : tr("Saving to flash failed (see Messages).")));
        m_saveToFlash->setEnabled(!ok);
    });
    // A read-all changes every value at once: compare once, after the burst.
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this, [this] {
        if (m_refreshPending)
            return;
        m_refreshPending = true;
        QTimer::singleShot(0, this, [this] {
            m_refreshPending = false;
            refreshValues();
        });
    });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &ProfileCompareDialog::updateButtons);

    refreshValues();
    retranslate();
    QSize size(fontMetrics().horizontalAdvance(QLatin1Char('x')) * 120,
               fontMetrics().height() * 40);
    // Never larger than the screen (a 1366×768 laptop at 150 % has 911×512 to offer).
    if (const QScreen *where = parent ? parent->screen() : screen())
        size = size.boundedTo(where->availableGeometry().size() * 0.95);
    resize(size);
    // Compare with what the controller holds now, not with what was read some time ago.
    // Reading never writes.
    if (session->connection()->isConnected())
        session->parameters()->readAll();
}

QString ProfileCompareDialog::forgetWarning()
{
    return tr("The controller forgets these values at power-off unless they are saved to "
              "flash.");
}

QString ProfileCompareDialog::labelOf(const Parameter &p)
{
    // "Step angle" is in every motor block: say which motor.
    const QString label = p.label.text(Language::instance().current());
    if (p.instance > 0 && p.block == QLatin1String("motor") &&
        !label.contains(QString::number(p.instance)))
        return tr("Motor %1 · %2").arg(p.instance).arg(label);
    return label;
}

QString ProfileCompareDialog::nameOf(const QString &key) const
{
    const Parameter *p = m_session->map().find(key);
    return p ? QStringLiteral("%1 (%2)").arg(labelOf(*p), key) : key;
}

void ProfileCompareDialog::refreshValues()
{
    QHash<QString, qint64> device;
    for (const Parameter *p : Profile::profileParameters(m_session->map(), true)) {
        if (const auto v = m_session->parameters()->store()->deviceValue(p->key))
            device.insert(p->key, *v);
    }
    m_rows = ProfileDiff::compare(m_session->map(), m_profile, device);
    // A key this controller does not have is neither a difference nor writable: left out,
    // and named below the table.
    m_leftOut.clear();
    const ParameterStore *store = m_session->parameters()->store();
    m_rows.removeIf([this, store](const ProfileDifference &r) {
        if (store->state(r.parameter->key) != ParameterStore::State::Unsupported)
            return false;
        m_leftOut << r.parameter->key;
        m_checked.remove(r.parameter->key);
        return true;
    });
    for (const ProfileDifference &r : std::as_const(m_rows)) {
        const QString &key = r.parameter->key;
        if (m_touched.contains(key))
            continue;
        m_checked[key] = r.differs() && (!r.linkSetting || m_includeLink->isChecked());
    }
    rebuild();
}

void ProfileCompareDialog::rebuild()
{
    m_updating = true;
    const QString lang = Language::instance().current();
    m_table->setRowCount(int(m_rows.size()));
    int differing = 0;
    for (int row = 0; row < m_rows.size(); ++row) {
        const ProfileDifference &r = m_rows.at(row);
        const Parameter &p = *r.parameter;
        const bool differs = r.differs();
        differing += differs ? 1 : 0;
        auto *check = new QTableWidgetItem;
        Qt::ItemFlags flags = Qt::ItemIsSelectable;
        if (r.profile && (!r.linkSetting || m_includeLink->isChecked()))
            flags |= Qt::ItemIsEnabled | Qt::ItemIsUserCheckable;
        check->setFlags(flags);
        check->setCheckState(m_checked.value(p.key) ? Qt::Checked : Qt::Unchecked);
        check->setData(Qt::UserRole, p.key);
        m_table->setItem(row, ApplyColumn, check);
        auto number = [&](const std::optional<qint64> &raw) {
            if (!raw)
                return QStringLiteral("—");
            const QString n = p.formatRaw(*raw);
            const QString shown = p.displayRaw(*raw, lang);
            return (!p.values.isEmpty() && shown != n) ? QStringLiteral("%1 (%2)").arg(n, shown)
                                                       : n;
        };
        QString label = labelOf(p);
        if (r.linkSetting)
            label += QStringLiteral(" — ") + tr("link setting");
        const QStringList cells{QString(),         label,  number(r.device),
                                number(r.profile), p.unit, p.key};
        for (int c = ParameterColumn; c < ColumnCount; ++c) {
            auto *item = new QTableWidgetItem(cells.at(c));
            item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
            if (c == KeyColumn)
                item->setToolTip(p.registerName());
            m_table->setItem(row, c, item);
        }
        for (int c = 0; c < ColumnCount; ++c) {
            QTableWidgetItem *item = m_table->item(row, c);
            if (differs) {
                // Differences stand out in the light and the dark palette alike.
                item->setBackground(QColor(255, 214, 140));
                item->setForeground(QColor(Qt::black));
                QFont f = item->font();
                f.setBold(c == DeviceColumn || c == ProfileColumn);
                item->setFont(f);
            }
        }
        if (!r.profile)
            m_table->item(row, ProfileColumn)
                ->setToolTip(tr("The profile does not hold this "
                                "value"));
    }
    // Sized to the contents the first time; after that an Apply or a read-back rebuilds the
    // rows but the columns only ever grow to fit, so a width the user chose stays.
    for (const int c : {int(ApplyColumn), int(DeviceColumn), int(ProfileColumn), int(UnitColumn),
                        int(KeyColumn)}) {
        const int fit = std::max(static_cast<QAbstractItemView *>(m_table)->sizeHintForColumn(c),
                                 m_table->horizontalHeader()->sectionSizeHint(c));
        m_table->setColumnWidth(c, m_columnsSized ? std::max(m_table->columnWidth(c), fit) : fit);
    }
    m_columnsSized = m_table->rowCount() > 0;
    const bool unknown = std::any_of(m_rows.cbegin(), m_rows.cend(),
                                     [](const auto &r) { return r.profile && !r.device; });
    m_summary->setText(unknown && differing == 0
                           ? tr("The controller's values are not known yet: connect, and they "
                                "are read.")
                       : differing == 0
                           ? tr("The controller holds every value of the profile.")
                           : tr("%n value(s) differ; %1 checked to be written.", nullptr, differing)
                                 .arg(checkedKeys().size()));
    if (!m_leftOut.isEmpty())
        m_summary->setText(m_summary->text() + QLatin1Char('\n') +
                           tr("Left out, not supported by this controller: %1.")
                               .arg(m_leftOut.join(QLatin1String(", "))));
    m_updating = false;
    updateFilter();
    updateButtons();
}

void ProfileCompareDialog::updateFilter()
{
    const bool only = m_differencesOnly->isChecked();
    for (int row = 0; row < m_rows.size(); ++row)
        m_table->setRowHidden(row, only && !m_rows.at(row).differs());
}

void ProfileCompareDialog::updateButtons()
{
    const bool connected = m_session->connection()->isConnected();
    m_apply->setEnabled(connected && !m_busy && !checkedKeys().isEmpty());
    m_apply->setToolTip(connected ? QString() : tr("Connect to a controller to apply"));
    m_checkDiffering->setEnabled(!m_busy);
    m_checkNone->setEnabled(!m_busy);
    m_includeLink->setEnabled(!m_busy);
    m_saveToFlash->setEnabled(m_saveToFlash->isEnabled() && connected && !m_busy);
}

void ProfileCompareDialog::onItemChanged(int row, int column)
{
    if (m_updating || column != ApplyColumn)
        return;
    const QString key = m_table->item(row, ApplyColumn)->data(Qt::UserRole).toString();
    m_checked[key] = m_table->item(row, ApplyColumn)->checkState() == Qt::Checked;
    m_touched.insert(key);
    rebuild();
}

int ProfileCompareDialog::rowOf(const QString &key) const
{
    for (int row = 0; row < m_rows.size(); ++row) {
        if (m_rows.at(row).parameter->key == key)
            return row;
    }
    return -1;
}

bool ProfileCompareDialog::isChecked(const QString &key) const
{
    return m_checked.value(key);
}

void ProfileCompareDialog::setChecked(const QString &key, bool checked)
{
    const int row = rowOf(key);
    if (row < 0)
        return;
    QTableWidgetItem *item = m_table->item(row, ApplyColumn);
    if (item->flags() & Qt::ItemIsUserCheckable)
        item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

QStringList ProfileCompareDialog::checkedKeys() const
{
    QStringList keys;
    for (const ProfileDifference &r : m_rows) {
        if (m_checked.value(r.parameter->key) && r.profile &&
            (!r.linkSetting || m_includeLink->isChecked()))
            keys << r.parameter->key;
    }
    return keys;
}

void ProfileCompareDialog::apply()
{
    if (m_busy || !m_session->connection()->isConnected())
        return;
    const QStringList keys = checkedKeys();
    if (keys.isEmpty())
        return;
    m_busy = true;
    m_progress->show();
    m_saveToFlash->hide();
    m_result->setText(
        tr("Writing %n value(s), then reading them back…", nullptr, int(keys.size())));
    updateButtons();
    // Read, compare, back up (the window's risk guard), write and verify: ProfileApply.
    delete m_applier;
    m_applier = new ProfileApply(m_session, m_profile, 0, this);
    m_applier->setIncludeLink(m_includeLink->isChecked());
    connect(m_applier, &ProfileApply::finished, this, &ProfileCompareDialog::finishApply);
    m_applier->apply(keys);
}

void ProfileCompareDialog::finishApply(const ProfileApplyResult &result)
{
    m_busy = false;
    m_progress->hide();
    const QStringList verified = result.keysIn(AppliedKey::State::Verified);
    QStringList problems;
    if (!result.error.isEmpty())
        problems << result.error;
    for (const AppliedKey &k : result.keys) {
        if (k.state != AppliedKey::State::Verified && k.state != AppliedKey::State::Unchanged)
            problems << ProfileApplyResult::describe(k, nameOf(k.key));
    }
    QString text = tr("Wrote and verified %n value(s).", nullptr, int(verified.size()));
    const QStringList held = result.keysIn(AppliedKey::State::Unchanged);
    if (!held.isEmpty())
        text += QLatin1Char(' ') +
                tr("%n value(s) the controller already held.", nullptr, int(held.size()));
    if (!problems.isEmpty())
        text += QLatin1Char('\n') + tr("Problems:") + QLatin1Char('\n') +
                problems.join(QLatin1Char('\n'));
    if (!verified.isEmpty())
        text += QLatin1Char('\n') + forgetWarning();
    m_result->setText(text);
    m_saveToFlash->setVisible(!verified.isEmpty());
    m_saveToFlash->setEnabled(!verified.isEmpty());
    for (const QString &key : verified)
        m_touched.remove(key); // written: its check follows the comparison again
    refreshValues();
    Q_EMIT applied(result.ok(), verified, problems);
}

void ProfileCompareDialog::retranslate()
{
    const QString name = m_profile.name.isEmpty() ? m_fileName : m_profile.name;
    setWindowTitle(tr("Profile %1 — compare and apply").arg(name));
    QString header = tr("Profile \"%1\" from %2").arg(name, m_fileName);
    if (m_profile.created.isValid())
        header +=
            QStringLiteral(", ") +
            tr("saved %1")
                .arg(QLocale().toString(m_profile.created.toLocalTime(), QLocale::ShortFormat));
    if (m_profile.deviceId > 0)
        header += QStringLiteral(", ") + tr("from controller id %1").arg(m_profile.deviceId);
    if (!m_profile.notes.isEmpty())
        header += QLatin1Char('\n') + m_profile.notes;
    // A profile of another map: what is left out, before anything is applied.
    if (const QString maps = m_profile.variance.describeMaps(); !maps.isEmpty())
        header += QLatin1Char('\n') + maps;
    const QStringList notApplied =
        m_profile.variance.describe(m_session->map(), Language::instance().current());
    if (!notApplied.isEmpty())
        header += QLatin1Char('\n') + tr("Not applied:") + QStringLiteral("\n  ") +
                  notApplied.join(QStringLiteral("\n  "));
    header += QLatin1Char('\n') + tr("Opening a profile writes nothing. Check the rows to "
                                     "write, then Apply.");
    m_header->setText(header);
    m_table->setHorizontalHeaderLabels(
        {tr("Apply"), tr("Parameter"), tr("Controller"), tr("Profile"), tr("Unit"), tr("Key")});
    m_differencesOnly->setText(tr("Differences only"));
    m_includeLink->setText(tr("Also apply the device id and baud (the connection follows)"));
    m_checkDiffering->setText(tr("Check differing"));
    m_checkNone->setText(tr("Check none"));
    m_apply->setText(tr("Apply checked"));
    m_saveToFlash->setText(tr("Save to flash"));
    m_close->setText(tr("Close"));
    rebuild();
}

void ProfileCompareDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

} // namespace stepcom

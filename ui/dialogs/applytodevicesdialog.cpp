#include "applytodevicesdialog.h"

#include "base/language.h"
#include "profile/profilerollout.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include <QCloseEvent>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {

constexpr int kIdRole = Qt::UserRole;
constexpr int kKeyRole = Qt::UserRole + 1;

QString valueText(const Parameter &p, const std::optional<qint64> &raw)
{
    if (!raw)
        return QStringLiteral("—");
    QString text = p.displayRaw(*raw, Language::instance().current());
    if (p.values.isEmpty() && !p.unit.isEmpty())
        text += QLatin1Char(' ') + p.unit;
    return text;
}

} // namespace

ApplyToDevicesDialog::ApplyToDevicesDialog(DeviceSession *session, const Profile &profile,
                                           const QString &title, const QHash<int, QString> &names,
                                           const QList<int> &preselected, QWidget *parent)
    : QDialog(parent)
    , m_session(session)
    , m_profile(profile)
    , m_names(names)
    , m_rollout(new ProfileRollout(session, profile, this))
    , m_intro(new QLabel(this))
    , m_devices(new QListWidget(this))
    , m_compare(new QPushButton(tr("&Compare the ticked devices"), this))
    , m_rows(new QTreeWidget(this))
    , m_summary(new QLabel(this))
    , m_write(new QPushButton(this))
    , m_close(new QPushButton(tr("Close"), this))
{
    setObjectName(QStringLiteral("applyToDevicesDialog"));
    setWindowTitle(tr("Apply %1 to several devices").arg(title));
    m_intro->setWordWrap(true);
    m_intro->setText(
        tr("Tick the devices, compare, then uncheck what is not to be written. Each device's "
           "settings are saved as a backup before anything is written to it; every value "
           "written is read back. Device id and baud rate are never applied to several "
           "devices: one id for all would make them collide."));
    for (int id : session->line()->deviceIds()) {
        const QString name = names.value(id);
        auto *item = new QListWidgetItem(
            name.isEmpty() ? tr("id %1").arg(id) : tr("id %1 (%2)").arg(id).arg(name), m_devices);
        item->setData(kIdRole, id);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setCheckState(preselected.isEmpty() || preselected.contains(id) ? Qt::Checked
                                                                              : Qt::Unchecked);
    }
    m_devices->setMaximumHeight(m_devices->sizeHintForRow(0) * 5 + 8);
    m_rows->setColumnCount(3);
    m_rows->setHeaderLabels({tr("Device / parameter"), tr("Device holds"), tr("Profile")});
    m_rows->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_summary->setWordWrap(true);
    m_write->setObjectName(QStringLiteral("writeToDevices"));
    auto *buttons = new QDialogButtonBox(this);
    buttons->addButton(m_write, QDialogButtonBox::AcceptRole);
    buttons->addButton(m_close, QDialogButtonBox::RejectRole);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addWidget(m_devices);
    layout->addWidget(m_compare);
    layout->addWidget(m_rows, 1);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    connect(m_compare, &QPushButton::clicked, this, &ApplyToDevicesDialog::compareChecked);
    connect(m_write, &QPushButton::clicked, this, &ApplyToDevicesDialog::writeChecked);
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(m_devices, &QListWidget::itemChanged, this, &ApplyToDevicesDialog::updateButtons);
    connect(m_rows, &QTreeWidget::itemChanged, this, [this] {
        if (!m_filling) {
            takeChoices();
            updateButtons();
        }
    });
    connect(m_rollout, &ProfileRollout::compared, this, &ApplyToDevicesDialog::showComparison);
    connect(m_rollout, &ProfileRollout::deviceFinished, this, &ApplyToDevicesDialog::updateDevice);
    connect(m_rollout, &ProfileRollout::finished, this, [this](bool ok) {
        const QStringList lines = resultLines();
        m_summary->setText((ok ? tr("Done:") : tr("Done, not everywhere:")) + QLatin1Char('\n') +
                           lines.join(QLatin1Char('\n')));
        for (const RolloutDevice &d : m_rollout->devices())
            Q_EMIT message(d.state != RolloutDevice::State::Failed, ProfileRollout::describe(d));
        updateButtons();
    });
    resize(720, 560);
    updateButtons();
}

QList<int> ApplyToDevicesDialog::checkedDevices() const
{
    QList<int> ids;
    for (int i = 0; i < m_devices->count(); ++i) {
        if (m_devices->item(i)->checkState() == Qt::Checked)
            ids << m_devices->item(i)->data(kIdRole).toInt();
    }
    return ids;
}

void ApplyToDevicesDialog::setDeviceChecked(int id, bool checked)
{
    for (int i = 0; i < m_devices->count(); ++i) {
        if (m_devices->item(i)->data(kIdRole).toInt() == id)
            m_devices->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
    }
}

void ApplyToDevicesDialog::compareChecked()
{
    const QList<int> ids = checkedDevices();
    if (ids.isEmpty() || m_rollout->isBusy())
        return;
    m_rows->clear();
    m_summary->setText(tr("Reading %n device(s)…", nullptr, int(ids.size())));
    m_rollout->compare(ids, m_names);
    updateButtons();
}

void ApplyToDevicesDialog::showComparison()
{
    m_filling = true;
    m_rows->clear();
    for (const RolloutDevice &d : m_rollout->devices()) {
        auto *top = new QTreeWidgetItem(m_rows, {ProfileRollout::describe(d)});
        top->setData(0, kIdRole, d.id);
        top->setFirstColumnSpanned(true);
        for (const ProfileDifference &row : d.differences) {
            const Parameter &p = *row.parameter;
            auto *child = new QTreeWidgetItem(
                top,
                {QStringLiteral("%1 (%2)").arg(p.label.text(Language::instance().current()), p.key),
                 valueText(p, row.device), valueText(p, row.profile)});
            child->setData(0, kKeyRole, p.key);
            child->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            child->setCheckState(0, d.chosen.contains(p.key) ? Qt::Checked : Qt::Unchecked);
        }
        top->setExpanded(true);
    }
    m_filling = false;
    m_summary->setText(m_rollout->chosenValues() > 0
                           ? tr("Nothing has been written yet.")
                           : tr("Nothing to write: the devices hold the profile's values or "
                                "could not be read."));
    updateButtons();
}

QTreeWidgetItem *ApplyToDevicesDialog::itemFor(int id) const
{
    for (int i = 0; i < m_rows->topLevelItemCount(); ++i) {
        if (m_rows->topLevelItem(i)->data(0, kIdRole).toInt() == id)
            return m_rows->topLevelItem(i);
    }
    return nullptr;
}

void ApplyToDevicesDialog::takeChoices()
{
    for (int i = 0; i < m_rows->topLevelItemCount(); ++i) {
        QTreeWidgetItem *top = m_rows->topLevelItem(i);
        QStringList keys;
        for (int c = 0; c < top->childCount(); ++c) {
            if (top->child(c)->checkState(0) == Qt::Checked)
                keys << top->child(c)->data(0, kKeyRole).toString();
        }
        m_rollout->choose(top->data(0, kIdRole).toInt(), keys);
    }
}

void ApplyToDevicesDialog::writeChecked()
{
    if (m_rollout->isBusy() || m_rollout->isApplied() || m_rollout->chosenValues() == 0)
        return;
    takeChoices();
    m_summary->setText(tr("Writing…"));
    m_rollout->apply();
    updateButtons();
}

void ApplyToDevicesDialog::updateDevice(int id)
{
    const RolloutDevice *d = m_rollout->device(id);
    QTreeWidgetItem *top = itemFor(id);
    if (!d || !top)
        return;
    m_filling = true;
    top->setText(0, ProfileRollout::describe(*d));
    for (int c = 0; c < top->childCount(); ++c) {
        QTreeWidgetItem *child = top->child(c);
        child->setFlags(Qt::ItemIsEnabled); // decided: no more choosing
        if (d->verified.contains(child->data(0, kKeyRole).toString()))
            child->setText(1, child->text(2));
    }
    m_filling = false;
}

void ApplyToDevicesDialog::closeEvent(QCloseEvent *event)
{
    if (m_rollout->isBusy() && m_rollout->isCompared()) {
        m_summary->setText(tr("Writing… this window stays open until every device has its "
                              "result. E-STOP (F12) stops what is left."));
        event->ignore();
        return;
    }
    QDialog::closeEvent(event);
}

void ApplyToDevicesDialog::reject()
{
    if (m_rollout->isBusy() && m_rollout->isCompared())
        return;
    QDialog::reject();
}

QStringList ApplyToDevicesDialog::resultLines() const
{
    QStringList lines;
    for (const RolloutDevice &d : m_rollout->devices())
        lines << ProfileRollout::describe(d);
    return lines;
}

void ApplyToDevicesDialog::updateButtons()
{
    const bool busy = m_rollout->isBusy();
    const bool done = m_rollout->isApplied();
    m_compare->setEnabled(!busy && !done && !checkedDevices().isEmpty());
    m_devices->setEnabled(!busy && !done);
    const int values = m_rollout->chosenValues();
    const int devices = m_rollout->chosenDevices();
    m_write->setText(values > 0
                         ? tr("&Write %n value(s) to %1 device(s)", nullptr, values).arg(devices)
                         : tr("&Write"));
    m_write->setEnabled(!busy && !done && values > 0 && m_session->connection()->isConnected());
    m_write->setDefault(false); // writing is never what Enter does
}

} // namespace stepcom

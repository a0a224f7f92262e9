#include "widgets/docks/devicelistdock.h"

#include "i18n/translators.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionstatus.h"
#include "widgets/docks/devicelistsettings.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>

namespace stepcom {

namespace {
enum Column { IdColumn, NameColumn, StateColumn, ReferencedColumn, ErrorsColumn, ColumnCount };
}

DeviceListDock::DeviceListDock(DeviceSession *session, QWidget *parent)
    : QDockWidget(parent)
    , m_session(session)
    , m_table(new QTableWidget(0, ColumnCount, this))
    , m_idBox(new QSpinBox(this))
    , m_add(new QPushButton(this))
    , m_problem(new QLabel(this))
    , m_backgroundLabel(new QLabel(this))
    , m_backgroundMs(new QSpinBox(this))
{
    setObjectName(QStringLiteral("deviceListDock"));
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    // One line a device: a bottom tab has room for a few rows only.
    m_table->setWordWrap(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    layout->addWidget(m_table);
    auto *addRow = new QHBoxLayout;
    m_idBox->setRange(1, 255);
    addRow->addWidget(m_idBox);
    addRow->addWidget(m_add);
    layout->addLayout(addRow);
    // The device in view is read at the live rate; the others in turn, as often as set here.
    auto *rateRow = new QHBoxLayout;
    m_backgroundMs->setObjectName(QStringLiteral("backgroundInterval"));
    m_backgroundMs->setRange(100, 60000);
    m_backgroundMs->setSingleStep(100);
    m_backgroundMs->setValue(QSettings()
                                 .value(QStringLiteral("devices/backgroundIntervalMs"),
                                        std::max(100, m_session->line()->backgroundIntervalMs()))
                                 .toInt());
    m_session->line()->setBackgroundIntervalMs(m_backgroundMs->value());
    m_backgroundLabel->setBuddy(m_backgroundMs);
    rateRow->addWidget(m_backgroundLabel);
    rateRow->addWidget(m_backgroundMs);
    rateRow->addStretch(1);
    layout->addLayout(rateRow);
    m_problem->setWordWrap(true);
    layout->addWidget(m_problem);
    setWidget(body);

    connect(m_table, &QTableWidget::cellClicked, this, &DeviceListDock::onCellClicked);
    connect(m_table, &QTableWidget::cellChanged, this, &DeviceListDock::onCellChanged);
    connect(m_add, &QPushButton::clicked, this, [this] { addDevice(m_idBox->value()); });
    connect(m_backgroundMs, &QSpinBox::valueChanged, this, [this](int ms) {
        m_session->line()->setBackgroundIntervalMs(ms);
        QSettings().setValue(QStringLiteral("devices/backgroundIntervalMs"), ms);
    });
    connect(m_session->line(), &SessionLine::deviceStatusChanged, this, &DeviceListDock::refresh);
    connect(m_session->line(), &SessionLine::deviceInViewChanged, this, &DeviceListDock::refresh);
    connect(m_session->line(), &SessionLine::deviceIdsChanged, this, [this] {
        refresh();
        saveList();
    });
    connect(m_session->connection(), &SessionConnection::connected, this,
            &DeviceListDock::onConnected);
    connect(m_session->connection(), &SessionConnection::disconnected, this,
            [this] { m_connectedBefore = false; });
    connect(m_session->connection(), &SessionConnection::linkStateChanged, this,
            &DeviceListDock::refresh);
    connect(m_session->status(), &SessionStatus::statusCycleFinished, this,
            &DeviceListDock::refresh);
    connect(m_session->motion()->references(), &ReferenceTracker::deviceChanged, this,
            &DeviceListDock::refresh);
    connect(m_session->motion(), &MotionSupervisor::changed, this, &DeviceListDock::refresh);
    retranslate();
}

bool DeviceListDock::addDevice(int id, const QString &name)
{
    QList<int> ids = m_session->line()->deviceIds();
    if (id < 1 || id > 255) {
        m_problem->setText(tr("Device ids are 1 to 255, not %1.").arg(id));
        return false;
    }
    if (ids.contains(id)) {
        m_problem->setText(tr("Device id %1 is already on the list.").arg(id));
        return false;
    }
    m_problem->clear();
    if (!name.trimmed().isEmpty()) {
        m_names.insert(id, name.trimmed());
        Q_EMIT namesChanged();
    }
    ids.append(id);
    m_session->line()->setDeviceIds(ids);
    refresh();
    return true;
}

void DeviceListDock::setName(int id, const QString &name)
{
    if (name.trimmed().isEmpty())
        m_names.remove(id);
    else
        m_names.insert(id, name.trimmed());
    refresh();
    saveList();
    Q_EMIT namesChanged();
}

void DeviceListDock::saveList() const
{
    // Only a real line the session is on has a key.
    if (!m_session->connection()->isConnected() ||
        DeviceListSettings::lineKey(*m_session).isEmpty())
        return;
    DeviceListSettings saved;
    saved.line = DeviceListSettings::lineKey(*m_session);
    saved.ids = m_session->line()->deviceIds();
    saved.names = m_names;
    saved.save();
}

bool DeviceListDock::restoreList()
{
    const DeviceListSettings saved = DeviceListSettings::load();
    if (saved.ids.size() < 2 || saved.line.isEmpty() ||
        saved.line != DeviceListSettings::lineKey(*m_session))
        return false;
    if (m_session->line()->deviceIds().size() > 1)
        return false; // the user (or a scan) named the devices for this connection already
    for (auto it = saved.names.cbegin(); it != saved.names.cend(); ++it)
        m_names.insert(it.key(), it.value());
    Q_EMIT namesChanged();
    QList<int> ids = saved.ids;
    // The device in view is on the list it belongs to.
    if (!ids.contains(m_session->line()->deviceInView()))
        ids.prepend(m_session->line()->deviceInView());
    m_session->line()->setDeviceIds(ids);
    refresh();
    return true;
}

void DeviceListDock::onConnected(bool ok)
{
    if (!ok)
        return;
    // Only a new connection restores: a baud change reopens the port, the list stays.
    const bool restored = !std::exchange(m_connectedBefore, true) && restoreList();
    if (!restored && m_session->line()->deviceIds().size() > 1) {
        QList<int> ids = m_session->line()->deviceIds();
        if (!ids.contains(m_session->line()->deviceInView())) {
            ids.prepend(m_session->line()->deviceInView());
            m_session->line()->setDeviceIds(ids); // saves
        } else {
            saveList();
        }
    }
}

QStringList DeviceListDock::rowTexts(int row) const
{
    QStringList texts;
    for (int c = 0; c < ColumnCount; ++c)
        texts << (m_table->item(row, c) ? m_table->item(row, c)->text() : QString());
    return texts;
}

void DeviceListDock::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void DeviceListDock::retranslate()
{
    setWindowTitle(tr("Devices on the line"));
    m_table->setHorizontalHeaderLabels(
        {tr("Id"), tr("Name"), tr("State"), tr("Referenced"), tr("Errors")});
    m_table->setAccessibleName(tr("Devices on the line"));
    m_add->setText(tr("Add device"));
    m_backgroundLabel->setText(tr("Other devices read every:"));
    m_backgroundMs->setSuffix(tr(" ms"));
    m_backgroundMs->setToolTip(tr("The device in view is read at the live rate; each of the "
                                  "others in turn, at most this often"));
    m_idBox->setAccessibleName(tr("Device id to add"));
    refresh();
}

void DeviceListDock::showReplay(const QList<int> &ids, const QHash<int, ReplayDeviceRow> &rows,
                                int inView, const std::function<void(int)> &choose)
{
    m_replay = Replay{ids, rows, inView, choose};
    refresh();
}

void DeviceListDock::endReplay()
{
    m_replay.reset();
    refresh();
}

QList<int> DeviceListDock::ids() const
{
    return m_replay ? m_replay->ids : m_session->line()->deviceIds();
}

int DeviceListDock::inView() const
{
    return m_replay ? m_replay->inView : m_session->line()->deviceInView();
}

QString DeviceListDock::stateText(int id) const
{
    if (m_replay) { // what the log says of it at the moment shown, in the live list's words
        const ReplayDeviceRow r = m_replay->rows.value(id);
        const bool inView = id == m_replay->inView;
        QString state;
        if (!r.linkUp)
            state = tr("not connected");
        else if (!r.runningMotors.isEmpty()) // the command in the language shown, as live
            state =
                tr("running: %1")
                    .arg(m_session->map().find(r.command)
                             ? m_session->map().find(r.command)->label.text(Translators::current())
                             : motorsText(r.runningMotors));
        else if (!r.asked)
            state = inView ? tr("asking (in view)") : tr("asking");
        else if (inView)
            state = r.answering ? tr("answering (in view)") : tr("not answering (in view)");
        else
            state = r.answering ? tr("answering") : tr("not answering");
        return r.restartAt.isEmpty() ? state : tr("%1; restarted %2").arg(state, r.restartAt);
    }
    if (!m_session->connection()->isConnected())
        return tr("not connected");
    // A motion followed on a device (in view or not) says more than "answering".
    if (const QList<MotionStart> moving = m_session->motion()->activeOn(id); !moving.isEmpty()) {
        const Parameter *p = m_session->map().find(moving.first().command);
        return tr("running: %1")
            .arg(p ? p->label.text(Translators::current()) : moving.first().command);
    }
    if (id == m_session->line()->deviceInView()) {
        switch (m_session->connection()->health()->state()) {
        case LinkHealth::State::Answering:
            return tr("answering (in view)");
        case LinkHealth::State::NotAnswering:
            return tr("not answering (in view)");
        default:
            return tr("asking (in view)");
        }
    }
    switch (m_session->line()->deviceStatus(id).state) {
    case BusDeviceStatus::State::Answering:
        return tr("answering");
    case BusDeviceStatus::State::NotAnswering:
        return tr("not answering");
    case BusDeviceStatus::State::Unknown:
        break;
    }
    return tr("asking");
}

QString DeviceListDock::referencedText(int id) const
{
    if (m_replay || !m_session->connection()->isConnected())
        return tr("unknown");
    // References are followed on every device of the line.
    const QList<int> motors = m_session->motion()->references()->referencedMotors(id);
    return motors.isEmpty() ? tr("no") : motorsText(motors);
}

QString DeviceListDock::motorsText(const QList<int> &motors) const
{
    QStringList numbers;
    for (const int m : motors)
        numbers << QString::number(m);
    return tr("motor %1").arg(numbers.join(QLatin1String(", ")));
}

void DeviceListDock::refresh()
{
    const QList<int> ids = this->ids();
    m_filling = true;
    m_table->setRowCount(int(ids.size()));
    for (int row = 0; row < ids.size(); ++row) {
        const int id = ids.at(row);
        BusDeviceStatus status =
            m_replay ? BusDeviceStatus::of(id) : m_session->line()->deviceStatus(id);
        QString name = m_names.value(id);
        QString stateTip;
        if (m_replay) { // the requests to it in the log up to the moment, and what failed
            const ReplayDeviceRow r = m_replay->rows.value(id);
            status.cycles = r.requests;
            status.errors = r.errors;
            status.lastError = r.lastError;
            stateTip = r.restartText;
            if (!r.name.isEmpty())
                name = r.name;
        }
        const QStringList texts{QString::number(id), name, stateText(id), referencedText(id),
                                status.cycles > 0 ? QString::number(status.errors) : QString()};
        for (int c = 0; c < ColumnCount; ++c) {
            QTableWidgetItem *item = m_table->item(row, c);
            if (!item) {
                item = new QTableWidgetItem;
                m_table->setItem(row, c, item);
            }
            // Only the name is the user's to edit.
            item->setFlags(c == NameColumn ? item->flags() | Qt::ItemIsEditable
                                           : item->flags() & ~Qt::ItemIsEditable);
            item->setText(texts.at(c));
            if (c == ErrorsColumn) // failed status reads; the last one's reason on hover
                item->setToolTip(status.errors > 0 ? status.lastError : QString());
            if (c == StateColumn)
                item->setToolTip(stateTip);
        }
        if (id == inView())
            m_table->selectRow(row);
    }
    m_filling = false;
}

void DeviceListDock::onCellClicked(int row)
{
    const int id = ids().value(row, 0);
    if (id <= 0 || id == inView())
        return;
    if (m_replay)
        m_replay->choose(id);
    else
        m_session->line()->showDevice(id);
}

void DeviceListDock::onCellChanged(int row, int column)
{
    if (m_filling || column != NameColumn)
        return;
    const int id = ids().value(row, 0);
    if (id > 0) {
        m_names.insert(id, m_table->item(row, column)->text().trimmed());
        saveList();
        Q_EMIT namesChanged();
    }
}

} // namespace stepcom

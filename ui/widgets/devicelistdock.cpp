#include "widgets/devicelistdock.h"

#include "device/devicesession.h"
#include "device/linkhealth.h"
#include "device/motionsupervisor.h"
#include "device/referencetracker.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

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
{
    setObjectName(QStringLiteral("deviceListDock"));
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table);
    auto *addRow = new QHBoxLayout;
    m_idBox->setRange(1, 255);
    addRow->addWidget(m_idBox);
    addRow->addWidget(m_add);
    layout->addLayout(addRow);
    m_problem->setWordWrap(true);
    layout->addWidget(m_problem);
    setWidget(body);

    connect(m_table, &QTableWidget::cellClicked, this, &DeviceListDock::onCellClicked);
    connect(m_table, &QTableWidget::cellChanged, this, &DeviceListDock::onCellChanged);
    connect(m_add, &QPushButton::clicked, this, [this] { addDevice(m_idBox->value()); });
    connect(m_session, &DeviceSession::deviceStatusChanged, this, &DeviceListDock::refresh);
    connect(m_session, &DeviceSession::deviceInViewChanged, this, &DeviceListDock::refresh);
    connect(m_session, &DeviceSession::linkStateChanged, this, &DeviceListDock::refresh);
    connect(m_session, &DeviceSession::statusCycleFinished, this, &DeviceListDock::refresh);
    connect(m_session->motion()->references(), &ReferenceTracker::changed, this,
            &DeviceListDock::refresh);
    retranslate();
}

bool DeviceListDock::addDevice(int id)
{
    QList<int> ids = m_session->deviceIds();
    if (ids.contains(id)) {
        m_problem->setText(tr("Device id %1 is already on the list.").arg(id));
        return false;
    }
    m_problem->clear();
    ids.append(id);
    m_session->setDeviceIds(ids);
    refresh();
    return true;
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
    m_idBox->setAccessibleName(tr("Device id to add"));
    refresh();
}

QString DeviceListDock::stateText(int id) const
{
    if (!m_session->isConnected())
        return tr("not connected");
    if (id == m_session->deviceInView()) {
        switch (m_session->health()->state()) {
        case LinkHealth::State::Answering:
            return tr("answering (in view)");
        case LinkHealth::State::NotAnswering:
            return tr("not answering (in view)");
        default:
            return tr("asking (in view)");
        }
    }
    switch (m_session->deviceStatus(id).state) {
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
    // References are followed for the device in view only.
    if (id != m_session->deviceInView() || !m_session->isConnected())
        return tr("unknown");
    const ReferenceTracker *refs = m_session->motion()->references();
    QStringList axes;
    for (int m = 1; m <= refs->motorCount(); ++m)
        if (refs->isReferenced(m))
            axes << QString::number(m);
    if (axes.isEmpty())
        return tr("no");
    return tr("motor %1").arg(axes.join(QLatin1String(", ")));
}

void DeviceListDock::refresh()
{
    const QList<int> ids = m_session->deviceIds();
    m_filling = true;
    m_table->setRowCount(int(ids.size()));
    for (int row = 0; row < ids.size(); ++row) {
        const int id = ids.at(row);
        const int errors =
            id == m_session->deviceInView() ? -1 : m_session->deviceStatus(id).errors;
        const QStringList texts{QString::number(id), m_names.value(id), stateText(id),
                                referencedText(id),
                                errors < 0 ? QString() : QString::number(errors)};
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
        }
        if (id == m_session->deviceInView())
            m_table->selectRow(row);
    }
    m_filling = false;
}

void DeviceListDock::onCellClicked(int row)
{
    const int id = m_session->deviceIds().value(row, 0);
    if (id > 0 && id != m_session->deviceInView())
        m_session->showDevice(id);
}

void DeviceListDock::onCellChanged(int row, int column)
{
    if (m_filling || column != NameColumn)
        return;
    const int id = m_session->deviceIds().value(row, 0);
    if (id > 0)
        m_names.insert(id, m_table->item(row, column)->text().trimmed());
}

} // namespace stepcom

#include "dialogs/busscandialog.h"

#include "line/busscanner.h"
#include "session/devicesession.h"
#include "session/idlist.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"

#include <QCheckBox>
#include <QEvent>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepcom {

namespace {

enum Column { BaudColumn, IdColumn, DetailColumn, ColumnCount };

bool samePort(const LinkSettings &a, const LinkSettings &b)
{
    if (a.transport != b.transport)
        return false;
    if (a.isNetwork())
        return a.host == b.host && a.tcpPort == b.tcpPort;
    if (a.portName == b.portName)
        return true;
    // A symlink (the simulator's --link, /dev/serial/by-id/...) names the same port.
    const QString ca = QFileInfo(a.portName).canonicalFilePath();
    return !ca.isEmpty() && ca == QFileInfo(b.portName).canonicalFilePath();
}

void addRow(QFormLayout *form, QWidget *field, QWidget *buddy = nullptr)
{
    auto *label = new QLabel(field->parentWidget());
    label->setBuddy(buddy ? buddy : field);
    form->addRow(label, field);
}

template<class W>
W *named(W *widget, const char *name)
{
    widget->setObjectName(QLatin1String(name));
    return widget;
}

QSpinBox *newSpin(QWidget *parent, const char *name, int min, int max, int value, int step = 1)
{
    auto *spin = named(new QSpinBox(parent), name);
    spin->setRange(min, max);
    spin->setValue(value);
    spin->setSingleStep(step);
    return spin;
}

QWidget *newRow(QWidget *parent, const QList<QWidget *> &widgets)
{
    auto *row = new QWidget(parent);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    for (QWidget *w : widgets) {
        w->setParent(row);
        layout->addWidget(w);
    }
    layout->addStretch(1);
    return row;
}

void setLabel(QFormLayout *form, QWidget *field, const QString &text)
{
    if (auto *label = qobject_cast<QLabel *>(form->labelForField(field)))
        label->setText(text);
}

} // namespace

BusScanDialog::BusScanDialog(DeviceSession *session, const LinkSettings &base, QWidget *parent)
    : QDialog(parent)
    , m_session(session)
    , m_scanner(new BusScanner(this))
{
    m_whereBox = new QGroupBox(this);
    m_whereForm = new QFormLayout(m_whereBox);
    m_port = new QLabel(m_whereBox);
    m_port->setTextInteractionFlags(Qt::TextSelectableByMouse);
    addRow(m_whereForm, m_port);
    m_warning = named(new QLabel(m_whereBox), "warning");
    m_warning->setWordWrap(true);
    m_whereForm->addRow(m_warning);

    m_optionsBox = new QGroupBox(this);
    m_optionsForm = new QFormLayout(m_optionsBox);
    m_optionsForm->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    for (int baud : LinkSettings::supportedBauds()) {
        auto *box = new QCheckBox(QString::number(baud), m_optionsBox);
        box->setObjectName(QStringLiteral("baud%1").arg(baud));
        box->setChecked(true);
        m_bauds.insert(baud, box);
        connect(box, &QCheckBox::toggled, this, &BusScanDialog::updateStatus);
    }
    m_baudRow = newRow(m_optionsBox, QList<QWidget *>(m_bauds.cbegin(), m_bauds.cend()));
    addRow(m_optionsForm, m_baudRow, m_bauds.first());
    m_firstId = newSpin(m_optionsBox, "firstId", 1, 255, 1);
    m_idTo = new QLabel(m_optionsBox);
    // 247 ends the Modbus unicast range; 248-255 only on request.
    m_lastId = newSpin(m_optionsBox, "lastId", 1, 255, 247);
    m_idRow = newRow(m_optionsBox, {m_firstId, m_idTo, m_lastId});
    addRow(m_optionsForm, m_idRow, m_firstId);
    // 0: fitted to each baud (the frames, the 35 ms answer delay and a USB adapter's latency);
    // more for controllers that answer slowly.
    m_probeTimeout = newSpin(m_optionsBox, "probeTimeout", 0, 5000, 0, 10);
    addRow(m_optionsForm, m_probeTimeout);
    m_stopAtFirst = named(new QCheckBox(m_optionsBox), "stopAtFirst");
    m_optionsForm->addRow(m_stopAtFirst);
    for (QSpinBox *spin : {m_firstId, m_lastId, m_probeTimeout})
        connect(spin, &QSpinBox::valueChanged, this, &BusScanDialog::updateStatus);

    m_start = named(new QPushButton(this), "start");
    m_cancel = named(new QPushButton(this), "cancel");
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setFormat(QString()); // no "0%" before anything ran
    m_status = named(new QLabel(this), "status");
    m_status->setWordWrap(true);
    auto *runRow = new QHBoxLayout;
    runRow->addWidget(m_start);
    runRow->addWidget(m_cancel);
    runRow->addWidget(m_progress, 1);

    m_foundBox = new QGroupBox(this);
    m_table = named(new QTableWidget(0, ColumnCount, m_foundBox), "found");
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    (new QVBoxLayout(m_foundBox))->addWidget(m_table);

    m_connect = named(new QPushButton(this), "connect");
    m_addAll = named(new QPushButton(this), "addAll");
    m_close = new QPushButton(this);
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_connect);
    bottom->addWidget(m_addAll);
    bottom->addStretch(1);
    bottom->addWidget(m_close);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_whereBox);
    layout->addWidget(m_optionsBox);
    layout->addLayout(runRow);
    layout->addWidget(m_status);
    layout->addWidget(m_foundBox, 1);
    layout->addLayout(bottom);

    QList<QWidget *> order(m_bauds.cbegin(), m_bauds.cend());
    order << m_firstId << m_lastId << m_probeTimeout << m_stopAtFirst << m_start << m_cancel
          << m_table << m_connect << m_addAll << m_close;
    for (qsizetype i = 1; i < order.size(); ++i)
        setTabOrder(order.at(i - 1), order.at(i));

    connect(m_start, &QPushButton::clicked, this, &BusScanDialog::startScan);
    connect(m_cancel, &QPushButton::clicked, this, &BusScanDialog::cancelScan);
    connect(m_connect, &QPushButton::clicked, this, &BusScanDialog::connectSelected);
    connect(m_addAll, &QPushButton::clicked, this, &BusScanDialog::addAllFound);
    connect(m_close, &QPushButton::clicked, this, &BusScanDialog::reject);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &BusScanDialog::updateControls);
    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row) {
        m_table->selectRow(row);
        connectSelected();
    });
    connect(m_scanner, &BusScanner::progress, this, &BusScanDialog::onProgress);
    connect(m_scanner, &BusScanner::finished, this, &BusScanDialog::onFinished);
    connect(m_scanner, &BusScanner::foundDevice, this, [this](const BusScanner::Found &f) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, BaudColumn, new QTableWidgetItem(QString::number(f.baud)));
        m_table->setItem(row, IdColumn, new QTableWidgetItem(QString::number(f.deviceId)));
        // A late answer: the controller needs a longer timeout than the link's to be used.
        const int timeoutMs = f.late ? BusScanner::suggestedTimeoutMs(f.answerMs) : 0;
        m_table->item(row, IdColumn)->setData(Qt::UserRole, timeoutMs);
        m_table->setItem(row, DetailColumn,
                         new QTableWidgetItem(f.late ? tr("%1 (answered after %2 ms: connects "
                                                          "with a %3 ms timeout)")
                                                           .arg(f.detail)
                                                           .arg(f.answerMs)
                                                           .arg(timeoutMs)
                                                     : f.detail));
        // The whole sentence a person reads ("id 7 at 9600 8N1 — a 2-axis controller, ...").
        for (int column = 0; column < ColumnCount; ++column)
            m_table->item(row, column)->setToolTip(f.summary());
        if (m_table->currentRow() < 0)
            m_table->selectRow(row); // so Connect is one click away
        updateStatus();
    });
    connect(m_session->connection(), &SessionConnection::linkStateChanged, this,
            &BusScanDialog::onSessionState);

    setBaseSettings(base);
    retranslate();
    // Sized by the font, so it scales with the screen.
    const QFontMetrics fm = fontMetrics();
    QSize size(std::max(sizeHint().width(), fm.averageCharWidth() * 72),
               std::max(sizeHint().height(), fm.height() * 34));
    // Never larger than the screen (a 1366×768 laptop at 150 % has 911×512 to offer).
    if (const QScreen *where = parent ? parent->screen() : screen())
        size = size.boundedTo(where->availableGeometry().size() * 0.95);
    resize(size);
}

BusScanDialog::~BusScanDialog()
{
    m_scanner->disconnect(this);
    m_scanner->cancel();
}

void BusScanDialog::retranslate()
{
    setWindowTitle(tr("Scan bus"));
    m_whereBox->setTitle(tr("Where"));
    setLabel(m_whereForm, m_port, tr("Port:"));
    m_optionsBox->setTitle(tr("What to try"));
    setLabel(m_optionsForm, m_baudRow, tr("&Baud rates:"));
    for (QCheckBox *box : std::as_const(m_bauds))
        box->setToolTip(tr("Try this baud rate (register 40213; the factory setting is 9600)"));
    setLabel(m_optionsForm, m_idRow, tr("Device &ids:"));
    m_idTo->setText(tr("to"));
    m_firstId->setToolTip(tr("First device id to try (register 40212; factory setting 1)"));
    m_lastId->setToolTip(tr("Last device id to try; 247 is the highest standard Modbus address"));
    setLabel(m_optionsForm, m_probeTimeout, tr("Probe &timeout:"));
    m_probeTimeout->setSuffix(tr(" ms"));
    m_probeTimeout->setSpecialValueText(tr("fitted to the baud"));
    m_probeTimeout->setToolTip(
        tr("How long to wait for an answer from each id. Fitted to the baud: the frames, the "
           "controller's 35 ms answer delay and a USB adapter's latency (67 ms at 9600). A "
           "controller that answers later is still found by its late answer; give more for "
           "one that answers very slowly."));
    m_stopAtFirst->setText(tr("Stop at the &first controller found"));
    m_stopAtFirst->setToolTip(tr("Finish as soon as one controller answers"));
    m_start->setText(tr("&Start"));
    m_start->setToolTip(tr("Start the scan; it only reads, nothing is written"));
    m_cancel->setText(tr("&Cancel"));
    m_cancel->setToolTip(tr("Stop the scan now"));
    m_foundBox->setTitle(tr("Controllers found"));
    m_table->setHorizontalHeaderLabels({tr("Baud"), tr("Device id"), tr("Controller")});
    m_table->setToolTip(tr("Double-click a controller to connect to it"));
    m_connect->setText(tr("C&onnect"));
    m_connect->setToolTip(tr("Connect to the selected controller with its baud rate and id"));
    m_addAll->setText(tr("&Add all found"));
    m_addAll->setToolTip(tr("Put every controller found on the device list (View → Devices on "
                            "the line)"));
    m_close->setText(tr("Close"));
    setBaseSettings(m_base); // the port line and the warning are texts too
}

void BusScanDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

QString BusScanDialog::parityText(QSerialPort::Parity parity)
{
    switch (parity) {
    case QSerialPort::EvenParity:
        return tr("even");
    case QSerialPort::OddParity:
        return tr("odd");
    default:
        return tr("none");
    }
}

void BusScanDialog::setBaseSettings(const LinkSettings &base)
{
    m_base = base;
    const bool tcp = base.isNetwork();
    m_port->setText(tcp ? (base.transport == LinkSettings::Transport::Tcp
                               ? tr("%1:%2 (Modbus TCP)")
                               : tr("%1:%2 (RTU over TCP)"))
                              .arg(base.host)
                              .arg(base.tcpPort)
                        : tr("%1, parity %2, %n stop bit(s)", nullptr,
                             base.stopBits == QSerialPort::TwoStop ? 2 : 1)
                              .arg(base.portName.isEmpty() ? tr("(no port chosen)") : base.portName,
                                   parityText(base.parity)));
    // A gateway talks to the serial side at its own baud: only ids are scanned on TCP.
    m_baudRow->setEnabled(!tcp);
    updateControls();
}

QList<int> BusScanDialog::checkedBauds() const
{
    QList<int> bauds;
    for (auto it = m_bauds.cbegin(); it != m_bauds.cend(); ++it)
        if (it.value()->isChecked())
            bauds << it.key();
    return bauds;
}

void BusScanDialog::setCheckedBauds(const QList<int> &bauds)
{
    for (auto it = m_bauds.cbegin(); it != m_bauds.cend(); ++it)
        it.value()->setChecked(bauds.contains(it.key()));
}

void BusScanDialog::setIdRange(int first, int last)
{
    m_firstId->setValue(first);
    m_lastId->setValue(last);
}

void BusScanDialog::setProbeTimeoutMs(int ms)
{
    m_probeTimeout->setValue(ms);
}

void BusScanDialog::setStopAtFirst(bool stop)
{
    m_stopAtFirst->setChecked(stop);
}

BusScanner::Plan BusScanDialog::plan() const
{
    BusScanner::Plan p;
    p.base = m_base;
    p.bauds = scanOrder();
    for (int id = m_firstId->value(); id <= m_lastId->value(); ++id)
        p.ids << id;
    p.probeTimeoutMs = m_probeTimeout->value();
    p.stopAtFirst = m_stopAtFirst->isChecked();
    return p;
}

QList<int> BusScanDialog::scanOrder() const
{
    if (m_base.isNetwork())
        return {m_base.baud};
    // The most likely first: the port's current baud, the factory 9600, then the rest.
    QList<int> order;
    for (int baud : {m_base.baud, 9600, 19200, 38400, 4800})
        if (m_bauds.contains(baud) && m_bauds.value(baud)->isChecked() && !order.contains(baud))
            order << baud;
    return order;
}

bool BusScanDialog::isScanning() const
{
    return m_scanner->isRunning();
}

int BusScanDialog::foundCount() const
{
    return m_table->rowCount();
}

LinkSettings BusScanDialog::settingsFor(int row) const
{
    LinkSettings s = m_base;
    if (row < 0 || row >= m_table->rowCount())
        return s;
    s.baud = m_table->item(row, BaudColumn)->text().toInt();
    s.deviceId = m_table->item(row, IdColumn)->text().toInt();
    s.timeoutMs = std::max(s.timeoutMs, m_table->item(row, IdColumn)->data(Qt::UserRole).toInt());
    return s;
}

bool BusScanDialog::sessionUsesPort() const
{
    return m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected &&
           samePort(m_session->connection()->settings(), m_base);
}

void BusScanDialog::startScan()
{
    if (isScanning())
        return;
    const QList<int> bauds = scanOrder();
    if (bauds.isEmpty()) {
        m_outcome = Outcome::NoBaud;
        updateStatus();
        return;
    }
    if (const QString problem = m_base.validate(); !problem.isEmpty()) {
        m_outcome = Outcome::Failed;
        m_error = problem;
        updateStatus();
        return;
    }
    // One port, one master: the session lets go of it for the scan.
    if (sessionUsesPort())
        m_session->connection()->disconnectFrom();
    m_table->setRowCount(0);
    m_added.clear();
    m_error.clear();
    m_outcome = Outcome::Running;
    const int ids = std::max(1, m_lastId->value() - m_firstId->value() + 1);
    m_progress->setRange(0, int(bauds.size()) * ids);
    m_progress->setValue(0);
    m_progress->setFormat(tr("starting…"));
    updateControls();
    m_scanner->start(plan());
    if (isScanning()) {
        m_progress->setRange(0, std::max(1, m_scanner->total()));
        updateControls();
    }
}

void BusScanDialog::cancelScan()
{
    m_scanner->cancel();
}

void BusScanDialog::connectSelected()
{
    const int row = m_table->currentRow();
    if (isScanning() || row < 0)
        return;
    Q_EMIT connectRequested(settingsFor(row));
    accept();
}

QList<int> BusScanDialog::addAllFound()
{
    if (isScanning() || m_table->rowCount() == 0)
        return {};
    // A session that is not connected lists only the id in its fields: no device of this line.
    QList<int> ids =
        m_session->connection()->isConnected() || m_session->line()->deviceIds().size() > 1
            ? m_session->line()->deviceIds()
            : QList<int>{};
    QList<int> added;
    QList<int> bauds;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const LinkSettings s = settingsFor(row);
        if (!bauds.contains(s.baud))
            bauds << s.baud;
        if (!ids.contains(s.deviceId)) {
            ids << s.deviceId;
            added << s.deviceId;
        }
    }
    if (added.isEmpty()) {
        m_added = tr("Every controller found is on the device list already.");
    } else {
        m_session->line()->setDeviceIds(ids);
        m_added = tr("Added to the device list: id %1.").arg(IdList::format(added));
    }
    // One line runs at one baud: controllers found at several cannot all answer at once.
    if (bauds.size() > 1)
        m_added += QLatin1Char(' ') +
                   tr("They answered at different baud rates; give them one baud rate (Device "
                      "page or Device → Assign device ids…) before working with the list.");
    updateStatus();
    if (!added.isEmpty())
        Q_EMIT devicesAdded(added);
    return added;
}

void BusScanDialog::reject()
{
    cancelScan();
    QDialog::reject();
}

void BusScanDialog::onProgress(int done, int total, int baud, int deviceId)
{
    m_progress->setRange(0, std::max(1, total));
    m_progress->setValue(done);
    m_progress->setFormat(tr("id %1 at %2 baud").arg(deviceId).arg(baud));
}

void BusScanDialog::onFinished(bool cancelled, const QString &error)
{
    if (m_outcome != Outcome::Interrupted)
        m_outcome = !error.isEmpty() ? Outcome::Failed
                    : cancelled      ? Outcome::Cancelled
                                     : Outcome::Done;
    m_error = error;
    if (m_outcome == Outcome::Done)
        m_progress->setValue(m_progress->maximum());
    m_progress->setFormat(m_outcome == Outcome::Done ? tr("done") : tr("stopped"));
    updateControls();
    if (m_connect->isEnabled())
        m_connect->setFocus();
}

void BusScanDialog::onSessionState()
{
    // Someone connected on this port mid-scan (the page, the command line): it has the port.
    if (isScanning() && sessionUsesPort()) {
        m_outcome = Outcome::Interrupted;
        m_scanner->cancel();
    }
    updateControls();
}

void BusScanDialog::updateControls()
{
    const bool running = isScanning();
    m_optionsBox->setEnabled(!running);
    m_start->setEnabled(!running);
    m_cancel->setEnabled(running);
    m_connect->setEnabled(!running && m_table->currentRow() >= 0 &&
                          !m_table->selectedItems().isEmpty());
    m_start->setDefault(!m_connect->isEnabled());
    m_connect->setDefault(m_connect->isEnabled());
    m_addAll->setEnabled(!running && m_table->rowCount() > 0);
    m_warning->setText(tr("StepCom is connected on this port: the scan disconnects first."));
    m_warning->setVisible(!running && sessionUsesPort());
    updateStatus();
}

QString BusScanDialog::statusText() const
{
    const int found = m_table->rowCount();
    switch (m_outcome) {
    case Outcome::Running:
        return tr("Scanning… %n controller(s) found so far.", nullptr, found);
    case Outcome::Done:
        if (!m_added.isEmpty())
            return m_added;
        if (found == 1 && m_scanner->found().size() == 1)
            return tr("Scan finished: %1. Press Connect.")
                .arg(m_scanner->found().first().summary());
        return found ? tr("Scan finished: %n controller(s) found. Select one and press Connect.",
                          nullptr, found)
                     : tr("Scan finished: no controller answered. Check the power, the wiring "
                          "(A and B swapped?) and the port.");
    case Outcome::Cancelled:
        return tr("Scan cancelled: %n controller(s) found.", nullptr, found);
    case Outcome::Failed:
        return tr("Scan stopped: %1").arg(m_error);
    case Outcome::NoBaud:
        if (scanOrder().isEmpty())
            return tr("Choose at least one baud rate.");
        break;
    case Outcome::Interrupted:
        return tr("Scan stopped: StepCom connected on this port.");
    case Outcome::Idle:
        break;
    }
    // The worst case, when nobody answers: every probe waits out its timeout.
    const BusScanner::Plan p = plan();
    const int probes = int(BusScanner::lines(p).size() * p.ids.size());
    const int seconds = int((BusScanner::worstCaseMs(p) + 999) / 1000);
    return tr("%n probe(s), at most about %1 s. A scan only reads; nothing is written.", nullptr,
              probes)
        .arg(seconds);
}

void BusScanDialog::updateStatus()
{
    m_status->setText(statusText());
}

} // namespace stepcom

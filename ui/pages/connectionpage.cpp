#include "pages/connectionpage.h"

#include "dialogs/busscandialog.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/serialports.h"
#include "widgets/fields/led.h"
#include "widgets/fields/lineoptionsbox.h"
#include "widgets/fields/statuspollrow.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

namespace stepcom {

namespace {

QFormLayout *newForm(QWidget *parent)
{
    auto *form = new QFormLayout(parent);
    // Spin boxes at their natural width read better than ones stretched across the page.
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    return form;
}

// A form row whose label text is set (and re-set) in retranslate().
template<class W>
W *addRow(QFormLayout *form, W *field)
{
    auto *label = new QLabel(field->parentWidget());
    label->setBuddy(field);
    form->addRow(label, field);
    return field;
}

void setRow(QFormLayout *form, QWidget *field, const QString &label, const QString &toolTip)
{
    if (auto *l = qobject_cast<QLabel *>(form->labelForField(field)))
        l->setText(label);
    field->setToolTip(toolTip);
}

QComboBox *newCombo(QWidget *parent, const QList<std::pair<QString, int>> &items)
{
    auto *combo = new QComboBox(parent);
    for (const auto &[text, value] : items)
        combo->addItem(text, value);
    return combo;
}

QSpinBox *newSpin(QWidget *parent, int min, int max, int step = 1)
{
    auto *spin = new QSpinBox(parent);
    spin->setRange(min, max);
    spin->setSingleStep(step);
    return spin;
}

QPushButton *newButton(QWidget *parent, const char *name)
{
    auto *button = new QPushButton(parent);
    button->setObjectName(QLatin1String(name));
    return button;
}

} // namespace

ConnectionPage::ConnectionPage(DeviceSession *session, QWidget *parent)
    : Page(session, parent)
    , m_serialPorts(new SerialPorts(this))
{
    buildUi();
    refreshPorts();
    connect(m_serialPorts, &SerialPorts::changed, this, &ConnectionPage::onPortsChanged);
    loadSettings();

    connect(m_transportGroup, &QButtonGroup::idClicked, this, [this] { updateVisibility(); });
    connect(m_refresh, &QPushButton::clicked, this, &ConnectionPage::refreshPorts);
    connect(m_connect, &QPushButton::clicked, this, &ConnectionPage::connectNow);
    connect(m_disconnect, &QPushButton::clicked, this, &ConnectionPage::disconnectNow);
    connect(m_scan, &QPushButton::clicked, this, [this] { openBusScan(); });

    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &ConnectionPage::updateState);
    connect(session->connection(), &SessionConnection::linkStatsChanged, this,
            &ConnectionPage::updateLine);
    connect(session->connection()->health(), &LinkHealth::stateChanged, this,
            &ConnectionPage::updateState);
    connect(session->connection(), &SessionConnection::connected, this,
            &ConnectionPage::onConnected);
    connect(session->connection(), &SessionConnection::echoSuspected, m_lineBox,
            &LineOptionsBox::offerEcho);
    connect(session->connection(), &SessionConnection::disconnected, this,
            [this] { setNote(false, [] { return tr("Disconnected."); }); });
    // Connected after the session's own handler of `lost`, so this note wins over the plain one.
    connect(session->connection(), &SessionConnection::linkLost, this,
            [this](const QString &reason) {
                setNote(true, [reason] { return tr("Connection lost: %1").arg(reason); });
            });
    // What a controller refuses to read is kept with the connection settings, so the next
    // connect reads it right away instead of learning it from refusals again.
    connect(session->connection(), &SessionConnection::readLimitsLearned, this,
            &ConnectionPage::saveReadLimits);
    connect(session->line(), &SessionLine::linkChanged, this, [this](const LinkSettings &s) {
        // The Device page moved the controller to a new id or baud: follow and remember it.
        if (!usesSimulator()) {
            applySettings(s);
            saveSettings();
        }
    });

    retranslate();
    updateVisibility();
}

ConnectionPage::~ConnectionPage()
{
    saveSettings();
}

void ConnectionPage::buildUi()
{
    m_transportBox = new QGroupBox(this);
    m_transportGroup = new QButtonGroup(this);
    auto *transportRow = new QHBoxLayout(m_transportBox);
    for (QRadioButton **radio : {&m_serialRadio, &m_tcpRadio, &m_simRadio}) {
        *radio = new QRadioButton(m_transportBox);
        m_transportGroup->addButton(*radio, int(m_transportGroup->buttons().size()));
        transportRow->addWidget(*radio);
    }
    transportRow->addStretch(1);
    m_serialRadio->setChecked(true);

    m_serialBox = new QGroupBox(this);
    m_serialForm = newForm(m_serialBox);
    m_port = new QComboBox(m_serialBox);
    m_port->setObjectName(QStringLiteral("port"));
    m_port->setEditable(true); // pseudo-terminals are never listed: any path can be typed
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setMinimumContentsLength(28);
    m_refresh = newButton(m_serialBox, "refresh");
    auto *portRow = new QHBoxLayout;
    portRow->addWidget(m_port, 1);
    portRow->addWidget(m_refresh);
    m_portLabel = new QLabel(m_serialBox);
    m_portLabel->setBuddy(m_port);
    m_serialForm->addRow(m_portLabel, portRow);
    QList<std::pair<QString, int>> bauds;
    for (int baud : LinkSettings::supportedBauds())
        bauds.append({QString::number(baud), baud});
    m_baud = addRow(m_serialForm, newCombo(m_serialBox, bauds));
    m_parity = addRow(m_serialForm, newCombo(m_serialBox, {{QString(), QSerialPort::NoParity},
                                                           {QString(), QSerialPort::EvenParity},
                                                           {QString(), QSerialPort::OddParity}}));
    m_stopBits =
        addRow(m_serialForm, newCombo(m_serialBox, {{QStringLiteral("1"), QSerialPort::OneStop},
                                                    {QStringLiteral("2"), QSerialPort::TwoStop}}));

    m_tcpBox = new QGroupBox(this);
    m_tcpForm = newForm(m_tcpBox);
    m_tcpForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_tcpMode = addRow(m_tcpForm, newCombo(m_tcpBox, {{QString(), 0}, {QString(), 1}}));
    m_tcpMode->setObjectName(QStringLiteral("tcpMode"));
    m_host = addRow(m_tcpForm, new QLineEdit(m_tcpBox));
    m_host->setObjectName(QStringLiteral("host"));
    m_tcpPort = addRow(m_tcpForm, newSpin(m_tcpBox, 1, 65535));
    m_tcpPort->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);

    m_deviceBox = new QGroupBox(this);
    m_deviceForm = newForm(m_deviceBox);
    m_deviceId = addRow(m_deviceForm, newSpin(m_deviceBox, 1, 255));
    m_timeout = addRow(m_deviceForm, newSpin(m_deviceBox, 20, 60000, 50));
    m_retries = addRow(m_deviceForm, newSpin(m_deviceBox, 0, 10));
    m_lineBox = new LineOptionsBox(this);
    connect(m_lineBox, &LineOptionsBox::echoAccepted, this, [this] {
        // Open the link again with the echo option, as the user asked.
        disconnectNow();
        connectNow();
    });

    m_simBox = new QGroupBox(this);
    m_simText = new QLabel(m_simBox);
    m_simText->setWordWrap(true);
    (new QVBoxLayout(m_simBox))->addWidget(m_simText);

    m_statusBox = new QGroupBox(this);
    m_led = new Led(m_statusBox);
    m_stateIcon = new QLabel(m_statusBox);
    m_status = new QLabel(m_statusBox);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse); // errors get copied into tickets
    m_line = new QLabel(m_statusBox);
    m_line->setObjectName(QStringLiteral("line"));
    m_line->setWordWrap(true);
    m_line->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_connect = newButton(m_statusBox, "connect");
    m_connect->setDefault(true);
    m_disconnect = newButton(m_statusBox, "disconnect");
    m_scan = newButton(m_statusBox, "scan");
    auto *statusLine = new QHBoxLayout;
    statusLine->addWidget(m_led, 0, Qt::AlignTop);
    statusLine->addWidget(m_stateIcon, 0, Qt::AlignTop);
    statusLine->addWidget(m_status, 1);
    auto *buttons = m_buttons = new QHBoxLayout;
    buttons->addWidget(m_connect);
    buttons->addWidget(m_disconnect);
    buttons->addStretch(1);
    buttons->addWidget(m_scan);
    auto *statusLayout = new QVBoxLayout(m_statusBox);
    statusLayout->addLayout(statusLine);
    statusLayout->addWidget(m_line);
    // How often the status is read lives with the link it loads (not beside every page).
    m_poll = new StatusPollRow(this->session(), m_statusBox);
    statusLayout->addWidget(m_poll);
    statusLayout->addLayout(buttons);

    auto *column = new QVBoxLayout;
    // Connect right below what is usually set; the rarely changed line timing after it.
    for (QWidget *box : std::initializer_list<QWidget *>{
             m_transportBox, m_serialBox, m_tcpBox, m_simBox, m_deviceBox, m_statusBox, m_lineBox})
        column->addWidget(box);
    column->addStretch(1);
    // A readable column on a wide window instead of fields stretched across the screen.
    auto *outer = new QHBoxLayout(this);
    outer->addLayout(column, 3);
    outer->addStretch(1);

    QWidget *order[] = {m_serialRadio, m_tcpRadio, m_simRadio, m_port,       m_refresh, m_baud,
                        m_parity,      m_stopBits, m_tcpMode,  m_host,       m_tcpPort, m_deviceId,
                        m_timeout,     m_retries,  m_connect,  m_disconnect, m_scan};
    for (size_t i = 1; i < std::size(order); ++i)
        setTabOrder(order[i - 1], order[i]);
}

QString ConnectionPage::title() const
{
    return tr("Connection");
}

void ConnectionPage::retranslate()
{
    m_transportBox->setTitle(tr("Connect through"));
    m_serialRadio->setText(tr("&Serial (RTU)"));
    m_serialRadio->setToolTip(tr("Modbus RTU over RS-485 or RS-232, e.g. a USB adapter"));
    m_tcpRadio->setText(tr("Modbus &TCP"));
    m_tcpRadio->setToolTip(tr("Modbus TCP, e.g. through an Ethernet-to-RS-485 gateway"));
    m_simRadio->setText(tr("Built-in si&mulator"));
    m_simRadio->setToolTip(tr("A simulated controller inside StepCom: try every page without "
                              "a machine"));

    m_serialBox->setTitle(tr("Serial port"));
    m_portLabel->setText(tr("&Port:"));
    m_port->setToolTip(tr("The serial port, e.g. /dev/ttyUSB0 or COM3. Any path can be typed: "
                          "pseudo-terminals are not listed."));
    m_port->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0 or a path"));
    m_refresh->setText(tr("Re&fresh"));
    m_refresh->setToolTip(tr("List the serial ports again (after plugging in an adapter)"));
    setRow(m_serialForm, m_baud, tr("&Baud rate:"),
           tr("The controller's baud rate (register 40213); factory setting 9600"));
    setRow(m_serialForm, m_parity, tr("Parit&y:"),
           tr("The controller uses no parity (8N1) unless set otherwise"));
    m_parity->setItemText(0, tr("None"));
    m_parity->setItemText(1, tr("Even"));
    m_parity->setItemText(2, tr("Odd"));
    setRow(m_serialForm, m_stopBits, tr("St&op bits:"), tr("The controller uses 1 stop bit"));

    m_tcpBox->setTitle(tr("Network"));
    setRow(m_tcpForm, m_tcpMode, tr("&Protocol:"),
           tr("Modbus TCP for a Modbus gateway; a transparent RS-485/Ethernet converter passes "
              "Modbus RTU frames (with CRC) over TCP, the default mode of most cheap converters"));
    m_tcpMode->setItemText(0, tr("Modbus TCP"));
    m_tcpMode->setItemText(1, tr("RS-485/Ethernet converter (transparent)"));
    setRow(m_tcpForm, m_host, tr("&Host:"),
           tr("Host name or IP address of the gateway or controller"));
    m_host->setPlaceholderText(tr("192.168.0.7"));
    setRow(m_tcpForm, m_tcpPort, tr("TCP p&ort:"),
           tr("TCP port of the Modbus server; 502 is the standard"));

    m_deviceBox->setTitle(tr("Controller"));
    setRow(m_deviceForm, m_deviceId, tr("Device &id:"),
           tr("The controller's Modbus address (register 40212); factory setting 1. Use Scan "
              "bus when it is not known."));
    setRow(m_deviceForm, m_timeout, tr("Tim&eout:"),
           tr("How long to wait for each answer before trying again"));
    m_timeout->setSuffix(tr(" ms"));
    setRow(m_deviceForm, m_retries, tr("&Retries:"),
           tr("How often an unanswered request is sent again"));
    m_lineBox->retranslate();

    m_simBox->setTitle(tr("Built-in simulator"));
    // One line on the page, the rest on demand.
    const QString simulator = tr("A simulated controller runs inside StepCom and answers like the "
                                 "real one: every page can be tried without a machine. Nothing "
                                 "reaches real hardware.");
    m_simText->setText(tr("A controller simulated inside StepCom: nothing reaches real hardware."));
    m_simText->setToolTip(simulator);
    m_simBox->setWhatsThis(simulator);

    m_statusBox->setTitle(tr("Link"));
    m_connect->setText(tr("&Connect"));
    m_connect->setToolTip(tr("Connect and read every parameter (nothing is written)"));
    m_disconnect->setText(tr("&Disconnect"));
    m_disconnect->setToolTip(tr("Close the port; edits that were not written stay"));
    m_scan->setText(tr("Sc&an bus…"));
    m_scan->setToolTip(tr("Find controllers whose device id or baud rate is not known"));
    updateState();
}

ConnectionPage::Transport ConnectionPage::transport() const
{
    return Transport(m_transportGroup->checkedId());
}

void ConnectionPage::setTransport(Transport transport)
{
    m_transportGroup->button(int(transport))->setChecked(true);
    updateVisibility();
}

void ConnectionPage::updateVisibility()
{
    const Transport t = transport();
    if (t != Transport::Simulator)
        m_realTransport = t;
    m_serialBox->setVisible(t == Transport::Serial);
    m_tcpBox->setVisible(t == Transport::Tcp);
    m_deviceBox->setVisible(t != Transport::Simulator);
    m_lineBox->setVisible(t != Transport::Simulator);
    m_simBox->setVisible(t == Transport::Simulator);
    updateState();
}

QString ConnectionPage::portFromCombo() const
{
    const QString text = m_port->currentText().trimmed();
    // A listed entry shows "ttyUSB0 — description"; its data is the path to open.
    const int index = m_port->findText(text);
    if (index >= 0 && !m_port->itemData(index).toString().isEmpty())
        return m_port->itemData(index).toString();
    return text;
}

void ConnectionPage::setPortInCombo(const QString &port)
{
    const int index = m_port->findData(port);
    if (index >= 0)
        m_port->setCurrentIndex(index);
    else
        m_port->setEditText(port);
}

void ConnectionPage::refreshPorts()
{
    fillPorts(m_serialPorts->scan());
}

void ConnectionPage::fillPorts(const QList<SerialPortEntry> &ports)
{
    const QString current = portFromCombo();
    m_port->clear();
    // The adapter by name, maker and serial number; the stable by-id link is what is opened
    // and remembered, so the setting survives the adapter coming back as another ttyUSB.
    for (const SerialPortEntry &port : ports) {
        m_port->addItem(port.text(), port.path());
        m_port->setItemData(m_port->count() - 1, port.details(), Qt::ToolTipRole);
    }
    // A remembered /dev/ttyUSB0 finds its adapter's entry under the by-id name too.
    QString wanted = current;
    for (const SerialPortEntry &port : ports) {
        if (port.systemLocation == current)
            wanted = port.path();
    }
    setPortInCombo(wanted);
}

void ConnectionPage::onPortsChanged(const QList<SerialPortEntry> &ports,
                                    const QList<SerialPortEntry> &added)
{
    fillPorts(ports);
    // The adapter just plugged in is the one the technician means to use.
    if (!added.isEmpty() && !session()->connection()->isConnected()) {
        const SerialPortEntry port = added.last();
        setPortInCombo(port.path());
        setNote(false, [port] { return tr("Serial port plugged in: %1").arg(port.text()); });
    }
}

void ConnectionPage::showEvent(QShowEvent *event)
{
    m_serialPorts->setWatching(true);
    Page::showEvent(event);
}

void ConnectionPage::hideEvent(QHideEvent *event)
{
    m_serialPorts->setWatching(false);
    Page::hideEvent(event);
}

void ConnectionPage::connectNow()
{
    saveSettings();
    if (transport() == Transport::Simulator) {
        setNote(false, {});
        session()->connection()->connectSimulator();
        return;
    }
    const LinkSettings s = currentSettings();
    if (const QString problem = s.validate(); !problem.isEmpty()) {
        setNote(true, [problem] { return tr("Cannot connect: %1.").arg(problem); });
        return;
    }
    setNote(false, {});
    session()->connection()->connectTo(s);
}

void ConnectionPage::disconnectNow()
{
    session()->connection()->disconnectFrom();
}

void ConnectionPage::onConnected(bool ok, const QString &reason)
{
    if (!ok) {
        const bool sim = transport() == Transport::Simulator || usesSimulator();
        const QString where = sim ? QString() : session()->connection()->settings().describe();
        setNote(true, [reason, where] {
            return tr("Could not connect to %1: %2")
                .arg(where.isEmpty() ? tr("the built-in simulator") : where, reason);
        });
        return;
    }
    setNote(false, {});
    // Whoever connected (this page, --port, a bus scan), the fields show what is in use.
    if (usesSimulator())
        setTransport(Transport::Simulator);
    else
        applySettings(session()->connection()->settings());
    saveSettings();
}

bool ConnectionPage::usesSimulator() const
{
    return session()->connection()->isSimulator();
}

void ConnectionPage::setNote(bool problem, std::function<QString()> note)
{
    m_noteIsProblem = problem && note;
    m_note = std::move(note);
    updateState();
}

QString ConnectionPage::statusText() const
{
    const SessionConnection::LinkState state = session()->connection()->linkState();
    const QString where = session()->connection()->settings().describe();
    if (state == SessionConnection::LinkState::Connected) {
        // "Connected" only once the controller answered: an open port proves nothing.
        switch (session()->connection()->health()->state()) {
        case LinkHealth::State::Answering:
            break;
        case LinkHealth::State::NotAnswering:
            return tr("%1 is open, but the controller does not answer.").arg(where) +
                   QLatin1Char(' ') + LinkHealth::likelyCauses();
        default:
            return tr("%1 is open; waiting for the controller to answer…").arg(where);
        }
        return usesSimulator() ? tr("Connected to the built-in simulator (%1).").arg(where)
                               : tr("Connected to %1.").arg(where);
    }
    if (state == SessionConnection::LinkState::Connecting)
        return tr("Connecting to %1…").arg(where);
    if (m_note)
        return m_note(); // built now, so a language switch retranslates it
    return tr("Not connected.");
}

void ConnectionPage::updateState()
{
    if (!m_status)
        return;
    const SessionConnection::LinkState state = session()->connection()->linkState();
    const bool idle = state == SessionConnection::LinkState::Disconnected;
    // Settings are what the link was opened with: changing them needs a reconnect.
    for (QGroupBox *box : {m_transportBox, m_serialBox, m_tcpBox, m_deviceBox})
        box->setEnabled(idle);
    // The line options only, not the echo offer's button: it reconnects on its own.
    m_lineBox->answerDelay()->setEnabled(idle);
    m_lineBox->turnaround()->setEnabled(idle);
    m_lineBox->echo()->setEnabled(idle);
    m_lineBox->rs485()->setEnabled(idle);
    m_connect->setEnabled(idle);
    m_disconnect->setEnabled(!idle);
    m_scan->setEnabled(transport() != Transport::Simulator);
    const LinkHealth::State health = session()->connection()->health()->state();
    m_led->setState(health == LinkHealth::State::Answering ? Led::State::On
                    : idle                                 ? Led::State::Off
                                                           : Led::State::Unknown);
    const bool problem = (idle && m_noteIsProblem) || health == LinkHealth::State::NotAnswering;
    if (problem) {
        const int size = m_status->fontMetrics().height();
        m_stateIcon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(size));
    }
    m_stateIcon->setVisible(problem);
    m_status->setText(statusText());
    updateLine();
}

void ConnectionPage::updateLine()
{
    const LinkStats &s = session()->connection()->linkStats();
    const bool shown = session()->connection()->isConnected() && s.answers > 0;
    m_line->setVisible(shown);
    if (shown)
        m_line->setText(tr("Line: %1").arg(s.lineText(session()->line()->deviceInView())));
}

BusScanDialog *ConnectionPage::scanDialog() const
{
    return m_scanDialog;
}

BusScanDialog *ConnectionPage::openBusScan()
{
    if (!m_scanDialog) {
        m_scanDialog = new BusScanDialog(session(), currentSettings(), this);
        connect(m_scanDialog, &BusScanDialog::connectRequested, this,
                [this](const LinkSettings &s) {
                    applySettings(s);
                    connectNow();
                });
    } else if (!m_scanDialog->isScanning()) {
        m_scanDialog->setBaseSettings(currentSettings());
    }
    m_scanDialog->show();
    m_scanDialog->raise();
    m_scanDialog->activateWindow();
    return m_scanDialog;
}

void ConnectionPage::addLineAction(QAction *action)
{
    auto *button = new QToolButton(m_statusBox);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_buttons->insertWidget(2, button);
}

} // namespace stepcom

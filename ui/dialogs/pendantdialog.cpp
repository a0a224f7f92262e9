#include "dialogs/pendantdialog.h"

#include "pendant/pendantcontrol.h"
#include "pendant/pendantserver.h"

#include <QCheckBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <qrencode.h>

namespace stepcom {

namespace {

constexpr int kDefaultPort = 8470;

} // namespace

PendantDialog::PendantDialog(PendantServer *server, QWidget *parent)
    : QDialog(parent)
    , m_server(server)
    , m_intro(new QLabel(this))
    , m_portLabel(new QLabel(this))
    , m_port(new QSpinBox(this))
    , m_start(new QPushButton(this))
    , m_error(new QLabel(this))
    , m_qr(new QLabel(this))
    , m_address(new QLabel(this))
    , m_allow(new QCheckBox(this))
    , m_control(new QLabel(this))
    , m_takeBack(new QPushButton(this))
    , m_phonesLabel(new QLabel(this))
    , m_phones(new QTableWidget(0, 3, this))
    , m_disconnect(new QPushButton(this))
    , m_safety(new QLabel(this))
    , m_close(new QPushButton(this))
{
    setObjectName(QStringLiteral("pendantDialog"));
    m_intro->setWordWrap(true);
    m_safety->setWordWrap(true);
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00000;"));
    m_port->setRange(1, 65535);
    m_port->setValue(server->port() ? server->port() : kDefaultPort);
    m_portLabel->setBuddy(m_port);
    m_start->setObjectName(QStringLiteral("pendantStart"));
    m_allow->setObjectName(QStringLiteral("pendantAllowJog"));
    m_address->setObjectName(QStringLiteral("pendantAddress"));
    m_address->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_qr->setAlignment(Qt::AlignCenter);
    m_phones->verticalHeader()->hide();
    m_phones->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_phones->setSelectionMode(QAbstractItemView::SingleSelection);
    m_phones->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_phones->horizontalHeader()->setStretchLastSection(true);
    m_phonesLabel->setBuddy(m_phones);

    auto *top = new QHBoxLayout;
    top->addWidget(m_portLabel);
    top->addWidget(m_port);
    top->addWidget(m_start);
    top->addStretch(1);
    auto *control = new QHBoxLayout;
    control->addWidget(m_control, 1);
    control->addWidget(m_takeBack);
    auto *phoneButtons = new QHBoxLayout;
    phoneButtons->addStretch(1);
    phoneButtons->addWidget(m_disconnect);
    phoneButtons->addWidget(m_close);
    // The code beside the rest: low enough for a 1366×768 screen at 150 %.
    auto *side = new QVBoxLayout;
    side->addWidget(m_address);
    side->addWidget(m_allow);
    side->addLayout(control);
    side->addWidget(m_phonesLabel);
    side->addWidget(m_phones, 1);
    auto *middle = new QHBoxLayout;
    middle->addWidget(m_qr, 0, Qt::AlignTop);
    middle->addLayout(side, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addLayout(top);
    layout->addWidget(m_error);
    layout->addLayout(middle, 1);
    layout->addWidget(m_safety);
    layout->addLayout(phoneButtons);

    connect(m_start, &QPushButton::clicked, this, &PendantDialog::toggle);
    connect(m_allow, &QCheckBox::toggled, this,
            [this](bool on) { m_server->control()->setAllowed(on); });
    connect(m_takeBack, &QPushButton::clicked, this, [this] { m_server->control()->takeBack(); });
    connect(m_disconnect, &QPushButton::clicked, this, [this] {
        const int row = m_phones->currentRow();
        if (QTableWidgetItem *item = m_phones->item(row, 0))
            m_server->disconnectClient(item->data(Qt::UserRole).toInt());
    });
    connect(m_phones, &QTableWidget::itemSelectionChanged, this, [this] {
        m_disconnect->setEnabled(m_phones->currentRow() >= 0 && m_phones->rowCount() > 0);
    });
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(server, &PendantServer::runningChanged, this, &PendantDialog::refresh);
    connect(server, &PendantServer::clientsChanged, this, &PendantDialog::refresh);
    connect(server->control(), &PendantControl::allowedChanged, this, &PendantDialog::refresh);
    connect(server->control(), &PendantControl::holderChanged, this, &PendantDialog::refresh);
    retranslate();
}

QImage PendantDialog::qrCode(const QString &text, int scale)
{
    const QByteArray data = text.toUtf8();
    QRcode *code = QRcode_encodeString(data.constData(), 0, QR_ECLEVEL_M, QR_MODE_8, 1);
    if (!code)
        return {};
    const int quiet = 4; // the white margin a phone's camera needs
    const int side = (code->width + 2 * quiet) * scale;
    QImage image(side, side, QImage::Format_RGB32);
    image.fill(Qt::white);
    for (int y = 0; y < code->width; ++y) {
        for (int x = 0; x < code->width; ++x) {
            if (!(code->data[y * code->width + x] & 1))
                continue;
            for (int dy = 0; dy < scale; ++dy)
                for (int dx = 0; dx < scale; ++dx)
                    image.setPixel((x + quiet) * scale + dx, (y + quiet) * scale + dy, 0xff000000);
        }
    }
    QRcode_free(code);
    return image;
}

void PendantDialog::toggle()
{
    if (m_server->isRunning()) {
        m_server->stop();
        return;
    }
    if (!m_server->start(QHostAddress::Any, quint16(m_port->value())))
        m_error->setText(m_server->error());
    refresh();
    adjustSize(); // room for the code and the address that just came
}

void PendantDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void PendantDialog::retranslate()
{
    setWindowTitle(tr("Pendant"));
    m_intro->setText(tr("A phone or tablet on the same network becomes the pendant: scan the "
                        "code or type the address into its browser. It shows the positions, "
                        "inputs and outputs and has an E-STOP; it jogs only while you allow it "
                        "here."));
    m_portLabel->setText(tr("&Port:"));
    m_allow->setText(tr("Allow jogging from the pendant"));
    m_takeBack->setText(tr("Take control back"));
    m_phonesLabel->setText(tr("Phones connected:"));
    m_phones->setHorizontalHeaderLabels({tr("Address"), tr("Browser"), tr("Since")});
    m_disconnect->setText(tr("&Disconnect"));
    m_safety->setText(tr("The phone is no safety device: the machine's own E-STOP circuit "
                         "stays the safety."));
    m_close->setText(tr("Close"));
    m_qr->setAccessibleName(tr("QR code of the pendant's address"));
    refresh();
}

void PendantDialog::refresh()
{
    const bool running = m_server->isRunning();
    m_start->setText(running ? tr("&Stop the pendant") : tr("&Start the pendant"));
    m_port->setEnabled(!running);
    if (running)
        m_error->clear();
    m_error->setVisible(!m_error->text().isEmpty());
    const QString url = m_server->url().toString();
    m_address->setText(running ? url : tr("The pendant is off."));
    // The whole address, never cut: it is typed into a phone when the code cannot be scanned.
    m_address->setMinimumWidth(m_address->fontMetrics().horizontalAdvance(m_address->text()));
    m_address->setAccessibleName(tr("Pendant address: %1").arg(m_address->text()));
    if (running) {
        const QImage code = qrCode(url, 5);
        m_qr->setPixmap(QPixmap::fromImage(code));
        // A cut code scans as nothing: the label never gets less than the whole code.
        m_qr->setMinimumSize(code.size());
    } else {
        m_qr->clear();
    }
    m_qr->setVisible(running);
    const QSignalBlocker block(m_allow);
    m_allow->setChecked(m_server->control()->isAllowed());
    m_allow->setEnabled(running);
    const int holder = m_server->control()->holder();
    m_control->setText(holder ? tr("Control: %1").arg(m_server->describe(holder))
                              : tr("Control: nobody (the window)"));
    m_takeBack->setEnabled(holder != 0);
    const QList<PendantServer::Client> clients = m_server->clients();
    const int selected = m_phones->currentRow();
    const QSignalBlocker quiet(m_phones); // rebuilt here: its own signals must not call back
    m_phones->setRowCount(int(clients.size()));
    for (int row = 0; row < clients.size(); ++row) {
        const PendantServer::Client &c = clients.at(row);
        auto *address = new QTableWidgetItem(c.address);
        address->setData(Qt::UserRole, c.id);
        m_phones->setItem(row, 0, address);
        m_phones->setItem(row, 1, new QTableWidgetItem(c.browser));
        m_phones->setItem(row, 2,
                          new QTableWidgetItem(c.since.toString(QStringLiteral("HH:mm:ss"))));
    }
    if (selected >= 0 && selected < clients.size())
        m_phones->selectRow(selected);
    m_disconnect->setEnabled(m_phones->currentRow() >= 0 && !clients.isEmpty());
}

} // namespace stepcom

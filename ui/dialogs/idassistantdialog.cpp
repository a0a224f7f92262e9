#include "dialogs/idassistantdialog.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace stepcom {

IdAssistantDialog::IdAssistantDialog(DeviceSession *session, QWidget *parent)
    : QDialog(parent)
    , m_session(session)
    , m_assigner(new IdAssigner(session, this))
{
    setObjectName(QStringLiteral("idAssistantDialog"));
    auto *layout = new QVBoxLayout(this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    layout->addWidget(m_intro);

    m_optionsBox = new QGroupBox(this);
    m_form = new QFormLayout(m_optionsBox);
    m_firstId = new QSpinBox(m_optionsBox);
    m_firstId->setObjectName(QStringLiteral("firstId"));
    m_firstId->setRange(IdAssigner::kFactoryId + 1, 255);
    m_firstId->setValue(2);
    m_baud = new QComboBox(m_optionsBox);
    m_baud->setObjectName(QStringLiteral("commonBaud"));
    m_newLine = new QCheckBox(m_optionsBox);
    m_newLine->setObjectName(QStringLiteral("newLine"));
    m_newLine->setChecked(true);
    // Asked here, on by default: an id not saved is gone at the next power-off.
    m_saveToFlash = new QCheckBox(m_optionsBox);
    m_saveToFlash->setObjectName(QStringLiteral("saveToFlash"));
    m_saveToFlash->setChecked(true);
    m_name = new QLineEdit(m_optionsBox);
    m_name->setObjectName(QStringLiteral("name"));
    // Labels made here: an empty label text makes no label at all.
    m_form->addRow(new QLabel(m_optionsBox), m_firstId);
    m_form->addRow(new QLabel(m_optionsBox), m_baud);
    m_form->addRow(m_newLine);
    m_form->addRow(m_saveToFlash);
    m_form->addRow(new QLabel(m_optionsBox), m_name);
    layout->addWidget(m_optionsBox);

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
    m_step = new QLabel(this);
    m_step->setObjectName(QStringLiteral("step"));
    m_step->setWordWrap(true);
    layout->addWidget(m_step);

    m_table = new QTableWidget(0, 2, this);
    m_table->setObjectName(QStringLiteral("assigned"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_table, 1);

    auto *buttons = new QHBoxLayout;
    const auto button = [this, buttons](const char *name) {
        auto *b = new QPushButton(this);
        b->setObjectName(QLatin1String(name));
        b->setAutoDefault(false);
        buttons->addWidget(b);
        return b;
    };
    m_start = button("start");
    m_next = button("next");
    m_finish = button("finish");
    buttons->addStretch(1);
    m_close = button("close");
    layout->addLayout(buttons);

    connect(m_start, &QPushButton::clicked, this, &IdAssistantDialog::start);
    connect(m_next, &QPushButton::clicked, this, &IdAssistantDialog::next);
    connect(m_finish, &QPushButton::clicked, this, &IdAssistantDialog::finish);
    connect(m_close, &QPushButton::clicked, this, &IdAssistantDialog::reject);
    connect(m_assigner, &IdAssigner::stateChanged, this, [this](IdAssigner::State state) {
        m_step->clear();
        updateControls();
        if (!m_closeWhenFinished || state == IdAssigner::State::Working)
            return;
        // Closing was asked: finish the run first, then close (also when finishing failed:
        // its reason stays in the messages of the run, and the window does not hang open).
        if (state == IdAssigner::State::Waiting || state == IdAssigner::State::Collision) {
            m_assigner->finish();
            return;
        }
        m_closeWhenFinished = false;
        QDialog::reject();
    });
    connect(m_assigner, &IdAssigner::progress, m_step, &QLabel::setText);
    connect(m_assigner, &IdAssigner::deviceAdded, this, &IdAssistantDialog::onDeviceAdded);
    connect(m_session->connection(), &SessionConnection::linkStateChanged, this,
            &IdAssistantDialog::updateControls);
    retranslate();
}

IdAssistantDialog::~IdAssistantDialog() = default;

QString IdAssistantDialog::statusText() const
{
    return m_status->text();
}

QStringList IdAssistantDialog::rowTexts(int row) const
{
    QStringList texts;
    for (int c = 0; c < m_table->columnCount(); ++c)
        texts << (m_table->item(row, c) ? m_table->item(row, c)->text() : QString());
    return texts;
}

int IdAssistantDialog::rowCount() const
{
    return m_table->rowCount();
}

void IdAssistantDialog::start()
{
    m_table->setRowCount(0);
    m_assigner->setFirstId(m_firstId->value());
    m_assigner->setCommonBaud(m_baud->isEnabled() ? m_baud->currentData().toInt() : 0);
    m_assigner->setSaveToFlash(m_saveToFlash->isChecked());
    m_assigner->start(m_newLine->isChecked());
    updateControls(); // a refusal changes no state, but says why
}

void IdAssistantDialog::next()
{
    m_pendingName = m_name->text().trimmed();
    m_assigner->next();
}

void IdAssistantDialog::finish()
{
    m_assigner->finish();
}

void IdAssistantDialog::reject()
{
    switch (m_assigner->state()) {
    case IdAssigner::State::Working:
        m_status->setText(tr("Wait: a controller is being changed. The window closes when "
                             "it is done."));
        m_closeWhenFinished = true;
        return;
    case IdAssigner::State::Waiting:
    case IdAssigner::State::Collision:
    case IdAssigner::State::Failed:
        m_closeWhenFinished = true;
        m_assigner->finish();
        return;
    case IdAssigner::State::Idle:
    case IdAssigner::State::Finished:
        break;
    }
    QDialog::reject();
}

void IdAssistantDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void IdAssistantDialog::onDeviceAdded(int id)
{
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    m_table->setItem(row, 0, new QTableWidgetItem(QString::number(id)));
    m_table->setItem(row, 1, new QTableWidgetItem(m_pendingName));
    Q_EMIT deviceNamed(id, m_pendingName);
    m_pendingName.clear();
    m_name->clear();
}

void IdAssistantDialog::retranslate()
{
    setWindowTitle(tr("Assign device ids"));
    m_intro->setText(
        tr("Gives each controller of a new line its own id. Every controller leaves the factory "
           "with id %1 at %2 baud, so connect them one at a time: connect one, press Next, "
           "wait until it answers at its new id, then connect the next. A new id or baud takes "
           "effect at once; the assistant follows each controller and checks that it answers "
           "at its new id and no longer at id %1.")
            .arg(IdAssigner::kFactoryId)
            .arg(IdAssigner::kFactoryBaud));
    m_optionsBox->setTitle(tr("Settings"));
    m_form->labelForField(m_firstId)->setProperty("text", tr("First id to give:"));
    m_form->labelForField(m_baud)->setProperty("text", tr("Common baud rate:"));
    m_form->labelForField(m_name)->setProperty("text", tr("Name of the next controller:"));
    const int baud = m_baud->currentData().toInt();
    m_baud->clear();
    m_baud->addItem(tr("keep %1 (factory)").arg(IdAssigner::kFactoryBaud), 0);
    for (int b : {19200, 38400, 4800})
        m_baud->addItem(QString::number(b), b);
    m_baud->setCurrentIndex(std::max(0, m_baud->findData(baud)));
    m_newLine->setText(tr("New line: start with an empty device list"));
    m_saveToFlash->setText(tr("Save each id to flash (else lost at power-off)"));
    m_saveToFlash->setToolTip(tr("Without saving, a controller is back at id %1 and %2 baud "
                                 "after its next power-off.")
                                  .arg(IdAssigner::kFactoryId)
                                  .arg(IdAssigner::kFactoryBaud));
    m_name->setPlaceholderText(tr("optional, e.g. X/Y table"));
    m_table->setHorizontalHeaderLabels({tr("Id"), tr("Name")});
    m_start->setText(tr("Start"));
    m_next->setText(tr("Next: the controller is connected"));
    m_finish->setText(tr("Finish"));
    m_close->setText(tr("Close"));
    updateControls();
}

void IdAssistantDialog::updateControls()
{
    using State = IdAssigner::State;
    const State state = m_assigner->state();
    const bool connected = m_session->connection()->isConnected();
    const bool idle = state == State::Idle || state == State::Finished;
    const bool serial =
        m_session->connection()->settings().transport == LinkSettings::Transport::Rtu || !connected;
    m_firstId->setEnabled(idle);
    m_baud->setEnabled(idle && serial);
    m_newLine->setEnabled(idle);
    m_saveToFlash->setEnabled(idle);
    m_start->setEnabled(idle && connected);
    m_next->setEnabled(connected && (state == State::Waiting || state == State::Collision ||
                                     state == State::Failed));
    m_finish->setEnabled(state == State::Waiting || state == State::Collision ||
                         state == State::Failed);
    QString text = m_assigner->text();
    if (text.isEmpty())
        text = connected ? tr("Press Start. The line's port is open at %1.")
                               .arg(m_session->connection()->settings().describe())
                         : tr("Connect to the line first (the port the controllers are on, "
                              "%1 baud, device id %2), then press Start.")
                               .arg(IdAssigner::kFactoryBaud)
                               .arg(IdAssigner::kFactoryId);
    m_status->setText(text);
}

} // namespace stepcom

#include "pages/devicepage.h"

#include "base/language.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>

#include <utility>

namespace stepcom {

namespace {

const QString kId = QStringLiteral("device.id");
const QString kBaud = QStringLiteral("device.baud");

QLabel *wrapped(QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setWordWrap(true);
    return label;
}

// An icon and a word-wrapped text in a row: status lines and the unsaved-to-flash warning.
QWidget *statusRow(QWidget *parent, QLabel **icon, QLabel **text)
{
    auto *row = new QWidget(parent);
    auto *h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    *icon = new QLabel(row);
    (*icon)->setAlignment(Qt::AlignTop);
    *text = wrapped(row);
    (*text)->setTextInteractionFlags(Qt::TextSelectableByMouse);
    h->addWidget(*icon);
    h->addWidget(*text, 1);
    return row;
}

} // namespace

DevicePage::DevicePage(DeviceSession *session, QWidget *parent)
    : Page(session, parent)
{
    QWidget *content = scrollableContent();
    auto *rows = new QVBoxLayout(content);

    m_linkBox = new QGroupBox(content);
    auto *grid = new QGridLayout(m_linkBox);
    m_idLabel = new QLabel(m_linkBox);
    m_id = new QSpinBox(m_linkBox);
    const Parameter *id = session->map().find(kId);
    m_id->setRange(id ? int(id->rawMin) : 1, id ? int(id->rawMax) : 255);
    m_idLabel->setBuddy(m_id);
    m_idHeld = new QLabel(m_linkBox);
    m_baudLabel = new QLabel(m_linkBox);
    m_baud = new QComboBox(m_linkBox);
    if (const Parameter *baud = session->map().find(kBaud)) {
        for (const EnumValue &v : baud->values)
            m_baud->addItem(QString::number(v.value), QVariant::fromValue(v.value));
    }
    m_baudLabel->setBuddy(m_baud);
    m_baudHeld = new QLabel(m_linkBox);
    grid->addWidget(m_idLabel, 0, 0, Qt::AlignRight | Qt::AlignVCenter);
    grid->addWidget(m_id, 0, 1);
    grid->addWidget(m_idHeld, 0, 2);
    grid->addWidget(m_baudLabel, 1, 0, Qt::AlignRight | Qt::AlignVCenter);
    grid->addWidget(m_baud, 1, 1);
    grid->addWidget(m_baudHeld, 1, 2);
    grid->setColumnStretch(2, 1);
    m_linkNote = wrapped(m_linkBox);
    grid->addWidget(m_linkNote, 2, 0, 1, 3);
    m_apply = new QPushButton(m_linkBox);
    grid->addWidget(m_apply, 3, 0, 1, 3, Qt::AlignLeft);
    QWidget *linkStatus = statusRow(m_linkBox, &m_linkIcon, &m_linkStatus);
    m_reconnect = new QPushButton(linkStatus);
    linkStatus->layout()->addWidget(m_reconnect);
    grid->addWidget(linkStatus, 4, 0, 1, 3);
    rows->addWidget(m_linkBox);

    m_flashBox = new QGroupBox(content);
    auto *flash = new QVBoxLayout(m_flashBox);
    m_flashNote = wrapped(m_flashBox);
    flash->addWidget(m_flashNote);
    m_unsavedRow = statusRow(m_flashBox, &m_unsavedIcon, &m_unsavedText);
    m_unsavedRow->setAutoFillBackground(true);
    m_unsavedRow->setBackgroundRole(QPalette::ToolTipBase); // the palette's "note" colours
    m_unsavedText->setForegroundRole(QPalette::ToolTipText);
    m_unsavedRow->layout()->setContentsMargins(6, 6, 6, 6);
    flash->addWidget(m_unsavedRow);
    m_save = new QPushButton(m_flashBox);
    flash->addWidget(m_save, 0, Qt::AlignLeft);
    flash->addWidget(statusRow(m_flashBox, &m_flashIcon, &m_flashStatus));
    rows->addWidget(m_flashBox);

    m_factoryBox = new QGroupBox(content);
    auto *factory = new QVBoxLayout(m_factoryBox);
    m_factoryNote = wrapped(m_factoryBox);
    factory->addWidget(m_factoryNote);
    m_reset = new QPushButton(m_factoryBox);
    factory->addWidget(m_reset, 0, Qt::AlignLeft);
    rows->addWidget(m_factoryBox);
    rows->addStretch(1);

    const QList<QWidget *> tabs = {m_id, m_baud, m_apply, m_reconnect, m_save, m_reset};
    for (qsizetype i = 1; i < tabs.size(); ++i)
        setTabOrder(tabs.at(i - 1), tabs.at(i));

    connect(m_id, &QSpinBox::valueChanged, this, [this] {
        m_idTouched = true;
        updateEnabled();
    });
    connect(m_baud, &QComboBox::currentIndexChanged, this, [this] {
        m_baudTouched = true;
        updateEnabled();
    });
    connect(m_apply, &QPushButton::clicked, this, &DevicePage::requestLinkChange);
    connect(m_reset, &QPushButton::clicked, this, &DevicePage::requestFactoryReset);
    connect(m_reconnect, &QPushButton::clicked, this, [this] {
        setLinkEvent(LinkEvent::Reconnecting);
        this->session()->connection()->connectTo(m_previous);
    });
    connect(m_save, &QPushButton::clicked, this, [this] {
        setFlashEvent(FlashEvent::Saving);
        this->session()->saveToFlash();
    });

    ParameterStore *store = session->parameters()->store();
    connect(store, &ParameterStore::valueChanged, this, [this](const QString &key) {
        if (key == kId || key == kBaud)
            showDeviceValues();
    });
    connect(store, &ParameterStore::unsavedChanged, this, &DevicePage::updateUnsaved);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &DevicePage::updateEnabled);
    connect(session->connection(), &SessionConnection::disconnected, this,
            &DevicePage::updateEnabled);
    connect(session->connection(), &SessionConnection::connected, this,
            [this](bool ok, const QString &reason) {
                if (m_linkEvent == LinkEvent::Reconnecting) {
                    m_reason = reason;
                    setLinkEvent(ok ? LinkEvent::Reconnected : LinkEvent::ReconnectFailed);
                }
                updateEnabled();
            });
    connect(session->line(), &SessionLine::linkChanged, this, [this](const LinkSettings &now) {
        m_targetId = now.deviceId;
        m_targetBaud = now.baud;
        m_idTouched = m_baudTouched = false;
        showDeviceValues();
        setLinkEvent(LinkEvent::Changed);
        // Saved at the new id and baud, as asked: without it they last until power-off.
        if (std::exchange(m_saveAfterLinkChange, false))
            this->session()->saveToFlash();
    });
    connect(session->line(), &SessionLine::linkChangeFailed, this,
            [this](const LinkSettings &previous, const QString &reason) {
                m_saveAfterLinkChange = false;
                m_previous = previous;
                m_reason = reason;
                setLinkEvent(LinkEvent::Failed);
            });
    connect(session, &DeviceSession::commandFinished, this, [this](const QString &key, bool ok) {
        if (key == QLatin1String("save_to_flash"))
            setFlashEvent(ok ? FlashEvent::Saved : FlashEvent::SaveFailed);
        else if (key == QLatin1String("factory_reset"))
            setFlashEvent(ok ? FlashEvent::ResetDone : FlashEvent::ResetFailed);
    });
    retranslate();
    showDeviceValues();
    updateUnsaved();
}

DevicePage::~DevicePage() = default;

QString DevicePage::title() const
{
    return tr("Device");
}

QStringList DevicePage::keys() const
{
    return {kId, kBaud};
}

QMessageBox *DevicePage::confirmation() const
{
    return m_confirmation.data();
}

int DevicePage::chosenBaud() const
{
    return m_baud->currentData().toInt();
}

QString DevicePage::describe(int id, int baud) const
{
    if (session()->connection()->settings().isNetwork() || baud <= 0)
        return tr("ID %1").arg(id);
    return tr("ID %1 at %2 baud").arg(id).arg(baud);
}

void DevicePage::showDeviceValues()
{
    const auto id = session()->parameters()->store()->deviceValue(kId);
    const auto baud = session()->parameters()->store()->deviceValue(kBaud);
    m_idHeld->setText(id ? tr("The controller holds %1").arg(*id) : tr("Not read yet"));
    m_baudHeld->setText(baud ? tr("The controller holds %1").arg(*baud) : tr("Not read yet"));
    // Follow the device until the user types something of their own.
    if (id && !m_idTouched) {
        const QSignalBlocker block(m_id);
        m_id->setValue(int(*id));
    }
    if (baud && !m_baudTouched) {
        const QSignalBlocker block(m_baud);
        m_baud->setCurrentIndex(m_baud->findData(QVariant::fromValue(*baud)));
    }
    updateEnabled();
}

void DevicePage::updateEnabled()
{
    const bool connected = session()->connection()->isConnected();
    const bool tcp = session()->connection()->settings().isNetwork();
    const auto id = session()->parameters()->store()->deviceValue(kId);
    const auto baud = session()->parameters()->store()->deviceValue(kBaud);
    const bool changed = id && baud && (m_id->value() != *id || (!tcp && chosenBaud() != *baud));
    m_baud->setEnabled(!tcp);
    m_apply->setEnabled(connected && changed && !m_confirmation);
    m_save->setEnabled(connected);
    m_reset->setEnabled(connected);
}

void DevicePage::updateUnsaved()
{
    m_unsavedRow->setHidden(!session()->parameters()->store()->unsavedToFlash());
    renderStatus(); // the "saved" line reads the same state
}

void DevicePage::setLinkEvent(LinkEvent event)
{
    m_linkEvent = event;
    renderStatus();
}

void DevicePage::setFlashEvent(FlashEvent event)
{
    m_flashEvent = event;
    renderStatus();
}

std::pair<DevicePage::Tone, QString> DevicePage::linkText() const
{
    const QString target = describe(m_targetId, m_targetBaud);
    const QString old = describe(m_previous.deviceId, m_previous.baud);
    QString reason = m_reason;
    while (reason.endsWith(QLatin1Char('.'))) // the texts below end their own sentences
        reason.chop(1);
    switch (m_linkEvent) {
    case LinkEvent::None:
        return {Tone::Busy, QString()};
    case LinkEvent::Changing:
        return {Tone::Busy, tr("Changing the controller to %1…").arg(target)};
    case LinkEvent::Changed:
        return {Tone::Ok, tr("The controller answers at %1. Save to flash to keep this after a "
                             "power cycle.")
                              .arg(target)};
    case LinkEvent::Failed:
        return {Tone::Failed, tr("The controller does not answer with the new settings (%1). It "
                                 "may be using them anyway. Reconnect with the old settings (%2), "
                                 "or connect with the new ones on the Connection page.")
                                  .arg(reason, old)};
    case LinkEvent::Reconnecting:
        return {Tone::Busy, tr("Reconnecting with the old settings (%1)…").arg(old)};
    case LinkEvent::Reconnected:
        return {Tone::Ok, tr("Connected again with the old settings.")};
    case LinkEvent::ReconnectFailed:
        return {Tone::Failed, tr("Reconnecting with the old settings failed: %1.").arg(reason)};
    }
    return {};
}

std::pair<DevicePage::Tone, QString> DevicePage::flashText() const
{
    switch (m_flashEvent) {
    case FlashEvent::None:
        return {Tone::Busy, QString()};
    case FlashEvent::Saving:
        return {Tone::Busy, tr("Saving to flash…")};
    case FlashEvent::Saved:
        // One flash state: a write since the save makes it "not saved", whatever happened here.
        if (session()->parameters()->store()->unsavedToFlash())
            return {Tone::Busy, QString()};
        return {Tone::Ok,
                tr("Saved to flash: the controller keeps its settings after a power cycle.")};
    case FlashEvent::SaveFailed:
        return {Tone::Failed, tr("Saving to flash failed; see the messages.")};
    case FlashEvent::Resetting:
        return {Tone::Busy, tr("Restoring the factory settings…")};
    case FlashEvent::ResetDone:
        return {Tone::Ok, tr("Factory settings restored; StepCom reads the controller again.")};
    case FlashEvent::ResetFailed:
        return {Tone::Failed, tr("Restoring the factory settings failed; see the messages.")};
    }
    return {};
}

void DevicePage::renderStatus()
{
    const int size = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    const auto icon = [&](QStyle::StandardPixmap p) {
        return style()->standardIcon(p, nullptr, this).pixmap(size, size);
    };
    const auto show = [&](QLabel *iconLabel, QLabel *textLabel, const std::pair<Tone, QString> &s) {
        const QStyle::StandardPixmap pixmaps[] = {QStyle::SP_MessageBoxInformation,
                                                  QStyle::SP_DialogApplyButton,
                                                  QStyle::SP_MessageBoxCritical};
        textLabel->setText(s.second);
        iconLabel->setPixmap(icon(pixmaps[int(s.first)]));
        textLabel->parentWidget()->setHidden(s.second.isEmpty());
    };
    show(m_linkIcon, m_linkStatus, linkText());
    show(m_flashIcon, m_flashStatus, flashText());
    m_reconnect->setVisible(m_linkEvent == LinkEvent::Failed ||
                            m_linkEvent == LinkEvent::ReconnectFailed);
    m_unsavedIcon->setPixmap(icon(QStyle::SP_MessageBoxWarning));
}

QMessageBox *DevicePage::makeConfirmation(const QString &title, const QString &text,
                                          const QString &details, const QString &yes)
{
    auto *box = new QMessageBox(QMessageBox::Warning, title, text,
                                QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setInformativeText(details);
    box->button(QMessageBox::Yes)->setText(yes);
    // A stray Enter must not change the controller: the safe answer is the default.
    box->setDefaultButton(QMessageBox::Cancel);
    box->setEscapeButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    m_confirmation = box;
    connect(box, &QMessageBox::finished, this, [this] {
        m_confirmation.clear();
        updateEnabled();
    });
    updateEnabled();
    return box;
}

void DevicePage::requestLinkChange()
{
    if (m_confirmation || !session()->connection()->isConnected())
        return;
    const int id = m_id->value();
    const int baud = chosenBaud();
    const LinkSettings now = session()->connection()->settings();
    QMessageBox *box =
        makeConfirmation(tr("Change device ID and baud rate"),
                         tr("Change the controller from %1 to %2?")
                             .arg(describe(now.deviceId, now.baud), describe(id, baud)),
                         tr("The controller switches at once. StepCom follows it and checks that "
                            "it answers; if it does not, you can reconnect with the old settings."
                            "\n\nEvery other master on the bus must use the new settings too, and "
                            "no other device may use the new ID. Unsaved, they last until the next "
                            "power-off."),
                         tr("&Change"));
    // Asked here, on by default: a new id or baud not saved is gone at the next power-off.
    auto *save = new QCheckBox(tr("Save to flash at the new settings (else lost at power-off)"));
    save->setObjectName(QStringLiteral("saveLinkToFlash"));
    save->setChecked(true);
    box->setCheckBox(save);
    connect(box, &QMessageBox::finished, this, [this, id, baud, save](int result) {
        if (result != QMessageBox::Yes)
            return;
        m_saveAfterLinkChange = save->isChecked();
        m_targetId = id;
        m_targetBaud = baud;
        m_previous = session()->connection()->settings();
        setLinkEvent(LinkEvent::Changing);
        session()->line()->changeLink(id, baud);
    });
    box->open();
}

void DevicePage::requestFactoryReset()
{
    if (m_confirmation || !session()->connection()->isConnected())
        return;
    const int motors = session()->map().blockCount(QStringLiteral("motor"));
    const auto id = session()->parameters()->store()->deviceValue(kId);
    const auto baud = session()->parameters()->store()->deviceValue(kBaud);
    const QString motorList = motors > 1 ? tr("motors 1 to %1").arg(motors) : tr("the motor");
    // Exactly what the factory reset replaces (docs/simulator.md, "Factory values").
    const QStringList lost = {
        tr("every motor parameter of %1: step angle, microsteps, start and accel/decel "
           "frequency, direction, speed, pitch, move distance")
            .arg(motorList),
        tr("the limit and home inputs"), tr("the homing order"),
        tr("the arc and line interpolation setup"),
        tr("the system mode and its number of round trips")};
    const QString details =
        tr("These settings in the controller are replaced by the factory values:") +
        QStringLiteral("\n• ") + lost.join(QStringLiteral("\n• ")) + QStringLiteral("\n\n") +
        tr("The device ID (%1) and the baud rate (%2) are kept, so StepCom stays connected. "
           "Edits not written yet stay in StepCom. The flash keeps the old settings until you "
           "save to flash.")
            .arg(id ? QString::number(*id) : QStringLiteral("?"),
                 baud ? QString::number(*baud) : QStringLiteral("?"));
    QMessageBox *box = makeConfirmation(tr("Restore factory settings"),
                                        tr("Restore the controller's factory settings?"), details,
                                        tr("&Restore factory settings"));
    connect(box, &QMessageBox::finished, this, [this](int result) {
        if (result != QMessageBox::Yes)
            return;
        setFlashEvent(FlashEvent::Resetting);
        session()->factoryReset();
    });
    box->open();
}

void DevicePage::retranslate()
{
    m_linkBox->setTitle(tr("Device ID and baud rate"));
    m_flashBox->setTitle(tr("Flash memory"));
    m_factoryBox->setTitle(tr("Factory settings"));
    m_idLabel->setText(tr("Device &ID:"));
    m_baudLabel->setText(tr("&Baud rate:"));
    const QString lang = Language::instance().current();
    for (const auto &[key, editor] : {std::pair<QString, QWidget *>{kId, m_id}, {kBaud, m_baud}}) {
        if (const Parameter *p = session()->map().find(key))
            editor->setToolTip(
                QStringLiteral("%1 — %2<br>%3")
                    .arg(p->label.text(lang), p->registerName(), p->help.text(lang)));
    }
    m_linkNote->setText(
        tr("The device ID matters on RS-485, where several controllers share the bus. "
           "On Modbus TCP only the ID can be changed here."));
    m_apply->setText(tr("&Apply ID and baud…"));
    m_reconnect->setText(tr("Reconnect with the &old settings"));
    m_flashNote->setText(
        tr("Written values take effect at once but live in working memory: without "
           "saving to flash, the controller forgets them when it is switched off."));
    m_unsavedText->setText(tr("Changes not saved to flash."));
    m_save->setText(tr("&Save to flash"));
    m_factoryNote->setText(
        tr("Puts every motor parameter, the limits, the homing order, the "
           "interpolation setup and the mode back to the factory values. The device "
           "ID and baud rate are kept."));
    m_reset->setText(tr("Restore &factory settings…"));
    showDeviceValues();
    renderStatus();
}

} // namespace stepcom

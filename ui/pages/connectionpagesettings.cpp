// ConnectionPage: its fields as LinkSettings, and the connection settings StepCom remembers
// (QSettings group "connection": the link, the simulator choice, what each controller refuses
// to read).
#include "line/linksettingsstore.h"
#include "pages/connectionpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "widgets/fields/lineoptionsbox.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSettings>
#include <QSpinBox>

namespace stepcom {

namespace {

const auto kGroup = QStringLiteral("connection");

} // namespace

LinkSettings ConnectionPage::currentSettings() const
{
    LinkSettings s;
    s.transport = m_realTransport != Transport::Tcp       ? LinkSettings::Transport::Rtu
                  : m_tcpMode->currentData().toInt() == 1 ? LinkSettings::Transport::RtuTcp
                                                          : LinkSettings::Transport::Tcp;
    s.portName = portFromCombo();
    s.baud = m_baud->currentData().toInt();
    s.parity = QSerialPort::Parity(m_parity->currentData().toInt());
    s.stopBits = QSerialPort::StopBits(m_stopBits->currentData().toInt());
    s.host = m_host->text().trimmed();
    s.tcpPort = m_tcpPort->value();
    s.deviceId = m_deviceId->value();
    s.timeoutMs = m_timeout->value();
    s.retries = m_retries->value();
    m_lineBox->fillInto(s);
    return s;
}

void ConnectionPage::applySettings(const LinkSettings &s)
{
    setPortInCombo(s.portName);
    const int baud = m_baud->findData(s.baud);
    m_baud->setCurrentIndex(baud >= 0 ? baud : m_baud->findData(9600));
    m_parity->setCurrentIndex(std::max(0, m_parity->findData(int(s.parity))));
    m_stopBits->setCurrentIndex(std::max(0, m_stopBits->findData(int(s.stopBits))));
    m_host->setText(s.host);
    m_tcpPort->setValue(s.tcpPort);
    m_deviceId->setValue(s.deviceId);
    m_timeout->setValue(s.timeoutMs);
    m_retries->setValue(s.retries);
    m_lineBox->apply(s);
    m_tcpMode->setCurrentIndex(s.transport == LinkSettings::Transport::RtuTcp ? 1 : 0);
    setTransport(s.isNetwork() ? Transport::Tcp : Transport::Serial);
}

void ConnectionPage::loadSettings()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    applySettings(LinkSettingsStore::read(settings));
    if (settings.value(QStringLiteral("simulator"), false).toBool())
        setTransport(Transport::Simulator);
    QMap<QString, QString> known;
    const QVariantMap saved = settings.value(QStringLiteral("readLimits")).toMap();
    for (auto it = saved.cbegin(); it != saved.cend(); ++it)
        known.insert(it.key(), it.value().toString());
    session()->connection()->setKnownReadLimits(known);
}

void ConnectionPage::saveSettings() const
{
    QSettings settings;
    settings.beginGroup(kGroup);
    LinkSettingsStore::write(settings, currentSettings());
    // The real link and the simulator choice apart, so choosing the simulator keeps the port.
    settings.setValue(QStringLiteral("simulator"), transport() == Transport::Simulator);
}

void ConnectionPage::saveReadLimits() const
{
    QVariantMap known;
    const QMap<QString, QString> limits = session()->connection()->knownReadLimits();
    for (auto it = limits.cbegin(); it != limits.cend(); ++it)
        known.insert(it.key(), it.value());
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue(QStringLiteral("readLimits"), known);
}

} // namespace stepcom

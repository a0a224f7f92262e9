#pragma once

#include "base/page.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QPointer>

#include <functional>

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QSpinBox;

class QAction;
class QHBoxLayout;

namespace stepcom {

class BusScanDialog;
class Led;
class LineOptionsBox;
class SerialPorts;
class StatusPollRow;
struct SerialPortEntry;

// Where the controller is and how to reach it: serial (RTU), Modbus TCP or the built-in
// simulator. Connects and disconnects the session and shows what the link is doing; it never
// writes to the device. The last settings are remembered in QSettings (group "connection").
class ConnectionPage : public Page
{
    Q_OBJECT
public:
    enum class Transport { Serial, Tcp, Simulator };
    Q_ENUM(Transport)

    explicit ConnectionPage(DeviceSession *session, QWidget *parent = nullptr);
    ~ConnectionPage() override;

    QString title() const override;
    QString iconName() const override { return QStringLiteral("connection"); }
    Stage stage() const override { return Stage::Connect; }

    Transport transport() const;
    void setTransport(Transport transport);
    // The serial or TCP settings in the fields; with the simulator chosen, those of the last
    // real transport (the simulator's own port is not a setting).
    LinkSettings currentSettings() const;
    // Fills the fields and selects Serial or TCP by `settings.transport`.
    void applySettings(const LinkSettings &settings);
    // What the status line says ("Connected to ...", "Connecting to ...", the last error).
    QString statusText() const;
    BusScanDialog *scanDialog() const;
    // How often the status is read and was, in the Link box.
    StatusPollRow *statusPoll() const { return m_poll; }

    // What the buttons do (also for MainWindow's actions and tests).
    void connectNow();
    void disconnectNow();
    void refreshPorts();
    // A button for `action` beside Connect and Disconnect (the window's "Listen only").
    void addLineAction(QAction *action);
    // The port list's source (tests hand it a fake listing); watched while the page is shown.
    SerialPorts *serialPorts() const { return m_serialPorts; }
    BusScanDialog *openBusScan();
    // Stores the fields in QSettings now (also done on connect and on destruction).
    void saveSettings() const;

protected:
    void retranslate() override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void buildUi();
    void fillPorts(const QList<SerialPortEntry> &ports);
    void onPortsChanged(const QList<SerialPortEntry> &ports, const QList<SerialPortEntry> &added);
    void loadSettings();
    // What the controllers refuse to read, kept with the connection settings
    // (connectionpagesettings.cpp, with the other settings).
    void saveReadLimits() const;
    void updateVisibility();
    void updateState();
    void updateLine();
    // What the status line says while disconnected; a function, so it follows the language.
    void setNote(bool problem, std::function<QString()> note);
    void onConnected(bool ok, const QString &reason);
    bool usesSimulator() const;
    QString portFromCombo() const;
    void setPortInCombo(const QString &port);

    QButtonGroup *m_transportGroup = nullptr;
    Transport m_realTransport = Transport::Serial; // the last non-simulator choice

    QGroupBox *m_transportBox = nullptr;
    QRadioButton *m_serialRadio = nullptr;
    QRadioButton *m_tcpRadio = nullptr;
    QRadioButton *m_simRadio = nullptr;

    QGroupBox *m_serialBox = nullptr;
    QFormLayout *m_serialForm = nullptr;
    QLabel *m_portLabel = nullptr;
    QComboBox *m_port = nullptr;
    SerialPorts *m_serialPorts = nullptr;
    QPushButton *m_refresh = nullptr;
    QComboBox *m_baud = nullptr;
    QComboBox *m_parity = nullptr;
    QComboBox *m_stopBits = nullptr;

    QGroupBox *m_tcpBox = nullptr;
    QFormLayout *m_tcpForm = nullptr;
    QLineEdit *m_host = nullptr;
    QSpinBox *m_tcpPort = nullptr;
    QComboBox *m_tcpMode = nullptr; // Modbus TCP, or RTU frames through a transparent converter

    QGroupBox *m_deviceBox = nullptr;
    QFormLayout *m_deviceForm = nullptr;
    QSpinBox *m_deviceId = nullptr;
    QSpinBox *m_timeout = nullptr;
    QSpinBox *m_retries = nullptr;
    LineOptionsBox *m_lineBox = nullptr;

    QGroupBox *m_simBox = nullptr;
    QLabel *m_simText = nullptr;

    QGroupBox *m_statusBox = nullptr;
    StatusPollRow *m_poll = nullptr; // how often the status is read, and was
    Led *m_led = nullptr;
    QLabel *m_stateIcon = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_line = nullptr; // what the line showed: answer times, echo, the timeout in use
    QPushButton *m_connect = nullptr;
    QPushButton *m_disconnect = nullptr;
    QPushButton *m_scan = nullptr;
    QHBoxLayout *m_buttons = nullptr;

    std::function<QString()> m_note;
    bool m_noteIsProblem = false;
    QPointer<BusScanDialog> m_scanDialog;
};

} // namespace stepcom

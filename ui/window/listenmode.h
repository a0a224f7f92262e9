#pragma once

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h" // LinkSettings

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>

class QAction;
class QFrame;
class QLabel;
class QListWidget;
class QMessageBox;
class QPushButton;
class QWidget;

namespace stepcom {

class EmergencyStop;
class MachineStrip;
class LineListener;
class ListenLog;
struct HeardEvent;

// The window beside another master (a PLC, an HMI) that drives the line: the port is heard,
// never driven (LineListener). What the other master read and wrote goes into the session's
// store as the values last heard (ParameterStore::showReplay: a value never heard stays
// unknown), so the strip and the pages show them; the banner says they were heard, not read by
// StepCom; its list gives the other master's writes as they come, and the traffic dock each
// request and answer decoded. No link is opened, so nothing writes, jogs or polls. The E-STOP
// stays: it asks first, then goes into the first silence after the other master's frame and
// again until the controller is heard to take it (its answer past the adapter's echo, its
// motors read back stopped). Everything heard goes to a session log.
// start() and the box's buttons are what tests drive; nothing here is modal.
class ListenMode : public QObject
{
    Q_OBJECT
public:
    ListenMode(DeviceSession *session, EmergencyStop *estop, QWidget *window);
    ~ListenMode() override;

    // Connection → Listen only: the connection page's settings (`settings`, asked for when
    // triggered).
    QAction *startAction() const { return m_start; }
    void setSettingsSource(std::function<LinkSettings()> source) { m_source = std::move(source); }
    // The strip says the line is heard, and whether the device in view answers on it.
    void setStrip(MachineStrip *strip);
    QFrame *banner() const { return m_banner; }
    QListWidget *writes() const { return m_writes; }
    // The E-STOP's question while it is open.
    QMessageBox *estopQuestion() const { return m_question; }

    // Listens on `settings`' serial port; false and why (connected, a file or replay open, the
    // port refused).
    bool start(const LinkSettings &settings, QString *why);
    void stop();
    bool isActive() const { return m_listener != nullptr; }
    // The id whose heard values the pages show.
    int deviceInView() const { return m_settings.deviceId; }
    QString logFile() const;
    void retranslate();

Q_SIGNALS:
    void activeChanged(bool active);
    // For the status bar and the messages: ok = false for errors.
    void finished(bool ok, const QString &message);

private:
    void onHeard(const HeardEvent &event);
    void askEmergencyStop();
    void sendEmergencyStop();
    void showValues();
    void updateBanner();

    DeviceSession *m_session;
    EmergencyStop *m_estop;
    QWidget *m_window;
    QAction *m_start;
    QFrame *m_banner;
    QLabel *m_bannerText;
    QListWidget *m_writes;
    QPushButton *m_stop;
    QPointer<QMessageBox> m_question;
    QPointer<MachineStrip> m_strip;
    std::function<LinkSettings()> m_source;
    LineListener *m_listener = nullptr;
    std::unique_ptr<ListenLog> m_log;
    LinkSettings m_settings;
    int m_heardWrites = 0;
};

} // namespace stepcom

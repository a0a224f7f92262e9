#pragma once

#include "line/busscanner.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"

#include <QDialog>
#include <QMap>

class QCheckBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepcom {

class DeviceSession;

// Finds controllers whose device id or baud rate was forgotten: tries the chosen baud rates
// and ids on one port (BusScanner; reads only) and lists who answered. A found controller is
// connected with one click (connectRequested). Non-modal: open it with show() or open().
class BusScanDialog : public QDialog
{
    Q_OBJECT
public:
    BusScanDialog(DeviceSession *session, const LinkSettings &base, QWidget *parent = nullptr);
    ~BusScanDialog() override;

    // The port (or TCP host) to scan, with its parity, stop bits, timeout and retries.
    void setBaseSettings(const LinkSettings &base);
    const LinkSettings &baseSettings() const { return m_base; }

    // The scan options, as the technician sets them in the dialog.
    QList<int> checkedBauds() const;
    void setCheckedBauds(const QList<int> &bauds);
    void setIdRange(int first, int last);
    void setProbeTimeoutMs(int ms);
    void setStopAtFirst(bool stop);

    bool isScanning() const;
    BusScanner *scanner() const { return m_scanner; }
    int foundCount() const;
    // The base settings with the baud and id of found row `row`.
    LinkSettings settingsFor(int row) const;
    // True while the session holds the port this dialog would scan.
    bool sessionUsesPort() const;
    QString statusText() const;

    // What the buttons do.
    void startScan();
    void cancelScan();
    void connectSelected();
    // Puts every id found on the session's device list (after the ones there); returns the ids
    // added. The dialog stays open, so one of them can still be connected.
    QList<int> addAllFound();
    // Closing (Close, Esc, the window's X) cancels a running scan first.
    void reject() override;

Q_SIGNALS:
    void connectRequested(const stepcom::LinkSettings &settings);
    void devicesAdded(const QList<int> &ids);

protected:
    void changeEvent(QEvent *event) override;

private:
    enum class Outcome { Idle, Running, Done, Cancelled, Failed, NoBaud, Interrupted };

    void retranslate();
    void updateControls();
    void updateStatus();
    void onProgress(int done, int total, int baud, int deviceId);
    void onFinished(bool cancelled, const QString &error);
    void onSessionState();
    QList<int> scanOrder() const;
    // What the options ask for; BusScanner runs it as it runs `stepcomctl scan`.
    BusScanner::Plan plan() const;
    static QString parityText(QSerialPort::Parity parity);

    DeviceSession *m_session;
    BusScanner *m_scanner;
    LinkSettings m_base;

    QGroupBox *m_whereBox = nullptr;
    QFormLayout *m_whereForm = nullptr;
    QLabel *m_port = nullptr;
    QLabel *m_warning = nullptr;
    QGroupBox *m_optionsBox = nullptr;
    QFormLayout *m_optionsForm = nullptr;
    QWidget *m_baudRow = nullptr;
    QMap<int, QCheckBox *> m_bauds;
    QWidget *m_idRow = nullptr;
    QLabel *m_idTo = nullptr;
    QSpinBox *m_firstId = nullptr;
    QSpinBox *m_lastId = nullptr;
    QSpinBox *m_probeTimeout = nullptr;
    QCheckBox *m_stopAtFirst = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_cancel = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QGroupBox *m_foundBox = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_connect = nullptr;
    QPushButton *m_addAll = nullptr;
    QPushButton *m_close = nullptr;

    Outcome m_outcome = Outcome::Idle;
    QString m_error;
    QString m_added; // what "Add all found" did, until the next scan
};

} // namespace stepcom

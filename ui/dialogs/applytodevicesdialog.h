#pragma once

#include "profile/profile.h"

#include <QDialog>
#include <QHash>

class QLabel;
class QListWidget;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace stepcom {

class DeviceSession;
class ProfileRollout;

// One profile applied to several controllers of the line. The user ticks the devices and
// compares (reading only); every device then lists what differs, device value and profile
// value, each row checked; "Write" -- which says how many values go to how many devices -- is
// the confirmation. Each device gets a backup, its checked values, a read-back; the results
// stand together under the devices at the end: written and verified, skipped or failed with
// why. Non-modal, so the window's E-STOP button stays at hand (F12 works from here too), and an
// E-STOP stops all that is left.
class ApplyToDevicesDialog : public QDialog
{
    Q_OBJECT
public:
    ApplyToDevicesDialog(DeviceSession *session, const Profile &profile, const QString &title,
                         const QHash<int, QString> &names, const QList<int> &preselected,
                         QWidget *parent = nullptr);

    ProfileRollout *rollout() const { return m_rollout; }
    QListWidget *deviceList() const { return m_devices; }
    QTreeWidget *rows() const { return m_rows; }
    QPushButton *compareButton() const { return m_compare; }
    QPushButton *writeButton() const { return m_write; }
    QLabel *summary() const { return m_summary; }
    // The ids ticked in the device list.
    QList<int> checkedDevices() const;
    void setDeviceChecked(int id, bool checked);
    // Compare the ticked devices (the Compare button).
    void compareChecked();
    // Write what is checked (the Write button: the user's confirmation).
    void writeChecked();
    // One line per device, as the results show them.
    QStringList resultLines() const;

Q_SIGNALS:
    // Every outcome for the message dock; ok = false for a device that failed.
    void message(bool ok, const QString &text);

protected:
    // Not while writing: every device's result is to be seen (the E-STOP stops it).
    void closeEvent(QCloseEvent *event) override;
    void reject() override; // Escape, the same

private:
    void showComparison();
    void updateDevice(int id);
    void updateButtons();
    void takeChoices();
    QTreeWidgetItem *itemFor(int id) const;

    DeviceSession *m_session;
    Profile m_profile;
    QHash<int, QString> m_names;
    ProfileRollout *m_rollout;
    QLabel *m_intro;
    QListWidget *m_devices;
    QPushButton *m_compare;
    QTreeWidget *m_rows;
    QLabel *m_summary;
    QPushButton *m_write;
    QPushButton *m_close;
    bool m_filling = false;
};

} // namespace stepcom

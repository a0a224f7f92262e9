#pragma once

#include "profile/profile.h"
#include "profile/profilediff.h"

#include <QDialog>
#include <QHash>
#include <QPointer>
#include <QSet>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace stepcom {

class DeviceSession;
class ProfileApply;
struct ProfileApplyResult;

// Device versus profile, one row per parameter: both values, the unit, differences highlighted
// and a check box per row (the differing rows checked). Opening it writes nothing; Apply writes
// only the checked rows through ProfileApply (backed up, verified) and then offers Save to
// flash. device.id and device.baud
// are applied only when "also the device id and baud" is chosen; the link follows them.
class ProfileCompareDialog : public QDialog
{
    Q_OBJECT
public:
    enum Column {
        ApplyColumn,
        ParameterColumn,
        DeviceColumn,
        ProfileColumn,
        UnitColumn,
        KeyColumn,
        ColumnCount
    };

    ProfileCompareDialog(DeviceSession *session, const Profile &profile, const QString &fileName,
                         QWidget *parent = nullptr);

    const Profile &profile() const { return m_profile; }
    QTableWidget *table() const { return m_table; }
    QCheckBox *differencesOnly() const { return m_differencesOnly; }
    QCheckBox *includeLink() const { return m_includeLink; }
    QPushButton *applyButton() const { return m_apply; }
    QPushButton *saveToFlashButton() const { return m_saveToFlash; }
    QLabel *resultLabel() const { return m_result; }
    // The table row of a key, or -1.
    int rowOf(const QString &key) const;
    bool isChecked(const QString &key) const;
    void setChecked(const QString &key, bool checked);
    QStringList checkedKeys() const;
    bool isBusy() const { return m_busy; }

    void apply();

Q_SIGNALS:
    // After every apply: what was written and verified, and the problems by parameter name.
    void applied(bool ok, const QStringList &verified, const QStringList &problems);

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuild();
    void refreshValues();
    void updateFilter();
    void updateButtons();
    void retranslate();
    void onItemChanged(int row, int column);
    void finishApply(const ProfileApplyResult &result);
    QString nameOf(const QString &key) const;
    static QString labelOf(const Parameter &p);
    static QString forgetWarning();

    DeviceSession *m_session;
    QPointer<ProfileApply> m_applier; // the last apply (ProfileApply)
    Profile m_profile;
    QString m_fileName;
    QList<ProfileDifference> m_rows;
    QStringList m_leftOut; // keys the controller does not support
    QHash<QString, bool> m_checked;
    QSet<QString> m_touched; // rows the user checked or unchecked: a refresh keeps the choice
    bool m_columnsSized = false;
    bool m_busy = false;
    bool m_updating = false;
    bool m_refreshPending = false;

    QLabel *m_header;
    QLabel *m_summary;
    QTableWidget *m_table;
    QCheckBox *m_differencesOnly;
    QCheckBox *m_includeLink;
    QPushButton *m_checkDiffering;
    QPushButton *m_checkNone;
    QPushButton *m_apply;
    QPushButton *m_saveToFlash;
    QPushButton *m_close;
    QProgressBar *m_progress;
    QLabel *m_result;
};

} // namespace stepcom

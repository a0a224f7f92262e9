#pragma once

#include "map/registermap.h"
#include "profile/profile.h"
#include "profile/profilecomparison.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QTableWidget;

namespace stepcom {

// Two profile files side by side, no controller: one row per setting of the map (file A,
// file B, unit, key) and the keys outside this map, each in its group (differ, the same, only
// in A, only in B, outside this map); rows that tell the files apart are highlighted. Nothing
// here reads or writes a controller.
class ProfileFilesDialog : public QDialog
{
    Q_OBJECT
public:
    enum Column { GroupColumn, ParameterColumn, AColumn, BColumn, UnitColumn, KeyColumn, Columns };
    enum class Group { Differ, Same, OnlyInA, OnlyInB, Outside };

    ProfileFilesDialog(const RegisterMap &map, const Profile &a, const QString &nameA,
                       const Profile &b, const QString &nameB, QWidget *parent = nullptr);

    const ProfileComparison &comparison() const { return m_comparison; }
    QTableWidget *table() const { return m_table; }
    QCheckBox *differencesOnly() const { return m_differencesOnly; }
    QLabel *summary() const { return m_summary; }
    // The table row of a key, or -1; its group; whether it is highlighted.
    int rowOf(const QString &key) const;
    Group groupOf(int row) const { return m_groups.value(row); }
    bool isHighlighted(int row) const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuild();
    void updateFilter();
    void retranslate();
    QString groupName(Group group) const;

    RegisterMap m_map; // a copy: the rows point into it
    Profile m_a;
    Profile m_b;
    QString m_nameA;
    QString m_nameB;
    ProfileComparison m_comparison;
    QList<Group> m_groups; // by table row
    QStringList m_keys;    // by table row

    QLabel *m_header;
    QLabel *m_summary;
    QTableWidget *m_table;
    QCheckBox *m_differencesOnly;
};

} // namespace stepcom

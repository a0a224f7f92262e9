#pragma once

#include <QDialog>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace stepcom {

class RegisterMap;

// File → Backups: the automatic backups, newest first, with their time, the device they were
// read from and what happened after; "Restore…" hands one to the usual compare and apply.
class BackupsDialog : public QDialog
{
    Q_OBJECT
public:
    BackupsDialog(const RegisterMap &map, const QString &directory, QWidget *parent = nullptr);

    QTreeWidget *list() const { return m_list; }
    QPushButton *restoreButton() const { return m_restore; }
    void reload();

Q_SIGNALS:
    void restoreRequested(const QString &path);

private:
    void retranslate();

    const RegisterMap &m_map;
    QString m_dir;
    QLabel *m_where;
    QTreeWidget *m_list;
    QPushButton *m_restore;
    QPushButton *m_close;
};

} // namespace stepcom

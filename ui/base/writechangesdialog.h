#pragma once

#include "device/writeplanner.h"

#include <QDialog>

class QTableWidget;
class QLabel;
class QPushButton;

namespace stepcom {

class ParameterStore;

// Shows exactly what "Write changes" will write -- each parameter, its register, what the
// controller holds now and the new value -- before anything is sent.
class WriteChangesDialog : public QDialog
{
    Q_OBJECT
public:
    WriteChangesDialog(const ParameterStore &store, QWidget *parent = nullptr);
    // Only the edits of `keys` (a page's own parameters); the others stay held.
    WriteChangesDialog(const ParameterStore &store, const QStringList &keys,
                       QWidget *parent = nullptr);
    // The writes shown, as they will be sent if the user accepts.
    const QList<ParameterWrite> &writes() const { return m_writes; }
    QTableWidget *table() const { return m_table; }
    // Geometry and wiring problems the pages already flag in these values (WriteFlow finds
    // them): shown above the table, and the Write button then says "Write anyway" and is no
    // longer the default.
    void setProblems(const QStringList &problems);
    const QStringList &problems() const { return m_problems; }

private:
    QList<ParameterWrite> m_writes;
    QTableWidget *m_table;
    QLabel *m_summary;
    QLabel *m_problemsLabel;
    QPushButton *m_write = nullptr;
    QPushButton *m_cancel = nullptr;
    QStringList m_problems;
};

} // namespace stepcom

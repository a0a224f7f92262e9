#pragma once

#include <QDockWidget>
#include <QHash>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepcom {

class DeviceSession;

// The controllers on the line beside the pages: id, the name the user gives it, its state,
// referenced or not, errors. Clicking one shows its pages at once, without reconnecting;
// "Add device" puts another id on the list. Hidden until the user opens it (View menu).
class DeviceListDock : public QDockWidget
{
    Q_OBJECT
public:
    explicit DeviceListDock(DeviceSession *session, QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }
    QSpinBox *idBox() const { return m_idBox; }
    QPushButton *addButton() const { return m_add; }
    // Adds `id` to the session's list (false and a reason beside the button when it is there).
    bool addDevice(int id);
    QString nameOf(int id) const { return m_names.value(id); }
    // The row's texts, for tests and the accessibility bus: id, name, state, referenced, errors.
    QStringList rowTexts(int row) const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh();
    void onCellClicked(int row);
    void onCellChanged(int row, int column);
    QString stateText(int id) const;
    QString referencedText(int id) const;

    DeviceSession *m_session;
    QTableWidget *m_table;
    QSpinBox *m_idBox;
    QPushButton *m_add;
    QLabel *m_problem;
    QHash<int, QString> m_names;
    bool m_filling = false;
};

} // namespace stepcom

#pragma once

#include <QDockWidget>
#include <QHash>

#include <functional>
#include <optional>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepcom {

class DeviceSession;

// What a replayed session log says of one device at the moment shown: the device
// list's row for it, as the live list shows a device.
struct ReplayDeviceRow
{
    bool linkUp = false;      // the line was up then
    bool asked = false;       // a request to it had come back or been given up by then
    bool answering = false;   // its last request was answered
    QList<int> runningMotors; // its motors running, as last read
    QString command;          // the motion command acknowledged last (its key), while they run
    int requests = 0;
    int errors = 0;      // refused or not answered, of those requests
    QString lastError;   // the last of them and when
    QString restartAt;   // the moment of the last restart the session saw, or empty
    QString restartText; // what the session said of it
    QString name;        // the name the log's header gives it (else the list's own)
};

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
    // How often each device not in view has its status read (the user sets it; remembered).
    QSpinBox *backgroundIntervalBox() const { return m_backgroundMs; }
    QPushButton *addButton() const { return m_add; }
    // Adds `id` to the session's list (false and a reason beside the button when it is there).
    bool addDevice(int id, const QString &name = QString());
    QString nameOf(int id) const { return m_names.value(id); }
    void setName(int id, const QString &name);
    // The line's ids and names go with the connection settings: saved whenever they change
    // while connected, restored when the same line is connected again (DeviceListSettings).
    void saveList() const;
    // Puts the saved list of this line on the session, unless the user already named devices.
    bool restoreList();
    // The row's texts, for tests and the accessibility bus: id, name, state, referenced, errors.
    QStringList rowTexts(int row) const;
    QHash<int, QString> names() const { return m_names; }
    // A replayed log's devices instead of the session's: each one's state at the
    // moment shown, the one in view, and what a click on another one does. endReplay(): the
    // session's again.
    void showReplay(const QList<int> &ids, const QHash<int, ReplayDeviceRow> &rows, int inView,
                    const std::function<void(int)> &choose);
    void endReplay();
    bool isReplay() const { return m_replay.has_value(); }

Q_SIGNALS:
    // The user named a device (or the saved names came back): the session log says them.
    void namesChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh();
    void onCellClicked(int row);
    void onCellChanged(int row, int column);
    void onConnected(bool ok);
    QString stateText(int id) const;
    QString referencedText(int id) const;
    QString motorsText(const QList<int> &motors) const; // "motor 1, 2"
    QList<int> ids() const;
    int inView() const;

    DeviceSession *m_session;
    QTableWidget *m_table;
    QSpinBox *m_idBox;
    QPushButton *m_add;
    QLabel *m_problem;
    QLabel *m_backgroundLabel;
    QSpinBox *m_backgroundMs;
    QHash<int, QString> m_names;
    bool m_filling = false;
    struct Replay
    {
        QList<int> ids;
        QHash<int, ReplayDeviceRow> rows;
        int inView = 0;
        std::function<void(int)> choose;
    };
    std::optional<Replay> m_replay;
    bool m_connectedBefore = false; // a reopen at another baud is no new connection
};

} // namespace stepcom

#pragma once

#include "session/parts/sessionconnection.h" // TrafficLog

#include <QMap>
#include <QWidget>

#include <functional>

class QCheckBox;
class QLineEdit;
class QPushButton;
class QTableView;

namespace stepcom {

class TrafficModel;

// The traffic dock's content: the frames with filters (polls hidden at first, reads, writes,
// commands, errors), a search, pause, copy, "Save log…" and "Open log folder" (the session log
// files, see SessionLog).
class TrafficView : public QWidget
{
    Q_OBJECT
public:
    explicit TrafficView(QWidget *parent = nullptr);
    void setLog(TrafficLog *log);
    TrafficModel *model() const { return m_model; }
    QTableView *table() const { return m_table; }
    // The folder of the session log files ("Open log folder"); empty hides the button.
    void setLogFolder(const QString &folder);
    QString logFolder() const { return m_logFolder; }
    // The rows shown, one line per frame, as TrafficLog::format writes it.
    QString text() const;
    bool saveTo(const QString &path, QString *error) const;
    // Opens the log folder in the desktop's file manager (made first if missing).
    bool openLogFolder(QString *error = nullptr) const;
    // A replay's view: `earlier` gives the lines before the first one kept, in order
    // (none: the start of the log). Scrolled to the top the view asks for them, as does
    // "Earlier lines". Unset: the live view, which has all it keeps.
    using Earlier = std::function<QList<TrafficEntry>()>;
    void setEarlier(const Earlier &earlier);
    // Earlier lines at the top until kEarlierRows more rows show, none are left or the view is
    // full; the rows that were first stay in sight. The rows added.
    int showEarlier();
    static constexpr int kEarlierRows = 50;
    QPushButton *earlierButton() const { return m_earlierButton; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void copySelection();
    void saveAs();

    TrafficModel *m_model;
    QTableView *m_table;
    QCheckBox *m_pause;
    QMap<TrafficEntry::Kind, QCheckBox *> m_kinds;
    QLineEdit *m_search;
    QPushButton *m_clear;
    QPushButton *m_copy;
    QPushButton *m_save;
    QPushButton *m_openFolder;
    QPushButton *m_earlierButton;
    Earlier m_earlier;
    QString m_logFolder;
};

} // namespace stepcom

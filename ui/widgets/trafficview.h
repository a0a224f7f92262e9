#pragma once

#include "device/devicesession.h" // TrafficLog

#include <QAbstractTableModel>
#include <QWidget>

class QCheckBox;
class QPushButton;
class QTableView;

namespace stepcom {

// Rows of a TrafficLog: time, direction, raw bytes in hex, decoded summary.
class TrafficModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    explicit TrafficModel(QObject *parent = nullptr);
    void setLog(TrafficLog *log);
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    void clear();
    const QList<TrafficEntry> &entries() const { return m_entries; }

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    int columnCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    void append(const TrafficEntry &entry);

    TrafficLog *m_log = nullptr;
    QList<TrafficEntry> m_entries;
    bool m_paused = false;
    int m_capacity = 5000;
};

// The traffic dock's content: the table plus pause, clear, copy and save.
class TrafficView : public QWidget
{
    Q_OBJECT
public:
    explicit TrafficView(QWidget *parent = nullptr);
    void setLog(TrafficLog *log);
    TrafficModel *model() const { return m_model; }
    // Everything shown, one line per frame, as TrafficLog::format writes it.
    QString text() const;
    bool saveTo(const QString &path, QString *error) const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void copySelection();
    void saveAs();

    TrafficModel *m_model;
    QTableView *m_table;
    QCheckBox *m_pause;
    QPushButton *m_clear;
    QPushButton *m_copy;
    QPushButton *m_save;
};

} // namespace stepcom

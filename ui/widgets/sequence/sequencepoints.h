#pragma once

#include <QMap>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace stepcom {

class DeviceSession;
class JogButton;

// The sequence's taught points: a table of names and positions per motor (an empty cell: the
// point leaves that axis where it is), edited in place, and the hands-on way to fill it --
// hold-to-move jog buttons per motor, then "Teach here", which takes the live position the
// status poll read. A position StepCom does not know is never taught: the point is refused
// and the reason said.
class SequencePoints : public QWidget
{
    Q_OBJECT
public:
    using Points = QMap<QString, QMap<int, double>>;

    explicit SequencePoints(DeviceSession *session, QWidget *parent = nullptr);

    void setPoints(const Points &points);
    const Points &points() const { return m_points; }
    // A point taken from the live position: the selected point re-taught with `update`, else a
    // new one ("p1", "p2", …). False and the reason said when no position is known.
    bool teach(bool update = false);
    // Adds a point at `position` (a clicked place); returns its name.
    QString addPoint(const QMap<int, double> &position);
    void setEditable(bool editable);
    // A line under the buttons: what was taught, or why not (`problem` in red).
    void say(const QString &text, bool problem);

    QTableWidget *table() const { return m_table; }
    QPushButton *teachButton() const { return m_teach; }
    QPushButton *updateButton() const { return m_update; }
    QPushButton *removeButton() const { return m_remove; }
    JogButton *jogButton(int motor, bool forward) const;
    QLabel *messageLabel() const { return m_message; }

Q_SIGNALS:
    void changed();
    void renamed(const QString &from, const QString &to);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fill();
    void updateButtons();
    void onCellChanged(int row, int column);
    // The live position of each motor the poll has read, in axis units.
    QMap<int, double> livePosition(QStringList *unknown) const;

    DeviceSession *m_session;
    Points m_points;
    int m_motors = 0;
    QTableWidget *m_table;
    QPushButton *m_teach;
    QPushButton *m_update;
    QPushButton *m_remove;
    QList<JogButton *> m_jog; // reverse, forward per motor
    QList<QLabel *> m_jogLabels;
    QLabel *m_message;
    bool m_editable = true;
    bool m_filling = false;
};

} // namespace stepcom

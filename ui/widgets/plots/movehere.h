#pragma once

#include <QObject>
#include <QPointF>
#include <QPointer>

#include <functional>

class QMenu;
class QWidget;

namespace stepcom {

class DeviceSession;
class SequenceMove;
class XYPlot;

// "Move here" on an XY view: a right-click offers to move both axes to the point clicked
// (motor 1 across, motor 2 up, rounded to the position's decimals). It is offered only while
// both axes are referenced and the point lies inside StepCom's travel limits; otherwise the
// menu says why, greyed. A question with the distance of each axis comes first; then both
// single moves start together and are judged as `stepcomctl move` is (arrived, or what
// stopped it). Its owner may add its own entries for the point (the Sequence page: teach it).
class MoveHere : public QObject
{
    Q_OBJECT
public:
    MoveHere(DeviceSession *session, XYPlot *plot, QWidget *parent);

    // Answers the question instead of a box (tests).
    void setConfirmer(std::function<bool(const QString &question)> confirm)
    {
        m_confirm = std::move(confirm);
    }
    // More entries for the clicked point (`at` in axis units).
    void setExtra(std::function<void(QMenu *menu, const QPointF &at)> extra)
    {
        m_extra = std::move(extra);
    }
    // The menu for a click at `value` (data units); the caller owns it.
    QMenu *menuFor(const QPointF &value);
    // Why a move to `target` cannot go now, or empty.
    QString refusal(const QPointF &target) const;
    // Asks, then moves; false when it did not start (said in `said`).
    bool moveTo(const QPointF &target);
    bool isBusy() const;

Q_SIGNALS:
    // What happened, in words: refused, started, and how it ended.
    void said(const QString &text);

private:
    QPointF rounded(const QPointF &value) const;

    DeviceSession *m_session;
    QWidget *m_parent;
    SequenceMove *m_move;
    std::function<bool(const QString &)> m_confirm;
    std::function<void(QMenu *, const QPointF &)> m_extra;
};

} // namespace stepcom

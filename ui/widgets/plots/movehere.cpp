#include "widgets/plots/movehere.h"

#include "map/parameter.h"
#include "motion/referencetracker.h"
#include "motion/travellimits.h"
#include "sequence/sequencemove.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/plots/xyplot.h"

#include <QMenu>
#include <QMessageBox>

#include <cmath>

namespace stepcom {

MoveHere::MoveHere(DeviceSession *session, XYPlot *plot, QWidget *parent)
    : QObject(parent)
    , m_session(session)
    , m_parent(parent)
    , m_move(new SequenceMove(session, this))
{
    connect(plot, &XYPlot::pointMenuRequested, this,
            [this](const QPointF &value, const QPoint &globalPos) {
                QMenu *menu = menuFor(value);
                menu->setAttribute(Qt::WA_DeleteOnClose);
                menu->popup(globalPos);
            });
    connect(m_move, &SequenceMove::finished, this, [this](const QList<StepMoveResult> &results) {
        QStringList texts;
        for (const StepMoveResult &r : results)
            texts << r.text;
        Q_EMIT said(texts.join(QLatin1Char(' ')));
    });
}

bool MoveHere::isBusy() const
{
    return m_move->isBusy();
}

QPointF MoveHere::rounded(const QPointF &value) const
{
    const auto round = [this](int motor, double v) {
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), motor);
        const double scale = std::pow(10.0, p ? p->decimals() : 2);
        return std::round(v * scale) / scale;
    };
    return {round(1, value.x()), round(2, value.y())};
}

QString MoveHere::refusal(const QPointF &target) const
{
    if (!m_session->connection()->isConnected())
        return tr("not connected");
    if (m_move->isBusy())
        return tr("a move is under way");
    const ReferenceTracker *refs = m_session->motion()->references();
    const ParameterStore *store = m_session->parameters()->store();
    for (int motor : {1, 2}) {
        if (!refs->isReferenced(motor))
            return tr("motor %1 is not referenced: home it first").arg(motor);
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), motor);
        const auto raw = p ? store->deviceValue(p->key) : std::nullopt;
        if (!raw)
            return tr("the position of motor %1 is not known").arg(motor);
        const QString why = m_session->travelLimits().refuseTarget(
            m_session->map(), motor, p->toEngineering(*raw), motor == 1 ? target.x() : target.y());
        if (!why.isEmpty())
            return why;
    }
    return {};
}

QMenu *MoveHere::menuFor(const QPointF &value)
{
    const QPointF at = rounded(value);
    auto *menu = new QMenu(m_parent);
    const QString why = refusal(at);
    QAction *move = menu->addAction(
        why.isEmpty() ? tr("Move here (%1, %2)").arg(at.x(), 0, 'f', 2).arg(at.y(), 0, 'f', 2)
                      : tr("Move here: %1").arg(why));
    move->setObjectName(QStringLiteral("moveHere"));
    move->setEnabled(why.isEmpty());
    connect(move, &QAction::triggered, this, [this, at] { moveTo(at); });
    if (m_extra)
        m_extra(menu, at);
    return menu;
}

bool MoveHere::moveTo(const QPointF &target)
{
    const QString why = refusal(target);
    if (!why.isEmpty()) {
        Q_EMIT said(tr("Not moved: %1.").arg(why));
        return false;
    }
    QStringList distances;
    const ParameterStore *store = m_session->parameters()->store();
    for (int motor : {1, 2}) {
        const Parameter *p = TravelLimits::positionParameter(m_session->map(), motor);
        const double from = p->toEngineering(*store->deviceValue(p->key));
        const double to = motor == 1 ? target.x() : target.y();
        distances << tr("motor %1: %2 → %3 %4 (%5%6 %4)")
                         .arg(motor)
                         .arg(from, 0, 'f', p->decimals())
                         .arg(to, 0, 'f', p->decimals())
                         .arg(p->unit)
                         .arg(to >= from ? QStringLiteral("+") : QString())
                         .arg(to - from, 0, 'f', p->decimals());
    }
    const QString q = tr("Move both axes to (%1, %2)?\n%3")
                          .arg(target.x(), 0, 'f', 2)
                          .arg(target.y(), 0, 'f', 2)
                          .arg(distances.join(QLatin1Char('\n')));
    const bool go = m_confirm ? m_confirm(q)
                              : QMessageBox::question(m_parent, tr("Move here"), q,
                                                      QMessageBox::Yes | QMessageBox::No,
                                                      QMessageBox::No) == QMessageBox::Yes;
    if (!go) {
        Q_EMIT said(tr("Not moved."));
        return false;
    }
    const QString refused = m_move->start({{StepMoveRequest::Kind::To, 1, target.x(), 0},
                                           {StepMoveRequest::Kind::To, 2, target.y(), 0}});
    if (!refused.isEmpty()) {
        Q_EMIT said(tr("Not moved: %1").arg(refused));
        return false;
    }
    Q_EMIT said(tr("Moving to (%1, %2)…").arg(target.x(), 0, 'f', 2).arg(target.y(), 0, 'f', 2));
    return true;
}

} // namespace stepcom

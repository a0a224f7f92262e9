#include "map/parameter.h"
#include "motion/referencetracker.h"
#include "motion/travellimits.h"
#include "proofsim.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "widgets/plots/movehere.h"
#include "widgets/plots/xyplot.h"

#include <QMenu>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace stepcom;

// "Move here" on an XY view: greyed with the reason while an axis is not referenced or the
// point lies beyond the travel limits; asked with each axis's distance; then both axes move
// there together and are judged.
class TestMoveHere : public QObject
{
    Q_OBJECT
    std::unique_ptr<SimHost> host;
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> window;
    XYPlot *plot = nullptr;
    MoveHere *moveHere = nullptr;

    double position(int motor) const
    {
        const Parameter *p = TravelLimits::positionParameter(session->map(), motor);
        return p->toEngineering(
            *host->device()->value(QStringLiteral("motor%1.position").arg(motor)));
    }
    QAction *moveAction(QMenu *menu) const
    {
        return menu->findChild<QAction *>(QStringLiteral("moveHere"));
    }

private Q_SLOTS:
    void init()
    {
        host = std::make_unique<SimHost>();
        QVERIFY(test::startProofSim(*host, test::proofAxis()));
        session = test::proofSession(*host);
        window = std::make_unique<QWidget>();
        plot = new XYPlot(window.get());
        moveHere = new MoveHere(session.get(), plot, window.get());
    }
    void cleanup()
    {
        window.reset();
        session.reset();
        host.reset();
    }

    void offeredOnlyWhenReferencedAndInsideTheLimits()
    {
        std::unique_ptr<QMenu> menu(moveHere->menuFor(QPointF(5, 5)));
        QVERIFY(!moveAction(menu.get())->isEnabled());
        QVERIFY2(moveAction(menu.get())->text().contains(QLatin1String("not referenced")),
                 qPrintable(moveAction(menu.get())->text()));
        ReferenceTracker *refs = session->motion()->references();
        refs->setReasonOn(1, 1, ReferenceTracker::Reason::Homed);
        refs->setReasonOn(1, 2, ReferenceTracker::Reason::Homed);
        menu.reset(moveHere->menuFor(QPointF(5.004, 4.996)));
        QVERIFY(moveAction(menu.get())->isEnabled());
        QCOMPARE(moveAction(menu.get())->text(), QStringLiteral("Move here (5.00, 5.00)"));
        TravelLimits limits;
        QCOMPARE(limits.setAxis(session->map(), 2, std::nullopt, 4.0), QString());
        session->setTravelLimits(limits);
        menu.reset(moveHere->menuFor(QPointF(5, 5)));
        QVERIFY(!moveAction(menu.get())->isEnabled());
        QVERIFY(!moveHere->refusal(QPointF(5, 5)).isEmpty());
    }

    void asksWithTheDistancesThenMovesBoth()
    {
        ReferenceTracker *refs = session->motion()->references();
        refs->setReasonOn(1, 1, ReferenceTracker::Reason::Homed);
        refs->setReasonOn(1, 2, ReferenceTracker::Reason::Homed);
        const QPointF target(position(1) + 3.0, position(2) - 2.0);
        QString asked;
        moveHere->setConfirmer([&asked](const QString &q) {
            asked = q;
            return false;
        });
        QVERIFY(!moveHere->moveTo(target));
        QVERIFY2(asked.contains(QLatin1String("(+3.00 mm)")) &&
                     asked.contains(QLatin1String("(-2.00 mm)")),
                 qPrintable(asked));
        QCOMPARE(host->device()->value(QStringLiteral("motor1.running")).value_or(-1), 0);
        moveHere->setConfirmer([](const QString &) { return true; });
        QSignalSpy said(moveHere, &MoveHere::said);
        QVERIFY(moveHere->moveTo(target));
        QTRY_VERIFY_WITH_TIMEOUT(!moveHere->isBusy(), 30000);
        QCOMPARE(position(1), target.x());
        QCOMPARE(position(2), target.y());
        QVERIFY(said.size() >= 2);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestMoveHere, Gui)
#include "tst_movehere.moc"

#include "simsession.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/builtinsimulator.h"
#include "sim/host/simhost.h"

#include <QSignalSpy>
#include <QTest>

namespace stepcom::test {

void useBuiltinSimulator(DeviceSession &session)
{
    if (!session.simulatorStarter())
        session.setSimulator(std::make_unique<BuiltinSimulator>());
}

void useBuiltinSimulator(DeviceSession &session, const QList<int> &ids)
{
    auto sim = std::make_unique<BuiltinSimulator>();
    sim->setIds(ids);
    session.setSimulator(std::move(sim));
}

void addAnswerTimeRows()
{
    QTest::addColumn<int>("delayMs");
    QTest::addColumn<int>("baud");
    for (int baud : {9600, 38400}) {
        for (int delay : {2, 5, 15, 35})
            QTest::addRow("%d ms at %d", delay, baud) << delay << baud;
    }
}

bool startModelledController(SimHost &host, int delayMs, int baud)
{
    SimOptions o;
    o.rtu = true;
    o.answerDelayMs = delayMs;
    o.wireBaud = baud;
    o.checkBaud = false;
    QString error;
    if (host.start(o, &error))
        return true;
    qWarning("%s", qPrintable(error));
    return false;
}

SimHost *simHost(const DeviceSession &session)
{
    const auto *sim = dynamic_cast<const BuiltinSimulator *>(session.simulatorStarter());
    return sim ? sim->host() : nullptr;
}

void connectToSimulator(DeviceSession &session)
{
    useBuiltinSimulator(session);
    QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
    session.connection()->connectSimulator();
    // Generous: a machine running other tests beside this one may take many seconds.
    QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 30000);
    QVERIFY(read.at(0).at(0).toBool());
}

} // namespace stepcom::test

#include "simsession.h"

#include "device/devicesession.h"

#include <QSignalSpy>
#include <QTest>

namespace stepcom::test {

void connectToSimulator(DeviceSession &session)
{
    QSignalSpy read(&session, &DeviceSession::readFinished);
    session.connectSimulator();
    QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
    QVERIFY(read.at(0).at(0).toBool());
}

} // namespace stepcom::test

// The link's port: one that vanishes under a request, one closed from a callback, one that is
// missing or no serial port at all, and settings the port refuses.
#include "modbuslinkfixture.h"

#include <QSignalSpy>
#include <QTemporaryFile>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

class TestModbusLinkPort : public LinkFixture
{
    Q_OBJECT

private Q_SLOTS:
    void init() { initLink(); }
    void cleanup() { cleanupLink(); }

    void vanishedPortDisconnectsOnceWithAReason()
    {
        openLink(300, 2); // silent device: the request hangs in flight
        QSignalSpy lost(link.get(), &ModbusLink::lost);
        QSignalSpy state(link.get(), &ModbusLink::stateChanged);
        LinkOutcome o;
        link->submit(Request::read(0, 1), into(&o));
        QTRY_COMPARE(device->requests().size(), 1);
        device->bridge().close();
        QTRY_VERIFY_WITH_TIMEOUT(o.done, 5000);
        QVERIFY(!o.result.ok);
        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 5000);
        QVERIFY(!lost.at(0).at(0).toString().isEmpty());
        QCOMPARE(link->state(), ModbusLink::State::Disconnected);
        QTest::qWait(200); // Qt 6.4 repeats port errors: they must not repeat our verdict
        QCOMPARE(lost.size(), 1);
        // and new requests fail at once instead of queueing
        LinkOutcome after;
        link->submit(Request::read(0, 1), into(&after));
        QTRY_VERIFY(after.done);
        QVERIFY(after.result.errorText.contains(QStringLiteral("not connected")));
    }

    // Every request ends exactly once, also the ones a failing request's callback submits on
    // its way out (a write's read-back, the next poll): the soak hung on a read-back queued
    // while the vanishing link was still "connected" and then never failed or sent.
    void followUpsOfFailedRequestsEndWhenThePortVanishes()
    {
        openLink(300, 2); // silent device: the first request hangs in flight
        QList<LinkOutcome> outcomes(4);
        link->submit(Request::read(0, 1), [&](const Result &r) {
            outcomes[0] = {true, r};
            link->submit(Request::read(1, 1), into(&outcomes[1]));
        });
        link->submit(Request::write(2, {5}), [&](const Result &r) {
            outcomes[2] = {true, r};
            link->submit(Request::read(2, 1), into(&outcomes[3]));
        });
        QTRY_COMPARE(device->requests().size(), 1);
        device->bridge().close();
        for (int i = 0; i < outcomes.size(); ++i) {
            QTRY_VERIFY2_WITH_TIMEOUT(outcomes.at(i).done, qPrintable(QString::number(i)), 5000);
            QVERIFY(!outcomes.at(i).result.ok);
        }
        QCOMPARE(link->state(), ModbusLink::State::Disconnected);
        QVERIFY(!link->isBusy());
        QCOMPARE(link->queuedCount(), 0);
    }

    void followUpsOfFailedRequestsEndWhenTheLinkIsClosed()
    {
        openLink(5000, 0);
        LinkOutcome first;
        LinkOutcome followUp;
        link->submit(Request::read(0, 1), [&](const Result &r) {
            first = {true, r};
            link->submit(Request::read(1, 1), into(&followUp));
        });
        QTRY_COMPARE(device->requests().size(), 1);
        link->close(QStringLiteral("the user pressed Disconnect"));
        QVERIFY(first.done);
        QTRY_VERIFY_WITH_TIMEOUT(followUp.done, 5000);
        QVERIFY(!followUp.result.ok);
        QVERIFY2(followUp.result.errorText.contains(QStringLiteral("the user pressed Disconnect")),
                 qPrintable(followUp.result.errorText));
        QCOMPARE(link->queuedCount(), 0);
    }

    // A callback that reconnects while the link closes gets a link that opens (the closing
    // must not declare the new attempt failed), and it works.
    void reopenedFromACallbackWhileClosingOpens()
    {
        device->useRegisterDevice();
        device->registers[3] = 42;
        // The first request is held in flight (no answer), then closed under it.
        device->setResponder([this](const QByteArray &r, int index) -> std::optional<QByteArray> {
            if (index == 0)
                return std::nullopt;
            return device->registerDevice(r);
        });
        openLink(5000, 0);
        const LinkSettings settings = link->settings();
        QSignalSpy opened(link.get(), &ModbusLink::opened);
        LinkOutcome first;
        link->submit(Request::read(0, 1), [&](const Result &r) {
            first = {true, r};
            link->open(settings);
        });
        QTRY_COMPARE(device->requests().size(), 1);
        link->close(QStringLiteral("switching"));
        QVERIFY(first.done);
        QVERIFY(!first.result.ok);
        QTRY_COMPARE_WITH_TIMEOUT(opened.size(), 1, 5000);
        QVERIFY2(opened.at(0).at(0).toBool(), qPrintable(opened.at(0).at(1).toString()));
        QVERIFY(link->isConnected());
        LinkOutcome after;
        link->submit(Request::read(3, 1), into(&after));
        QTRY_VERIFY_WITH_TIMEOUT(after.done, 5000);
        QVERIFY2(after.result.ok, qPrintable(after.result.errorText));
        QCOMPARE(after.result.values, QVector<quint16>{42});
        QTest::qWait(100);
        QCOMPARE(opened.size(), 1);
    }

    void missingPortIsNamed()
    {
        LinkSettings s;
        s.portName = QStringLiteral("/dev/stepcom-no-such-port");
        QSignalSpy opened(link.get(), &ModbusLink::opened);
        link->open(s);
        QTRY_COMPARE(opened.size(), 1);
        QVERIFY(!opened.at(0).at(0).toBool());
        QVERIFY(opened.at(0).at(1).toString().contains(
            QStringLiteral("/dev/stepcom-no-such-port does not exist")));
    }

    // Regression: Qt reports the error inside connectDevice(), which tore the client down
    // under open()'s feet (segfault on a file that is no serial port).
    void aFileThatIsNoSerialPortFailsCleanly()
    {
        LinkSettings s;
        s.portName = QStringLiteral("/dev/null");
        QSignalSpy opened(link.get(), &ModbusLink::opened);
        link->open(s);
        QTRY_COMPARE(opened.size(), 1);
        QVERIFY(!opened.at(0).at(0).toBool());
        QVERIFY2(opened.at(0).at(1).toString().contains(
                     QStringLiteral("/dev/null is not a serial port")),
                 qPrintable(opened.at(0).at(1).toString()));
        QCOMPARE(link->state(), ModbusLink::State::Disconnected);
        // A regular file too.
        QTemporaryFile file;
        QVERIFY(file.open());
        s.portName = file.fileName();
        link->open(s);
        QTRY_COMPARE(opened.size(), 2);
        QVERIFY2(opened.at(1).at(1).toString().contains(QStringLiteral("is not a serial port")),
                 qPrintable(opened.at(1).at(1).toString()));
    }

    void badSettingsAreRefused()
    {
        LinkSettings s;
        s.portName = device->clientPath();
        s.baud = 1200;
        QSignalSpy opened(link.get(), &ModbusLink::opened);
        link->open(s);
        QTRY_COMPARE(opened.size(), 1);
        QVERIFY(opened.at(0).at(1).toString().contains(QStringLiteral("baud 1200")));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestModbusLinkPort, Guiless)
#include "tst_modbuslinkport.moc"

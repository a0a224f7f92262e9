// The window's replay of logs made for the purpose: a line of several controllers, a
// big log cancelled while it is read, a dead line's thousands of timeouts, and files that are no
// session log at all (each named by what is wrong, the window left as it was).
#include "logbuilder.h"
#include "replay/replaybar.h"
#include "replay/replayslider.h"
#include "replayfixture.h"
#include "widgets/docks/devicelistdock.h"
#include "window/windowprobe.h"

#include <QComboBox>
#include <QProgressDialog>
#include <QTableWidget>
#include <QTest>

using namespace stepcom;

class TestReplayInputs : public test::ReplayFixture
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { openWindow(); }
    void cleanupTestCase() { closeWindow(); }
    void cleanup() { closeReplay(); }

    void badFilesNameWhatIsWrong_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("expected");
        QTest::newRow("garbage") << QByteArray("hello\nthis is no log\n\x01\x02\x03\n")
                                 << QStringLiteral("not a StepCom session log");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("is empty");
        QTest::newRow("header only")
            << QByteArray("# StepCom 0.1.0 session log, part 1: x\n# program: StepCom 0.1.0\n")
            << QStringLiteral("holds no frames");
        QTest::newRow("other map")
            << QByteArray("# StepCom 0.1.0 session log, part 1: x\n# map: other/9\n")
            << QStringLiteral("register map other/9");
        QTest::newRow("zip without logs")
            << QByteArray("PK\x03\x04garbage") << QStringLiteral("cannot be replayed");
    }
    void badFilesNameWhatIsWrong()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, expected);
        const QString title = window->windowTitle();
        const QString path = writeFile(QStringLiteral("bad.log"), bytes);
        const QString reason = failure(path);
        QVERIFY2(reason.contains(expected), qPrintable(reason));
        QVERIFY(replay()->errorBox());
        QCOMPARE(replay()->errorBox()->text(), reason);
        QVERIFY(!replay()->isActive());
        QVERIFY(!store()->isReplay());
        QCOMPARE(window->windowTitle(), title);
        QVERIFY(failure(dir.filePath(QStringLiteral("missing.log")))
                    .contains(QStringLiteral("no such file")));
    }

    // A line of several controllers: each one's values, chosen on the bar.
    void severalDevicesEachTheirOwn()
    {
        const Parameter *speed = session->map().find(key("speed"));
        test::LogBuilder log;
        log.header();
        log.read(1, speed->address, {300});
        log.read(2, speed->address, {450});
        log.read(1, speed->address, {310});
        const QString path = log.save(dir, QStringLiteral("two.log"));
        QVERIFY(openReplay(path));
        QCOMPARE(replay()->devices(), (QList<int>{1, 2}));
        QComboBox *devices = replay()->bar()->deviceList();
        QVERIFY(devices->isVisibleTo(window.get()));
        QCOMPARE(devices->count(), 2);
        replay()->seek(replay()->log().durationMs());
        QCOMPARE(store()->deviceValue(speed->key), 310);
        devices->setCurrentIndex(1);
        Q_EMIT devices->activated(1);
        QCOMPARE(replay()->device(), 2);
        QCOMPARE(store()->deviceValue(speed->key), 450);
        // The device list shows the log's devices, and a click there shows one too.
        DeviceListDock *list = WindowProbe(*window).deviceListDock();
        QVERIFY(list->isReplay());
        QCOMPARE(list->table()->rowCount(), 2);
        QCOMPARE(list->rowTexts(0).value(0), QStringLiteral("1"));
        QCOMPARE(list->rowTexts(1).value(2), QStringLiteral("answering (in view)"));
        Q_EMIT list->table()->cellClicked(0, 0);
        QCOMPARE(replay()->device(), 1);
        QCOMPARE(store()->deviceValue(speed->key), 310);
        QCOMPARE(list->rowTexts(0).value(2), QStringLiteral("answering (in view)"));
        replay()->close();
        QVERIFY(!list->isReplay());
    }

    // A big log shows its progress while it is read, and Cancel leaves the window as it was.
    void aBigLogCanBeCancelled()
    {
        const Parameter *speed = session->map().find(key("speed"));
        test::LogBuilder log;
        log.header();
        for (int i = 0; i < 150000; ++i) // about 20 MB
            log.read(1, speed->address, {quint16(300 + i % 100)});
        const QString path = log.save(dir, QStringLiteral("big.log"));
        QSignalSpy failed(replay(), &ReplayMode::failed);
        QVERIFY(replay()->openPath(path));
        QVERIFY(replay()->isOpening());
        QVERIFY(replay()->progress());
        Q_EMIT replay()->progress()->canceled(); // what its Cancel button does
        QVERIFY(failed.wait(15000) || !failed.isEmpty());
        QVERIFY2(failed.at(0).at(0).toString().contains(QStringLiteral("cancelled")),
                 qPrintable(failed.at(0).at(0).toString()));
        QVERIFY(!replay()->isOpening());
        QVERIFY(!replay()->isActive());
        QVERIFY(!store()->isReplay());
    }

    // A dead line's thousands of timeouts: every one a marker, the list names the first ones.
    void aDeadLineListsItsFirstEvents()
    {
        const Parameter *speed = session->map().find(key("speed"));
        test::LogBuilder log;
        log.header();
        for (int i = 0; i < 3000; ++i) // requests without an answer: a timeout each
            log.frame(true, test::LogBuilder::readRequest(1, speed->address, 1), 600);
        QVERIFY(openReplay(log.save(dir, QStringLiteral("dead.log"))));
        const int events = int(replay()->log().events().size());
        QVERIFY(events >= 2999);
        QCOMPARE(replay()->bar()->slider()->markerCount(), events);
        QCOMPARE(replay()->bar()->eventList()->count(), ReplayBar::kListedEvents + 1);
        replay()->seek(replay()->log().durationMs());
        QCOMPARE(replay()->bar()->eventList()->currentIndex(), -1);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReplayInputs, Gui)
#include "tst_replayinputs.moc"

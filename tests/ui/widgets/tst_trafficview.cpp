// The Traffic dock fit for support: polls hidden at first, filters by kind, search, pause that
// keeps frames, a bounded memory that drops the oldest rows, "Save log…", and the session log
// file written for a real connection of the window.
#include "base/language.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/sessionlog.h"
#include "simsession.h"
#include "widgets/docks/trafficmodel.h"
#include "widgets/docks/trafficview.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QCheckBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

QByteArray rtu(const char *hex)
{
    return QByteArray::fromHex(hex) + QByteArray(2, '\0'); // the checksum is not decoded
}

// One frame of each kind, as the link logs them.
void feedOneOfEach(TrafficLog &log)
{
    const Request poll = Request::read(0x0005, 1, Priority::Poll);
    const Request read = Request::read(0x0000, 2, Priority::Read);
    const Request write = Request::write(0x0005, {300});
    const Request coil = Request::coil(0x0000, true);
    log.addFrame(TrafficEntry::Direction::Sent, rtu("010300050001"), 1, 2, &poll);
    log.addFrame(TrafficEntry::Direction::Sent, rtu("010300000002"), 1, 2, &read);
    log.addFrame(TrafficEntry::Direction::Sent, rtu("01060005012C"), 1, 2, &write);
    log.addFrame(TrafficEntry::Direction::Sent, rtu("01050000FF00"), 1, 2, &coil);
    log.addFrame(TrafficEntry::Direction::Received, rtu("018302"), 1, 2, &read);
    log.addEvent(QStringLiteral("connected to the simulator"));
}

QStringList kinds(const TrafficModel &model)
{
    QStringList out;
    for (int row = 0; row < model.rowCount(); ++row)
        out << SessionLog::kindName(model.entryAt(row).kind);
    return out;
}

} // namespace

class TestTrafficView : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
    }

    void pollsHiddenAtFirstAndFilters()
    {
        TrafficLog log;
        TrafficView view;
        view.setLog(&log);
        TrafficModel *model = view.model();
        feedOneOfEach(log);
        QCOMPARE(model->rowCount(), 0); // batched
        model->flush();
        QCOMPARE(kinds(*model), (QStringList{"read", "write", "command", "error", "event"}));
        auto *polls = view.findChildren<QCheckBox *>().at(1);
        QCOMPARE(polls->text(), QStringLiteral("Polls"));
        QVERIFY(!polls->isChecked());
        polls->setChecked(true);
        QCOMPARE(kinds(*model),
                 (QStringList{"poll", "read", "write", "command", "error", "event"}));
        for (QCheckBox *box : view.findChildren<QCheckBox *>()) {
            if (box->text() == QStringLiteral("Writes") || box->text() == QStringLiteral("Reads"))
                box->setChecked(false);
        }
        QCOMPARE(kinds(*model), (QStringList{"poll", "command", "error", "event"}));
        QCOMPARE(model->storedCount(), 6); // hidden, not dropped
    }

    void search()
    {
        TrafficLog log;
        TrafficView view;
        view.setLog(&log);
        feedOneOfEach(log);
        view.model()->flush();
        auto *search = view.findChild<QLineEdit *>(QStringLiteral("search"));
        search->setText(QStringLiteral("illegal data ADDRESS")); // any case, in the meaning
        QCOMPARE(kinds(*view.model()), QStringList{"error"});
        search->setText(QStringLiteral("01 05 00")); // in the bytes
        QCOMPARE(kinds(*view.model()), QStringList{"command"});
        search->clear();
        QCOMPARE(view.model()->rowCount(), 5);
    }

    // Paused, the rows stand still but nothing is lost; on resume they are all there.
    void pauseKeepsFrames()
    {
        TrafficLog log;
        TrafficView view;
        view.setLog(&log);
        auto *pause = view.findChild<QCheckBox *>(QStringLiteral("pause"));
        pause->setChecked(true);
        for (int i = 0; i < 3; ++i)
            log.addEvent(QStringLiteral("event %1").arg(i));
        view.model()->flush();
        QCOMPARE(view.model()->rowCount(), 0);
        QCOMPARE(view.model()->pendingCount(), 3);
        pause->setChecked(false);
        QCOMPARE(view.model()->rowCount(), 3);
        QCOMPARE(view.model()->entryAt(2).summary, QStringLiteral("event 2"));
    }

    // Bounded: the oldest frames and their rows go; the newest are all kept, in order; the
    // batch timer does the flushing.
    void boundedToItsCapacity()
    {
        TrafficLog log;
        log.setCapacity(10);
        TrafficModel model;
        model.setLog(&log);
        model.setCapacity(1000);
        QCOMPARE(model.capacity(), 1000);
        for (int i = 0; i < 2500; ++i) {
            log.addEvent(QStringLiteral("event %1").arg(i));
            if (i % 300 == 0)
                model.flush();
        }
        QTRY_COMPARE(model.pendingCount(), 0);
        QCOMPARE(model.storedCount(), 1000);
        QCOMPARE(model.rowCount(), 1000);
        QCOMPARE(model.entryAt(0).summary, QStringLiteral("event 1500"));
        QCOMPARE(model.entryAt(999).summary, QStringLiteral("event 2499"));
        QCOMPARE(TrafficModel::kDefaultCapacity, 250000);
    }

    void saveLog()
    {
        TrafficLog log;
        TrafficView view;
        view.setLog(&log);
        feedOneOfEach(log);
        view.model()->flush();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("traffic.log"));
        QString error;
        QVERIFY2(view.saveTo(path, &error), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(f.readAll()).trimmed().split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 5); // the rows shown: the poll is hidden
        QVERIFY2(lines.at(1).contains(QStringLiteral("01 06 00 05 01 2C")),
                 qPrintable(lines.at(1)));
        QVERIFY(!view.saveTo(dir.filePath(QStringLiteral("no/such/dir/x.log")), &error));
        QVERIFY(!error.isEmpty());
    }

    // The window: a connection writes its session log file in the data location; the dock
    // offers its folder.
    void windowWritesTheSessionLog()
    {
        DeviceSession session;
        MainWindow window(&session);
        QVERIFY(WindowProbe(window).sessionLog());
        QCOMPARE(WindowProbe(window).trafficView()->logFolder(),
                 WindowProbe(window).sessionLog()->directory());
        QVERIFY(WindowProbe(window).sessionLog()->directory().startsWith(
            QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)));
        QTemporaryDir dir;
        WindowProbe(window).sessionLog()->setDirectory(dir.path());
        window.show();
        QVERIFY(WindowProbe(window)
                    .trafficView()
                    ->findChild<QPushButton *>(QStringLiteral("openLogFolder"))
                    ->isVisible());
        test::useBuiltinSimulator(session);
        test::connectToSimulator(session);
        const QString file = WindowProbe(window).sessionLog()->currentFile();
        QVERIFY(file.startsWith(dir.path()));
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(f.readAll());
        QVERIFY2(text.contains(QStringLiteral("  TX  read     ")), qPrintable(text.left(2000)));
        QTRY_VERIFY(WindowProbe(window).trafficView()->model()->rowCount() > 0);
        session.connection()->disconnectFrom();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestTrafficView, Gui)
#include "tst_trafficview.moc"

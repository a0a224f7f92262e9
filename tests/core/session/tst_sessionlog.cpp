// The session log file: every frame with its date and time, a file per connection, rotated at a
// size, the oldest deleted beyond a total, and a real connection feeding it.
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/sessionlog.h"
#include "simsession.h"

#include <QDateTime>
#include <QFile>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

QString readAll(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll());
}

qint64 totalSize(const QStringList &paths)
{
    qint64 total = 0;
    for (const QString &p : paths)
        total += QFileInfo(p).size();
    return total;
}

} // namespace

class TestSessionLog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void defaultDirectoryIsTheApplicationsDataLocation()
    {
        QVERIFY(SessionLog::defaultDirectory().startsWith(
            QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)));
    }

    // A frame line carries the date, the time to the millisecond, the direction, the kind and
    // the bytes, so support can line it up with what the technician saw.
    void lineFormat()
    {
        TrafficEntry e;
        e.time = QDateTime(QDate(2026, 11, 24), QTime(22, 10, 1, 123));
        e.direction = TrafficEntry::Direction::Sent;
        e.kind = TrafficEntry::Kind::Poll;
        e.bytes = QByteArray::fromHex("010300000002C40B");
        e.summary = QStringLiteral("read 40001-40002");
        QCOMPARE(SessionLog::formatLine(e),
                 QStringLiteral("2026-11-24 22:10:01.123  TX  poll     01 03 00 00 00 02 C4 0B  "
                                "read 40001-40002\n"));
    }

    void writesEveryEntryInAFilePerConnection()
    {
        QTemporaryDir dir;
        DeviceSession session;
        SessionLog log(&session);
        log.setDirectory(dir.path());
        QSignalSpy started(&log, &SessionLog::fileStarted);
        log.beginConnection(QStringLiteral("/dev/ttyUSB0 9600 8N1 id 1"));
        for (int i = 0; i < 10; ++i)
            session.connection()->traffic()->addEvent(QStringLiteral("entry %1").arg(i));
        QCOMPARE(started.count(), 1);
        const QString first = log.currentFile();
        QVERIFY(first.contains(QStringLiteral("dev_ttyUSB0_9600_8N1_id_1")));
        const QString text = readAll(first);
        QVERIFY2(text.startsWith(QStringLiteral("# StepCom ")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("/dev/ttyUSB0 9600 8N1 id 1")));
        for (int i = 0; i < 10; ++i)
            QVERIFY(text.contains(QStringLiteral("entry %1\n").arg(i)));

        // Reconnecting starts another file; the first stays, whole.
        // The names carry milliseconds: the next one is in a later millisecond.
        const qint64 named = QDateTime::currentMSecsSinceEpoch();
        QVERIFY(
            QTest::qWaitFor([named] { return QDateTime::currentMSecsSinceEpoch() > named; }, 5000));
        log.beginConnection(QStringLiteral("localhost:1502 id 1"));
        session.connection()->traffic()->addEvent(QStringLiteral("second connection"));
        QCOMPARE(started.count(), 2);
        QVERIFY(log.currentFile() != first);
        QCOMPARE(readAll(first), text);
        QCOMPARE(log.files(), (QStringList{log.currentFile(), first}));
        QVERIFY(readAll(log.currentFile()).contains(QStringLiteral("second connection")));
    }

    // Past its size a file continues in a new part; beyond the total the oldest files go, never
    // the one being written, and no file grows past its limit.
    void rotatedAndBounded()
    {
        QTemporaryDir dir;
        DeviceSession session;
        SessionLog log(&session);
        log.setDirectory(dir.path());
        log.setLimits(4096, 16384);
        log.beginConnection(QStringLiteral("sim"));
        const QString line = QStringLiteral("x").repeated(80);
        int written = 0;
        for (; written < 2000; ++written) {
            session.connection()->traffic()->addEvent(
                QStringLiteral("%1 %2").arg(written).arg(line));
            QVERIFY(QFileInfo(log.currentFile()).size() <= log.fileLimit());
            QVERIFY2(totalSize(log.files()) <= log.totalLimit(),
                     qPrintable(QString::number(totalSize(log.files()))));
        }
        const QStringList files = log.files();
        QVERIFY(files.size() >= 3);
        QCOMPARE(files.first(), log.currentFile());
        QVERIFY(files.first().contains(QStringLiteral(".part")));
        // The newest entries are all kept, in order, across the surviving parts.
        QString all;
        for (auto it = files.crbegin(); it != files.crend(); ++it)
            all += readAll(*it);
        const QRegularExpression number(QStringLiteral("^\\S+ \\S+  --  event    (\\d+) x+$"),
                                        QRegularExpression::MultilineOption);
        QList<int> seen;
        for (auto it = number.globalMatch(all); it.hasNext();)
            seen << it.next().captured(1).toInt();
        QVERIFY(!seen.isEmpty());
        QCOMPARE(seen.last(), written - 1);
        for (int i = 1; i < seen.size(); ++i)
            QCOMPARE(seen.at(i), seen.at(i - 1) + 1);
    }

    void unwritableFolderIsReported()
    {
        QTemporaryDir dir;
        QFile blocker(dir.filePath(QStringLiteral("file")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        DeviceSession session;
        SessionLog log(&session);
        log.setDirectory(blocker.fileName() + QStringLiteral("/logs")); // under a plain file
        QSignalSpy failed(&log, &SessionLog::failed);
        session.connection()->traffic()->addEvent(QStringLiteral("a"));
        session.connection()->traffic()->addEvent(QStringLiteral("b"));
        QCOMPARE(failed.count(), 1); // once, not per frame
        QVERIFY2(failed.first().first().toString().contains(blocker.fileName()),
                 qPrintable(failed.first().first().toString()));
    }

    // Wired to a real session: connecting opens a file that receives the frames of the
    // read-all with their kinds.
    void fedByAConnection()
    {
        QTemporaryDir dir;
        DeviceSession session;
        SessionLog log(&session);
        log.setDirectory(dir.path());
        test::useBuiltinSimulator(session);
        test::connectToSimulator(session);
        const QString text = readAll(log.currentFile());
        QVERIFY2(text.contains(QStringLiteral("  TX  read     ")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("  RX  read     ")));
        QCOMPARE(log.files().size(), 1);
    }

    // The session's own log (what the window and stepcomctl --log use): one per session, made
    // when asked and from then on fed by every connection; a session never asked writes none.
    void theSessionsOwnLogIsMadeWhenAsked()
    {
        QTemporaryDir dir;
        DeviceSession quiet;
        QVERIFY(quiet.findChild<SessionLog *>() == nullptr);
        DeviceSession session;
        SessionLog *log = session.log();
        QVERIFY(log);
        QCOMPARE(session.log(), log);
        QCOMPARE(log->parent(), &session);
        log->setDirectory(dir.path());
        test::useBuiltinSimulator(session);
        test::connectToSimulator(session);
        QVERIFY(readAll(log->currentFile()).contains(QStringLiteral("  RX  read     ")));
        QVERIFY(quiet.findChild<SessionLog *>() == nullptr);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestSessionLog, Guiless)
#include "tst_sessionlog.moc"

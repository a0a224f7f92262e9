#include "device/parameterstore.h"
#include "device/poller.h"
#include "device/statusrecorder.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace stepcom;

// StatusRecorder: one sample per completed poll cycle, bounded history, CSV recording/export.
class TstStatusRecorder : public QObject
{
    Q_OBJECT

    static QStringList readLines(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
            return {};
        QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
        if (!lines.isEmpty() && lines.last().isEmpty())
            lines.removeLast();
        return lines;
    }

    // Waits until a millisecond clock started before has moved on (2 ms on one of our own,
    // read in whole milliseconds): a sample taken next is stamped later than the one before.
    static bool clockMovesOn()
    {
        QElapsedTimer clock;
        clock.start();
        return QTest::qWaitFor([&clock] { return clock.elapsed() >= 2; }, 5000);
    }

    static void setStatus(ParameterStore &store, qint64 pos1, qint64 pos2)
    {
        store.setDeviceValues({{"motor1.position", pos1},
                               {"motor2.position", pos2},
                               {"motor1.running", 1},
                               {"motor2.running", 0},
                               {"io.in1", 0},
                               {"io.in2", 1},
                               {"io.in3", 0},
                               {"io.in4", 0},
                               {"io.out1", 1},
                               {"io.out2", 0},
                               {"io.out3", 0}});
    }

private Q_SLOTS:
    void samplesOncePerCompletedPollCycle()
    {
        DeviceSession session;
        StatusRecorder recorder(session.map(), session.parameters()->store());
        recorder.attach(SessionInternals::poller(session));
        QSignalSpy read(session.parameters(), &SessionParameters::readFinished);
        test::useBuiltinSimulator(session);
        session.connection()->connectSimulator();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        SimDevice *sim = test::simHost(session)->device();
        sim->setMachinePosition(1, 12.5);
        sim->setMachinePosition(2, -3.25);
        QSignalSpy cycles(SessionInternals::poller(session), &Poller::cycleFinished);
        QSignalSpy samples(&recorder, &StatusRecorder::sampleAdded);
        QTRY_VERIFY_WITH_TIMEOUT(cycles.size() >= 5, 5000);
        session.status()->stop();
        int ok = 0;
        for (const auto &c : cycles)
            ok += c.at(0).toBool() ? 1 : 0;
        QCOMPARE(samples.size(), ok);
        QVERIFY(ok >= 5);
        // Engineering units: the register holds hundredths of the distance unit.
        const StatusSample &last = recorder.last();
        QCOMPARE(last.positions.size(), 2);
        QCOMPARE(last.positions.at(0), double(sim->position(1)) / 100.0);
        QCOMPARE(last.positions.at(1), double(sim->position(2)) / 100.0);
        QVERIFY(last.running == (QVector<qint8>{0, 0}));
        QCOMPARE(last.inputs.size(), 4);
        QCOMPARE(last.outputs.size(), 3);
        for (int i = 1; i < recorder.size(); ++i)
            QVERIFY(recorder.at(i).elapsedMs >= recorder.at(i - 1).elapsedMs);
        // Detached: no more samples.
        recorder.attach(nullptr);
        const int before = recorder.size();
        session.status()->start();
        QTRY_VERIFY(cycles.size() >= ok + 2);
        QCOMPARE(recorder.size(), before);
    }

    void unknownValuesStayUnknown()
    {
        ParameterStore store(RegisterMap::builtin());
        StatusRecorder recorder(store.map(), &store);
        QCOMPARE(recorder.motorCount(), 2);
        QCOMPARE(recorder.inputCount(), 4);
        QCOMPARE(recorder.outputCount(), 3);
        recorder.takeSample();
        QVERIFY(std::isnan(recorder.last().positions.at(0)));
        QCOMPARE(recorder.last().running.at(1), qint8(-1));
        QCOMPARE(recorder.last().inputs.at(0), qint8(-1));
        setStatus(store, 12345, -50);
        recorder.takeSample();
        QCOMPARE(recorder.last().positions, (QVector<double>{123.45, -0.5}));
        QVERIFY(recorder.last().running == (QVector<qint8>{1, 0}));
        QVERIFY(recorder.last().inputs == (QVector<qint8>{0, 1, 0, 0}));
        QVERIFY(recorder.last().outputs == (QVector<qint8>{1, 0, 0}));
    }

    void historyIsBoundedByCountAndAge()
    {
        ParameterStore store(RegisterMap::builtin());
        StatusRecorder recorder(store.map(), &store);
        recorder.setCapacity(5);
        for (int i = 0; i < 8; ++i) {
            setStatus(store, i * 100, 0);
            recorder.takeSample();
        }
        QCOMPARE(recorder.size(), 5);
        QCOMPARE(recorder.at(0).positions.at(0), 3.0); // the three oldest went
        QCOMPARE(recorder.last().positions.at(0), 7.0);
        QCOMPARE(recorder.samples(1, 3).size(), 2);

        recorder.setCapacity(1000);
        recorder.setMaxAgeMs(100);
        QTest::qWait(150);
        recorder.takeSample();
        QCOMPARE(recorder.size(), 1); // everything older than 100 ms before it is gone
        QCOMPARE(recorder.indexAtOrAfter(0), 0);
        QCOMPARE(recorder.indexAtOrAfter(recorder.last().elapsedMs + 1), 1);
        QSignalSpy cleared(&recorder, &StatusRecorder::cleared);
        recorder.clear();
        QVERIFY(recorder.isEmpty());
        QCOMPARE(cleared.size(), 1);
    }

    void recordingWritesHeaderUnitsAndOneRowPerSample()
    {
        QTemporaryDir dir;
        ParameterStore store(RegisterMap::builtin());
        StatusRecorder recorder(store.map(), &store);
        const QString path = dir.filePath("rec.csv");
        QString error;
        QSignalSpy changed(&recorder, &StatusRecorder::recordingChanged);
        QVERIFY2(recorder.startRecording(path, &error), qPrintable(error));
        QVERIFY(recorder.isRecording());
        QCOMPARE(recorder.recordingPath(), path);
        // Flushed as it goes: the header is on disk before any sample.
        QCOMPARE(readLines(path).size(), 1);
        setStatus(store, 12345, -50);
        recorder.takeSample();
        QVERIFY(clockMovesOn());
        store.forgetDeviceValues();
        recorder.takeSample();
        QVERIFY(clockMovesOn());
        setStatus(store, 0, 100000);
        recorder.takeSample();
        QCOMPARE(readLines(path).size(), 4);
        recorder.stopRecording();
        QVERIFY(!recorder.isRecording());
        QCOMPARE(changed.size(), 2);
        QCOMPARE(recorder.recordedRows(), 3);
        recorder.takeSample(); // after stop: not written
        const QStringList lines = readLines(path);
        QCOMPARE(lines.size(), 4);
        QCOMPARE(lines.at(0), QStringLiteral("time,ms,motor1.position [mm],motor2.position [mm],"
                                             "motor1.running,motor2.running,io.in1,io.in2,io.in3,"
                                             "io.in4,io.out1,io.out2,io.out3"));
        const QStringList first = lines.at(1).split(QLatin1Char(','));
        QCOMPARE(first.size(), 13);
        const QDateTime t = QDateTime::fromString(first.at(0), Qt::ISODateWithMs);
        QVERIFY2(t.isValid(), qPrintable(first.at(0)));
        QVERIFY(std::abs(t.toMSecsSinceEpoch() - QDateTime::currentMSecsSinceEpoch()) < 60000);
        QCOMPARE(first.at(1), QStringLiteral("0"));
        QCOMPARE(first.mid(2), QString("123.45,-0.50,1,0,0,1,0,0,1,0,0").split(QLatin1Char(',')));
        // Unknown values are empty fields, not zeros.
        QCOMPARE(lines.at(2).split(QLatin1Char(',')).mid(2), QStringList(11, QString()));
        QCOMPARE(lines.at(3).split(QLatin1Char(',')).at(3), QStringLiteral("1000.00"));
        qint64 previous = -1;
        for (int i = 1; i < lines.size(); ++i) {
            const qint64 ms = lines.at(i).split(QLatin1Char(',')).at(1).toLongLong();
            QVERIFY(ms > previous);
            previous = ms;
        }
    }

    void exportWritesTheGivenSamples()
    {
        QTemporaryDir dir;
        ParameterStore store(RegisterMap::builtin());
        StatusRecorder recorder(store.map(), &store);
        for (int i = 0; i < 4; ++i) {
            setStatus(store, i, 0);
            recorder.takeSample();
            QVERIFY(clockMovesOn());
        }
        QString error;
        const QString path = dir.filePath("export.csv");
        QVERIFY2(recorder.writeCsv(path, recorder.samples(1), &error), qPrintable(error));
        const QStringList lines = readLines(path);
        QCOMPARE(lines.size(), 4);
        QCOMPARE(lines.at(0), recorder.csvHeader());
        QCOMPARE(lines.at(1).split(QLatin1Char(',')).at(1), QStringLiteral("0"));
        QCOMPARE(lines.at(1).split(QLatin1Char(',')).at(2), QStringLiteral("0.01"));
        QCOMPARE(lines.at(3).split(QLatin1Char(',')).at(2), QStringLiteral("0.03"));
    }

    void badPathsSayWhichPath()
    {
        ParameterStore store(RegisterMap::builtin());
        StatusRecorder recorder(store.map(), &store);
        const QString bad = QStringLiteral("/nonexistent-stepcom-dir/sub/rec.csv");
        QString error;
        QVERIFY(!recorder.startRecording(bad, &error));
        QVERIFY2(error.contains(bad), qPrintable(error));
        QVERIFY(!recorder.isRecording());
        error.clear();
        QVERIFY(!recorder.writeCsv(bad, {}, &error));
        QVERIFY2(error.contains(bad), qPrintable(error));
        error.clear();
        QVERIFY(!recorder.startRecording(QString(), &error));
        QVERIFY(!error.isEmpty());
        QTemporaryDir dir; // a directory is not a file
        QVERIFY(!recorder.startRecording(dir.path(), &error));
        QVERIFY2(error.contains(dir.path()), qPrintable(error));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstStatusRecorder, Guiless)
#include "tst_statusrecorder.moc"

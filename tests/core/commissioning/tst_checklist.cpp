#include "commissioning/checklist.h"
#include "commissioning/checklistfile.h"
#include "map/registermap.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

namespace {

const QDateTime t0(QDate(2024, 6, 1), QTime(9, 30), Qt::UTC);

QList<ChecklistMeasurement> calibration()
{
    return {{QStringLiteral("commanded"), QStringLiteral("100.00"), QStringLiteral("mm")},
            {QStringLiteral("measured"), QStringLiteral("99.20"), QStringLiteral("mm")},
            {QStringLiteral("pitch_after"), QStringLiteral("4.96"), QStringLiteral("mm")}};
}

// A checklist with some of everything: passes, a failure repeated into a pass, a skip.
Checklist sample()
{
    Checklist c = Checklist::forMap(RegisterMap::builtin());
    c.machine = QStringLiteral("Machine A");
    c.settingsFingerprint = QStringLiteral("3f2a-9c1b-77e0-12ab");
    c.record(QStringLiteral("motor1.direction"), StepResult::Passed,
             {{QStringLiteral("moved_toward_plus"), QStringLiteral("yes"), {}}}, {}, t0);
    c.record(QStringLiteral("motor1.calibration"), StepResult::Failed, calibration(),
             QStringLiteral("caliper slipped"), t0.addSecs(60));
    c.record(QStringLiteral("motor1.calibration"), StepResult::Passed, calibration(),
             QStringLiteral("measured with a dial gauge\n2nd line: \"quoted\""), t0.addSecs(120));
    c.record(QStringLiteral("motor1.limit_positive"), StepResult::Skipped, {},
             QStringLiteral("no switch at + on this machine"), t0.addSecs(180));
    return c;
}

QByteArray json(const QJsonObject &o)
{
    return QJsonDocument(o).toJson();
}

} // namespace

// The commissioning checklist: steps, transitions, the file, resuming.
class TestChecklist : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

private Q_SLOTS:
    void stepsFollowTheMap()
    {
        const Checklist c = Checklist::forMap(RegisterMap::builtin());
        QCOMPARE(c.motorCount(), 2);
        QCOMPARE(c.steps().size(), 2 * 8 + 4);
        QStringList ids;
        for (const ChecklistStep &s : c.steps()) {
            ids << s.id;
            QVERIFY(!s.title().isEmpty() && !s.instruction().isEmpty());
            QCOMPARE(s.result(), StepResult::Pending);
        }
        QCOMPARE(ids.mid(0, 6),
                 (QStringList{"motor1.direction", "motor1.calibration", "motor1.limit_positive",
                              "motor1.limit_negative", "motor1.home_input", "motor1.homing"}));
        QCOMPARE(ids.mid(16), (QStringList{"machine.homing_order", "machine.interpolation",
                                           "machine.run_in", "machine.save_to_flash"}));
        QCOMPARE(c.step(QStringLiteral("motor2.homing"))->title(),
                 QStringLiteral("Motor 2: homing"));
        QCOMPARE(c.verdict(), Checklist::Verdict::NotStarted);
        QCOMPARE(c.nextPending()->id, QStringLiteral("motor1.direction"));
    }

    void transitions()
    {
        Checklist c = Checklist::forMap(RegisterMap::builtin());
        const QString id = QStringLiteral("motor1.direction");
        QCOMPARE(c.record(id, StepResult::Failed, {}, QStringLiteral("went toward −"), t0),
                 QString());
        QCOMPARE(c.step(id)->result(), StepResult::Failed);
        QCOMPARE(c.verdict(), Checklist::Verdict::Failed);
        // Repeated after the fix: the latest counts, the failure stays on record.
        QCOMPARE(c.record(id, StepResult::Passed, {}, {}, t0.addSecs(30)), QString());
        QCOMPARE(c.step(id)->result(), StepResult::Passed);
        QCOMPARE(c.step(id)->attempts.size(), 2);
        QCOMPARE(c.step(id)->attempts.first().result, StepResult::Failed);
        QCOMPARE(c.step(id)->latest()->number, 2);
        QCOMPARE(c.verdict(), Checklist::Verdict::InProgress);
        QCOMPARE(c.nextPending()->id, QStringLiteral("motor1.calibration"));
        const Checklist fresh = Checklist::forMap(RegisterMap::builtin());
        for (const ChecklistStep &s : fresh.steps()) {
            if (s.id != id)
                QCOMPARE(c.record(s.id, StepResult::Passed, {}, {}, t0.addSecs(60)), QString());
        }
        QCOMPARE(c.verdict(), Checklist::Verdict::Passed);
        QVERIFY(c.nextPending() == nullptr);
        QCOMPARE(c.summary(),
                 QStringLiteral("20 of 20 steps passed, 0 failed, 0 skipped, 0 not run"));
        QCOMPARE(c.record(QStringLiteral("machine.interpolation"), StepResult::Skipped, {}, {}, t0),
                 QString());
        QCOMPARE(c.verdict(), Checklist::Verdict::PassedWithSkips);
        QCOMPARE(c.lastRecorded(), t0.addSecs(60));
    }

    void badRecordsChangeNothing_data()
    {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("result");
        QTest::addColumn<QList<ChecklistMeasurement>>("measurements");
        QTest::addColumn<QString>("note");
        QTest::addColumn<QString>("message");
        const QList<ChecklistMeasurement> none;
        QTest::newRow("unknown step") << "motor3.direction" << int(StepResult::Passed) << none << ""
                                      << "\"motor3.direction\" is not a step of this checklist";
        QTest::newRow("pending") << "motor1.homing" << int(StepResult::Pending) << none << ""
                                 << "not pending";
        QTest::newRow("long note") << "motor1.homing" << int(StepResult::Passed) << none
                                   << QString(Checklist::MaxNoteChars + 1, QLatin1Char('x'))
                                   << "the note has 2001 characters (at most 2000)";
        QTest::newRow("bad key") << "motor1.homing" << int(StepResult::Passed)
                                 << QList<ChecklistMeasurement>{{"Bad Key", "1", ""}} << ""
                                 << "\"Bad Key\" is not a measurement key";
        QTest::newRow("long value")
            << "motor1.homing" << int(StepResult::Passed)
            << QList<ChecklistMeasurement>{{"measured", QString(300, QLatin1Char('9')), ""}} << ""
            << "the measurement \"measured\" is too long";
        QList<ChecklistMeasurement> many;
        for (int i = 0; i <= Checklist::MaxMeasurements; ++i)
            many << ChecklistMeasurement{QStringLiteral("m%1").arg(i), QStringLiteral("1"), {}};
        QTest::newRow("too many") << "motor1.homing" << int(StepResult::Passed) << many << ""
                                  << "25 measurements (at most 24)";
    }
    void badRecordsChangeNothing()
    {
        QFETCH(QString, id);
        QFETCH(int, result);
        QFETCH(QList<ChecklistMeasurement>, measurements);
        QFETCH(QString, note);
        QFETCH(QString, message);
        Checklist c = sample();
        const Checklist before = c;
        const QString why = c.record(id, StepResult(result), measurements, note, t0);
        QVERIFY2(why.contains(message), qPrintable(why));
        QVERIFY(c == before);
    }

    void attemptsAreBounded()
    {
        Checklist c = Checklist::forMap(RegisterMap::builtin());
        for (int i = 0; i < Checklist::MaxAttempts + 5; ++i)
            QCOMPARE(c.record(QStringLiteral("motor2.homing"), StepResult::Failed, {}, {},
                              t0.addSecs(i)),
                     QString());
        const auto &attempts = c.step(QStringLiteral("motor2.homing"))->attempts;
        QCOMPARE(attempts.size(), Checklist::MaxAttempts);
        QCOMPARE(attempts.first().number, 6);
        QCOMPARE(attempts.last().number, Checklist::MaxAttempts + 5);
        // Still a valid file, read back the same.
        const auto r = ChecklistFile::parse(ChecklistFile::toJson(c), RegisterMap::builtin());
        QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
        QVERIFY(*r.checklist == c);
    }

    void fileRoundTrip()
    {
        const Checklist c = sample();
        const QByteArray bytes = ChecklistFile::toJson(c);
        const auto r = ChecklistFile::parse(bytes, RegisterMap::builtin());
        QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
        QVERIFY(*r.checklist == c);
        QCOMPARE(r.checklist->machine, QStringLiteral("Machine A"));
        const ChecklistAttempt *a =
            r.checklist->step(QStringLiteral("motor1.calibration"))->latest();
        QCOMPARE(a->time, t0.addSecs(120));
        QCOMPARE(a->note, QStringLiteral("measured with a dial gauge\n2nd line: \"quoted\""));
        QCOMPARE(a->measurements, calibration());
        // Pending steps are not written: the map gives them.
        QCOMPARE(QJsonDocument::fromJson(bytes).object().value("steps").toArray().size(), 3);
    }

    void interruptedChecklistResumes()
    {
        const QString profile = dir.filePath(QStringLiteral("machine-a.json"));
        const QString path = ChecklistFile::pathFor(profile);
        QCOMPARE(path, dir.filePath(QStringLiteral("machine-a.checklist.json")));
        Checklist c = sample();
        QCOMPARE(ChecklistFile::save(path, c), QString());
        // The window closed here; a new session loads the file and goes on where it stopped.
        auto r = ChecklistFile::load(path, RegisterMap::builtin());
        QVERIFY2(r.ok(), qPrintable(r.errors.join('\n')));
        Checklist resumed = *r.checklist;
        QCOMPARE(resumed.nextPending()->id, QStringLiteral("motor1.limit_negative"));
        QCOMPARE(resumed.record(resumed.nextPending()->id, StepResult::Passed,
                                {{QStringLiteral("input_answered"), QStringLiteral("IN2"), {}}}, {},
                                t0.addSecs(240)),
                 QString());
        QCOMPARE(ChecklistFile::save(path, resumed), QString());
        r = ChecklistFile::load(path, RegisterMap::builtin());
        QVERIFY(r.ok());
        QCOMPARE(r.checklist->nextPending()->id, QStringLiteral("motor1.home_input"));
        QCOMPARE(r.checklist->count(StepResult::Passed), 3);
        QCOMPARE(r.checklist->count(StepResult::Skipped), 1);
        // A save into a folder that does not exist fails and says where.
        const QString bad = dir.filePath(QStringLiteral("nope/x.checklist.json"));
        QVERIFY(ChecklistFile::save(bad, resumed).contains(bad));
    }

    void malformedFilesAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("message");
        const QJsonObject good = QJsonDocument::fromJson(ChecklistFile::toJson(sample())).object();
        auto with = [&](const QString &key, const QJsonValue &v) {
            QJsonObject o = good;
            o.insert(key, v);
            return json(o);
        };
        auto step = [&](const QJsonObject &s) { return with("steps", QJsonArray{s}); };
        auto attempt = [&](const QJsonObject &a) {
            return step({{"id", "motor1.homing"}, {"attempts", QJsonArray{a}}});
        };
        const QJsonObject ok{
            {"attempt", 1}, {"result", "passed"}, {"time", "2024-06-01T09:30:00Z"}};
        auto change = [&](const QString &k, const QJsonValue &v) {
            QJsonObject a = ok;
            a.insert(k, v);
            return attempt(a);
        };
        QTest::newRow("empty") << QByteArray("  \n") << "the file is empty";
        QTest::newRow("not json") << QByteArray(
                                         "{\"format\": \"stepcom-checklist\",\n  \"schema\": 1,,}")
                                  << "not valid JSON at line 2";
        QTest::newRow("list") << QByteArray("[1, 2]") << "a JSON list, not a checklist";
        QTest::newRow("a profile")
            << with("format", "stepcom-profile") << "this is a profile, not a checklist";
        QTest::newRow("other format")
            << with("format", "x") << "\"format\" must be \"stepcom-checklist\"";
        QTest::newRow("newer schema")
            << with("schema", 2) << "checklist schema 2 is newer than this StepCom reads (1)";
        QTest::newRow("other map")
            << with("map", "stepper3/1")
            << "the checklist is for register map \"stepper3/1\", but this map is \"stepper2/1\"";
        QTest::newRow("unknown field") << with("owner", "me") << "unknown field \"owner\"";
        QTest::newRow("steps not a list")
            << with("steps", QJsonObject{}) << "\"steps\" must be a list, found an object";
        QTest::newRow("unknown step")
            << step({{"id", "motor3.direction"}, {"attempts", QJsonArray{ok}}})
            << "step 1: \"motor3.direction\" is not a step of this checklist (2 motor(s))";
        QTest::newRow("step twice")
            << with("steps",
                    QJsonArray{QJsonObject{{"id", "motor1.homing"}, {"attempts", QJsonArray{ok}}},
                               QJsonObject{{"id", "motor1.homing"}, {"attempts", QJsonArray{ok}}}})
            << "step 2: \"motor1.homing\" appears more than once";
        QTest::newRow("bad result") << change("result", "ok")
                                    << "\"result\" must be passed, failed or skipped, found \"ok\"";
        QTest::newRow("pending result") << change("result", "pending") << "found \"pending\"";
        QTest::newRow("bad time") << change("time", "yesterday")
                                  << "\"time\" is not a date and time";
        QTest::newRow("time a number")
            << change("time", 5) << "\"time\" must be a text, found a number";
        QTest::newRow("attempt zero")
            << change("attempt", 0) << "\"attempt\" must be a whole number from 1";
        QTest::newRow("measurement key")
            << change("measurements", QJsonArray{QJsonObject{{"key", "A B"}, {"value", "1"}}})
            << "\"A B\" is not a measurement key";
        QTest::newRow("measurement field")
            << change("measurements",
                      QJsonArray{QJsonObject{{"key", "a"}, {"value", "1"}, {"x", 1}}})
            << "measurement 1: unknown field \"x\"";
        QTest::newRow("attempts downwards")
            << step({{"id", "motor1.homing"},
                     {"attempts", QJsonArray{QJsonObject{{"attempt", 2},
                                                         {"result", "failed"},
                                                         {"time", "2024-06-01T09:30:00Z"}},
                                             ok}}})
            << "the attempts must be numbered upwards (found 1 after 2)";
        QByteArray huge = "{\"format\": \"stepcom-checklist\", \"note\": \"";
        huge += QByteArray(ChecklistFile::MaxBytes, 'x') + "\"}";
        QTest::newRow("huge") << huge << "far too large for a checklist";
    }
    void malformedFilesAreRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, message);
        const auto r = ChecklistFile::parse(bytes, RegisterMap::builtin());
        QVERIFY(!r.ok());
        QVERIFY2(r.errors.join('\n').contains(message), qPrintable(r.errors.join('\n')));
    }

    void loadNamesTheFile()
    {
        const QString path = dir.filePath(QStringLiteral("bad.checklist.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("[]");
        f.close();
        const auto r = ChecklistFile::load(path, RegisterMap::builtin());
        QCOMPARE(r.errors,
                 QStringList{"bad.checklist.json: the file holds a JSON list, not a checklist"});
        QVERIFY(ChecklistFile::load(dir.filePath("none.json"), RegisterMap::builtin())
                    .errors.first()
                    .contains("no such file"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestChecklist, Guiless)
#include "tst_checklist.moc"

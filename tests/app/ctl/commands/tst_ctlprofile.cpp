#include "map/registermap.h"
#include "profile/profilefile.h"
#include "programrun.h"
#include "scripteddevice.h"
#include "testmaps.h"
#include "testpaths.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

using Run = ProgramRun;

QList<QByteArray> writeFrames(const QList<QByteArray> &requests)
{
    QList<QByteArray> out;
    for (const QByteArray &r : requests) {
        if (quint8(r.at(1)) == 0x06 || quint8(r.at(1)) == 0x10)
            out << r;
    }
    return out;
}

} // namespace

// stepcomctl dump, diff, apply and report against a fake controller on a pty.
class TestCtlProfile : public QObject
{
    Q_OBJECT
    std::unique_ptr<ScriptedDevice> device;
    QTemporaryDir dir;

    // Runs stepcomctl without blocking the event loop, so the fake device keeps answering;
    // `input` goes to its standard input, which is then closed.
    Run ctl(const QStringList &args, const QByteArray &input = {}, bool withPort = true)
    {
        const QStringList link{QStringLiteral("--port"),    device->clientPath(),
                               QStringLiteral("--timeout"), QStringLiteral("300"),
                               QStringLiteral("--retries"), QStringLiteral("0")};
        ProgramOptions options;
        options.input = input;
        return runProgram(QStringLiteral("stepcomctl"), (withPort ? link : QStringList()) + args,
                          options);
    }
    QString file(const char *name) const { return dir.filePath(QLatin1String(name)); }
    // Loads a profile into the fake controller's registers.
    void load(const QString &path)
    {
        const ProfileParseResult r = ProfileFile::load(path, RegisterMap::builtin());
        QVERIFY(r.ok());
        for (auto it = r.profile->values.cbegin(); it != r.profile->values.cend(); ++it) {
            const Parameter *p = RegisterMap::builtin().find(it.key());
            const auto words = p->encode(it.value());
            for (int i = 0; i < words.size(); ++i)
                device->registers[p->address + i] = words.at(i);
        }
    }
    QString machineA() const
    {
        return sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json"));
    }
    // Machine A's values as StepCom with another map saves them, with `extra` (raw) on top.
    QString variant(const char *name, const QString &map, const QHash<QString, qint64> &extra)
    {
        QStringList errors;
        const auto other =
            map == QLatin1String("stepper3") ? threeAxisMap(&errors) : liteVariantMap(&errors);
        if (!other)
            qFatal("%s", qPrintable(errors.join(QLatin1Char('\n'))));
        QHash<QString, qint64> values;
        const Profile a = *ProfileFile::load(machineA(), RegisterMap::builtin()).profile;
        for (auto it = a.values.cbegin(); it != a.values.cend(); ++it)
            values.insert(it.key(), it.value());
        for (auto it = extra.cbegin(); it != extra.cend(); ++it)
            values.insert(it.key(), it.value());
        QFile f(file(name));
        if (!f.open(QIODevice::WriteOnly))
            qFatal("cannot write %s", name);
        f.write(profileSavedWith(*other, values, QStringLiteral("Machine B")));
        return f.fileName();
    }
    QString threeAxes()
    {
        return variant(
            "three.json", QStringLiteral("stepper3"),
            {{QStringLiteral("motor1.speed"), 4500}, {QStringLiteral("motor3.speed"), 900}});
    }
    QString liteFirmware() { return variant("lite.json", QStringLiteral("stepper2-lite"), {}); }

private Q_SLOTS:
    void init()
    {
        // apply saves a backup first: into the test's folder, never the user's data.
        qputenv("XDG_DATA_HOME", QFile::encodeName(dir.filePath(QStringLiteral("data"))));
        device = std::make_unique<ScriptedDevice>();
        QString error;
        QVERIFY2(device->open(&error), qPrintable(error));
        device->useRegisterDevice();
        load(machineA());
        device->registers[211] = 1;    // device.id
        device->registers[212] = 9600; // device.baud
    }

    void dumpThenDiffIsTheSame()
    {
        const Run dump = ctl({QStringLiteral("dump"), file("a.json"), QStringLiteral("--name"),
                              QStringLiteral("Line 3"), QStringLiteral("--notes"),
                              QStringLiteral("after the gearbox change")});
        QVERIFY2(dump.exitCode == 0, qPrintable(dump.err));
        QVERIFY(dump.out.contains(QStringLiteral("saved 44 parameters")));
        const ProfileParseResult saved = ProfileFile::load(file("a.json"), RegisterMap::builtin());
        QVERIFY2(saved.ok(), qPrintable(saved.errors.join(QLatin1Char('\n'))));
        QCOMPARE(saved.profile->name, QStringLiteral("Line 3"));
        QCOMPARE(saved.profile->notes, QStringLiteral("after the gearbox change"));
        QCOMPARE(saved.profile->deviceId, 1);
        QCOMPARE(saved.profile->baud, 9600);
        QVERIFY(!saved.profile->values.contains(QStringLiteral("device.id")));
        QCOMPARE(writeFrames(device->requests()).size(), 0); // dumping writes nothing

        const Run diff = ctl({QStringLiteral("diff"), file("a.json")});
        QCOMPARE(diff.exitCode, 0);
        QVERIFY(diff.out.contains(QStringLiteral("holds every value")));
    }

    void diffNamesTheDifferences()
    {
        device->registers[5] = 450; // motor1.speed
        device->registers[199] = 0; // arc.direction: clockwise
        const Run r = ctl({QStringLiteral("diff"), machineA()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QStringLiteral("motor1.speed: 450 rpm -> 300 rpm")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("arc.direction: Clockwise -> Counter-clockwise")));
        QVERIFY(r.out.contains(QStringLiteral("2 values differ")));
        QCOMPARE(writeFrames(device->requests()).size(), 0);
    }

    void badFilesSendNothing_data()
    {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("message");
        const QString corpus = sourcePath(QStringLiteral("tests/core/profile/corpus/"));
        QTest::newRow("diff unknown key") << "diff" << corpus + "unknown-key.json"
                                          << "unknown parameter \"motor3.speed\"";
        // A same-map file with a key this map lacks is broken (another map's profile is not).
        QTest::newRow("apply unknown key") << "apply" << corpus + "unknown-key.json"
                                           << "unknown parameter \"motor3.speed\"";
        QTest::newRow("apply truncated") << "apply" << corpus + "truncated.json"
                                         << "not valid JSON at line";
        QTest::newRow("apply empty") << "apply" << corpus + "empty.json"
                                     << "the file is empty";
        QTest::newRow("apply missing file") << "apply" << corpus + "nope.json"
                                            << "no such file";
    }
    void badFilesSendNothing()
    {
        QFETCH(QString, command);
        QFETCH(QString, path);
        QFETCH(QString, message);
        const Run r = ctl({command, path, QStringLiteral("--yes")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.err.contains(QStringLiteral("nothing was written")));
        QVERIFY(device->takeEverythingSent());
        QCOMPARE(device->requests().size(), 0); // not even connected
    }

    void applyWritesOnlyTheDifferencesAndVerifies()
    {
        device->registers[5] = 450;  // motor1.speed
        device->registers[200] = 60; // arc.speed
        device->registers[211] = 4;  // device.id differs too, but the profile holds none
        const Run r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QVERIFY(r.out.contains(QStringLiteral("will write motor1.speed: 450 rpm -> 300 rpm")));
        QVERIFY(r.out.contains(QStringLiteral("will write arc.speed: 60 rpm -> 100 rpm")));
        QVERIFY(r.out.contains(QStringLiteral("arc.speed = 100 rpm  (written, verified)")));
        QVERIFY(r.out.contains(QStringLiteral("not saved to flash")));
        QCOMPARE(writeFrames(device->requests()),
                 (QList<QByteArray>{withCrc(fromHex("01 06 00 05 01 2C")),
                                    withCrc(fromHex("01 06 00 C8 00 64"))}));
        QCOMPARE(device->registers[211], quint16(4));
    }

    void applyAsksFirst_data()
    {
        QTest::addColumn<QByteArray>("answer");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<int>("writes");
        QTest::newRow("yes") << QByteArray("y\n") << 0 << 1;
        QTest::newRow("no") << QByteArray("n\n") << 2 << 0;
        QTest::newRow("no answer") << QByteArray() << 2 << 0;
    }
    void applyAsksFirst()
    {
        QFETCH(QByteArray, answer);
        QFETCH(int, exitCode);
        QFETCH(int, writes);
        device->registers[5] = 450;
        const Run r = ctl({QStringLiteral("apply"), machineA()}, answer);
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY(r.out.contains(QStringLiteral("Write 1 value to the controller? [y/N]")));
        QCOMPARE(writeFrames(device->requests()).size(), writes);
        QCOMPARE(device->registers[5], quint16(writes ? 300 : 450));
        if (!writes)
            QVERIFY2(r.err.contains(QStringLiteral("nothing was written")), qPrintable(r.err));
    }

    void applySavesToFlashWhenAsked()
    {
        device->registers[5] = 450;
        const Run r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes"),
                           QStringLiteral("--save-to-flash")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("saved to flash")));
        QCOMPARE(device->requests().last(), withCrc(fromHex("01 05 00 5F FF 00"))); // coil 96
    }

    void linkSettingsOnlyWithIncludeLink()
    {
        Profile p = *ProfileFile::load(machineA(), RegisterMap::builtin()).profile;
        p.values.insert(QStringLiteral("device.id"), 1);
        p.values.insert(QStringLiteral("device.baud"), 9600);
        p.values[QStringLiteral("motor1.speed")] = 310;
        device->registers[212] = 19200; // the profile wants 9600
        QCOMPARE(ProfileFile::save(file("link.json"), p, RegisterMap::builtin()), QString());
        const Run r = ctl({QStringLiteral("apply"), file("link.json"), QStringLiteral("--yes")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("not applied (needs --include-link): device.baud: "
                                               "19200 baud -> 9600 baud")),
                 qPrintable(r.out));
        QCOMPARE(device->registers[212], quint16(19200));
        QCOMPARE(device->registers[5], quint16(310));
    }

    void verificationCatchesADeviceThatIgnoresAWrite()
    {
        device->registers[5] = 450;
        QList<quint16> *regs = &device->registers;
        device->setResponder([regs](const QByteArray &request, int) -> std::optional<QByteArray> {
            if (quint8(request.at(1)) != 0x03)
                return quint8(request.at(1)) == 0x06 ? request : withCrc(request.left(6));
            const int address = (quint8(request.at(2)) << 8) | quint8(request.at(3));
            const int count = (quint8(request.at(4)) << 8) | quint8(request.at(5));
            QByteArray answer = request.left(2);
            answer.append(char(count * 2));
            for (int i = 0; i < count; ++i) {
                answer.append(char((*regs)[address + i] >> 8));
                answer.append(char((*regs)[address + i] & 0xFF));
            }
            return withCrc(answer);
        });
        const Run r = ctl({QStringLiteral("apply"), machineA(), QStringLiteral("--yes")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("motor1.speed: wrote 300 but the controller "
                                               "holds 450")),
                 qPrintable(r.err));
    }

    void silentDeviceIsALinkErrorForDiff()
    {
        device->setResponder({});
        const Run r = ctl({QStringLiteral("diff"), machineA()});
        QCOMPARE(r.exitCode, 3); // 1 means "different" for diff
    }

    void missingPortIsALinkErrorForDiff()
    {
        const Run r =
            ctl({QStringLiteral("--port"), file("no-such-tty"), QStringLiteral("diff"), machineA()},
                {}, false);
        QCOMPARE(r.exitCode, 3); // not 1, which would read as "different"
        QVERIFY2(r.err.contains(QStringLiteral("does not exist")), qPrintable(r.err));
    }

    void reportWritesPdfAndHtml()
    {
        const Run pdf = ctl({QStringLiteral("report"), file("r.pdf"), QStringLiteral("--notes"),
                             QStringLiteral("cabinet 2")});
        QVERIFY2(pdf.exitCode == 0, qPrintable(pdf.err));
        QFile f(file("r.pdf"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.read(5) == "%PDF-");
        QVERIFY(f.size() > 20000);
        const Run html = ctl({QStringLiteral("report"), file("r.html")});
        QCOMPARE(html.exitCode, 0);
        QFile h(file("r.html"));
        QVERIFY(h.open(QIODevice::ReadOnly));
        const QByteArray text = h.readAll();
        QVERIFY(text.contains("motor2.step_angle"));
        QVERIFY(text.contains("40213 · 0x00D4"));
        QCOMPARE(writeFrames(device->requests()).size(), 0);
        const Run zh = ctl({QStringLiteral("report"), file("r-zh.html"), QStringLiteral("--lang"),
                            QStringLiteral("zh_CN")});
        QVERIFY2(zh.exitCode == 0, qPrintable(zh.err));
        QFile z(file("r-zh.html"));
        QVERIFY(z.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(z.readAll()).contains(QStringLiteral("步距角")));
        QCOMPARE(ctl({QStringLiteral("report"), file("x.pdf"), QStringLiteral("--lang"),
                      QStringLiteral("fr")})
                     .exitCode,
                 2);
        const Run bad = ctl({QStringLiteral("report"), file("r.docx")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.contains(QStringLiteral(".pdf or .html")));
    }

    void diffTwoFilesNeedsNoController()
    {
        Profile b = *ProfileFile::load(machineA(), RegisterMap::builtin()).profile;
        b.values[QStringLiteral("motor1.speed")] = 450;
        b.values[QStringLiteral("arc.direction")] = 0;
        QCOMPARE(ProfileFile::save(file("b.json"), b, RegisterMap::builtin()), QString());
        const Run r = ctl({QStringLiteral("diff"), machineA(), file("b.json")}, {}, false);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QStringLiteral("differ (A -> B):\n"
                                               "  motor1.speed: 300 rpm -> 450 rpm\n"
                                               "  arc.direction: 1 (Counter-clockwise) -> 0 "
                                               "(Clockwise)\n")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("A = machine-a.json: \"Machine A\", register map "
                                              "stepper2/1")));
        QVERIFY(r.out.contains(QStringLiteral("2 differ, 0 only in A, 0 only in B, 0 outside "
                                              "this map")));

        const Run same = ctl({QStringLiteral("diff"), machineA(), machineA()}, {}, false);
        QCOMPARE(same.exitCode, 0);
        QVERIFY(same.out.contains(QStringLiteral("the two profiles hold the same values")));

        const QString corpus = sourcePath(QStringLiteral("tests/core/profile/corpus/"));
        const Run bad = ctl(
            {QStringLiteral("diff"), corpus + "truncated.json", corpus + "empty.json"}, {}, false);
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(QStringLiteral("truncated.json: not valid JSON")) &&
                     bad.err.contains(QStringLiteral("empty.json: the file is empty")) &&
                     bad.err.contains(QStringLiteral("nothing was compared")),
                 qPrintable(bad.err));
        QCOMPARE(
            ctl({QStringLiteral("diff"), machineA(), machineA(), machineA()}, {}, false).exitCode,
            2);
        QVERIFY(device->takeEverythingSent());
        QCOMPARE(device->requests().size(), 0); // no controller was asked
    }

    void diffTwoFilesAcrossVariants()
    {
        const Run r = ctl({QStringLiteral("diff"), threeAxes(), liteFirmware()}, {}, false);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QStringLiteral("only in A (three.json):\n"
                                               "  motor1.home_input = 2 (IN2)\n")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("  line.end_x = 20.00 mm\n")));
        QVERIFY(r.out.contains(QStringLiteral("register map stepper2-lite/1")));
        QVERIFY(r.out.contains(
            QStringLiteral("  motor1.speed: 4500 -> 300  (motor1.speed: 4500 is out of range "
                           "(1 .. 3000 rpm))\n")));
        QVERIFY(r.out.contains(QStringLiteral(
            "  motor3.speed: 900 -> (none)  (not in register map \"stepper2/1\")\n")));
        QVERIFY2(r.out.contains(QStringLiteral("0 differ, 8 only in A, 0 only in B, 2 outside "
                                               "this map")),
                 qPrintable(r.out));
        QCOMPARE(ctl({QStringLiteral("diff"), threeAxes(), threeAxes()}, {}, false).exitCode, 0);
    }

    void diffWithAVariantListsWhatIsLeftOut()
    {
        device->registers[15] = 100; // motor2.speed
        const Run r = ctl({QStringLiteral("diff"), threeAxes()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.out.contains(QStringLiteral("motor2.speed: 100 rpm -> 300 rpm\n"
                                               "the profile was made with register map "
                                               "\"stepper3/1\"; this map is \"stepper2/1\"")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("left out of the comparison:\n")));
        QVERIFY(r.out.contains(QStringLiteral("  unknown to this map: motor3.speed = 900 (not in "
                                              "register map \"stepper2/1\")\n")));
        QVERIFY(r.out.contains(QStringLiteral("  cannot be applied: motor1.speed: 4500 is out of "
                                              "range (1 .. 3000 rpm)\n")));
        QVERIFY(r.out.contains(QStringLiteral("1 value differs")));

        device->registers[15] = 300;
        const Run lite = ctl({QStringLiteral("diff"), liteFirmware()});
        QCOMPARE(lite.exitCode, 1); // a comparison that left values out is not "the same"
        QVERIFY2(
            lite.out.contains(QStringLiteral("  not in the profile: line.speed (Line speed)\n")),
            qPrintable(lite.out));
        QVERIFY(lite.out.contains(
            QStringLiteral("the controller holds every value both maps have; 8 left out")));
        QCOMPARE(writeFrames(device->requests()).size(), 0);
    }

    void applyAVariantSaysWhatIsNotApplied_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QByteArray>("answer");
        QTest::addColumn<int>("exitCode");
        QTest::newRow("--yes") << QStringList{QStringLiteral("--yes")} << QByteArray() << 0;
        QTest::newRow("asked, yes") << QStringList() << QByteArray("y\n") << 0;
        QTest::newRow("asked, no") << QStringList() << QByteArray("n\n") << 2;
    }
    void applyAVariantSaysWhatIsNotApplied()
    {
        QFETCH(QStringList, options);
        QFETCH(QByteArray, answer);
        QFETCH(int, exitCode);
        device->registers[5] = 450;  // motor1.speed: in the lite profile
        device->registers[210] = 60; // line.speed: the lite firmware has none
        device->registers[82] = 0;   // motor1.home_input: neither
        const Run r = ctl(QStringList{QStringLiteral("apply"), liteFirmware()} + options, answer);
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.out.contains(QStringLiteral("will write motor1.speed: 450 rpm -> 300 rpm\n"
                                               "the profile was made with register map "
                                               "\"stepper2-lite/1\"")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("not applied:\n")));
        QVERIFY(r.out.contains(QStringLiteral("  not in the profile: motor1.home_input (Motor 1 "
                                              "home input)\n")));
        QVERIFY(r.out.contains(QStringLiteral("  not in the profile: line.speed (Line speed)\n")));
        // The list comes before the question, never after it.
        if (options.isEmpty())
            QVERIFY(r.out.indexOf(QStringLiteral("not applied:")) <
                    r.out.indexOf(QStringLiteral("Write 1 value to the controller? [y/N]")));
        const QList<QByteArray> frames = writeFrames(device->requests());
        QCOMPARE(frames, exitCode == 0 ? QList<QByteArray>{withCrc(fromHex("01 06 00 05 01 2C"))}
                                       : QList<QByteArray>{});
        QCOMPARE(device->registers[210], quint16(60));
        QCOMPARE(device->registers[82], quint16(0));
    }

    void applyNeedsASharedSetting()
    {
        QFile f(file("alien.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "stepcom-profile", "schema": 1,
                    "map": {"id": "spindle1", "version": 3}, "metadata": {},
                    "values": {"spindle.rpm": 12000}})");
        f.close();
        const Run r = ctl({QStringLiteral("apply"), f.fileName(), QStringLiteral("--yes")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.out.contains(QStringLiteral("unknown to this map: spindle.rpm = 12000")),
                 qPrintable(r.out));
        QVERIFY(r.err.contains(QStringLiteral("holds no setting of this map")));
        QVERIFY(device->takeEverythingSent());
        QCOMPARE(device->requests().size(), 0);
    }

    void reportFromAFileNeedsNoController()
    {
        const Run html =
            ctl({QStringLiteral("report"), QStringLiteral("--from"), machineA(), file("from.html")},
                {}, false);
        QVERIFY2(html.exitCode == 0, qPrintable(html.err));
        QVERIFY(html.out.contains(QStringLiteral("made from the profile file")));
        QFile h(file("from.html"));
        QVERIFY(h.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(h.readAll());
        QVERIFY(text.contains(QStringLiteral("Commissioning report (from a profile file)")));
        QVERIFY(text.contains(QStringLiteral("Made from the profile file machine-a.json")));
        QVERIFY(text.contains(QStringLiteral("XY table, lead screws 5 mm"))); // the file's notes

        const Run zh = ctl({QStringLiteral("report"), QStringLiteral("--from"), threeAxes(),
                            file("from-zh.pdf"), QStringLiteral("--lang"), QStringLiteral("zh_CN")},
                           {}, false);
        QVERIFY2(zh.exitCode == 0, qPrintable(zh.err));
        QVERIFY2(zh.out.contains(QStringLiteral("此寄存器表中没有：motor3.speed = 900")),
                 qPrintable(zh.out));
        QFile z(file("from-zh.pdf"));
        QVERIFY(z.open(QIODevice::ReadOnly));
        QVERIFY(z.read(5) == "%PDF-");

        const QString corpus = sourcePath(QStringLiteral("tests/core/profile/corpus/"));
        const Run bad = ctl({QStringLiteral("report"), QStringLiteral("--from"),
                             corpus + "missing-key.json", file("bad.pdf")},
                            {}, false);
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains(QStringLiteral("missing \"motor2.pitch\"")) &&
                     bad.err.contains(QStringLiteral("no report")),
                 qPrintable(bad.err));
        QVERIFY(!QFile::exists(file("bad.pdf")));
        QVERIFY(device->takeEverythingSent());
        QCOMPARE(device->requests().size(), 0);
    }

    void helpListsTheProfileCommands()
    {
        const Run r = ctl({QStringLiteral("--help")}, {}, false);
        QCOMPARE(r.exitCode, 0);
        for (const char *s :
             {"dump FILE|FOLDER/", "diff FILE", "diff A.json B.json", "apply FILE",
              "report FILE.pdf|.html", "--include-link", "--notes", "--from PROFILE"})
            QVERIFY2(r.out.contains(QLatin1String(s)), s);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlProfile, Guiless)
#include "tst_ctlprofile.moc"

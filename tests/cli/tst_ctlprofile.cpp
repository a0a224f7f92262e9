#include "map/registermap.h"
#include "profile/profilefile.h"
#include "programrun.h"
#include "scripteddevice.h"
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
        return sourcePath(QStringLiteral("tests/profile/data/machine-a.json"));
    }

private Q_SLOTS:
    void init()
    {
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
        const QString corpus = sourcePath(QStringLiteral("tests/profile/corpus/"));
        QTest::newRow("diff unknown key") << "diff" << corpus + "unknown-key.json"
                                          << "unknown parameter \"motor3.speed\"";
        QTest::newRow("apply other map") << "apply" << corpus + "other-map.json"
                                         << "register map \"stepper5\"";
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
        QTest::qWait(50);
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

    void helpListsTheProfileCommands()
    {
        const Run r = ctl({QStringLiteral("--help")}, {}, false);
        QCOMPARE(r.exitCode, 0);
        for (const char *s : {"dump FILE", "diff FILE", "apply FILE", "report FILE.pdf|.html",
                              "--include-link", "--notes"})
            QVERIFY2(r.out.contains(QLatin1String(s)), s);
    }
};

QTEST_GUILESS_MAIN(TestCtlProfile)
#include "tst_ctlprofile.moc"

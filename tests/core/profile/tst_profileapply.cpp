#include "bus/modbuslink.h"
#include "device/deviceclient.h"
#include "profile/profilediff.h"
#include "profile/profilefile.h"
#include "scripteddevice.h"
#include "testmaps.h"
#include "testpaths.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

// One fake controller (a register device on a pty bridge) with a link and a client to it.
struct Bench
{
    ScriptedDevice device;
    ModbusLink link;
    std::unique_ptr<DeviceClient> client;
};

// The write requests (FC06/FC10) among everything the device saw.
QList<QByteArray> writeFrames(const QList<QByteArray> &requests)
{
    QList<QByteArray> out;
    for (const QByteArray &r : requests) {
        const int fc = quint8(r.at(1));
        if (fc == 0x06 || fc == 0x10)
            out << r;
    }
    return out;
}

} // namespace

// Device -> file -> device, the diff against a controller, and applying only a chosen subset.
class TestProfileApply : public QObject
{
    Q_OBJECT
    const RegisterMap &map = RegisterMap::builtin();

    std::unique_ptr<Bench> open()
    {
        auto b = std::make_unique<Bench>();
        QString error;
        if (!b->device.open(&error))
            qFatal("%s", qPrintable(error));
        b->device.useRegisterDevice();
        LinkSettings s;
        s.portName = b->device.clientPath();
        // No retry, so a slow answer must not count as none: on a loaded machine the scripted
        // device's answers have come 0.4 s late. What is tested is the round trip, not timing.
        s.timeoutMs = 2000;
        s.retries = 0;
        QSignalSpy opened(&b->link, &ModbusLink::opened);
        b->link.open(s);
        if (!QTest::qWaitFor([&] { return opened.size() == 1; }, 5000) ||
            !opened.at(0).at(0).toBool())
            qFatal("link did not open");
        b->link.setQuietTimeMs(20);
        b->client = std::make_unique<DeviceClient>(&b->link, map);
        return b;
    }
    Profile machineA() const
    {
        QFile f(sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json")));
        if (!f.open(QIODevice::ReadOnly))
            qFatal("no machine-a.json");
        return *ProfileFile::parse(f.readAll(), map).profile;
    }
    void load(ScriptedDevice &device, const Profile &p) const
    {
        for (auto it = p.values.cbegin(); it != p.values.cend(); ++it) {
            const Parameter *param = map.find(it.key());
            const QVector<quint16> words = param->encode(it.value());
            for (int i = 0; i < words.size(); ++i)
                device.registers[param->address + i] = words.at(i);
        }
    }
    static ReadOutcome readProfileParameters(DeviceClient &client, const RegisterMap &map)
    {
        ReadOutcome out;
        bool done = false;
        client.read(Profile::profileParameters(map, true), Priority::Read,
                    [&](const ReadOutcome &r) {
                        out = r;
                        done = true;
                    });
        if (!QTest::qWaitFor([&] { return done; }, 10000))
            out.errors << QStringLiteral("test: the read never finished");
        return out;
    }
    static WriteOutcome write(DeviceClient &client, const QList<ParameterWrite> &writes)
    {
        WriteOutcome out;
        bool done = false;
        client.write(writes, [&](const WriteOutcome &w) {
            out = w;
            done = true;
        });
        if (!QTest::qWaitFor([&] { return done; }, 10000))
            out.errors << QStringLiteral("test: the write never finished");
        return out;
    }

private Q_SLOTS:
    void roundTripDeviceFileDevice()
    {
        auto a = open();
        Profile original = machineA();
        original.values[QStringLiteral("arc.start_x")] = -2550; // a negative 32-bit value
        original.values[QStringLiteral("motor2.move_distance")] = 7000000;
        load(a->device, original);
        a->device.registers[211] = 1; // device.id
        a->device.registers[212] = 9600;

        const ReadOutcome read = readProfileParameters(*a->client, map);
        QVERIFY2(read.ok, qPrintable(read.errors.join(QLatin1Char('\n'))));
        Profile saved = Profile::fromValues(map, read.values, false);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.json"));
        QCOMPARE(ProfileFile::save(path, saved, map), QString());

        const ProfileParseResult loaded = ProfileFile::load(path, map);
        QVERIFY2(loaded.ok(), qPrintable(loaded.errors.join(QLatin1Char('\n'))));
        QCOMPARE(loaded.profile->values, original.values);

        auto b = open(); // the next machine: every register 0
        const ReadOutcome before = readProfileParameters(*b->client, map);
        QVERIFY(before.ok);
        QStringList keys;
        for (const ProfileDifference &d :
             ProfileDiff::differences(ProfileDiff::compare(map, *loaded.profile, before.values)))
            keys << d.parameter->key;
        QStringList errors;
        const auto writes = ProfileDiff::writesFor(map, *loaded.profile, keys, false, &errors);
        QVERIFY(errors.isEmpty());
        const WriteOutcome w = write(*b->client, writes);
        QVERIFY2(w.ok, qPrintable(w.errors.join(QLatin1Char('\n'))));
        for (const Parameter *p : Profile::profileParameters(map, false)) {
            for (int i = 0; i < p->words; ++i)
                QCOMPARE(b->device.registers[p->address + i], a->device.registers[p->address + i]);
        }
        QCOMPARE(b->device.registers[211], quint16(0)); // link settings were not part of it
        // Only what differed went out, as planned: fewer requests than values.
        const auto frames = writeFrames(b->device.requests());
        QCOMPARE(frames.size(), WritePlanner::plan(writes, map.maxRegistersPerRequest()).size());
        QVERIFY(frames.size() < writes.size());
    }

    void applyingASubsetWritesOnlyThoseRegisters()
    {
        auto b = open();
        const Profile profile = machineA();
        load(b->device, profile);
        // The controller differs in four places; only three are chosen.
        b->device.registers[5] = 450;  // motor1.speed
        b->device.registers[6] = 100;  // motor1.pitch, low word (1.00)
        b->device.registers[8] = 1;    // motor1.move_distance, low word
        b->device.registers[200] = 60; // arc.speed: differs, not chosen
        const ReadOutcome read = readProfileParameters(*b->client, map);
        const auto diffs =
            ProfileDiff::differences(ProfileDiff::compare(map, profile, read.values));
        QStringList differing;
        for (const ProfileDifference &d : diffs)
            differing << d.parameter->key;
        QCOMPARE(differing, (QStringList{"motor1.speed", "motor1.pitch", "motor1.move_distance",
                                         "arc.speed"}));
        const qsizetype requestsBefore = b->device.requests().size();
        QStringList errors;
        const auto writes = ProfileDiff::writesFor(
            map, profile, {"motor1.speed", "motor1.pitch", "motor1.move_distance"}, false, &errors);
        const WriteOutcome w = write(*b->client, writes);
        QVERIFY2(w.ok, qPrintable(w.errors.join(QLatin1Char('\n'))));
        const QList<QByteArray> frames = writeFrames(b->device.requests().mid(requestsBefore));
        // Registers 0x0005..0x0009 follow each other: one FC10, the 32-bit values whole.
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames.at(0),
                 withCrc(fromHex("01 10 00 05 00 05 0A 01 2C 01 F4 00 00 03 E8 00 00")));
        QCOMPARE(b->device.registers[200], quint16(60)); // the unchosen row stays
        QCOMPARE(b->device.registers[5], quint16(300));
        // Verified by reading back.
        QCOMPARE(quint8(b->device.requests().last().at(1)), quint8(0x03));
    }

    void verificationCatchesADeviceThatIgnoresAWrite()
    {
        auto b = open();
        const Profile profile = machineA();
        load(b->device, profile);
        b->device.registers[5] = 450;
        b->device.registers[200] = 60;
        ScriptedDevice *device = &b->device;
        // Acknowledges every write but keeps arc.speed (register 200) as it was: a firmware
        // that silently ignores one register.
        QList<quint16> *regs = &device->registers;
        device->setResponder([regs](const QByteArray &request, int) -> std::optional<QByteArray> {
            auto word = [&](int at) {
                return int((quint8(request.at(at)) << 8) | quint8(request.at(at + 1)));
            };
            const int fc = quint8(request.at(1));
            const int address = word(2);
            if (fc == 0x06) {
                if (address != 200)
                    (*regs)[address] = quint16(word(4));
                return request;
            }
            if (fc == 0x10) {
                for (int i = 0; i < word(4); ++i)
                    if (address + i != 200)
                        (*regs)[address + i] = quint16(word(7 + 2 * i));
                return withCrc(request.left(6));
            }
            QByteArray answer = request.left(2);
            answer.append(char(word(4) * 2));
            for (int i = 0; i < word(4); ++i) {
                answer.append(char((*regs)[address + i] >> 8));
                answer.append(char((*regs)[address + i] & 0xFF));
            }
            return withCrc(answer);
        });
        QStringList errors;
        const auto writes =
            ProfileDiff::writesFor(map, profile, {"motor1.speed", "arc.speed"}, false, &errors);
        const WriteOutcome w = write(*b->client, writes);
        QVERIFY(!w.ok);
        QCOMPARE(w.mismatches.size(), 1);
        QCOMPARE(w.mismatches.at(0).key, QStringLiteral("arc.speed"));
        QCOMPARE(w.mismatches.at(0).got.value_or(-1), 60);
        QVERIFY2(w.errors.join(QLatin1Char('\n'))
                     .contains(QStringLiteral("arc.speed: wrote 100 but the controller holds 60")),
                 qPrintable(w.errors.join(QLatin1Char('\n'))));
        QCOMPARE(device->registers[5], quint16(300)); // the honest one went through
    }

    // A profile of another map: only the settings both maps have, within this map's ranges,
    // are written; what differs only in what the profile lacks or this map cannot take stays.
    void variantProfilesWriteOnlyTheSharedSettings_data()
    {
        QTest::addColumn<QString>("variant");
        QTest::addColumn<QStringList>("written");
        QTest::addColumn<QList<QByteArray>>("frames");
        // motor1.speed is 4500 in the three-axis profile (out of range here); the lite
        // firmware's profile has no home inputs and no line.
        QTest::newRow("three axes")
            << "stepper3" << QStringList{"motor2.speed", "motor1.home_input", "line.speed"}
            << QList<QByteArray>{withCrc(fromHex("01 06 00 0F 01 2C")),
                                 withCrc(fromHex("01 06 00 52 00 02")),
                                 withCrc(fromHex("01 06 00 D2 00 C8"))};
        QTest::newRow("lite firmware")
            << "stepper2-lite" << QStringList{"motor1.speed", "motor2.speed"}
            << QList<QByteArray>{withCrc(fromHex("01 06 00 05 01 2C")),
                                 withCrc(fromHex("01 06 00 0F 01 2C"))};
    }
    void variantProfilesWriteOnlyTheSharedSettings()
    {
        QFETCH(QString, variant);
        QFETCH(QStringList, written);
        QFETCH(QList<QByteArray>, frames);
        QStringList errors;
        const auto other =
            variant == QLatin1String("stepper3") ? threeAxisMap(&errors) : liteVariantMap(&errors);
        QVERIFY2(other, qPrintable(errors.join(QLatin1Char('\n'))));
        const Profile a = machineA();
        QHash<QString, qint64> values;
        for (auto it = a.values.cbegin(); it != a.values.cend(); ++it)
            values.insert(it.key(), it.value());
        values.insert(QStringLiteral("motor3.speed"), 900);
        if (variant == QLatin1String("stepper3"))
            values[QStringLiteral("motor1.speed")] = 4500;
        const ProfileParseResult parsed =
            ProfileFile::parse(profileSavedWith(*other, values, QStringLiteral("B")), map,
                               ProfileFile::OtherMaps::Accept);
        QVERIFY2(parsed.ok(), qPrintable(parsed.errors.join(QLatin1Char('\n'))));
        const Profile &profile = *parsed.profile;

        auto b = open();
        load(b->device, a);
        b->device.registers[5] = 450;  // motor1.speed
        b->device.registers[15] = 100; // motor2.speed
        b->device.registers[82] = 0;   // motor1.home_input
        b->device.registers[210] = 60; // line.speed
        const ReadOutcome read = readProfileParameters(*b->client, map);
        QVERIFY(read.ok);
        QStringList keys;
        for (const ProfileDifference &d :
             ProfileDiff::differences(ProfileDiff::compare(map, profile, read.values)))
            keys << d.parameter->key;
        QCOMPARE(keys, written);
        const qsizetype before = b->device.requests().size();
        const auto writes = ProfileDiff::writesFor(map, profile, keys, false, &errors);
        QVERIFY(errors.isEmpty());
        const WriteOutcome w = write(*b->client, writes);
        QVERIFY2(w.ok, qPrintable(w.errors.join(QLatin1Char('\n'))));
        QCOMPARE(writeFrames(b->device.requests().mid(before)), frames);
        // What the profile could not give stays as the controller held it.
        if (!written.contains(QStringLiteral("motor1.speed")))
            QCOMPARE(b->device.registers[5], quint16(450));
        if (!written.contains(QStringLiteral("line.speed")))
            QCOMPARE(b->device.registers[210], quint16(60));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProfileApply, Guiless)
#include "tst_profileapply.moc"

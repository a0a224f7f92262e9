#include "commissioning/checklistfile.h"
#include "i18n/translators.h"
#include "profile/profilefile.h"
#include "profile/settingsfingerprint.h"
#include "report/commissioningreport.h"
#include "testpaths.h"

#include <QFile>
#include <QGuiApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;
using namespace stepcom::test;

namespace {

const QDateTime kCertT0(QDate(2024, 6, 1), QTime(9, 30), Qt::UTC);

QByteArray machineABytes()
{
    QFile f(sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json")));
    if (!f.open(QIODevice::ReadOnly))
        qFatal("no machine-a.json");
    return f.readAll();
}

Profile certMachineA()
{
    return *ProfileFile::parse(machineABytes(), RegisterMap::builtin()).profile;
}

// A checklist run on machine A: passes with measurements, a failure repeated into a pass, a skip.
Checklist checklist()
{
    Checklist c = Checklist::forMap(RegisterMap::builtin());
    c.machine = QStringLiteral("Machine A");
    c.record("motor1.direction", StepResult::Passed, {{"moved_toward_plus", "yes", {}}}, {},
             kCertT0);
    c.record("motor1.calibration", StepResult::Failed, {{"measured", "97.00", "mm"}}, "slipped",
             kCertT0);
    c.record(
        "motor1.calibration", StepResult::Passed,
        {{"commanded", "100.00", "mm"}, {"measured", "99.20", "mm"}, {"pitch_after", "4.96", "mm"}},
        "dial gauge <0.01>", kCertT0.addSecs(60));
    c.record("motor1.limit_negative", StepResult::Passed,
             {{"input_configured", "IN2", {}},
              {"input_answered", "IN1", {}},
              {"fix", "motor1.limit_negative = IN1", {}}},
             {}, kCertT0.addSecs(120));
    c.record("machine.interpolation", StepResult::Skipped, {}, "no arc on this machine",
             kCertT0.addSecs(180));
    return c;
}

QString pdfText(const QString &path)
{
    QProcess p;
    p.start(QStringLiteral("pdftotext"),
            {QStringLiteral("-enc"), QStringLiteral("UTF-8"), path, QStringLiteral("-")});
    if (!p.waitForFinished(20000))
        return {};
    return QString::fromUtf8(p.readAllStandardOutput()).normalized(QString::NormalizationForm_KC);
}

} // namespace

// The certificate: the report with the checklist, the fingerprint, limits and signatures.
class TestCertificate : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

    ReportInput input(const QString &locale) const
    {
        ReportInput in = ReportInput::fromProfile(RegisterMap::builtin(), certMachineA(),
                                                  "machine-a.json", locale);
        in.checklist = checklist();
        in.checklistFile = "machine-a.checklist.json";
        in.date = QDateTime(QDate(2024, 6, 1), QTime(12, 0));
        TravelLimits limits;
        limits.setAxis(RegisterMap::builtin(), 1, 0.0, 200.0);
        in.travelLimits = limits;
        return in;
    }

private Q_SLOTS:
    void fingerprintIsStable()
    {
        const RegisterMap &map = RegisterMap::builtin();
        const Profile a = certMachineA();
        // The same values with the keys in reverse order in the file.
        QJsonObject o = QJsonDocument::fromJson(machineABytes()).object();
        const QJsonObject values = o.value("values").toObject();
        QByteArray reversed = "{";
        const QStringList keys = values.keys();
        for (auto it = keys.crbegin(); it != keys.crend(); ++it)
            reversed += "\"" + it->toUtf8() +
                        "\": " + QByteArray::number(values.value(*it).toDouble()) + ",";
        reversed.chop(1);
        reversed += "}";
        QByteArray bytes = machineABytes();
        const qsizetype at = bytes.indexOf("\"values\"");
        QVERIFY(at > 0);
        bytes = bytes.left(at) + "\"values\": " + reversed + "\n}\n";
        const auto b = ProfileFile::parse(bytes, map);
        QVERIFY2(b.ok(), qPrintable(b.errors.join('\n')));
        QCOMPARE(SettingsFingerprint::hash(map, b.profile->values),
                 SettingsFingerprint::hash(map, a.values));

        QVERIFY(SettingsFingerprint::canonicalText(map, a.values)
                    .startsWith("stepcom-settings 1\nmap=stepper2/1\narc.center_x="));
        QVERIFY(SettingsFingerprint::canonicalText(map, a.values)
                    .contains("\nmotor1.step_angle=1.80\n"));
        const QString line = SettingsFingerprint::line(map, a.values);
        QVERIFY2(QRegularExpression(
                     "^stepper2/1 · 44 · [0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}$")
                     .match(line)
                     .hasMatch(),
                 qPrintable(line));
        // Any value changes it; the link (id, baud) and status values do not.
        QMap<QString, qint64> changed = a.values;
        changed["motor2.speed"] += 1;
        QVERIFY(SettingsFingerprint::hash(map, changed) !=
                SettingsFingerprint::hash(map, a.values));
        QMap<QString, qint64> link = a.values;
        link["device.id"] = 7;
        link["motor1.position"] = 99;
        QCOMPARE(SettingsFingerprint::hash(map, link), SettingsFingerprint::hash(map, a.values));
    }

    void certificateInEnglish()
    {
        const ReportInput in = input(QString());
        const QString html = CommissioningReport(in).html("x.png");
        for (const char *s :
             {"Commissioning checklist", "Motor 1: travel calibration", "Passed (attempt 2)",
              "Commanded distance: 100.00 mm; Measured distance: 99.20 mm; Pitch after: 4.96 mm",
              "dial gauge &lt;0.01&gt;", "Input that answered: IN1",
              "Fix written: motor1.limit_negative = IN1", "Machine: interpolation test",
              "no arc on this machine", "Not run", "Settings fingerprint", "Software travel limits",
              "200.00 mm", "Commissioned by", "Accepted by (customer)",
              "Checklist file: machine-a.checklist.json"})
            QVERIFY2(html.contains(QString::fromUtf8(s)), s);
        // The failure was repeated into a pass: the latest attempt counts.
        QVERIFY(html.contains("In progress: not every step was run"));
        QVERIFY(html.contains("3 of 20 steps passed, 0 failed, 1 skipped, 16 not run"));
        QVERIFY(html.contains(
            SettingsFingerprint::line(in.map, SettingsFingerprint::ordered(in.values))));

        const QString path = dir.filePath("certificate.pdf");
        QCOMPARE(CommissioningReport(in).write(path), QString());
        if (QStandardPaths::findExecutable("pdftotext").isEmpty())
            QSKIP("pdftotext (poppler-utils) is not installed: the PDF text was not checked");
        // Table cells wrap in the PDF: compare with the line breaks as spaces.
        const QString text = pdfText(path).simplified();
        for (const char *s : {"Commissioning checklist", "Motor 1: travel calibration", "99.20 mm",
                              "Passed (attempt 2)", "Settings fingerprint", "Commissioned by",
                              "Accepted by (customer)", "Software travel limits"})
            QVERIFY2(text.contains(QString::fromUtf8(s)),
                     qPrintable(QString::fromUtf8(s) + "\n" + text));
        QVERIFY(text.contains(
            SettingsFingerprint::shortHash(in.map, SettingsFingerprint::ordered(in.values))));
    }

    void certificateInChinese()
    {
        Translators translators;
        QVERIFY(translators.install("zh_CN"));
        const ReportInput in = input("zh_CN");
        const QString html = CommissioningReport(in).html("x.png");
        const QStringList expected{
            "调试检查表", "电机 1：行程校准", "通过（第 2 次）", "指令距离：100.00 mm",
            "设置指纹",   "软件行程限位",     "调试人",          "验收人（客户）"};
        for (const QString &s : expected)
            QVERIFY2(html.contains(s), qPrintable(s));
        const QString path = dir.filePath("certificate-zh.pdf");
        QCOMPARE(CommissioningReport(in).write(path), QString());
        translators.uninstall();
        if (QStandardPaths::findExecutable("pdftotext").isEmpty())
            QSKIP("pdftotext (poppler-utils) is not installed: the PDF text was not checked");
        // Cells wrap anywhere in Chinese: compare without any white space.
        const QRegularExpression space(QStringLiteral("\\s"));
        const QString text = pdfText(path).remove(space);
        // Short texts only: a long cell's lines interleave with its neighbours' in the text.
        for (const char *s :
             {"调试检查表", "电机 1：行程校准", "设置指纹", "软件行程限位", "调试人", "验收人"}) {
            const QString want =
                QString::fromUtf8(s).normalized(QString::NormalizationForm_KC).remove(space);
            QVERIFY2(text.contains(want), qPrintable(want + "\n" + text.left(3000)));
        }
    }

    void withoutAChecklistItSaysSo()
    {
        ReportInput in = input(QString());
        in.checklist.reset();
        const QString html = CommissioningReport(in).html("x.png");
        QVERIFY(html.contains("No commissioning checklist was recorded for this machine"));
    }

    void staleChecklistIsNamed()
    {
        ReportInput in = input(QString());
        in.checklist->settingsFingerprint = "0000-0000-0000-0000";
        const QString html = CommissioningReport(in).html("x.png");
        QVERIFY(html.contains(
            "The checklist was last run with other settings (fingerprint 0000-0000-0000-0000)"));
    }

    void fromProfileReadsTheChecklistBesideIt()
    {
        const QString profile = dir.filePath("machine-b.json");
        QCOMPARE(ProfileFile::save(profile, certMachineA(), RegisterMap::builtin()), QString());
        ReportInput in =
            ReportInput::fromProfile(RegisterMap::builtin(), certMachineA(), profile, {});
        QVERIFY(!in.checklist && in.checklistErrors.isEmpty()); // none there
        QCOMPARE(ChecklistFile::save(ChecklistFile::pathFor(profile), checklist()), QString());
        in = ReportInput::fromProfile(RegisterMap::builtin(), certMachineA(), profile, {});
        QVERIFY(in.checklist.has_value());
        QVERIFY(*in.checklist == checklist());
        QCOMPARE(in.checklistFile, QStringLiteral("machine-b.checklist.json"));
        QFile bad(ChecklistFile::pathFor(profile));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"format\": \"stepcom-checklist\", \"schema\": 7}");
        bad.close();
        in = ReportInput::fromProfile(RegisterMap::builtin(), certMachineA(), profile, {});
        QVERIFY(!in.checklist);
        QCOMPARE(in.checklistErrors,
                 QStringList{"machine-b.checklist.json: checklist schema 7 is newer than this "
                             "StepCom reads (1): update StepCom"});
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCertificate, Gui)
#include "tst_certificate.moc"

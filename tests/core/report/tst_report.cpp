#include "i18n/translators.h"
#include "profile/profilefile.h"
#include "report/commissioningreport.h"
#include "report/xypicture.h"
#include "testmaps.h"
#include "testpaths.h"

#include <QFile>
#include <QGuiApplication>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextTable>

using namespace stepcom;
using namespace stepcom::test;

// The commissioning report renders offscreen to PDF and HTML, in English and Chinese.
class TestReport : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

    ReportInput input(const QString &locale = QString()) const
    {
        QFile f(sourcePath(QStringLiteral("tests/core/profile/data/machine-a.json")));
        if (!f.open(QIODevice::ReadOnly))
            qFatal("no machine-a.json");
        const Profile p = *ProfileFile::parse(f.readAll(), RegisterMap::builtin()).profile;
        ReportInput in;
        in.map = RegisterMap::builtin();
        for (auto it = p.values.cbegin(); it != p.values.cend(); ++it)
            in.values.insert(it.key(), it.value());
        in.values.insert(QStringLiteral("device.id"), 3);
        in.values.insert(QStringLiteral("device.baud"), 19200);
        in.values.insert(QStringLiteral("motor1.position"), -250);
        in.values[QStringLiteral("arc.enabled")] = 1;
        in.link = QStringLiteral("/dev/ttyUSB0 · 19200 8N1 · id 3");
        in.deviceId = 3;
        in.title = QStringLiteral("Machine A");
        in.notes = QStringLiteral("Commissioned by <Li Wei> & team");
        in.date = QDateTime(QDate(2024, 6, 1), QTime(9, 30));
        in.locale = locale;
        return in;
    }
    static QString pdfText(const QString &path)
    {
        QProcess p;
        p.start(QStringLiteral("pdftotext"),
                {QStringLiteral("-enc"), QStringLiteral("UTF-8"), path, QStringLiteral("-")});
        if (!p.waitForFinished(20000))
            return {};
        // NFKC: pdftotext may name a glyph by its Kangxi radical (⾓ for 角); same glyph.
        return QString::fromUtf8(p.readAllStandardOutput())
            .normalized(QString::NormalizationForm_KC);
    }
    static bool havePdfToText()
    {
        return !QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty();
    }

private Q_SLOTS:
    void pdfRendersOffscreen()
    {
        const QString path = dir.filePath(QStringLiteral("report.pdf"));
        QCOMPARE(CommissioningReport(input()).write(path), QString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        QVERIFY(bytes.startsWith("%PDF-"));
        QVERIFY(bytes.size() > 20000); // text, tables and the picture
        if (!havePdfToText())
            QSKIP("pdftotext (poppler-utils) is not installed: the text was not checked");
        const QString text = pdfText(path);
        for (const char *s : {"Commissioning report", "Machine A", "motor1.step_angle",
                              "40001 · 0x0000", "1.80", "IN1", "Motor 1", "Counter-clockwise",
                              "/dev/ttyUSB0", "19200", "Li Wei", "Homing order"})
            QVERIFY2(text.contains(QString::fromUtf8(s)), s);
    }

    void chinesePdfCarriesTheGlyphs()
    {
        const QString path = dir.filePath(QStringLiteral("report-zh.pdf"));
        QCOMPARE(CommissioningReport(input(QStringLiteral("zh_CN"))).write(path), QString());
        if (!havePdfToText())
            QSKIP("pdftotext (poppler-utils) is not installed");
        const QString text = pdfText(path);
        // Map labels in Chinese: the PDF holds real CJK glyphs, not empty boxes.
        // (步距角 is not checked: readers map its 角 glyph back to the radical ⻆, same shape.)
        for (const char *s : {"细分", "加减频率", "逆圆弧", "两轴步进电机控制器 (stepper2/1)"})
            QVERIFY2(text.contains(QString::fromUtf8(s)), qPrintable(text.left(2000)));
    }

    void htmlHoldsEveryParameterAndThePicture()
    {
        const QString path = dir.filePath(QStringLiteral("report.html"));
        QCOMPARE(CommissioningReport(input()).write(path), QString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString html = QString::fromUtf8(f.readAll());
        for (const Parameter &p : RegisterMap::builtin().parameters()) {
            if (!p.writable())
                continue;
            QVERIFY2(html.contains(p.key), qPrintable(p.key));
            QVERIFY2(html.contains(p.registerName()), qPrintable(p.key));
        }
        QVERIFY(html.contains(QStringLiteral("<img src=\"data:image/png;base64,")));
        QVERIFY(html.contains(QStringLiteral("&lt;Li Wei&gt; &amp; team"))); // escaped
        QVERIFY(html.contains(QStringLiteral("Motor 2")));
        QVERIFY(!html.contains(QStringLiteral("Motor 0")));
    }

    void documentHasThePictureAsAResource()
    {
        const auto doc = CommissioningReport(input()).document();
        const QVariant image =
            doc->resource(QTextDocument::ImageResource, QUrl(QStringLiteral("stepcom-xy.png")));
        QVERIFY(image.canConvert<QImage>());
        QVERIFY(!image.value<QImage>().isNull());
        QVERIFY(doc->toPlainText().contains(QStringLiteral("motor2.pitch")));
    }

    // Every table with a header row marks it as one, so it is repeated on each page the
    // table runs onto; the parameter tables are among them.
    void tableHeadersRepeatOnEveryPage()
    {
        const auto doc = CommissioningReport(input()).document();
        int tables = 0;
        int withHeader = 0;
        for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
            auto *table = qobject_cast<QTextTable *>(QTextCursor(b).currentTable());
            if (!table || QTextCursor(b).position() != table->firstPosition())
                continue;
            ++tables;
            if (table->format().headerRowCount() == 1)
                ++withHeader;
        }
        QVERIFY(tables > 10);
        // Wiring, every parameter group of each motor, signatures...
        QVERIFY2(withHeader >= 8, qPrintable(QString::number(withHeader)));
    }

    // The first page is full: the long tables start on it, the picture (which cannot be split)
    // comes after them.
    void firstPageIsNotHalfEmpty()
    {
        const QString path = dir.filePath(QStringLiteral("pages.pdf"));
        QCOMPARE(CommissioningReport(input()).write(path), QString());
        if (!havePdfToText())
            QSKIP("pdftotext (poppler-utils) is not installed");
        QProcess p;
        p.start(QStringLiteral("pdftotext"),
                {QStringLiteral("-f"), QStringLiteral("1"), QStringLiteral("-l"),
                 QStringLiteral("1"), path, QStringLiteral("-")});
        QVERIFY(p.waitForFinished(20000));
        const QString first = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(first.contains(QStringLiteral("Parameters")), qPrintable(first));
        QVERIFY(first.contains(QStringLiteral("motor1.step_angle")));
    }

    void flashStateAndTimeOfTheRead_data()
    {
        QTest::addColumn<int>("saved"); // -1 unknown, 0 not saved, 1 saved
        QTest::addColumn<QString>("text");
        QTest::newRow("saved") << 1 << "saved: nothing written since connecting";
        QTest::newRow("not saved") << 0 << "NOT saved: values were written since the last save";
        QTest::newRow("unknown") << -1 << "unknown: this program did not follow the writes";
    }
    void flashStateAndTimeOfTheRead()
    {
        QFETCH(int, saved);
        QFETCH(QString, text);
        ReportInput in = input();
        in.lastRead = QDateTime(QDate(2024, 6, 1), QTime(9, 29, 41));
        if (saved >= 0)
            in.savedToFlash = saved == 1;
        const QString html = CommissioningReport(in).html(QStringLiteral("x.png"));
        QVERIFY2(html.contains(text), qPrintable(html.left(3000)));
        QVERIFY(html.contains(QStringLiteral("Values read")));
        QVERIFY(
            html.contains(QLocale().toString(in.lastRead, QLocale::LongFormat).toHtmlEscaped()));
    }

    void gridSteps_data()
    {
        QTest::addColumn<double>("span");
        QTest::addColumn<double>("step");
        QTest::newRow("100 mm") << 100.0 << 20.0;
        QTest::newRow("12 mm") << 12.0 << 2.0;
        QTest::newRow("1.1 mm") << 1.1 << 0.2;
        QTest::newRow("550 mm") << 550.0 << 100.0;
        QTest::newRow("60 mm") << 60.0 << 10.0;
    }
    void gridSteps()
    {
        QFETCH(double, span);
        QFETCH(double, step);
        QCOMPARE(XyPicture::gridStep(span), step);
    }

    void pictureDrawsTheArcAndTheLine()
    {
        const ReportInput in = input();
        const QImage image = XyPicture(in.map, in.values).render(QSize(300, 300));
        int blue = 0;
        int orange = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                blue += c.blue() > 150 && c.red() < 100 ? 1 : 0;
                orange += c.red() > 180 && c.green() > 80 && c.green() < 150 && c.blue() < 80;
            }
        }
        QVERIFY2(blue > 100, qPrintable(QString::number(blue)));
        QVERIFY2(orange > 100, qPrintable(QString::number(orange)));
    }

    void undrawableArcIsSaid()
    {
        ReportInput in = input();
        in.values[QStringLiteral("arc.mode")] = 1;       // start, end, middle point
        in.values[QStringLiteral("arc.middle_x")] = 500; // (5, 0): on the line start-end
        in.values[QStringLiteral("arc.middle_y")] = 0;
        QCOMPARE(XyPicture(in.map, in.values).arcProblem(),
                 QStringLiteral("start, middle and end point are on one line"));
        QVERIFY(CommissioningReport(in)
                    .html(QStringLiteral("x.png"))
                    .contains(QStringLiteral("The arc cannot be drawn")));
        in.values[QStringLiteral("arc.mode")] = 0;
        in.values[QStringLiteral("arc.center_x")] = 0; // the start point
        QCOMPARE(XyPicture(in.map, in.values).arcProblem(),
                 QStringLiteral("the start point is the centre"));
    }

    void badTargetsAreNamed()
    {
        const QString txt = dir.filePath(QStringLiteral("report.txt"));
        QVERIFY(CommissioningReport(input()).write(txt).contains(QStringLiteral(".pdf or .html")));
        const QString nowhere = dir.filePath(QStringLiteral("no/such/dir/r.pdf"));
        const QString e = CommissioningReport(input()).write(nowhere);
        QVERIFY2(e.contains(nowhere), qPrintable(e));
        QVERIFY(!QFile::exists(nowhere));
    }

    // Made from a profile file, not read from a controller: said in the title, under it and in
    // the controller section, in both languages; a variant's left-out values are listed.
    void reportFromAFile_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("en") << "en"
                            << QStringList{"Commissioning report (from a profile file)",
                                           "Made from the profile file machine-b.json, not "
                                           "read from a controller",
                                           "none: made from a file, not read from a controller",
                                           "the profile was made with stepper3/1",
                                           "unknown to this map: motor3.speed = 900",
                                           "Machine B",
                                           "motor2.pitch"};
        QTest::newRow("zh_CN") << "zh_CN"
                               << QStringList{"调试报告（来自参数文件）",
                                              "根据参数文件 machine-b.json 生成，未读取控制器",
                                              "无：根据文件生成，未读取控制器",
                                              "参数文件由 stepper3/1 生成",
                                              "此寄存器表中没有：motor3.speed = 900",
                                              "Machine B",
                                              "细分"};
    }
    void reportFromAFile()
    {
        QFETCH(QString, language);
        QFETCH(QStringList, expected);
        Translators translators;
        QVERIFY(translators.install(language));
        QStringList errors;
        const auto threeAxis = threeAxisMap(&errors);
        QVERIFY2(threeAxis, qPrintable(errors.join(QLatin1Char('\n'))));
        QHash<QString, qint64> values = input().values;
        values.insert(QStringLiteral("motor3.speed"), 900);
        const ProfileParseResult parsed =
            ProfileFile::parse(profileSavedWith(*threeAxis, values, QStringLiteral("Machine B")),
                               RegisterMap::builtin(), ProfileFile::OtherMaps::Accept);
        QVERIFY2(parsed.ok(), qPrintable(parsed.errors.join(QLatin1Char('\n'))));
        const ReportInput in =
            ReportInput::fromProfile(RegisterMap::builtin(), *parsed.profile,
                                     QStringLiteral("/somewhere/machine-b.json"), language);
        QVERIFY(in.fromFile());
        QVERIFY(in.link.isEmpty()); // nothing claims a link
        const QString html = CommissioningReport(in).html(QStringLiteral("x.png"));
        for (const QString &s : expected)
            QVERIFY2(html.contains(s.toHtmlEscaped()), qPrintable(s));
        QVERIFY(!html.contains(QStringLiteral("Baud rate (register)")));
        QVERIFY(html.contains(QStringLiteral("<td>19200</td>"))); // the file's metadata

        const QString path = dir.filePath(QStringLiteral("from-file-%1.pdf").arg(language));
        QCOMPARE(CommissioningReport(in).write(path), QString());
        if (!havePdfToText())
            QSKIP("pdftotext (poppler-utils) is not installed: the PDF text was not checked");
        const QString text = pdfText(path).simplified();
        // The mark that it was made from a file is in the PDF itself, not only in the HTML.
        QVERIFY2(text.contains(expected.at(0).normalized(QString::NormalizationForm_KC)),
                 qPrintable(text.left(1500)));
        QVERIFY2(text.contains(QStringLiteral("machine-b.json")), qPrintable(text.left(1500)));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReport, Gui)
#include "tst_report.moc"

// --version and --help of the three programs, and the language of their help: the same
// translators as the window (StepCom's compiled-in catalogue and Qt's qtbase one), chosen by
// --lang or by LANGUAGE / LC_ALL / LANG.
#include "programrun.h"
#include "testpaths.h"

#include <QLibraryInfo>
#include <QLocale>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>
#include <QTranslator>

using namespace stepcom::test;

namespace {

using Run = ProgramRun;

// Runs a program that only prints and exits (no device involved).
Run run(const QString &program, const QStringList &args, const QStringList &environment)
{
    ProgramOptions options;
    options.cleanLocale = true;
    options.environment = environment + QStringList{QStringLiteral("QT_QPA_PLATFORM=offscreen")};
    options.timeoutMs = 30000;
    return runProgram(program, args, options);
}

bool hasHan(const QString &text)
{
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    return han.match(text).hasMatch();
}

} // namespace

class TestProgramInfo : public QObject
{
    Q_OBJECT
    QTranslator stepcomZh;
    QTranslator qtZh;

    // What a text becomes in Chinese, from the same catalogues the programs load.
    QString zh(const char *context, const char *source) const
    {
        const QString app = stepcomZh.translate(context, source);
        if (!app.isEmpty())
            return app;
        return qtZh.translate(context, source);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(stepcomZh.load(QStringLiteral(":/i18n/stepcom_zh_CN.qm")));
        QVERIFY2(qtZh.load(QLocale(QStringLiteral("zh_CN")), QStringLiteral("qtbase"),
                           QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath)),
                 "qtbase_zh_CN.qm is missing: install qt6-translations-l10n (scripts/deps.sh)");
    }

    void version_data()
    {
        QTest::addColumn<QString>("program");
        QTest::newRow("stepcomctl") << QStringLiteral("stepcomctl");
        QTest::newRow("stepcom-sim") << QStringLiteral("stepcom-sim");
        QTest::newRow("stepcom") << QStringLiteral("stepcom");
    }
    void version()
    {
        QFETCH(QString, program);
        for (const QString &option : {QStringLiteral("--version"), QStringLiteral("-v")}) {
            const Run r = run(program, {option}, {QStringLiteral("LC_ALL=C.UTF-8")});
            QCOMPARE(r.exitCode, 0);
            QCOMPARE(r.out.trimmed(), program + QLatin1Char(' ') + QStringLiteral(STEPCOM_VERSION));
        }
    }

    // The help in English under an English or C locale: Qt's texts, the program's own options.
    void helpInEnglish_data() { version_data(); }
    void helpInEnglish()
    {
        QFETCH(QString, program);
        const Run r = run(program, {QStringLiteral("--help")}, {QStringLiteral("LANG=C.UTF-8")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("Displays help on commandline options.")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("--lang <language>")), qPrintable(r.out));
        QVERIFY2(!hasHan(r.out), qPrintable(r.out));
        // Two parts adding the same option make QCommandLineParser complain on stderr.
        QVERIFY2(!r.err.contains(QStringLiteral("QCommandLineParser")), qPrintable(r.err));
    }

    // `stepcom FILE` (a file manager's "Open with StepCom"): the help names it; a file that is
    // not there, two files, or a file with a link to connect to are answered in the terminal,
    // naming what was wrong, before any window (the window says what an existing file is).
    void stepcomTakesAFile_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("said");
        const QString missing = QStringLiteral("/nonexistent/machine.json");
        QTest::newRow("missing") << QStringList{missing}
                                 << missing + QStringLiteral(": no such file");
        QTest::newRow("two") << QStringList{missing, missing}
                             << QStringLiteral("one file at a time");
        QTest::newRow("with --sim")
            << QStringList{QStringLiteral("--sim"), sourcePath(QStringLiteral("README.md"))}
            << QStringLiteral("without --sim");
    }
    void stepcomTakesAFile()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, said);
        const Run help = run(QStringLiteral("stepcom"), {QStringLiteral("--help")},
                             {QStringLiteral("LANG=C.UTF-8")});
        QVERIFY2(help.out.contains(QStringLiteral("[FILE]")) &&
                     help.out.simplified().contains(
                         QStringLiteral("session log or support bundle to replay")),
                 qPrintable(help.out));
        const Run r = run(QStringLiteral("stepcom"), args, {QStringLiteral("LANG=C.UTF-8")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(said), qPrintable(r.err));
    }

    // The help in Chinese, however the environment or the command line asks for it.
    void helpInChinese_data()
    {
        QTest::addColumn<QString>("program");
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QStringList>("environment");
        QTest::addColumn<QString>("context"); // a text of the program's own, to find in Chinese
        QTest::addColumn<QString>("source");
        const QString ctl = QStringLiteral("stepcomctl");
        const QStringList help{QStringLiteral("--help")};
        const QString ctlContext = QStringLiteral("stepcom::CtlOptions");
        const QString ctlText =
            QStringLiteral("Use the built-in simulated controller (it keeps what it saved to flash "
                           "between runs).");
        QTest::newRow("stepcomctl LANGUAGE, C locale")
            << ctl << help
            << QStringList{QStringLiteral("LANGUAGE=zh_CN"), QStringLiteral("LC_ALL=C.UTF-8")}
            << ctlContext << ctlText;
        QTest::newRow("stepcomctl LC_ALL")
            << ctl << help << QStringList{QStringLiteral("LC_ALL=zh_CN.UTF-8")} << ctlContext
            << ctlText;
        QTest::newRow("stepcomctl LANG")
            << ctl << help << QStringList{QStringLiteral("LANG=zh_CN.UTF-8")} << ctlContext
            << ctlText;
        QTest::newRow("stepcomctl --lang")
            << ctl
            << QStringList{QStringLiteral("--lang"), QStringLiteral("zh_CN"),
                           QStringLiteral("--help")}
            << QStringList{QStringLiteral("LC_ALL=C.UTF-8")} << ctlContext << ctlText;
        QTest::newRow("stepcom-sim LANGUAGE")
            << QStringLiteral("stepcom-sim") << help
            << QStringList{QStringLiteral("LANGUAGE=zh_CN:en"), QStringLiteral("LANG=en_US.UTF-8")}
            << QStringLiteral("stepcom::SimCommandLine")
            << QStringLiteral("Listen for TCP on every interface.");
        QTest::newRow("stepcom LANG")
            << QStringLiteral("stepcom") << help << QStringList{QStringLiteral("LANG=zh_CN.UTF-8")}
            << QStringLiteral("stepcom")
            << QStringLiteral("Start connected to the built-in simulator.");
    }
    void helpInChinese()
    {
        QFETCH(QString, program);
        QFETCH(QStringList, args);
        QFETCH(QStringList, environment);
        QFETCH(QString, context);
        QFETCH(QString, source);
        const Run r = run(program, args, environment);
        QCOMPARE(r.exitCode, 0);
        // Qt's own option texts come from qtbase_zh_CN.qm, the program's from stepcom_zh_CN.qm.
        const QString qtHelp = zh("QCommandLineParser", "Displays help on commandline options.");
        const QString qtUsage = zh("QCommandLineParser", "Usage: %1").arg(QString());
        const QString own = zh(context.toUtf8().constData(), source.toUtf8().constData());
        QVERIFY(hasHan(qtHelp));
        QVERIFY2(hasHan(own), qPrintable(QStringLiteral("no Chinese for ") + source));
        QVERIFY2(r.out.contains(qtHelp), qPrintable(r.out));
        QVERIFY2(r.out.contains(qtUsage.trimmed()), qPrintable(r.out));
        QVERIFY2(r.out.contains(own), qPrintable(r.out));
        QVERIFY2(!r.out.contains(QStringLiteral("Displays help on commandline options.")),
                 qPrintable(r.out));
    }

    // Chinese is asked for but English is preferred: English.
    void languagePreferenceOrder()
    {
        const Run r =
            run(QStringLiteral("stepcomctl"), {QStringLiteral("--help")},
                {QStringLiteral("LANGUAGE=en:zh_CN"), QStringLiteral("LANG=zh_CN.UTF-8")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(!hasHan(r.out), qPrintable(r.out));
    }

    void unknownLanguage_data() { version_data(); }
    void unknownLanguage()
    {
        QFETCH(QString, program);
        const Run r = run(
            program, {QStringLiteral("--lang"), QStringLiteral("fr"), QStringLiteral("--version")},
            {QStringLiteral("LC_ALL=C.UTF-8")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(QStringLiteral("unknown language 'fr' (known: en, zh_CN)")),
                 qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    // On a machine with no display (ssh, a build server, a package check) the window's program
    // still answers --help, --version and a mistyped option instead of aborting.
    void noDisplay_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("expected"); // in stdout, or in stderr for a mistake
        QTest::newRow("--version") << QStringList{QStringLiteral("--version")} << 0
                                   << QStringLiteral("stepcom " STEPCOM_VERSION);
        QTest::newRow("-v") << QStringList{QStringLiteral("-v")} << 0
                            << QStringLiteral("stepcom " STEPCOM_VERSION);
        QTest::newRow("--help") << QStringList{QStringLiteral("--help")} << 0
                                << QStringLiteral("--port <path>");
        QTest::newRow("-h zh_CN") << QStringList{QStringLiteral("--lang"), QStringLiteral("zh_CN"),
                                                 QStringLiteral("-h")}
                                  << 0 << QStringLiteral("--port <");
        QTest::newRow("bad --rtu-tcp")
            << QStringList{QStringLiteral("--rtu-tcp"), QStringLiteral("10.0.0.7")} << 2
            << QStringLiteral("--rtu-tcp: '10.0.0.7' is not HOST:PORT");
        QTest::newRow("bad --parity")
            << QStringList{QStringLiteral("--port"), QStringLiteral("/dev/ttyUSB0"),
                           QStringLiteral("--parity"), QStringLiteral("mark")}
            << 2 << QStringLiteral("--parity: 'mark' is not none, even or odd");
        QTest::newRow("--echo over Modbus TCP")
            << QStringList{QStringLiteral("--tcp"), QStringLiteral("10.0.0.7"),
                           QStringLiteral("--echo")}
            << 2 << QStringLiteral("--echo: Modbus TCP has no echo");
        QTest::newRow("two targets")
            << QStringList{QStringLiteral("--sim"), QStringLiteral("--port"),
                           QStringLiteral("/dev/ttyUSB0")}
            << 2 << QStringLiteral("give only one of");
        QTest::newRow("unknown option")
            << QStringList{QStringLiteral("--frobnicate")} << 1 << QStringLiteral("frobnicate");
    }
    void noDisplay()
    {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QFETCH(QString, expected);
        ProgramOptions options;
        options.cleanLocale = true;
        options.unset = {QStringLiteral("DISPLAY"), QStringLiteral("WAYLAND_DISPLAY"),
                         QStringLiteral("QT_QPA_PLATFORM")};
        options.environment = {QStringLiteral("LC_ALL=C.UTF-8")};
        options.timeoutMs = 30000;
        const Run r = runProgram(QStringLiteral("stepcom"), args, options);
        QVERIFY2(r.exitCode != -2, qPrintable(QStringLiteral("crashed: ") + r.err));
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2((exitCode == 0 ? r.out : r.err).contains(expected), qPrintable(r.out + r.err));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestProgramInfo, Guiless)
#include "tst_programinfo.moc"

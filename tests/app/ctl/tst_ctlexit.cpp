// stepcomctl's one exit-code table: each command's failures (a link that cannot be opened, bad
// usage, a missing file) end with the code the table in --help gives them; `NAME --help` shows
// that command alone; the help's columns never run together, in English and in Chinese.
#include "programrun.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom::test;

class TestCtlExit : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;
    QString profile;

    static ProgramRun ctl(const QStringList &args, const QString &lang = QStringLiteral("en"))
    {
        ProgramOptions options;
        options.cleanLocale = true;
        return runProgram(QStringLiteral("stepcomctl"),
                          QStringList{QStringLiteral("--lang"), lang} + args, options);
    }
    // The table's rows from --help: code -> its words (the continuation lines joined).
    static QHash<int, QString> exitTable(const QString &help)
    {
        QHash<int, QString> rows;
        const qsizetype at = help.indexOf(QStringLiteral("Exit codes"));
        int code = -1;
        static const QRegularExpression row(QStringLiteral("^  (\\d)  +(.*)$"));
        for (const QString &line : help.mid(at).split(QLatin1Char('\n')).mid(1)) {
            if (line.trimmed().isEmpty())
                break;
            const auto m = row.match(line);
            if (m.hasMatch())
                code = m.captured(1).toInt();
            rows[code] += QLatin1Char(' ') + (m.hasMatch() ? m.captured(2) : line.trimmed());
        }
        return rows;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(dir.isValid());
        profile = dir.filePath(QStringLiteral("machine.json"));
        const ProgramRun r = ctl({QStringLiteral("--sim"), QStringLiteral("dump"), profile});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // A profile the built-in controller does not hold: diff says "different", apply writes.
        QFile f(profile);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        f.close();
        QJsonObject values = o.value(QStringLiteral("values")).toObject();
        values.insert(QStringLiteral("motor1.speed"), 123);
        o.insert(QStringLiteral("values"), values);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(QJsonDocument(o).toJson());
    }

    void failuresEndWithTheTablesCode_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("words"); // what the table's row for the code must say
        const QString missing = dir.filePath(QStringLiteral("nope.json"));
        QTest::newRow("params") << QStringList{"params"} << 0 << "success";
        QTest::newRow("read dead") << QStringList{"read"} << 1 << "link or device error";
        QTest::newRow("read unknown") << QStringList{"read", "nope"} << 2 << "usage";
        QTest::newRow("write dead")
            << QStringList{"write", "motor1.speed=300"} << 1 << "link or device error";
        QTest::newRow("write bad") << QStringList{"write", "motor1.speed=x"} << 2 << "validation";
        QTest::newRow("command dead") << QStringList{"command", "estop"} << 1 << "link";
        QTest::newRow("command unknown") << QStringList{"command", "nope"} << 2 << "usage";
        QTest::newRow("command --wait dead")
            << QStringList{"command", "motor1.move", "--wait"} << 1 << "link";
        QTest::newRow("move dead") << QStringList{"move", "motor1", "--by", "1"} << 1 << "link";
        QTest::newRow("move bad") << QStringList{"move", "motor9", "--by", "1"} << 2 << "usage";
        QTest::newRow("monitor dead") << QStringList{"monitor", "--count", "1"} << 1 << "link";
        QTest::newRow("dump dead")
            << QStringList{"dump", dir.filePath(QStringLiteral("x.json"))} << 1 << "link";
        QTest::newRow("diff dead") << QStringList{"diff", profile} << 3 << "diff";
        QTest::newRow("diff missing") << QStringList{"diff", missing} << 2 << "bad";
        QTest::newRow("apply dead") << QStringList{"apply", profile, "--yes"} << 1 << "link";
        QTest::newRow("apply missing") << QStringList{"apply", missing} << 2 << "bad";
        QTest::newRow("assign-id dead") << QStringList{"assign-id", "--to", "2"} << 1 << "link";
        QTest::newRow("scan dead") << QStringList{"scan", "--ids", "1-2"} << 3 << "scan";
        QTest::newRow("report dead")
            << QStringList{"report", dir.filePath(QStringLiteral("r.pdf"))} << 1 << "link";
        QTest::newRow("replay missing") << QStringList{"replay", missing, "--events"} << 2 << "bad";
        QTest::newRow("unknown command") << QStringList{"frobnicate"} << 2 << "usage";
    }
    void failuresEndWithTheTablesCode()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, words);
        static const QHash<int, QString> table = exitTable(ctl({QStringLiteral("--help")}).out);
        QVERIFY2(table.contains(code), qPrintable(QStringLiteral("no row for %1").arg(code)));
        QVERIFY2(table.value(code).contains(words), qPrintable(table.value(code)));
        // A link nobody listens on: refused at once.
        const QStringList dead{QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:1"),
                               QStringLiteral("--timeout"), QStringLiteral("200")};
        const ProgramRun r = ctl(dead + args);
        QVERIFY2(r.exitCode == code,
                 qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
    }

    void aBackupThatCannotBeSavedIsNotAUsageError()
    {
        // The backups' folder cannot be made, a file stands in its place: not done (1), not bad
        // usage (2). The rest of the data folder stays usable (the simulator keeps its flash
        // there).
        const QString data = dir.filePath(QStringLiteral("data"));
        QVERIFY(QDir().mkpath(data + QStringLiteral("/StepCom/stepcom")));
        QFile blocker(data + QStringLiteral("/StepCom/stepcom/backups"));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        ProgramOptions options;
        options.environment = {QStringLiteral("XDG_DATA_HOME=") + data};
        const ProgramRun r = runProgram(
            QStringLiteral("stepcomctl"),
            {QStringLiteral("--sim"), QStringLiteral("command"), QStringLiteral("save_to_flash")},
            options);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("no backup")), qPrintable(r.err));
    }

    void jsonForEveryCommand_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::newRow("write") << QStringList{"write", "motor1.speed=250"} << 0;
        QTest::newRow("write asked") << QStringList{"write", "mode.system=4"} << 2;
        QTest::newRow("command") << QStringList{"command", "output1_on"} << 0;
        // The built-in controller's speed differs from the profile's: diff says 1.
        QTest::newRow("diff") << QStringList{"diff", QStringLiteral("PROFILE")} << 1;
        QTest::newRow("apply") << QStringList{"--yes", "--no-backup", "apply", "PROFILE"} << 0;
        QTest::newRow("dump") << QStringList{"dump", "DUMP"} << 0;
    }
    void jsonForEveryCommand()
    {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        args.replaceInStrings(QStringLiteral("PROFILE"), profile);
        args.replaceInStrings(QStringLiteral("DUMP"), dir.filePath(QStringLiteral("d.json")));
        // One id, and two: the same object, alone or as each id's member.
        for (const QString &ids : {QStringLiteral("1"), QStringLiteral("1-2")}) {
            // write takes one id; dump's files per id are checked in tst_ctlbus.
            if (ids != QLatin1String("1") &&
                (args.contains(QStringLiteral("write")) || args.contains(QStringLiteral("dump"))))
                continue;
            QStringList line{QStringLiteral("--sim"), QStringLiteral("--id"), ids,
                             QStringLiteral("--json")};
            const ProgramRun r = ctl(line + args);
            const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8());
            QVERIFY2(doc.isObject(), qPrintable(r.out + r.err));
            // The same object, for one id, and with two as the result holding each id's.
            QCOMPARE(doc.object().value(QStringLiteral("exit")).toInt(-1), code);
            QList<QJsonObject> runs;
            if (ids == QLatin1String("1")) {
                runs << doc.object();
            } else {
                const QJsonObject all = doc.object().value(QStringLiteral("result")).toObject();
                runs << all.value(QStringLiteral("1")).toObject()
                     << all.value(QStringLiteral("2")).toObject();
            }
            for (const QJsonObject &o : std::as_const(runs)) {
                QVERIFY2(o.value(QStringLiteral("result")).isObject(), qPrintable(r.out));
                QVERIFY(o.value(QStringLiteral("errors")).isArray());
                QVERIFY(!o.contains(QStringLiteral("output")));
                QCOMPARE(o.value(QStringLiteral("exit")).toInt(-1), code);
            }
            QCOMPARE(r.exitCode, code);
        }
    }

    void theManPageHasTheTable()
    {
        // help2man puts --help in the page; its EXIT STATUS section is written by hand.
        QFile man(sourcePath(QStringLiteral("packaging/man/stepcomctl.h2m")));
        QVERIFY(man.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(man.readAll());
        const QHash<int, QString> table = exitTable(ctl({QStringLiteral("--help")}).out);
        for (auto it = table.cbegin(); it != table.cend(); ++it)
            QVERIFY2(text.contains(QStringLiteral(".B %1\n").arg(it.key())),
                     qPrintable(QStringLiteral("the man page lacks exit code %1").arg(it.key())));
    }

    void oneCommandsHelp_data()
    {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("usage");
        QTest::newRow("read") << "read"
                              << "stepcomctl read [KEY...]";
        QTest::newRow("move") << "move"
                              << "stepcomctl move MOTOR --by D|--to X";
        QTest::newRow("diff") << "diff"
                              << "stepcomctl diff A.json B.json";
        QTest::newRow("command") << "command"
                                 << "stepcomctl command NAME --wait";
    }
    void oneCommandsHelp()
    {
        QFETCH(QString, command);
        QFETCH(QString, usage);
        const ProgramRun r = ctl({command, QStringLiteral("--help")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(usage), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("Exit codes")));
        QVERIFY2(!r.out.contains(QStringLiteral("bundle OUT.zip")) || command == "bundle",
                 qPrintable(r.out));
        QVERIFY(!r.out.contains(QStringLiteral("--rtu-tcp")));
    }

    void columnsNeverRunTogether_data()
    {
        QTest::addColumn<QString>("lang");
        QTest::newRow("en") << "en";
        QTest::newRow("zh_CN") << "zh_CN";
    }
    void columnsNeverRunTogether()
    {
        QFETCH(QString, lang);
        const ProgramRun r = ctl({QStringLiteral("--help")}, lang);
        QCOMPARE(r.exitCode, 0);
        // Every usage of the table stands apart from its help by two spaces or more.
        for (const char *usage : {"move MOTOR --by D|--to X", "command NAME --wait",
                                  "report FILE.pdf|.html", "replay LOG|BUNDLE.zip"}) {
            const qsizetype at = r.out.indexOf(QLatin1String(usage));
            QVERIFY2(at > 0, usage);
            const qsizetype end = at + qsizetype(qstrlen(usage));
            QVERIFY2(r.out.mid(end, 2) == QStringLiteral("  "), qPrintable(r.out.mid(at, 80)));
        }
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestCtlExit, Guiless)
#include "tst_ctlexit.moc"

// stepcom-sim --serial: the simulated controller on a serial port (here one end of a socat
// null-modem pair, as com0com gives on Windows), checked with mbpoll (libmodbus) on the other.
#include "sim/host/simcommandline.h"
#include "testpaths.h"

#include <QCommandLineParser>

#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;

class TestSimSerial : public QObject
{
    Q_OBJECT
    QString m_mbpoll;
    QString m_socat;
    QTemporaryDir m_dir;
    std::unique_ptr<QProcess> m_pair; // socat: m_dir/sim <-> m_dir/client
    std::unique_ptr<QProcess> m_sim;

    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }

    // One mbpoll request on the client end: "-r 213 -c 1" reads, "-r 213 ... 19200" writes.
    QString mbpoll(int baud, const QStringList &args, const QStringList &values = {}) const
    {
        QProcess p;
        p.start(m_mbpoll,
                QStringList{QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-b"),
                            QString::number(baud), QStringLiteral("-P"), QStringLiteral("none"),
                            QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-o"),
                            QStringLiteral("0.5"), QStringLiteral("-1")} +
                    args + QStringList{path("client")} + values);
        p.waitForFinished(10000);
        return QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
    }
    static bool readsBaud(const QString &out, int baud)
    {
        return QRegularExpression(QStringLiteral("\\[213\\]:\\s+%1\\b").arg(baud))
            .match(out)
            .hasMatch();
    }
    static QStringList readBaud() { return QString::fromLatin1("-r 213 -c 1").split(u' '); }

private Q_SLOTS:
    void init()
    {
        m_mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
        m_socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (m_mbpoll.isEmpty() || m_socat.isEmpty())
            QSKIP("mbpoll or socat is not installed (scripts/deps.sh --test)");
        QVERIFY(m_dir.isValid());
        m_pair = std::make_unique<QProcess>();
        m_pair->start(m_socat, {QStringLiteral("pty,raw,echo=0,link=") + path("sim"),
                                QStringLiteral("pty,raw,echo=0,link=") + path("client")});
        QVERIFY(m_pair->waitForStarted(5000));
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(path("sim")) && QFile::exists(path("client")),
                                 10000);
        m_sim = std::make_unique<QProcess>();
        m_sim->start(test::programPath(QStringLiteral("stepcom-sim")),
                     {QStringLiteral("--serial"), path("sim")});
        QVERIFY(m_sim->waitForStarted(5000));
        QByteArray out;
        while (!out.contains("serial:") && m_sim->waitForReadyRead(5000))
            out += m_sim->readAllStandardOutput();
        QVERIFY2(out.contains("serial: " + path("sim").toUtf8()), out.constData());
    }
    void cleanup()
    {
        for (QProcess *p : {m_sim.get(), m_pair.get()}) {
            if (p && p->state() != QProcess::NotRunning) {
                p->terminate();
                if (!p->waitForFinished(5000))
                    p->kill();
                p->waitForFinished();
            }
        }
        m_sim.reset();
        m_pair.reset();
    }

    void answersOnTheSerialPort()
    {
        const QString out = mbpoll(9600, readBaud());
        QVERIFY2(readsBaud(out, 9600), qPrintable(out));
    }

    // Register 40213 changes the baud at once and the port follows. (A pty pair passes bytes
    // at any baud, so the port's own setting is what shows it: stty on the simulator's end.)
    void followsANewBaud()
    {
        QCOMPARE(portSpeed(), QStringLiteral("9600"));
        const QString written =
            mbpoll(9600, {QStringLiteral("-r"), QStringLiteral("213")}, {QStringLiteral("19200")});
        QVERIFY2(written.contains(QStringLiteral("Written 1 references")), qPrintable(written));
        QTRY_COMPARE_WITH_TIMEOUT(portSpeed(), QStringLiteral("19200"), 10000);
        const QString out = mbpoll(19200, readBaud());
        QVERIFY2(readsBaud(out, 19200), qPrintable(out));
    }

    void badOptions_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("error");
        QTest::newRow("with --pty") << QStringList{"--serial", "COM10", "--pty"}
                                    << "--serial: give either --serial or --pty/--link, not both";
        QTest::newRow("with --link") << QStringList{"--serial", "COM10", "--link", "/tmp/x"}
                                     << "--serial: give either --serial or --pty/--link, not both";
        QTest::newRow("empty") << QStringList{"--serial", ""} << "--serial: no port given";
        QTest::newRow("corrupt CRC")
            << QStringList{"--serial", "COM10", "--corrupt-crc", "5%"}
            << "--corrupt-crc works on the pseudo-terminal only, not with --serial";
    }
    void badOptions()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, error);
        QCommandLineParser parser;
        SimCommandLine::addOptions(parser);
        QVERIFY(parser.parse(QStringList{"stepcom-sim"} + args));
        SimOptions options;
        QString why;
        QVERIFY(!SimCommandLine::toOptions(parser, &options, &why));
        QCOMPARE(why, error);
    }

    void portThatCannotBeOpened()
    {
        QProcess sim;
        sim.start(test::programPath(QStringLiteral("stepcom-sim")),
                  {QStringLiteral("--serial"), path("missing")});
        QVERIFY(sim.waitForFinished(10000));
        QCOMPARE(sim.exitCode(), 1);
        const QString err = QString::fromUtf8(sim.readAllStandardError());
        QVERIFY2(err.contains(QStringLiteral("cannot open the serial port ") + path("missing")),
                 qPrintable(err));
    }

private:
    QString portSpeed() const
    {
        QProcess stty;
        stty.start(QStringLiteral("stty"),
                   {QStringLiteral("-F"), path("sim"), QStringLiteral("speed")});
        stty.waitForFinished(5000);
        return QString::fromUtf8(stty.readAllStandardOutput()).trimmed();
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestSimSerial, Guiless)
#include "tst_simserial.moc"

// A port another program holds is named as in use, with the program and its process id, from
// the lock file or from /proc (a fixture tree here, then two real stepcomctl on one pty); the
// dialout advice stays for a real permission error.
#include "bus/portholders.h"
#include "programrun.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

using namespace stepcom;
using namespace stepcom::test;

namespace {

bool writeFile(const QString &path, const QByteArray &content)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(content) == content.size();
}

} // namespace

class TestPortInUse : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void cleanup() { PortHolders::setRoots({}, {}); }

    void fromTheLockFile()
    {
        QTemporaryDir dir;
        const QString proc = dir.filePath(QStringLiteral("proc"));
        QVERIFY(writeFile(proc + QStringLiteral("/4242/comm"), "stepcomctl\n"));
        // Qt's QLockFile: the pid, the program, the host.
        QVERIFY(writeFile(dir.filePath(QStringLiteral("lock/LCK..ttyUSB0")),
                          "4242\nstepcomctl\nbench\n"));
        // A stale lock of a process gone is nobody's.
        QVERIFY(writeFile(dir.filePath(QStringLiteral("lock/LCK..ttyUSB1")), "     999\n"));
        PortHolders::setRoots({dir.filePath(QStringLiteral("lock"))}, proc);
        const QList<PortHolders::Holder> h = PortHolders::holders(QStringLiteral("/dev/ttyUSB0"));
        QCOMPARE(h.size(), 1);
        QCOMPARE(h.first().pid, 4242);
        QCOMPARE(h.first().program, QStringLiteral("stepcomctl"));
        QCOMPARE(PortHolders::inUseMessage(QStringLiteral("/dev/ttyUSB0"), h),
                 QStringLiteral("/dev/ttyUSB0 is in use by another program (stepcomctl, "
                                "process 4242)"));
        QVERIFY(PortHolders::holders(QStringLiteral("/dev/ttyUSB1")).isEmpty());
    }

    void fromTheOpenFiles()
    {
        QTemporaryDir dir;
        const QString proc = dir.filePath(QStringLiteral("proc"));
        QVERIFY(writeFile(proc + QStringLiteral("/77/comm"), "minicom\n"));
        QVERIFY(QDir().mkpath(proc + QStringLiteral("/77/fd")));
        QVERIFY(QFile::link(QStringLiteral("/dev/ttyUSB3"), proc + QStringLiteral("/77/fd/3")));
        QVERIFY(writeFile(proc + QStringLiteral("/78/comm"), "bash\n"));
        QVERIFY(QDir().mkpath(proc + QStringLiteral("/78/fd")));
        QVERIFY(QFile::link(QStringLiteral("/dev/pts/1"), proc + QStringLiteral("/78/fd/0")));
        PortHolders::setRoots({dir.filePath(QStringLiteral("nolock"))}, proc);
        QCOMPARE(PortHolders::holders(QStringLiteral("/dev/ttyUSB3")),
                 (QList<PortHolders::Holder>{{77, QStringLiteral("minicom")}}));
        // Qt's lock message with nobody found is still "in use", never the dialout advice.
        QCOMPARE(PortHolders::openFailure(QStringLiteral("/dev/ttyUSB3"),
                                          QSerialPort::PermissionError,
                                          QStringLiteral("Permission error while locking the "
                                                         "device")),
                 QStringLiteral("/dev/ttyUSB3 is in use by another program (minicom, process 77)"));
    }

    // Two programs on one pty: the second names the first.
    void aSecondProgramNamesTheFirst()
    {
        int master = -1;
        int slave = -1;
        char name[256] = {};
        QVERIFY(::openpty(&master, &slave, name, nullptr, nullptr) == 0);
        const QString pty = QString::fromLocal8Bit(name);
        ::close(slave); // this test holds the master only: the programs are the port's holders
        QProcess first;
        first.start(programPath(QStringLiteral("stepcomctl")),
                    {QStringLiteral("listen"), QStringLiteral("--port"), pty,
                     QStringLiteral("--seconds"), QStringLiteral("60")});
        QByteArray err;
        QTRY_VERIFY_WITH_TIMEOUT((err += first.readAllStandardError()).contains("listening on"),
                                 20000);
        const ProgramRun second = runProgram(QStringLiteral("stepcomctl"),
                                             {QStringLiteral("read"), QStringLiteral("--port"), pty,
                                              QStringLiteral("motor1.speed")});
        QCOMPARE(second.exitCode, 1);
        const QString expected = QStringLiteral("%1 is in use by another program (stepcomctl, "
                                                "process %2)")
                                     .arg(pty)
                                     .arg(first.processId());
        QVERIFY2(second.err.contains(expected), qPrintable(second.err));
        QVERIFY2(!second.err.contains(QStringLiteral("dialout")), qPrintable(second.err));
        first.terminate();
        QVERIFY(first.waitForFinished(20000));
        ::close(master);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestPortInUse, Guiless)
#include "tst_portinuse.moc"

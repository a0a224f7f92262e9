// A port another program holds is named as in use, with the program and its process id, from
// the lock file (named as Qt names it, in each format a lock is written) or from /proc (a
// fixture tree here, then two real stepcomctl on one pty); the dialout advice stays for a real
// permission error; another user's processes make the search incomplete.
#include "bus/portholders.h"
#include "bus/systemroot.h"
#include "programrun.h"
#include "testpaths.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <fcntl.h>
#include <pty.h>
#include <sys/stat.h>
#include <sys/wait.h>
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
    void cleanup() { SystemRoot::set({}); }

    void fromTheLockFile()
    {
        QTemporaryDir dir;
        const QString proc = dir.filePath(QStringLiteral("proc"));
        QVERIFY(writeFile(proc + QStringLiteral("/4242/comm"), "stepcomctl\n"));
        // Qt's QLockFile: the pid, the program, the host.
        QVERIFY(writeFile(dir.filePath(QStringLiteral("run/lock/LCK..ttyUSB0")),
                          "4242\nstepcomctl\nbench\n"));
        // A stale lock of a process gone is nobody's.
        QVERIFY(writeFile(dir.filePath(QStringLiteral("run/lock/LCK..ttyUSB1")), "     999\n"));
        SystemRoot::set(dir.path());
        const QList<PortHolders::Holder> h = PortHolders::holders(QStringLiteral("/dev/ttyUSB0"));
        QCOMPARE(h.size(), 1);
        QCOMPARE(h.first().pid, 4242);
        QCOMPARE(h.first().program, QStringLiteral("stepcomctl"));
        QCOMPARE(h.first().lockFile, QStringLiteral("/run/lock/LCK..ttyUSB0"));
        QVERIFY(!h.first().open);
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
        SystemRoot::set(dir.path());
        bool incomplete = true;
        QCOMPARE(PortHolders::holders(QStringLiteral("/dev/ttyUSB3"), &incomplete),
                 (QList<PortHolders::Holder>{{77, QStringLiteral("minicom"), QString(), true}}));
        QVERIFY(!incomplete);
        // Qt's lock message with nobody found is still "in use", never the dialout advice.
        QCOMPARE(PortHolders::openFailure(QStringLiteral("/dev/ttyUSB3"),
                                          QSerialPort::PermissionError,
                                          QStringLiteral("Permission error while locking the "
                                                         "device")),
                 QStringLiteral("/dev/ttyUSB3 is in use by another program (minicom, process 77)"));
    }

    // Qt names the lock after the path below /dev with '/' as '_': /dev/pts/5 is LCK..pts_5,
    // never LCK..5; a by-id link and a bare name are the device they stand for.
    void theLockIsNamedAsQtNamesIt()
    {
        QCOMPARE(PortHolders::lockName(QStringLiteral("/dev/ttyUSB0")),
                 QStringLiteral("LCK..ttyUSB0"));
        QCOMPARE(PortHolders::lockName(QStringLiteral("/dev/pts/5")), QStringLiteral("LCK..pts_5"));
        QTemporaryDir dir;
        const QString root = dir.path();
        QVERIFY(writeFile(root + QStringLiteral("/proc/500/comm"), "stepcom\n"));
        QVERIFY(writeFile(root + QStringLiteral("/proc/501/comm"), "other\n"));
        QVERIFY(writeFile(root + QStringLiteral("/proc/502/comm"), "minicom\n"));
        QVERIFY(writeFile(root + QStringLiteral("/run/lock/LCK..pts_5"), "500\nstepcom\nbench\n"));
        QVERIFY(writeFile(root + QStringLiteral("/run/lock/LCK..5"), "501\n"));
        QVERIFY(writeFile(root + QStringLiteral("/var/lock/LCK..ttyUSB0"), "       502\n"));
        QVERIFY(writeFile(root + QStringLiteral("/dev/ttyUSB0"), {}));
        QVERIFY(QDir().mkpath(root + QStringLiteral("/dev/serial/by-id")));
        QVERIFY(QFile::link(QStringLiteral("../../ttyUSB0"),
                            root + QStringLiteral("/dev/serial/by-id/usb-FTDI-if00-port0")));
        SystemRoot::set(root);
        QCOMPARE(PortHolders::holders(QStringLiteral("/dev/pts/5")),
                 (QList<PortHolders::Holder>{{500, QStringLiteral("stepcom"),
                                              QStringLiteral("/run/lock/LCK..pts_5"), false}}));
        const QList<PortHolders::Holder> minicom{
            {502, QStringLiteral("minicom"), QStringLiteral("/var/lock/LCK..ttyUSB0"), false}};
        QCOMPARE(PortHolders::holders(QStringLiteral("/dev/serial/by-id/usb-FTDI-if00-port0")),
                 minicom);
        QCOMPARE(PortHolders::holders(QStringLiteral("ttyUSB0")), minicom);
    }

    // An old program's lock holds its pid as 4 binary bytes; a process both locking and having
    // the port open is one holder, with both said.
    void aBinaryLockAndOneHolderBothWays()
    {
        QTemporaryDir dir;
        const QString root = dir.path();
        QVERIFY(writeFile(root + QStringLiteral("/proc/4242/comm"), "cu\n"));
        QVERIFY(QDir().mkpath(root + QStringLiteral("/proc/4242/fd")));
        QVERIFY(
            QFile::link(QStringLiteral("/dev/ttyS1"), root + QStringLiteral("/proc/4242/fd/4")));
        const qint32 pid = 4242;
        QVERIFY(writeFile(root + QStringLiteral("/var/lock/LCK..ttyS1"),
                          QByteArray(reinterpret_cast<const char *>(&pid), sizeof pid)));
        SystemRoot::set(root);
        QCOMPARE(PortHolders::holders(QStringLiteral("/dev/ttyS1")),
                 (QList<PortHolders::Holder>{
                     {4242, QStringLiteral("cu"), QStringLiteral("/var/lock/LCK..ttyS1"), true}}));
    }

    // Another user's /proc/PID/fd cannot be looked into: the holders found are said to be
    // perhaps not all. Run as another user (nobody) when the test runs as root, who sees all.
    void anotherUsersProcessMakesItIncomplete()
    {
        QTemporaryDir dir;
        const QString root = dir.path();
        QVERIFY(::chmod(QFile::encodeName(root).constData(), 0755) == 0);
        QVERIFY(writeFile(root + QStringLiteral("/proc/77/comm"), "minicom\n"));
        QVERIFY(QDir().mkpath(root + QStringLiteral("/proc/77/fd")));
        QVERIFY(
            QFile::link(QStringLiteral("/dev/ttyUSB3"), root + QStringLiteral("/proc/77/fd/3")));
        QVERIFY(writeFile(root + QStringLiteral("/proc/78/comm"), "daemon\n"));
        QVERIFY(QDir().mkpath(root + QStringLiteral("/proc/78/fd")));
        QVERIFY(::chmod(QFile::encodeName(root + QStringLiteral("/proc/78/fd")).constData(),
                        0700) == 0);
        SystemRoot::set(root);
        const auto seenIncomplete = [] {
            bool incomplete = false;
            const QList<PortHolders::Holder> found =
                PortHolders::holders(QStringLiteral("/dev/ttyUSB3"), &incomplete);
            return found.size() == 1 && found.first().pid == 77 && incomplete;
        };
        if (::geteuid() != 0) {
            QVERIFY(::chmod(QFile::encodeName(root + QStringLiteral("/proc/78/fd")).constData(),
                            0) == 0);
            QVERIFY(seenIncomplete());
            return;
        }
        bool incomplete = true;
        QCOMPARE(PortHolders::holders(QStringLiteral("/dev/ttyUSB3"), &incomplete).size(), 1);
        QVERIFY(!incomplete); // root sees every process
        const pid_t child = ::fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            const bool ok = ::setgid(65534) == 0 && ::setuid(65534) == 0 && seenIncomplete();
            ::_exit(ok ? 0 : 1);
        }
        int status = 0;
        QCOMPARE(::waitpid(child, &status, 0), child);
        QVERIFY(WIFEXITED(status));
        QCOMPARE(WEXITSTATUS(status), 0);
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

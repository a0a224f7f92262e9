#include "sim/serve/ptybridge.h"

#include "bus/rtuframe.h"

#include <QFile>
#include <QFileInfo>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

using stepcom::PtyBridge;
using Side = stepcom::PtyBridge::Side;

namespace {

// A program on one side: a QSerialPort set to 8N1 explicitly, collecting what it reads.
class Peer
{
public:
    explicit Peer(const QString &path, qint32 baud = 9600)
    {
        m_port.setPortName(path);
        m_port.setBaudRate(baud);
        m_port.setDataBits(QSerialPort::Data8);
        m_port.setParity(QSerialPort::NoParity);
        m_port.setStopBits(QSerialPort::OneStop);
        m_port.setFlowControl(QSerialPort::NoFlowControl);
        QObject::connect(&m_port, &QSerialPort::readyRead, &m_port,
                         [this] { m_received += m_port.readAll(); });
    }
    bool open() { return m_port.isOpen() || m_port.open(QIODevice::ReadWrite); }
    QSerialPort &port() { return m_port; }
    const QByteArray &received() const { return m_received; }
    void write(const QByteArray &bytes) { m_port.write(bytes); }
    void clearReceived() { m_received.clear(); }

private:
    QSerialPort m_port;
    QByteArray m_received;
};

QByteArray allByteValues()
{
    QByteArray bytes;
    for (int i = 0; i < 256; ++i)
        bytes.append(static_cast<char>(i));
    return bytes;
}

QByteArray seenFrom(const QSignalSpy &spy, Side side)
{
    QByteArray bytes;
    for (const QList<QVariant> &args : spy) {
        if (args.at(0).value<Side>() == side)
            bytes += args.at(1).toByteArray();
    }
    return bytes;
}

} // namespace

class TestPtyBridge : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void forwardsBothWays();
    void isEightBitClean();
    void noEchoFromASideNobodyHasOpen();
    void tapModifies();
    void tapDrops();
    void framerHandsOnOneFrameAtATime();
    void injectDeliversWithoutTap();
    void bytesSeenReportsEveryChunkBeforeTap();
    void clientBaudFollowsSerialPort();
    void reopeningASideKeepsBridgeWorking();
    void largeTransferArrivesInOrder();
    void holdsBytesForASideThatIsNotReading();
    void closeHangsUpOpenPort();
    void closingFromInsideTapOrSignalIsSafe();
    void openTwiceFails();
    void createLinkMakesWorkingSymlinkAndRemovesIt();
    void createLinkRefusesRegularFile();
    void destructionRemovesLinkButKeepsForeignOne();
    void survivesHangUpOfKeptSlave();
};

#define OPEN_BRIDGE(bridge)                                                                        \
    do {                                                                                           \
        QString openError;                                                                         \
        QVERIFY2((bridge).open(&openError), qPrintable(openError));                                \
    } while (false)

// QSerialPort locks LCK..pts_N; another process may briefly hold a hung-up port whose number the
// kernel has already handed to our new pty, so opening is retried instead of failing at once.
#define OPEN_PEER(peer)                                                                            \
    QTRY_VERIFY2_WITH_TIMEOUT((peer).open(), qPrintable((peer).port().errorString()), 10000)

void TestPtyBridge::forwardsBothWays()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    QVERIFY(bridge.isOpen());
    QVERIFY(bridge.path(Side::A).startsWith(u'/'));
    QVERIFY(bridge.path(Side::A) != bridge.path(Side::B));
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);

    a.write(QByteArrayLiteral("\x01\x03\x00\x00\x00\x02\xC4\x0B"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("\x01\x03\x00\x00\x00\x02\xC4\x0B"));
    b.write(QByteArrayLiteral("answer"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("answer"));
    // Nothing echoes back to the sender.
    QCOMPARE(b.received(), QByteArrayLiteral("\x01\x03\x00\x00\x00\x02\xC4\x0B"));
}

void TestPtyBridge::isEightBitClean()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    // NUL, CR, XON/XOFF, ^C and 0xFF would all be eaten or rewritten by a cooked tty.
    a.write(allByteValues());
    QTRY_COMPARE(b.received(), allByteValues());
    b.write(allByteValues());
    QTRY_COMPARE(a.received(), allByteValues());
}

void TestPtyBridge::noEchoFromASideNobodyHasOpen()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    QSignalSpy seen(&bridge, &PtyBridge::bytesSeen);
    Peer a(bridge.path(Side::A));
    OPEN_PEER(a);
    // A fresh pty echoes: unless the bridge made it raw, "ping" would come back from side B.
    a.write(QByteArrayLiteral("ping"));
    QTRY_COMPARE(seenFrom(seen, Side::A), QByteArrayLiteral("ping"));
    bridge.inject(Side::A, QByteArrayLiteral("sync"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("sync"));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(b);
    b.write(QByteArrayLiteral("marker"));
    QTRY_COMPARE(seenFrom(seen, Side::B), QByteArrayLiteral("marker"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("syncmarker"));
}

void TestPtyBridge::tapModifies()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    bridge.setTap([](Side from, const QByteArray &bytes) {
        return from == Side::A ? bytes.toUpper() : bytes + QByteArrayLiteral("!");
    });
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    a.write(QByteArrayLiteral("hello"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("HELLO"));
    b.write(QByteArrayLiteral("x"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("x!"));
}

void TestPtyBridge::tapDrops()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    bool dropping = true;
    bridge.setTap(
        [&dropping](Side, const QByteArray &bytes) { return dropping ? QByteArray() : bytes; });
    QSignalSpy seen(&bridge, &PtyBridge::bytesSeen);
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    b.write(QByteArrayLiteral("secret"));
    // Seen means the tap has run on it; a forwarded copy would then precede the marker below.
    QTRY_COMPARE(seenFrom(seen, Side::B), QByteArrayLiteral("secret"));
    dropping = false;
    b.write(QByteArrayLiteral("marker"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("marker"));
}

// Requests that arrive glued together (the program on side A was too busy to read between
// them) are handed on one by one, each once A has read the one before; a burst that makes no
// whole frame goes on after a silence, as it came.
void TestPtyBridge::framerHandsOnOneFrameAtATime()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    bridge.setFramer(Side::B, &stepcom::RtuFrame::requestLength);
    QList<QByteArray> tapped;
    bridge.setTap([&tapped](Side from, const QByteArray &bytes) {
        if (from == Side::B)
            tapped << bytes;
        return bytes;
    });
    QSignalSpy seen(&bridge, &PtyBridge::bytesSeen);
    // Side A read by hand, so that nothing reads it while the test does not.
    const int a =
        ::open(QFile::encodeName(bridge.path(Side::A)).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    QVERIFY(a >= 0);
    QByteArray onA; // what side A has read so far
    const auto readA = [a, &onA] {
        char buffer[256];
        const ssize_t n = ::read(a, buffer, sizeof buffer);
        if (n > 0)
            onA += QByteArray(buffer, n);
        return onA;
    };
    Peer b(bridge.path(Side::B));
    OPEN_PEER(b);
    const QByteArray first = QByteArray::fromHex("010300000001840A");
    const QByteArray second = QByteArray::fromHex("020600010004D9FA");
    b.write(first + second + QByteArray::fromHex("03"));
    QTRY_COMPARE(seenFrom(seen, Side::B).size(), first.size() + second.size() + 1);
    QTest::qWait(50); // time enough to hand on more, had it done so
    QCOMPARE(readA(), first);
    QTRY_COMPARE(readA(), first + second);
    // The lone byte makes no frame: after a silence it goes on all the same.
    QTRY_COMPARE(readA(), first + second + QByteArray::fromHex("03"));
    QCOMPARE(tapped, (QList<QByteArray>{first, second, QByteArray::fromHex("03")}));
    ::close(a);
}

void TestPtyBridge::injectDeliversWithoutTap()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    int tapCalls = 0;
    bridge.setTap([&tapCalls](Side, const QByteArray &bytes) {
        ++tapCalls;
        return bytes;
    });
    QSignalSpy seen(&bridge, &PtyBridge::bytesSeen);
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    bridge.inject(Side::B, QByteArrayLiteral("to B"));
    bridge.inject(Side::A, QByteArrayLiteral("to A"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("to B"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("to A"));
    QCOMPARE(tapCalls, 0);
    QCOMPARE(seen.count(), 0);
}

void TestPtyBridge::bytesSeenReportsEveryChunkBeforeTap()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    bridge.setTap([](Side, const QByteArray &) { return QByteArray(); });
    QSignalSpy seen(&bridge, &PtyBridge::bytesSeen);
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    a.write(QByteArrayLiteral("from a"));
    QTRY_COMPARE(seenFrom(seen, Side::A), QByteArrayLiteral("from a"));
    b.write(QByteArrayLiteral("from b"));
    QTRY_COMPARE(seenFrom(seen, Side::B), QByteArrayLiteral("from b"));
    QCOMPARE(seenFrom(seen, Side::A), QByteArrayLiteral("from a"));
    QVERIFY(a.received().isEmpty());
    QVERIFY(b.received().isEmpty());
}

void TestPtyBridge::clientBaudFollowsSerialPort()
{
    PtyBridge bridge;
    QCOMPARE(bridge.clientBaud(Side::A), 0);
    OPEN_BRIDGE(bridge);
    QCOMPARE(bridge.clientBaud(Side::A), 0); // nobody has set a speed yet
    Peer a(bridge.path(Side::A), 19200);
    OPEN_PEER(a);
    QCOMPARE(bridge.clientBaud(Side::A), 19200);
    QCOMPARE(bridge.clientBaud(Side::B), 0);
    QVERIFY(a.port().setBaudRate(9600));
    QCOMPARE(bridge.clientBaud(Side::A), 9600);
    QVERIFY(a.port().setBaudRate(115200));
    QCOMPARE(bridge.clientBaud(Side::A), 115200);
    Peer b(bridge.path(Side::B), 38400);
    OPEN_PEER(b);
    QCOMPARE(bridge.clientBaud(Side::B), 38400);
    QCOMPARE(bridge.clientBaud(Side::A), 115200);
    // QSerialPort restores the settings it found, so a closed side reads "unknown" again.
    a.port().close();
    QCOMPARE(bridge.clientBaud(Side::A), 0);
}

void TestPtyBridge::reopeningASideKeepsBridgeWorking()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    Peer b(bridge.path(Side::B));
    OPEN_PEER(b);
    for (int round = 0; round < 3; ++round) {
        Peer a(bridge.path(Side::A));
        OPEN_PEER(a);
        const QByteArray request = QByteArrayLiteral("request ") + QByteArray::number(round);
        a.write(request);
        QTRY_COMPARE(b.received(), request);
        b.write(QByteArrayLiteral("reply"));
        QTRY_COMPARE(a.received(), QByteArrayLiteral("reply"));
        a.port().close();
        // Let the bridge see side A with no program on it before the next one opens it.
        b.clearReceived();
        bridge.inject(Side::B, QByteArrayLiteral("sync"));
        QTRY_COMPARE(b.received(), QByteArrayLiteral("sync"));
        b.clearReceived();
    }
}

void TestPtyBridge::largeTransferArrivesInOrder()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    QByteArray data;
    for (int i = 0; data.size() < 512 * 1024; ++i)
        data += QByteArray::number(i) + ',';
    a.write(data);
    QTRY_COMPARE_WITH_TIMEOUT(b.received().size(), data.size(), 30000);
    QCOMPARE(b.received(), data);
}

void TestPtyBridge::holdsBytesForASideThatIsNotReading()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    QByteArray data;
    for (int i = 0; data.size() < 300 * 1024; ++i)
        data += QByteArray::number(i) + ';';
    // More than the kernel buffers for a slave nobody reads: the rest must wait in the bridge.
    bridge.inject(Side::B, data);
    Peer b(bridge.path(Side::B));
    OPEN_PEER(b);
    QTRY_COMPARE_WITH_TIMEOUT(b.received().size(), data.size(), 30000);
    QCOMPARE(b.received(), data);
}

void TestPtyBridge::closeHangsUpOpenPort()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    Peer a(bridge.path(Side::A));
    OPEN_PEER(a);
    QSignalSpy errors(&a.port(), &QSerialPort::errorOccurred);
    QSignalSpy hungUp(&bridge, &PtyBridge::hungUp);

    bridge.close();
    QCOMPARE(hungUp.count(), 1);
    QVERIFY(!bridge.isOpen());
    QVERIFY(bridge.path(Side::A).isEmpty());
    QCOMPARE(bridge.clientBaud(Side::A), 0);

    a.write(QByteArrayLiteral("anyone there?"));
    const auto sawError = [&errors] {
        for (const QList<QVariant> &args : errors) {
            if (args.at(0).value<QSerialPort::SerialPortError>() != QSerialPort::NoError)
                return true;
        }
        return false;
    };
    QTRY_VERIFY(sawError());
    a.port().close(); // must return, not hang on a hung-up tty

    bridge.close();
    QCOMPARE(hungUp.count(), 1);
    bridge.inject(Side::A, QByteArrayLiteral("ignored")); // harmless when closed
}

void TestPtyBridge::closingFromInsideTapOrSignalIsSafe()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    QSignalSpy hungUp(&bridge, &PtyBridge::hungUp);
    int tapCalls = 0;
    bridge.setTap([&](Side, const QByteArray &bytes) {
        ++tapCalls;
        bridge.setTap({}); // replacing the running tap must not destroy it mid-call
        bridge.close();
        return bytes;
    });
    {
        Peer a(bridge.path(Side::A));
        OPEN_PEER(a);
        a.write(QByteArrayLiteral("bye"));
        QTRY_COMPARE(hungUp.count(), 1);
        QCOMPARE(tapCalls, 1);
    }

    OPEN_BRIDGE(bridge);
    connect(&bridge, &PtyBridge::bytesSeen, &bridge, [&bridge] { bridge.close(); });
    Peer b(bridge.path(Side::B));
    OPEN_PEER(b);
    b.write(QByteArrayLiteral("bye"));
    QTRY_COMPARE(hungUp.count(), 2);
    QCOMPARE(tapCalls, 1);
    QVERIFY(!bridge.isOpen());
}

void TestPtyBridge::openTwiceFails()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    const QString pathA = bridge.path(Side::A);
    QString error;
    QVERIFY(!bridge.open(&error));
    QVERIFY(!error.isEmpty());
    QCOMPARE(bridge.path(Side::A), pathA);
    bridge.close();
    OPEN_BRIDGE(bridge); // reopens after a hang-up
    Peer a(bridge.path(Side::A));
    Peer b(bridge.path(Side::B));
    OPEN_PEER(a);
    OPEN_PEER(b);
    a.write(QByteArrayLiteral("again"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("again"));
}

void TestPtyBridge::createLinkMakesWorkingSymlinkAndRemovesIt()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString linkA = dir.filePath(QStringLiteral("ttyA"));
    const QString linkB = dir.filePath(QStringLiteral("ttyB"));
    // A stale link from an earlier run is replaced, even a dangling one.
    QVERIFY(QFile::link(dir.filePath(QStringLiteral("gone")), linkB));

    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    QString error;
    QVERIFY2(bridge.createLink(Side::A, linkA, &error), qPrintable(error));
    QVERIFY2(bridge.createLink(Side::B, linkB, &error), qPrintable(error));
    QVERIFY(QFileInfo(linkA).isSymLink());
    QCOMPARE(QFileInfo(linkA).symLinkTarget(), bridge.path(Side::A));
    QCOMPARE(QFileInfo(linkB).symLinkTarget(), bridge.path(Side::B));

    Peer a(linkA);
    Peer b(linkB);
    OPEN_PEER(a);
    OPEN_PEER(b);
    a.write(QByteArrayLiteral("via link"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("via link"));
    a.port().close();
    b.port().close();

    bridge.close();
    QVERIFY(!QFileInfo(linkA).isSymLink());
    QVERIFY(!QFileInfo::exists(linkA));
    QVERIFY(!QFileInfo(linkB).isSymLink());
    QVERIFY(!bridge.createLink(Side::A, linkA, &error)); // closed: nothing to point at
}

void TestPtyBridge::createLinkRefusesRegularFile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString plain = dir.filePath(QStringLiteral("plain"));
    QFile file(plain);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("keep me");
    file.close();

    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    QString error;
    QVERIFY(!bridge.createLink(Side::A, plain, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(!QFileInfo(plain).isSymLink());
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArrayLiteral("keep me"));
    QVERIFY(!bridge.createLink(Side::A, dir.path(), &error)); // nor a directory
    QVERIFY(QFileInfo(dir.path()).isDir());
}

void TestPtyBridge::destructionRemovesLinkButKeepsForeignOne()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString ours = dir.filePath(QStringLiteral("ours"));
    const QString repointed = dir.filePath(QStringLiteral("repointed"));
    {
        PtyBridge bridge;
        OPEN_BRIDGE(bridge);
        QString error;
        QVERIFY2(bridge.createLink(Side::A, ours, &error), qPrintable(error));
        QVERIFY2(bridge.createLink(Side::B, repointed, &error), qPrintable(error));
        // Someone else takes the name over; the bridge must not delete their link.
        QVERIFY(QFile::remove(repointed));
        QVERIFY(QFile::link(QStringLiteral("/dev/null"), repointed));
    }
    QVERIFY(!QFileInfo(ours).isSymLink());
    QVERIFY(QFileInfo(repointed).isSymLink());
}

void TestPtyBridge::survivesHangUpOfKeptSlave()
{
    PtyBridge bridge;
    OPEN_BRIDGE(bridge);
    const QByteArray pathA = QFile::encodeName(bridge.path(Side::A));
    const int fd = ::open(pathA.constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    QVERIFY(fd >= 0);
    // What a program that had the slave as controlling tty does on exit: hang up every open of
    // it, the bridge's kept fd included. The bridge must keep working for the next program.
    const int rc = ::ioctl(fd, TIOCVHANGUP);
    const int err = errno;
    ::close(fd);
    if (rc != 0)
        QSKIP(
            qPrintable(QStringLiteral("TIOCVHANGUP not permitted: %1").arg(qt_error_string(err))));

    // A round trip through side B lets the event loop deliver side A's hang-up first.
    Peer b(bridge.path(Side::B));
    OPEN_PEER(b);
    bridge.inject(Side::B, QByteArrayLiteral("sync"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("sync"));

    Peer a(bridge.path(Side::A));
    OPEN_PEER(a);
    a.write(QByteArrayLiteral("still here"));
    QTRY_COMPARE(b.received(), QByteArrayLiteral("syncstill here"));
    b.write(QByteArrayLiteral("me too"));
    QTRY_COMPARE(a.received(), QByteArrayLiteral("me too"));
}

#include "testregistry.h"
STEPCOM_TEST(TestPtyBridge, Guiless)
#include "tst_ptybridge.moc"

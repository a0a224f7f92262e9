// Reconnect after a link loss: the session tries again on its own with a growing
// pause, finds a USB adapter that came back under another name by its serial number, sends the
// pending stops first, then reads the status and everything else again.
#include "bus/modbuslink.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/reconnector.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;

namespace {

// A simulated controller behind a named pty link ("ttyUSB0" in a temporary directory), as a
// USB adapter would appear.
std::unique_ptr<SimHost> startSim(const QString &linkPath)
{
    auto host = std::make_unique<SimHost>();
    SimOptions options;
    options.rtu = true;
    options.linkPath = linkPath;
    QString error;
    if (!host->start(options, &error)) {
        qWarning("simulator: %s", qPrintable(error));
        return nullptr;
    }
    return host;
}

QStringList whats(const QSignalSpy &dispatched)
{
    QStringList all;
    for (const QList<QVariant> &args : dispatched)
        all << args.at(1).value<Request>().what;
    return all;
}

QStringList texts(const QSignalSpy &messages)
{
    QStringList all;
    for (const QList<QVariant> &args : messages)
        all << args.at(1).toString();
    return all;
}

} // namespace

class TestReconnect : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_current; // where the adapter is now, for the fake listing
    std::unique_ptr<SimHost> m_host;
    std::unique_ptr<DeviceSession> m_session;

    QString path(const QString &name) const { return m_dir.filePath(name); }

    // The listing a computer gives: one FTDI adapter with its serial number, wherever it is now.
    QList<SerialPortEntry> listing() const
    {
        if (m_current.isEmpty() || !QFileInfo::exists(m_current))
            return {};
        SerialPortEntry e;
        e.portName = QFileInfo(m_current).fileName();
        e.systemLocation = m_current;
        e.description = QStringLiteral("FT232R USB UART");
        e.manufacturer = QStringLiteral("FTDI");
        e.serialNumber = QStringLiteral("A10K3B5Q");
        e.vendorId = 0x0403;
        e.productId = 0x6001;
        return {e};
    }

    void connectAt(const QString &name)
    {
        m_current = path(name);
        m_host = startSim(m_current);
        QVERIFY(m_host);
        Reconnector *r = m_session->connection()->reconnector();
        r->setEnabled(true);
        r->setDelaysMs({150, 300});
        r->setPortLister([this] { return listing(); });
        r->setByIdDirectory(path(QStringLiteral("by-id"))); // none: found by serial number
        LinkSettings s;
        s.portName = m_current;
        s.baud = 9600;
        s.deviceId = 1;
        QSignalSpy read(m_session->parameters(), &SessionParameters::readFinished);
        m_session->connection()->connectTo(s);
        QVERIFY(read.wait(10000));
        QVERIFY(read.first().first().toBool());
    }

    // The adapter is pulled: the pty and its name vanish; the session notices.
    void pull()
    {
        QSignalSpy lost(m_session->connection(), &SessionConnection::linkLost);
        m_host.reset();
        m_current.clear();
        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 10000);
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }
    void init() { m_session = std::make_unique<DeviceSession>(); }
    void cleanup()
    {
        m_session.reset();
        m_host.reset();
    }

    void backUnderAnotherNameStopFirstThenStatus()
    {
        connectAt(QStringLiteral("ttyUSB0"));
        Reconnector *r = m_session->connection()->reconnector();
        // A jog runs when the cable is pulled: its stop is due on reconnect.
        QVERIFY(m_session->jog()->press(1, JogController::Direction::Forward));
        QTRY_VERIFY(m_host->device()->running(1));
        pull();
        QTRY_COMPARE(r->state(), Reconnector::State::Waiting);
        QVERIFY(!m_session->connection()->isConnected());
        // An attempt or two at the old name fails while nothing is plugged in.
        QTRY_VERIFY_WITH_TIMEOUT(r->attempt() >= 2, 5000);
        QCOMPARE(m_session->connection()->linkState(), SessionConnection::LinkState::Disconnected);

        QSignalSpy dispatched(SessionInternals::link(*m_session), &ModbusLink::dispatched);
        QSignalSpy restored(r, &Reconnector::restored);
        QSignalSpy read(m_session->parameters(), &SessionParameters::readFinished);
        // Plugged in again, the system names it ttyUSB1.
        m_current = path(QStringLiteral("ttyUSB1"));
        m_host = startSim(m_current);
        QVERIFY(m_host);
        QTRY_COMPARE_WITH_TIMEOUT(restored.size(), 1, 10000);
        QCOMPARE(m_session->connection()->settings().portName, m_current);
        QVERIFY(read.wait(10000));
        QVERIFY(read.first().first().toBool());
        const QStringList sent = whats(dispatched);
        QVERIFY2(sent.size() >= 3, qPrintable(sent.join(QLatin1Char(','))));
        QCOMPARE(sent.first(), QStringLiteral("motor1.stop")); // the pending stop first
        QVERIFY2(sent.at(1).startsWith(QLatin1String("poll")), qPrintable(sent.at(1)));
        QVERIFY(m_session->connection()->isConnected());
        QCOMPARE(r->state(), Reconnector::State::Idle);
        QVERIFY(m_session->parameters()
                    ->store()
                    ->deviceValue(QStringLiteral("motor1.speed"))
                    .has_value());
    }

    void emergencyStopWhileAwayIsSentFirst()
    {
        connectAt(QStringLiteral("ttyUSB0"));
        pull();
        QSignalSpy messages(m_session.get(), &DeviceSession::message);
        m_session->emergencyStop();
        const QString said = texts(messages).join(QLatin1Char('\n'));
        QVERIFY2(said.contains(QLatin1String("NOT")) && said.contains(QLatin1String("first")),
                 qPrintable(said));
        QSignalSpy dispatched(SessionInternals::link(*m_session), &ModbusLink::dispatched);
        QSignalSpy restored(m_session->connection()->reconnector(), &Reconnector::restored);
        m_current = path(QStringLiteral("ttyUSB0")); // back under its own name this time
        m_host = startSim(m_current);
        QVERIFY(m_host);
        QTRY_COMPARE_WITH_TIMEOUT(restored.size(), 1, 10000);
        QTRY_VERIFY(!dispatched.isEmpty());
        QCOMPARE(whats(dispatched).first(), QStringLiteral("estop"));
    }

    void cancelStopsTrying()
    {
        connectAt(QStringLiteral("ttyUSB0"));
        Reconnector *r = m_session->connection()->reconnector();
        QSignalSpy cancelled(r, &Reconnector::cancelled);
        pull();
        QTRY_COMPARE(r->state(), Reconnector::State::Waiting);
        r->cancel();
        QCOMPARE(cancelled.size(), 1);
        QCOMPARE(r->state(), Reconnector::State::Idle);
        const int attempts = r->attempt();
        m_current = path(QStringLiteral("ttyUSB0"));
        m_host = startSim(m_current);
        QVERIFY(m_host);
        QTest::qWait(800); // longer than every pause: nothing may try again
        QCOMPARE(r->attempt(), attempts);
        QVERIFY(!m_session->connection()->isConnected());
    }

    void userDisconnectIsNoLoss()
    {
        connectAt(QStringLiteral("ttyUSB0"));
        m_session->connection()->disconnectFrom();
        QCOMPARE(m_session->connection()->reconnector()->state(), Reconnector::State::Idle);
    }

    void locateByIdLinkOrSerialNumber()
    {
        Reconnector r;
        QList<SerialPortEntry> ports;
        r.setPortLister([&ports] { return ports; });
        r.setByIdDirectory(path(QStringLiteral("by-id")));
        SerialPortEntry a;
        a.portName = QStringLiteral("ttyUSB0");
        a.systemLocation = QStringLiteral("/dev/ttyUSB0");
        a.serialNumber = QStringLiteral("A10K3B5Q");
        a.vendorId = 0x0403;
        a.productId = 0x6001;
        SerialPortEntry other = a;
        other.portName = QStringLiteral("ttyUSB1");
        other.systemLocation = QStringLiteral("/dev/ttyUSB1");
        other.serialNumber = QStringLiteral("ZZZ");
        ports = {a, other};
        LinkSettings s;
        s.portName = QStringLiteral("/dev/ttyUSB0");
        r.linkOpened(s);
        QCOMPARE(r.locate().portName, QStringLiteral("/dev/ttyUSB0"));
        // Back as ttyUSB2, and someone else's adapter took ttyUSB0.
        a.portName = QStringLiteral("ttyUSB2");
        a.systemLocation = QStringLiteral("/dev/ttyUSB2");
        other.portName = QStringLiteral("ttyUSB0");
        other.systemLocation = QStringLiteral("/dev/ttyUSB0");
        ports = {other, a};
        QCOMPARE(r.locate().portName, QStringLiteral("/dev/ttyUSB2"));
        // Not plugged in: the old name is tried.
        ports = {other};
        QCOMPARE(r.locate().portName, QStringLiteral("/dev/ttyUSB0"));
        // TCP: nothing to look for.
        LinkSettings tcp;
        tcp.transport = LinkSettings::Transport::Tcp;
        tcp.host = QStringLiteral("10.0.0.5");
        r.linkOpened(tcp);
        QCOMPARE(r.locate().host, QStringLiteral("10.0.0.5"));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReconnect, Guiless)
#include "tst_reconnect.moc"

// The window after a link loss: it tries again on its own, shows the countdown and a
// Cancel button in the status bar, and shows the controller's values again when it is back.
#include "base/language.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/reconnector.h"
#include "sim/host/simhost.h"
#include "widgets/docks/linkstatus.h"
#include "window/mainwindow.h"

#include <QApplication>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace stepcom;

class TestReconnectWindow : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;
    std::unique_ptr<SimHost> m_host;
    std::unique_ptr<DeviceSession> m_session;
    std::unique_ptr<MainWindow> m_window;

    QString port() const { return m_dir.filePath(QStringLiteral("ttyUSB0")); }
    void startSim()
    {
        m_host = std::make_unique<SimHost>();
        SimOptions options;
        options.rtu = true;
        options.linkPath = port();
        QString error;
        QVERIFY2(m_host->start(options, &error), qPrintable(error));
    }
    QLabel *countdown() const
    {
        return m_window->findChild<QLabel *>(QStringLiteral("reconnectText"));
    }
    QPushButton *cancel() const
    {
        return m_window->findChild<QPushButton *>(QStringLiteral("reconnectCancel"));
    }
    void pull()
    {
        QSignalSpy lost(m_session->connection(), &SessionConnection::linkLost);
        m_host.reset();
        QTRY_COMPARE_WITH_TIMEOUT(lost.size(), 1, 10000);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
    }

    void init()
    {
        Language::instance().setLanguage(QStringLiteral("en"));
        startSim();
        m_session = std::make_unique<DeviceSession>();
        m_window = std::make_unique<MainWindow>(m_session.get());
        m_window->show();
        QVERIFY(m_session->connection()->reconnector()->isEnabled()); // the window turns it on
        m_session->connection()->reconnector()->setDelaysMs({1500, 3000});
        LinkSettings s;
        s.portName = port();
        s.baud = 9600;
        s.deviceId = 1;
        QSignalSpy read(m_session->parameters(), &SessionParameters::readFinished);
        m_session->connection()->connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QVERIFY(countdown() && cancel());
        QVERIFY(!countdown()->isVisible());
        QVERIFY(!cancel()->isVisible());
    }

    void cleanup()
    {
        m_window.reset();
        m_session.reset();
        m_host.reset();
    }

    void countdownThenBack()
    {
        pull();
        QTRY_VERIFY(countdown()->isVisible());
        QVERIFY(cancel()->isVisible());
        QVERIFY2(countdown()->text().contains(QLatin1String("reconnecting in ")),
                 qPrintable(countdown()->text()));
        QVERIFY2(countdown()->text().contains(QLatin1String(" s")),
                 qPrintable(countdown()->text()));
        QSignalSpy read(m_session->parameters(), &SessionParameters::readFinished);
        startSim();
        QTRY_VERIFY_WITH_TIMEOUT(m_session->connection()->isConnected(), 15000);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000); // everything read again
        QTRY_VERIFY(!countdown()->isVisible());
        QVERIFY(!cancel()->isVisible());
        QTRY_COMPARE(m_window->findChild<LinkStatus *>()->stateText(), QStringLiteral("Connected"));
    }

    void cancelEndsTheWait()
    {
        pull();
        QTRY_VERIFY(cancel()->isVisible());
        QTest::mouseClick(cancel(), Qt::LeftButton);
        QCOMPARE(m_session->connection()->reconnector()->state(), Reconnector::State::Idle);
        QVERIFY(!countdown()->isVisible());
        QVERIFY(!cancel()->isVisible());
        startSim();
        QTest::qWait(2000); // past the first pause: nothing tries again
        QVERIFY(!m_session->connection()->isConnected());
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestReconnectWindow, Gui)
#include "tst_reconnectwindow.moc"

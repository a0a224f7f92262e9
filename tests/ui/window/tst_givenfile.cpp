// A file given to the window (`stepcom FILE`, what a file manager's "Open with StepCom" runs):
// a profile is edited without a controller, a session log or a support bundle is replayed,
// told by what the file holds; a file that is none of them, or cannot be read, is refused
// with a message naming it, and the window stays as it was.
#include "base/language.h"
#include "logbuilder.h"
#include "profile/profiledocument.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "support/supportbundle.h"
#include "window/givenfile.h"
#include "window/mainwindow.h"
#include "window/offlineactions.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace stepcom;

class TestGivenFile : public QObject
{
    Q_OBJECT
    QTemporaryDir dir;

    QString writeFile(const QString &name, const QByteArray &bytes)
    {
        const QString path = dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            return {};
        return path;
    }

    QString sessionLog(const DeviceSession &session, const QString &name)
    {
        const Parameter *speed = session.map().find(QStringLiteral("motor1.speed"));
        test::LogBuilder log;
        log.header();
        log.read(1, speed->address, {321});
        return log.save(dir, name);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QSettings().clear();
        Language::instance().setLanguage(QStringLiteral("en"));
    }

    void profileIsEditedWithoutAController()
    {
        DeviceSession session;
        QString path;
        {
            MainWindow maker(&session);
            QVERIFY(WindowProbe(maker).offlineActions()->newFromFactory());
            path = dir.filePath(QStringLiteral("machine.json"));
            QVERIFY(WindowProbe(maker).offlineActions()->saveFile(path));
            QVERIFY(WindowProbe(maker).offlineActions()->closeFile());
        }
        QString why;
        QCOMPARE(GivenFile::classify(path, &why), GivenFile::Kind::Profile);
        MainWindow window(&session);
        QVERIFY(window.openGivenFile(path));
        QVERIFY(WindowProbe(window).offlineActions()->document()->isOpen());
        QCOMPARE(WindowProbe(window).offlineActions()->document()->path(), path);
        QVERIFY(session.parameters()->store()->isFile());
        QVERIFY(window.windowTitle().contains(QStringLiteral("machine.json")));
    }

    // A log by its first line, whatever its name.
    void sessionLogIsReplayed()
    {
        DeviceSession session;
        MainWindow window(&session);
        const QString path = sessionLog(session, QStringLiteral("from-the-field.txt"));
        QString why;
        QCOMPARE(GivenFile::classify(path, &why), GivenFile::Kind::SessionLog);
        QSignalSpy opened(WindowProbe(window).replayMode(), &ReplayMode::opened);
        QVERIFY(window.openGivenFile(path));
        QVERIFY(opened.wait(10000) || !opened.isEmpty());
        QVERIFY(WindowProbe(window).replayMode()->isActive());
        QCOMPARE(WindowProbe(window).replayMode()->displayName(),
                 QStringLiteral("from-the-field.txt"));
        WindowProbe(window).replayMode()->seek(
            WindowProbe(window).replayMode()->log().durationMs());
        QCOMPARE(session.parameters()->store()->deviceValue(QStringLiteral("motor1.speed")), 321);
    }

    void supportBundleIsReplayed()
    {
        DeviceSession session;
        MainWindow window(&session);
        QDir(dir.path()).mkpath(QStringLiteral("logs"));
        sessionLog(session, QStringLiteral("logs/stepcom-20261124-221000.log"));
        BundleInput input;
        input.logDirectory = dir.filePath(QStringLiteral("logs"));
        const QString zip = dir.filePath(QStringLiteral("stepcom-support-1.zip"));
        QString error;
        QVERIFY2(SupportBundle::create(zip, input, nullptr, &error), qPrintable(error));
        QString why;
        QCOMPARE(GivenFile::classify(zip, &why), GivenFile::Kind::SupportBundle);
        QSignalSpy opened(WindowProbe(window).replayMode(), &ReplayMode::opened);
        QVERIFY(window.openGivenFile(zip));
        QVERIFY(opened.wait(10000) || !opened.isEmpty());
        QVERIFY(WindowProbe(window).replayMode()->displayName().contains(
            QStringLiteral("stepcom-support-1")));
    }

    void otherFilesAreRefusedByName_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("said");
        QTest::newRow("a picture")
            << QStringLiteral("photo.png") << QByteArray("\x89PNG\r\n\x1a\n", 8)
            << QStringLiteral("neither a StepCom profile, a sequence");
        QTest::newRow("missing") << QStringLiteral("gone.json") << QByteArray()
                                 << QStringLiteral("no such file");
        QTest::newRow("broken profile")
            << QStringLiteral("broken.json") << QByteArray("{ \"format\": ") << QString();
    }
    void otherFilesAreRefusedByName()
    {
        QFETCH(QString, name);
        QFETCH(QByteArray, bytes);
        QFETCH(QString, said);
        DeviceSession session;
        MainWindow window(&session);
        const QString path = bytes.isEmpty() ? dir.filePath(name) : writeFile(name, bytes);
        QVERIFY(!window.openGivenFile(path));
        QVERIFY(!session.parameters()->store()->isFile());
        QVERIFY(!session.parameters()->store()->isReplay());
        if (said.isEmpty()) // the profile reader says what is wrong, in its own box
            return;
        QVERIFY(WindowProbe(window).givenFileError());
        QVERIFY2(WindowProbe(window).givenFileError()->text().contains(said),
                 qPrintable(WindowProbe(window).givenFileError()->text()));
        QVERIFY(WindowProbe(window).givenFileError()->text().contains(path));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestGivenFile, Gui)
#include "tst_givenfile.moc"

// The writes of the "Jog and home" and "Special modes" pages -- the jog speed's "Apply speed",
// the homing order's "Apply order" and a change of the system mode -- go the window's one way,
// its WriteFlow: the write dialog (or, for a mode, the mode's own question, and no second
// one), the read-back, the outcome said, a refusal too, and the session log.
#include "base/language.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "device/deviceclient.h"
#include "device/parameterstore.h"
#include "pages/modespage.h"
#include "pages/motionpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/sessionlog.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/motion/homingordereditor.h"
#include "widgets/motion/jogpanel.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QWidget>

#include <memory>
#include <optional>

using namespace stepcom;

class TestPageWrites : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<QWidget> dialogs; // the write flow's dialogs open over it, as over the window
    WriteFlow *writes = nullptr;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    qint64 simValue(const QString &key) const { return sim()->value(key).value_or(-99999); }
    ParameterStore *store() const { return session->parameters()->store(); }
    static QStringList keysOf(const QList<ParameterWrite> &writes)
    {
        QStringList keys;
        for (const ParameterWrite &w : writes)
            keys << w.parameter->key;
        return keys;
    }
    // What the session said at the error level while `spy` listened.
    static QStringList errorsSaid(const QSignalSpy &spy)
    {
        QStringList said;
        for (const QList<QVariant> &m : spy) {
            if (m.at(0).value<DeviceSession::Severity>() == DeviceSession::Severity::Error)
                said << m.at(1).toString();
        }
        return said;
    }
    // The outcome of the next write, once the store has taken it.
    struct NextOutcome
    {
        std::optional<WriteOutcome> outcome;
        QMetaObject::Connection connection;
        explicit NextOutcome(DeviceSession *session)
        {
            connection = QObject::connect(session->parameters(), &SessionParameters::writeFinished,
                                          [this](const WriteOutcome &o) {
                                              if (!outcome)
                                                  outcome = o;
                                          });
        }
        ~NextOutcome() { QObject::disconnect(connection); }
    };

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        Language::instance().setLanguage(QStringLiteral("en"));
    }
    void init()
    {
        session = std::make_unique<DeviceSession>();
        dialogs = std::make_unique<QWidget>();
        writes = new WriteFlow(session.get(), dialogs.get());
    }
    void cleanup()
    {
        dialogs.reset();
        session.reset();
    }

    // Apply speed opens the flow's dialog for the speed alone: nothing before it is accepted,
    // nothing when it is cancelled; accepted, it is confirmed, written and read back.
    void applySpeedGoesThroughTheWriteDialog()
    {
        test::connectToSimulator(*session);
        MotionPage page(session.get(), writes);
        JogPanel *p = page.panel(1);
        QSignalSpy confirmed(writes, &WriteFlow::confirmed);
        QVERIFY(store()->edit(QStringLiteral("motor1.microsteps"), 16).isEmpty());
        p->speedField()->enterText(QStringLiteral("450"));
        p->applySpeedButton()->click();
        QVERIFY(writes->dialog());
        QCOMPARE(keysOf(writes->dialog()->writes()), QStringList{QStringLiteral("motor1.speed")});
        QVERIFY(writes->dialog()->problems().isEmpty()); // a speed the review has nothing against
        writes->dialog()->reject();
        QVERIFY(test::waitForStatusCycles(*session)); // a write would have gone out by then
        QCOMPARE(simValue(QStringLiteral("motor1.speed")), 300);
        QVERIFY(confirmed.isEmpty());
        QCOMPARE(store()->state(QStringLiteral("motor1.speed")), ParameterStore::State::Edited);
        QVERIFY(p->applySpeedButton()->isEnabled()); // still to apply

        NextOutcome next(session.get());
        p->applySpeedButton()->click();
        QVERIFY(writes->dialog());
        writes->dialog()->accept();
        QCOMPARE(confirmed.size(), 1);
        QCOMPARE(confirmed.first().first().toString(), QStringLiteral("motor1.speed = 450"));
        QTRY_VERIFY(next.outcome);
        QVERIFY(next.outcome->verified(QStringLiteral("motor1.speed"))); // read back equal
        QCOMPARE(simValue(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(store()->state(QStringLiteral("motor1.speed")), ParameterStore::State::InSync);
        QCOMPARE(store()->state(QStringLiteral("motor1.microsteps")),
                 ParameterStore::State::Edited);
    }

    // A speed the controller refuses is said as an error, and the speed is not taken as written.
    void aRefusedJogSpeedIsReported()
    {
        test::connectToSimulator(*session);
        MotionPage page(session.get(), writes);
        JogPanel *p = page.panel(2);
        p->speedField()->enterText(QStringLiteral("450"));
        QSignalSpy messages(session.get(), &DeviceSession::message);
        NextOutcome next(session.get());
        p->applySpeedButton()->click();
        QVERIFY(writes->dialog());
        sim()->setLacking({QStringLiteral("motor2.speed")}); // answers it with exception 02
        writes->dialog()->accept();
        QTRY_VERIFY(next.outcome);
        QVERIFY(!next.outcome->ok);
        QVERIFY(next.outcome->refused.contains(QStringLiteral("motor2.speed")));
        QVERIFY2(!errorsSaid(messages).isEmpty(), "the refusal was not said");
        QCOMPARE(simValue(QStringLiteral("motor2.speed")), 300);
        QVERIFY(store()->state(QStringLiteral("motor2.speed")) != ParameterStore::State::InSync);
    }

    // Apply order: the flow's dialog with both slots of the order and nothing else.
    void applyOrderGoesThroughTheWriteDialog()
    {
        test::connectToSimulator(*session);
        MotionPage page(session.get(), writes);
        QSignalSpy confirmed(writes, &WriteFlow::confirmed);
        QVERIFY(store()->edit(QStringLiteral("motor1.speed"), 450).isEmpty());
        QVERIFY(page.homingOrder()->choose(1, 0));
        QVERIFY(page.homingOrder()->choose(0, 2));
        page.applyOrderButton()->click();
        QVERIFY(writes->dialog());
        QCOMPARE(keysOf(writes->dialog()->writes()),
                 (QStringList{QStringLiteral("homing.first"), QStringLiteral("homing.second")}));
        writes->dialog()->reject();
        QVERIFY(test::waitForStatusCycles(*session)); // a write would have gone out by then
        QCOMPARE(simValue(QStringLiteral("homing.first")), 1);
        QVERIFY(page.applyOrderButton()->isEnabled());

        NextOutcome next(session.get());
        page.applyOrderButton()->click();
        QVERIFY(writes->dialog());
        writes->dialog()->accept();
        QCOMPARE(confirmed.size(), 1);
        QCOMPARE(confirmed.first().first().toString(),
                 QStringLiteral("homing.first = 2, homing.second = 0"));
        QTRY_VERIFY(next.outcome);
        QVERIFY(next.outcome->ok);
        QCOMPARE(simValue(QStringLiteral("homing.first")), 2);
        QCOMPARE(simValue(QStringLiteral("homing.second")), 0);
        QCOMPARE(store()->state(QStringLiteral("motor1.speed")), ParameterStore::State::Edited);
    }

    // A mode: the mode's own question (with the review in it) is the only one; on Yes the flow
    // confirms, writes and reads it back. A refusal is said.
    void aModeIsAskedOnceThenConfirmedAndVerified()
    {
        test::connectToSimulator(*session);
        ModesPage page(session.get(), writes);
        QSignalSpy confirmed(writes, &WriteFlow::confirmed);
        NextOutcome next(session.get());
        page.chooseMode(4);
        QVERIFY(page.confirmation());
        QVERIFY(page.confirmation()->informativeText().contains(
            QLatin1String("ignores the limit settings"))); // the review's question, in it
        page.confirmation()->button(QMessageBox::Yes)->click();
        QVERIFY(!writes->dialog()); // no second question
        QCOMPARE(confirmed.size(), 1);
        QCOMPARE(confirmed.first().first().toString(), QStringLiteral("mode.system = 4"));
        QTRY_VERIFY(next.outcome);
        QVERIFY(next.outcome->verified(QStringLiteral("mode.system")));
        QCOMPARE(simValue(QStringLiteral("mode.system")), 4);
        QCOMPARE(store()->state(QStringLiteral("mode.system")), ParameterStore::State::InSync);

        QSignalSpy messages(session.get(), &DeviceSession::message);
        NextOutcome refused(session.get());
        QTRY_VERIFY(page.modeBox()->isEnabled());
        page.chooseMode(0);
        QVERIFY(page.confirmation());
        sim()->setLacking({QStringLiteral("mode.system")}); // answers it with exception 02
        page.confirmation()->button(QMessageBox::Yes)->click();
        QTRY_VERIFY(refused.outcome);
        QVERIFY(refused.outcome->refused.contains(QStringLiteral("mode.system")));
        QVERIFY2(!errorsSaid(messages).isEmpty(), "the refusal was not said");
        QCOMPARE(simValue(QStringLiteral("mode.system")), 4);
    }

    // Not connected, or nothing to write: the flow confirms and sends nothing.
    void writeConfirmedSendsNothingWhileDisconnected()
    {
        const Parameter *p = session->map().find(QStringLiteral("mode.system"));
        QVERIFY(p);
        QSignalSpy confirmed(writes, &WriteFlow::confirmed);
        QVERIFY(!writes->writeConfirmed({ParameterWrite{p, 3}}));
        test::connectToSimulator(*session);
        QVERIFY(!writes->writeConfirmed({}));
        QVERIFY(confirmed.isEmpty());
    }

    // In the window the three go through its own flow: its dialog, and its session log.
    void theWindowLogsEveryOneOfThem()
    {
        QTemporaryDir logs;
        MainWindow window(session.get());
        WindowProbe probe(window);
        probe.sessionLog()->setDirectory(logs.path());
        window.resize(1100, 800);
        window.show();
        test::connectToSimulator(*session);
        MotionPage *motion = probe.motionPage();
        ModesPage *modes = nullptr;
        for (Page *page : probe.pages()) {
            if (auto *m = qobject_cast<ModesPage *>(page))
                modes = m;
        }
        QVERIFY(motion && modes);
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);

        motion->panel(1)->speedField()->enterText(QStringLiteral("450"));
        motion->panel(1)->applySpeedButton()->click();
        QTRY_VERIFY(probe.writeDialog() && probe.writeDialog()->isVisible());
        QCOMPARE(keysOf(probe.writeDialog()->writes()),
                 QStringList{QStringLiteral("motor1.speed")});
        probe.writeDialog()->accept();
        QTRY_COMPARE(written.size(), 1);

        QVERIFY(motion->homingOrder()->choose(1, 0));
        motion->applyOrderButton()->click();
        QTRY_VERIFY(probe.writeDialog() && probe.writeDialog()->isVisible());
        probe.writeDialog()->accept();
        QTRY_COMPARE(written.size(), 2);

        modes->chooseMode(1);
        QVERIFY(modes->confirmation());
        modes->confirmation()->button(QMessageBox::Yes)->click();
        QVERIFY(!probe.writeDialog());
        QTRY_COMPARE(written.size(), 3);
        QTRY_COMPARE(simValue(QStringLiteral("mode.system")), 1);

        QFile log(probe.sessionLog()->currentFile());
        QVERIFY2(log.open(QIODevice::ReadOnly), qPrintable(log.fileName()));
        const QByteArray logged = log.readAll();
        for (const char *line :
             {"write changes: motor1.speed = 450", "write changes: homing.second = 0",
              "write changes: mode.system = 1"})
            QVERIFY2(logged.contains(line), qPrintable(QString::fromUtf8(logged.right(3000))));
        QCOMPARE(simValue(QStringLiteral("motor1.speed")), 450);
        QCOMPARE(simValue(QStringLiteral("homing.second")), 0);
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestPageWrites, Gui)
#include "tst_pagewrites.moc"

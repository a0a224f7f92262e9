#include "base/language.h"
#include "device/parameterstore.h"
#include "pages/devicepage.h"
#include "pages/inputspage.h"
#include "pages/motorpage.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/fields/derivedvalues.h"
#include "widgets/fields/led.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"
#include "widgets/fields/wiringwarnings.h"

#include "testmaps.h"

#include "darkpalette.h"
#include "screenshots.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include <memory>

using namespace stepcom;

// The motor, inputs and device pages against the built-in simulator, offscreen.
class TstPages : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    qint64 simValue(const char *key) const { return sim()->value(QLatin1String(key)).value_or(-1); }
    void connectSim() { test::connectToSimulator(*session); }
    void readAgain()
    {
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        session->parameters()->readAll();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 5000);
        QVERIFY(read.at(0).at(0).toBool());
    }
    static QString lineText(ParameterField *field)
    {
        auto *line = qobject_cast<QLineEdit *>(field->editor());
        return line ? line->text() : QString();
    }

private Q_SLOTS:
    void init() { session = std::make_unique<DeviceSession>(); }
    void cleanup() { session.reset(); }

    void motorPageShowsItsOwnMotor()
    {
        connectSim();
        QVERIFY(sim()->setValue(QStringLiteral("motor2.microsteps"), 16));
        QVERIFY(sim()->setValue(QStringLiteral("motor2.speed"), 450));
        readAgain();
        MotorPage page(session.get(), 2);
        QCOMPARE(page.title(), QStringLiteral("Motor 2"));
        QCOMPARE(page.keys().size(), 8);
        for (const QString &k : page.keys())
            QVERIFY2(k.startsWith(QLatin1String("motor2.")), qPrintable(k));
        QCOMPARE(lineText(page.form()->field(QStringLiteral("motor2.microsteps"))),
                 QStringLiteral("16"));
        QCOMPARE(lineText(page.form()->field(QStringLiteral("motor2.speed"))),
                 QStringLiteral("450"));
        QCOMPARE(lineText(page.form()->field(QStringLiteral("motor2.step_angle"))),
                 QStringLiteral("1.80"));
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::PulsesPerRev),
                 QStringLiteral("3200 pulses/rev"));
        // 450 rpm × 3200 / 60
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::PulseRate),
                 QStringLiteral("24000 Hz"));
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::SpeedPerSecond),
                 QStringLiteral("37.5 mm/s"));
        MotorPage first(session.get(), 1);
        QCOMPARE(lineText(first.form()->field(QStringLiteral("motor1.microsteps"))),
                 QStringLiteral("8"));
        QCOMPARE(first.derivedValues()->text(DerivedValues::Row::PulsesPerRev),
                 QStringLiteral("1600 pulses/rev"));
        QCOMPARE(first.derivedValues()->text(DerivedValues::Row::RevolutionsPerMove),
                 QStringLiteral("2 rev"));
        QCOMPARE(first.derivedValues()->text(DerivedValues::Row::Ramp), QStringLiteral("95 ms"));
    }

    void unknownValuesShowADash()
    {
        MotorPage page(session.get(), 1); // never connected
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::PulsesPerRev), QStringLiteral("—"));
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::MoveTime), QStringLiteral("—"));
        QVERIFY(!page.stopButton()->isEnabled());
    }

    void anyMotorCountOfTheMap()
    {
        QStringList errors;
        const auto map = stepcom::test::builtinMapWithMotors(3, &errors);
        QVERIFY2(map, qPrintable(errors.join(QLatin1Char('\n'))));
        DeviceSession three(*map);
        MotorPage page(&three, 3);
        QCOMPARE(page.title(), QStringLiteral("Motor 3"));
        QCOMPARE(page.keys().size(), 8);
        QVERIFY(page.keys().contains(QStringLiteral("motor3.move_distance")));
        InputsPage inputs(&three);
        QCOMPARE(inputs.keys().size(), 9);
        QVERIFY(inputs.field(3, QStringLiteral("home_input")));
    }

    void editingIsHeldAndDerivedValuesFollow()
    {
        connectSim();
        MotorPage page(session.get(), 1);
        const QString before = page.derivedValues()->text(DerivedValues::Row::MoveTime);
        page.form()->field(QStringLiteral("motor1.microsteps"))->enterText(QStringLiteral("16"));
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor1.microsteps")),
                 ParameterStore::State::Edited);
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::PulsesPerRev),
                 QStringLiteral("3200 pulses/rev"));
        QCOMPARE(page.derivedValues()->text(DerivedValues::Row::PulsesPerMove),
                 QStringLiteral("6400 pulses"));
        QVERIFY(page.derivedValues()->text(DerivedValues::Row::MoveTime) != before);
        page.form()->field(QStringLiteral("motor1.pitch"))->enterText(QStringLiteral("0"));
        QVERIFY(session->parameters()->store()->state(QStringLiteral("motor1.pitch")) !=
                ParameterStore::State::Edited);
        // Nothing was written: the simulator still holds the old value after a few poll cycles.
        QVERIFY(test::waitForStatusCycles(*session, 3));
        QCOMPARE(simValue("motor1.microsteps"), 8);
        QVERIFY(session->parameters()->store()->hasEdits());
    }

    void stopButtonStopsTheMotor()
    {
        connectSim();
        MotorPage page(session.get(), 2);
        QVERIFY(page.stopButton()->isEnabled());
        QVERIFY(sim()->command(QStringLiteral("motor2.forward")));
        QVERIFY(sim()->running(2));
        QTest::mouseClick(page.stopButton(), Qt::LeftButton);
        QTRY_VERIFY(!sim()->running(2));
        session->connection()->disconnectFrom();
        QTRY_VERIFY(!page.stopButton()->isEnabled());
    }

    void inputsPageWarnsAndShowsLiveInputs()
    {
        connectSim();
        InputsPage page(session.get());
        QCOMPARE(page.title(), QStringLiteral("Inputs and limits"));
        QCOMPARE(page.keys().size(), 6);
        QVERIFY(page.warnings().isEmpty());
        QCOMPARE(page.warningsView()->texts(),
                 QStringList{QStringLiteral("No suspicious wiring found.")});

        page.field(1, QStringLiteral("limit_positive"))->enterText(QStringLiteral("IN2"));
        QCOMPARE(
            *session->parameters()->store()->shownValue(QStringLiteral("motor1.limit_positive")),
            2);
        QVERIFY(page.warningsView()->texts().contains(
            QStringLiteral("Motor 1: IN2 is both the positive and the negative limit")));
        QCOMPARE(simValue("motor1.limit_positive"), 1); // held, not written

        QCOMPARE(page.inputCount(), 4);
        QCOMPARE(page.outputCount(), 3);
        QTRY_COMPARE(page.inputLed(3)->state(), Led::State::Off);
        sim()->setInput(3, SimDevice::InputForce::On);
        QTRY_COMPARE(page.inputLed(3)->state(), Led::State::On);
        QCOMPARE(page.inputLed(1)->state(), Led::State::Off);
        sim()->setInput(3, SimDevice::InputForce::Off);
        QTRY_COMPARE(page.inputLed(3)->state(), Led::State::Off);
        QVERIFY(sim()->command(QStringLiteral("output1_on")));
        QTRY_COMPARE(page.outputLed(1)->state(), Led::State::On);

        session->connection()->disconnectFrom();
        QCOMPARE(page.inputLed(3)->state(), Led::State::Unknown);
    }

    void deviceIdChangeFollowsTheController()
    {
        connectSim();
        DevicePage page(session.get());
        QCOMPARE(page.idEditor()->value(), 1);
        QVERIFY(!page.applyLinkButton()->isEnabled()); // nothing to change yet
        page.idEditor()->setValue(5);
        QVERIFY(page.applyLinkButton()->isEnabled());
        QTest::mouseClick(page.applyLinkButton(), Qt::LeftButton);
        QMessageBox *box = page.confirmation();
        QVERIFY(box);
        QVERIFY2(box->text().contains(QLatin1String("ID 5")), qPrintable(box->text()));
        QCOMPARE(simValue("device.id"), 1); // asking changes nothing
        QSignalSpy changed(session->line(), &SessionLine::linkChanged);
        box->button(QMessageBox::Yes)->click();
        QTRY_COMPARE_WITH_TIMEOUT(changed.size(), 1, 5000);
        QCOMPARE(sim()->deviceId(), 5);
        QCOMPARE(session->connection()->settings().deviceId, 5);
        QVERIFY2(page.linkStatus().contains(QLatin1String("answers at ID 5")),
                 qPrintable(page.linkStatus()));
        QVERIFY(page.reconnectButton()->isHidden());
        readAgain(); // the session reads at the new id
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("device.id")), 5);
        QCOMPARE(page.idEditor()->value(), 5);
    }

    // The change asks whether to save to flash (yes by default): saved, the id survives the
    // next power-off; not saved, the controller is back at the old one.
    void anIdChangeIsSavedWhenAsked_data()
    {
        QTest::addColumn<bool>("save");
        QTest::addColumn<int>("idAfter");
        QTest::newRow("saved") << true << 6;
        QTest::newRow("not saved") << false << 1;
    }
    void anIdChangeIsSavedWhenAsked()
    {
        QFETCH(bool, save);
        QFETCH(int, idAfter);
        connectSim();
        DevicePage page(session.get());
        page.idEditor()->setValue(6);
        QTest::mouseClick(page.applyLinkButton(), Qt::LeftButton);
        QMessageBox *box = page.confirmation();
        QVERIFY(box && box->checkBox());
        QVERIFY(box->checkBox()->isChecked());
        QVERIFY(!box->checkBox()->text().isEmpty());
        box->checkBox()->setChecked(save);
        QSignalSpy saved(session.get(), &DeviceSession::commandFinished);
        box->button(QMessageBox::Yes)->click();
        QTRY_COMPARE_WITH_TIMEOUT(sim()->deviceId(), 6, 5000);
        if (save)
            QTRY_COMPARE_WITH_TIMEOUT(saved.size(), 1, 10000);
        sim()->powerCycle(1);
        QTRY_VERIFY_WITH_TIMEOUT(!sim()->isPoweredOff(), 10000);
        QCOMPARE(sim()->deviceId(), idAfter);
    }

    void failedIdChangeOffersTheOldSettings()
    {
        connectSim();
        DevicePage page(session.get());
        page.idEditor()->setValue(7);
        QTest::mouseClick(page.applyLinkButton(), Qt::LeftButton);
        QVERIFY(page.confirmation());
        test::simHost(*session)->stop(); // the controller is gone: nothing will answer
        QSignalSpy failed(session->line(), &SessionLine::linkChangeFailed);
        page.confirmation()->button(QMessageBox::Yes)->click();
        QTRY_COMPARE_WITH_TIMEOUT(failed.size(), 1, 10000);
        QVERIFY2(page.linkStatus().contains(QLatin1String("does not answer")),
                 qPrintable(page.linkStatus()));
        QVERIFY2(page.linkStatus().contains(QLatin1String("ID 1")), qPrintable(page.linkStatus()));
        QVERIFY(!page.reconnectButton()->isHidden());
        QVERIFY(page.reconnectButton()->isEnabled());
        const LinkSettings previous = failed.at(0).at(0).value<LinkSettings>();
        QCOMPARE(previous.deviceId, 1);
        QSignalSpy attempt(session->connection(), &SessionConnection::connected);
        QTest::mouseClick(page.reconnectButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(attempt.size(), 1, 5000);
        QCOMPARE(session->connection()->settings().deviceId, 1); // it tried the old settings
    }

    void factoryResetSaysWhatIsLost()
    {
        connectSim();
        QVERIFY(sim()->setValue(QStringLiteral("motor1.speed"), 600));
        QVERIFY(sim()->setValue(QStringLiteral("motor2.limit_positive"), 0));
        readAgain();
        DevicePage page(session.get());
        QTest::mouseClick(page.factoryResetButton(), Qt::LeftButton);
        QMessageBox *box = page.confirmation();
        QVERIFY(box);
        const QString said = box->text() + box->informativeText();
        for (const char *part : {"every motor parameter", "limit and home inputs", "homing order",
                                 "arc and line interpolation", "system mode",
                                 "device ID (1) and the baud rate (9600) are kept"})
            QVERIFY2(said.contains(QLatin1String(part)), part);
        box->button(QMessageBox::Cancel)->click();
        QTRY_VERIFY(!page.confirmation());
        QVERIFY(test::waitForStatusCycles(*session)); // a reset would have gone out by then
        QCOMPARE(simValue("motor1.speed"), 600);      // cancelled: nothing sent

        QTest::mouseClick(page.factoryResetButton(), Qt::LeftButton);
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        page.confirmation()->button(QMessageBox::Yes)->click();
        QTRY_COMPARE_WITH_TIMEOUT(simValue("motor1.speed"), 300, 5000);
        QCOMPARE(simValue("motor2.limit_positive"), 3);
        QCOMPARE(sim()->deviceId(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1,
                                  5000); // the session reads what the controller holds now
        QCOMPARE(*session->parameters()->store()->deviceValue(QStringLiteral("motor1.speed")), 300);
        QVERIFY2(page.flashStatus().contains(QLatin1String("restored")),
                 qPrintable(page.flashStatus()));
    }

    void unsavedToFlashIsShownUntilSaved()
    {
        connectSim();
        DevicePage page(session.get());
        QVERIFY(!page.unsavedWarningShown());
        QVERIFY(
            session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 420).isEmpty());
        QSignalSpy written(session->parameters(), &SessionParameters::writeFinished);
        session->parameters()->writeChanges(); // what MainWindow's "Write changes" does
        QTRY_COMPARE(written.size(), 1);
        QVERIFY(page.unsavedWarningShown());
        QTest::mouseClick(page.saveButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!page.unsavedWarningShown(), 5000);
        QVERIFY2(page.flashStatus().startsWith(QLatin1String("Saved")),
                 qPrintable(page.flashStatus()));
    }

    void languageSwitchRetranslatesMapTexts()
    {
        connectSim();
        InputsPage page(session.get());
        const QLabel *line = page.findChild<QLabel *>(QStringLiteral("systemModeLine"));
        QVERIFY(line);
        const auto modeLine = [line] { return line->text(); };
        QVERIFY2(modeLine().contains(QLatin1String("Normal")), qPrintable(modeLine()));
        Language::instance().setLanguage(QStringLiteral("zh_CN"));
        QTRY_VERIFY2(modeLine().contains(QStringLiteral("常规模式")), qPrintable(modeLine()));
        Language::instance().setLanguage(QStringLiteral("en"));
        QTRY_VERIFY2(modeLine().contains(QLatin1String("Normal")), qPrintable(modeLine()));
    }

    // The motor, inputs and device pages in both languages, light and dark, with edits, a
    // wiring warning and an input on; a link change that fails. Each picture is checked.
    // STEPCOM_SCREENSHOTS=/tmp/shots tests_ui tst_pages screenshots keeps them to look at.
    void screenshots()
    {
        const test::ScreenshotDir dir;
        QVERIFY(dir.isValid());
        connectSim();
        session->parameters()->store()->edit(QStringLiteral("motor1.speed"), 450);
        session->parameters()->store()->edit(QStringLiteral("motor1.limit_positive"), 2);
        session->parameters()->store()->edit(QStringLiteral("motor2.home_input"), 3);
        session->parameters()->store()->setUnsavedToFlash(true);
        sim()->setInput(4, SimDevice::InputForce::On);
        QTRY_VERIFY_WITH_TIMEOUT(
            session->parameters()->store()->deviceValue(QStringLiteral("io.in4")) == 1, 10000);
        const QPalette dark = stepcom::test::darkPalette();
        const QPalette light = QApplication::palette();
        for (const QString &lang : {QStringLiteral("en"), QStringLiteral("zh_CN")}) {
            Language::instance().setLanguage(lang);
            for (const bool isDark : {false, true}) {
                QApplication::setPalette(isDark ? dark : light);
                MotorPage motor(session.get(), 1);
                InputsPage inputs(session.get());
                DevicePage device(session.get());
                const QString suffix = lang + (isDark ? QStringLiteral("-dark") : QString());
                for (auto [page, name] : {std::pair<Page *, const char *>{&motor, "motor"},
                                          {&inputs, "inputs"},
                                          {&device, "device"}}) {
                    page->resize(page->sizeHint().expandedTo(QSize(900, 560)));
                    page->show();
                    QVERIFY(QTest::qWaitForWindowExposed(page));
                    const QString problem = test::saveAndCheckGrab(
                        page,
                        dir.filePath(QStringLiteral("%1-%2.png").arg(QLatin1String(name), suffix)));
                    QVERIFY2(problem.isEmpty(), qPrintable(problem));
                }
            }
        }
        QApplication::setPalette(light);
        Language::instance().setLanguage(QStringLiteral("en"));
        DevicePage failed(session.get());
        failed.resize(900, 560);
        failed.show();
        failed.idEditor()->setValue(9);
        failed.requestLinkChange();
        QVERIFY(failed.confirmation());
        const QString confirm = test::saveAndCheckGrab(
            failed.confirmation(), dir.filePath(QStringLiteral("device-confirm.png")));
        QVERIFY2(confirm.isEmpty(), qPrintable(confirm));
        test::simHost(*session)->stop();
        QSignalSpy done(session->line(), &SessionLine::linkChangeFailed);
        failed.confirmation()->button(QMessageBox::Yes)->click();
        QTRY_COMPARE_WITH_TIMEOUT(done.size(), 1, 10000);
        const QString problem =
            test::saveAndCheckGrab(&failed, dir.filePath(QStringLiteral("device-failed.png")));
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TstPages, Gui)
#include "tst_pages.moc"

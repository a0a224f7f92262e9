#include "base/emergencystop.h"
#include "base/language.h"
#include "base/page.h"
#include "base/writechangesdialog.h"
#include "bus/modbuslink.h"
#include "pages/connectionpage.h"
#include "pages/devicepage.h"
#include "scripteddevice.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionline.h"
#include "session/parts/sessionparameters.h"
#include "session/sessioninternals.h"
#include "sim/host/simhost.h"
#include "sim/model/simdevice.h"
#include "simsession.h"
#include "widgets/docks/linkstatus.h"
#include "widgets/docks/messageview.h"
#include "widgets/docks/trafficview.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"
#include "window/mainwindow.h"
#include "window/windowprobe.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTest>
#include <QToolButton>

using namespace stepcom;

namespace {
// The window's insides (docks, pages, actions, open dialogs) are reached through WindowProbe;
// MainWindow keeps public only what the program calls. Each concept: whether W offers it.
template<class W>
concept OffersDocks = requires(W &w)
{
    w.machineStrip();
}
|| requires(W &w)
{
    w.statusDock();
}
|| requires(W &w)
{
    w.trafficView();
};
template<class W>
concept OffersPages = requires(W &w)
{
    w.pages();
}
|| requires(W &w)
{
    w.showPage(0);
}
|| requires(W &w)
{
    w.sidebar();
};
template<class W>
concept OffersDialogs = requires(W &w)
{
    w.writeDialog();
}
|| requires(W &w)
{
    w.closeQuestion();
}
|| requires(W &w)
{
    w.action(QString());
};
template<class W>
concept OffersWhatTheProgramCalls = requires(W &w)
{
    w.showOnScreen();
    w.openGivenFile(QString());
    w.pendantActions();
    w.listenMode();
};
static_assert(!OffersDocks<MainWindow> && !OffersPages<MainWindow> && !OffersDialogs<MainWindow>);
static_assert(OffersDocks<WindowProbe> && OffersPages<WindowProbe> && OffersDialogs<WindowProbe>);
static_assert(OffersWhatTheProgramCalls<MainWindow>);
} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT
    std::unique_ptr<DeviceSession> session;
    std::unique_ptr<MainWindow> window;

    SimDevice *sim() const { return test::simHost(*session)->device(); }
    ParameterField *field(const QString &key) const
    {
        for (ParameterField *f : window->findChildren<ParameterField *>()) {
            if (f->parameter().key == key)
                return f;
        }
        return nullptr;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
    }

    void init()
    {
        Language::instance().setLanguage(QStringLiteral("en"));
        session = std::make_unique<DeviceSession>();
        window = std::make_unique<MainWindow>(session.get());
        window->show();
        QSignalSpy read(session->parameters(), &SessionParameters::readFinished);
        test::useBuiltinSimulator(*session);
        session->connection()->connectSimulator();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
    }

    void cleanup()
    {
        window.reset();
        session.reset();
    }

    void editWriteAndTheSimulatorHoldsIt()
    {
        ParameterField *speed = field(QStringLiteral("motor1.speed"));
        QVERIFY(speed);
        speed->enterText(QStringLiteral("450"));
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor1.speed")),
                 ParameterStore::State::Edited);
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300); // nothing written yet
        QVERIFY(WindowProbe(*window).action(QStringLiteral("writeChanges"))->isEnabled());
        WindowProbe(*window).action(QStringLiteral("writeChanges"))->trigger();
        QTRY_VERIFY(WindowProbe(*window).writeDialog() &&
                    WindowProbe(*window).writeDialog()->isVisible());
        // the dialog shows what will change before anything is sent
        QTableWidget *table = WindowProbe(*window).writeDialog()->table();
        QCOMPARE(table->rowCount(), 1);
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("300 rpm"));
        QCOMPARE(table->item(0, 3)->text(), QStringLiteral("450 rpm"));
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300);
        WindowProbe(*window)
            .writeDialog()
            ->findChild<QPushButton *>(QStringLiteral("writeButton"))
            ->click();
        QTRY_COMPARE(*sim()->value(QStringLiteral("motor1.speed")), 450);
        QTRY_COMPARE(session->parameters()->store()->state(QStringLiteral("motor1.speed")),
                     ParameterStore::State::InSync);
        QVERIFY(session->parameters()->store()->unsavedToFlash());
    }

    void rejectedValueWritesNothing()
    {
        int writes = 0;
        connect(SessionInternals::link(*session), &ModbusLink::dispatched, this,
                [&writes](quint64, const Request &r) {
                    writes += r.type != Request::Type::ReadHolding ? 1 : 0;
                });
        ParameterField *speed = field(QStringLiteral("motor1.speed"));
        QSignalSpy rejected(speed, &ParameterField::rejected);
        speed->enterText(QStringLiteral("99999"));
        QCOMPARE(rejected.size(), 1);
        // The reason is beside the field, in words: label, range and unit, no internal key.
        const QString why =
            QStringLiteral("Speed: 99999 is outside the allowed range 1 – 3000 rpm.");
        QCOMPARE(rejected.at(0).at(0).toString(), why);
        QVERIFY(!speed->reasonLabel()->isHidden());
        QCOMPARE(speed->reasonLabel()->text(), why);
        QVERIFY(!speed->reasonLabel()->text().contains(QLatin1String("motor1.")));
        auto *line = qobject_cast<QLineEdit *>(speed->editor());
        QCOMPARE(line->text(), QStringLiteral("99999")); // kept for correction
        QVERIFY(!session->parameters()->store()->hasEdits());
        QVERIFY(!WindowProbe(*window).action(QStringLiteral("writeChanges"))->isEnabled());
        QVERIFY(test::waitForStatusCycles(*session)); // a write would have gone out by then
        QCOMPARE(writes, 0);
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300);

        // Not a number, then a valid value: the red and the reason go at once.
        speed->enterText(QStringLiteral("abc"));
        QCOMPARE(speed->rejectionText(),
                 QStringLiteral("Speed: “abc” is not a number. Allowed: 1 – 3000 rpm."));
        speed->enterText(QStringLiteral("-100"));
        QVERIFY(speed->rejectionText().contains(QLatin1String("-100 is outside")));
        speed->enterText(QStringLiteral("400"));
        QVERIFY(speed->rejectionText().isEmpty());
        QVERIFY(speed->reasonLabel()->isHidden());
        QCOMPARE(session->parameters()->store()->state(QStringLiteral("motor1.speed")),
                 ParameterStore::State::Edited);
        // Revert drops a refused text too, and a write never leaves a stale reason behind.
        speed->enterText(QStringLiteral("0"));
        QVERIFY(!speed->rejectionText().isEmpty());
        WindowProbe(*window).action(QStringLiteral("revert"))->trigger();
        QVERIFY(speed->rejectionText().isEmpty());
        QCOMPARE(line->text(), QStringLiteral("300"));
    }

    // A port with nobody behind it is "not answering", never "Connected"; the window stays on
    // the Connection page with the likely causes, and the counts start again per connection.
    void aSilentPortIsNeverConnected()
    {
        session->connection()->disconnectFrom();
        WindowProbe(*window).showPage(0);
        test::ScriptedDevice device;
        QString error;
        QVERIFY2(device.open(&error), qPrintable(error));
        device.setResponder([](const QByteArray &, int) { return std::nullopt; });
        QList<LinkHealth::State> seen;
        connect(session->connection()->health(), &LinkHealth::stateChanged, this,
                [&seen](LinkHealth::State st) { seen << st; });
        auto *status = window->findChild<LinkStatus *>();
        LinkSettings s;
        s.portName = device.clientPath();
        s.timeoutMs = 100;
        s.retries = 0;
        session->connection()->connectTo(s);
        QTRY_COMPARE(session->connection()->health()->state(), LinkHealth::State::NotAnswering);
        QCOMPARE(status->stateText(), QStringLiteral("Not answering"));
        auto *page = qobject_cast<ConnectionPage *>(WindowProbe(*window).currentPage());
        QVERIFY(page); // no jump to Motor 1 with blank fields
        QVERIFY2(page->statusText().contains(QLatin1String("does not answer")) &&
                     page->statusText().contains(QLatin1String("A and B swapped")),
                 qPrintable(page->statusText()));
        QVERIFY(!seen.contains(LinkHealth::State::Answering));
        QVERIFY(session->connection()->linkStats().timeouts > 0);

        // The controller answers now: "Connected", and on to the first motor.
        device.useRegisterDevice();
        session->connection()->disconnectFrom();
        session->connection()->connectTo(s);
        QCOMPARE(session->connection()->linkStats().timeouts, quint64(0)); // per connection
        QTRY_COMPARE(session->connection()->health()->state(), LinkHealth::State::Answering);
        QCOMPARE(status->stateText(), QStringLiteral("Connected"));
        QTRY_VERIFY(!qobject_cast<ConnectionPage *>(WindowProbe(*window).currentPage()));
    }

    // One flash state: a baud or id change makes it "not saved", only a save clears it, and
    // the Device page never says "saved" beside "not saved".
    void flashStateAfterLinkWritesAndSave()
    {
        DevicePage *device = window->findChild<DevicePage *>();
        QVERIFY(device);
        QVERIFY(!session->parameters()->store()->unsavedToFlash());
        session->saveToFlash();
        QTRY_VERIFY(device->flashStatus().startsWith(QLatin1String("Saved to flash")));
        QSignalSpy changed(session->line(), &SessionLine::linkChanged);
        session->line()->changeLink(1, 19200);
        QTRY_COMPARE(changed.size(), 1);
        QVERIFY(session->parameters()->store()->unsavedToFlash());
        QVERIFY(device->unsavedWarningShown());
        QVERIFY2(!device->flashStatus().contains(QLatin1String("Saved")),
                 qPrintable(device->flashStatus()));
        QVERIFY(window->findChild<LinkStatus *>()->findChildren<QLabel *>().size() > 0);
        session->saveToFlash();
        QTRY_VERIFY(!session->parameters()->store()->unsavedToFlash());
        QVERIFY(!device->unsavedWarningShown());
        QVERIFY(device->flashStatus().startsWith(QLatin1String("Saved to flash")));
        session->line()->changeLink(7, 19200); // the id alone
        QTRY_COMPARE(changed.size(), 2);
        QVERIFY(session->parameters()->store()->unsavedToFlash());
        QVERIFY(!device->flashStatus().contains(QLatin1String("Saved")));
    }

    // The write flow lists what the pages already flag, and asks before writing it anyway.
    void writeDialogListsKnownProblems()
    {
        ParameterStore *store = session->parameters()->store();
        const qint64 speed = *store->deviceValue(QStringLiteral("motor1.speed"));
        QVERIFY(store->edit(QStringLiteral("motor1.speed"), speed + 10).isEmpty());
        WindowProbe(*window).writeChanges();
        QTRY_VERIFY(WindowProbe(*window).writeDialog() &&
                    WindowProbe(*window).writeDialog()->isVisible());
        QVERIFY(WindowProbe(*window).writeDialog()->problems().isEmpty());
        auto *label =
            WindowProbe(*window).writeDialog()->findChild<QLabel *>(QStringLiteral("problems"));
        QVERIFY(label && label->isHidden());
        QCOMPARE(WindowProbe(*window)
                     .writeDialog()
                     ->findChild<QPushButton *>(QStringLiteral("writeButton"))
                     ->text(),
                 QStringLiteral("&Write"));
        WindowProbe(*window).writeDialog()->reject();
        // The centre on the start point: the arc editor flags it as invalid geometry.
        const qint64 sx = *store->deviceValue(QStringLiteral("arc.start_x"));
        const qint64 sy = *store->deviceValue(QStringLiteral("arc.start_y"));
        QVERIFY(store->edit(QStringLiteral("arc.start_x"), sx + 100).isEmpty());
        QVERIFY(store->edit(QStringLiteral("arc.center_x"), sx + 100).isEmpty());
        QVERIFY(store->edit(QStringLiteral("arc.center_y"), sy).isEmpty() ||
                store->deviceValue(QStringLiteral("arc.center_y")) == sy);
        QVERIFY(store->edit(QStringLiteral("arc.mode"), 0).isEmpty() ||
                store->deviceValue(QStringLiteral("arc.mode")) == 0);
        // One input as both limits of motor 1: the wiring check flags it.
        QVERIFY(store->edit(QStringLiteral("motor1.limit_positive"), 3).isEmpty());
        QVERIFY(store->edit(QStringLiteral("motor1.limit_negative"), 3).isEmpty());
        WindowProbe(*window).writeChanges();
        QTRY_VERIFY(WindowProbe(*window).writeDialog() &&
                    WindowProbe(*window).writeDialog()->isVisible());
        WriteChangesDialog *dialog = WindowProbe(*window).writeDialog();
        const QString all = dialog->problems().join(QLatin1Char('|'));
        QVERIFY2(dialog->problems().size() >= 2, qPrintable(all));
        QVERIFY2(all.contains(QLatin1String("Arc: ")), qPrintable(all));
        QVERIFY2(all.contains(QLatin1String("IN3")), qPrintable(all));
        label = dialog->findChild<QLabel *>(QStringLiteral("problems"));
        QVERIFY(label && !label->isHidden());
        auto *write = dialog->findChild<QPushButton *>(QStringLiteral("writeButton"));
        QCOMPARE(write->text(), QStringLiteral("&Write anyway"));
        QVERIFY(!write->isDefault());
        dialog->reject(); // nothing written
        QCOMPARE(*sim()->value(QStringLiteral("motor1.limit_positive")),
                 *store->deviceValue(QStringLiteral("motor1.limit_positive")));
        store->revertAll();
    }

    void emergencyStopFromInsideADialogGoesFirst()
    {
        QSignalSpy done(session.get(), &DeviceSession::commandFinished);
        session->command(QStringLiteral("motor1.forward"));
        QTRY_COMPARE(done.size(), 1);
        QTRY_VERIFY(sim()->running(1));
        field(QStringLiteral("motor1.speed"))->enterText(QStringLiteral("200"));
        WindowProbe(*window).writeChanges();
        QTRY_VERIFY(WindowProbe(*window).writeDialog() &&
                    WindowProbe(*window).writeDialog()->isVisible());
        QStringList order;
        connect(SessionInternals::link(*session), &ModbusLink::dispatched, this,
                [&order](quint64, const Request &r) { order << r.what; });
        session->parameters()->readAll(); // a queue of work in front
        QTest::keyClick(WindowProbe(*window).writeDialog()->table(), Qt::Key_F12);
        QTRY_VERIFY(order.contains(QStringLiteral("estop")));
        QVERIFY2(order.indexOf(QStringLiteral("estop")) <= 1,
                 qPrintable(order.join(QLatin1Char(','))));
        QTRY_VERIFY(!sim()->running(1));
        QVERIFY(WindowProbe(*window).writeDialog()->isVisible()); // the stop never asked anything
        QCOMPARE(*sim()->value(QStringLiteral("motor1.speed")), 300); // and wrote nothing else
    }

    void languageSwitchRetranslatesTheOpenWindow()
    {
        QCOMPARE(WindowProbe(*window).action(QStringLiteral("readAll"))->text(),
                 QStringLiteral("&Read all"));
        QVERIFY(Language::instance().setLanguage(QStringLiteral("zh_CN")));
        QCOMPARE(WindowProbe(*window).action(QStringLiteral("readAll"))->text(),
                 QStringLiteral("读取全部(&R)"));
        QCOMPARE(WindowProbe(*window).emergencyStopButton()->text(), QStringLiteral("急停"));
        const QLabel *label = nullptr;
        for (QLabel *l : window->findChildren<QLabel *>()) {
            if (l->property("parameterKey").toString() == QLatin1String("motor1.microsteps"))
                label = l;
        }
        QVERIFY(label);
        QCOMPARE(label->text(), QStringLiteral("细分:"));
        Language::instance().setLanguage(QStringLiteral("en"));
        QCOMPARE(WindowProbe(*window).action(QStringLiteral("readAll"))->text(),
                 QStringLiteral("&Read all"));
    }

    // The first start on a small screen (the offscreen one is 800×600): maximized, every pixel
    // for the page and the strip. Later starts come back as the window was left.
    void firstStartFillsASmallScreen()
    {
        window.reset();
        QSettings().remove(QStringLiteral("window"));
        window = std::make_unique<MainWindow>(session.get());
        window->showOnScreen();
        QVERIFY(window->isMaximized());
        window->showNormal();
        QVERIFY(window->close()); // saves where it was
        window = std::make_unique<MainWindow>(session.get());
        window->showOnScreen();
        QVERIFY(!window->isMaximized());
    }

    // The bottom docks leave the height to the page on a low screen (at 1024×600 they
    // took 140 px, the page 294): each may be as low as a row of controls and two rows of what
    // it lists, and the first start asks no more of them than a sixth of the screen.
    void bottomDocksLeaveTheHeightToThePage()
    {
        window.reset();
        QSettings().remove(QStringLiteral("window"));
        window = std::make_unique<MainWindow>(session.get());
        window->showOnScreen();
        QVERIFY(QTest::qWaitForWindowExposed(window.get()));
        const int line = window->fontMetrics().height();
        const int room = window->screen()->availableGeometry().height();
        for (QWidget *content : {static_cast<QWidget *>(WindowProbe(*window).messageView()),
                                 static_cast<QWidget *>(WindowProbe(*window).trafficView())}) {
            auto *dock = qobject_cast<QDockWidget *>(content->parentWidget());
            QVERIFY(dock);
            QVERIFY2(dock->minimumSizeHint().height() <= 8 * line,
                     qPrintable(QStringLiteral("%1 needs %2 px, more than 8 lines of %3")
                                    .arg(dock->windowTitle())
                                    .arg(dock->minimumSizeHint().height())
                                    .arg(line)));
        }
        auto *messages =
            qobject_cast<QDockWidget *>(WindowProbe(*window).messageView()->parentWidget());
        QTRY_VERIFY2(messages->height() <=
                         std::max(messages->minimumSizeHint().height(), room / 6) + line,
                     qPrintable(QStringLiteral("the messages take %1 px of a %2 px screen")
                                    .arg(messages->height())
                                    .arg(room)));
        const auto *list = WindowProbe(*window).messageView()->findChild<QListWidget *>();
        QVERIFY(list && list->height() >= 2 * list->fontMetrics().height());
        QVERIFY(window->close());
    }

    void closingWithEditsAsks()
    {
        field(QStringLiteral("motor2.speed"))->enterText(QStringLiteral("123"));
        QVERIFY(!window->close());
        QTRY_VERIFY(WindowProbe(*window).closeQuestion() &&
                    WindowProbe(*window).closeQuestion()->isVisible());
        QVERIFY(window->isVisible());
        WindowProbe(*window).closeQuestion()->button(QMessageBox::Discard)->click();
        QTRY_VERIFY(!window->isVisible());
        QCOMPARE(*sim()->value(QStringLiteral("motor2.speed")), 300); // discarded, not written
    }

    void closingWithoutEditsJustCloses() { QVERIFY(window->close()); }
};

#include "testregistry.h"
STEPCOM_TEST(TestMainWindow, Gui)
#include "tst_mainwindow.moc"

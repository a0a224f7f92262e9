// The window fits the laptops technicians carry: every page (before and after the values are
// read), the status bar and the main dialogs (write changes, bus scan, profile save and
// compare, files compare, backups, the user guide) at the screen the test runs on (ctest runs
// it at 1024×600 and 1366×768, at scale 1 and 1.5, see CMakeLists.txt), in English and
// Chinese. Fails when a text is clipped (a label's or button's text wider than the widget, a
// combo box's current text wider than its field), a widget lies outside its visible parent, a
// view scrolls sideways or a page is cut off at the right, a dialog is larger than the screen,
// a guide picture is wider than the guide, a status message runs into the link status, the
// E-STOP is off screen, or a page's main action needs scrolling. The machine strip (issue 25):
// both positions and its E-STOP on every page, its widest value never cut, its width steady.
#include "device/parameterstore.h"
#include "dialogs/backupsdialog.h"
#include "dialogs/busscandialog.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilefilesdialog.h"
#include "dialogs/profilesavedialog.h"
#include "dialogs/writechangesdialog.h"
#include "emergencystop.h"
#include "help/guidewindow.h"
#include "language.h"
#include "mainwindow.h"
#include "map/factoryvalues.h"
#include "page.h"
#include "pages/connectionpage.h"
#include "profile/backupstore.h"
#include "session/devicesession.h"
#include "simsession.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/messageview.h"
#include "widgets/docks/pagesidebar.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QRadioButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyleOptionComboBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>

using namespace stepcom;

namespace {

QString describe(const QWidget *w)
{
    QStringList path;
    for (const QWidget *p = w; p && !p->isWindow(); p = p->parentWidget()) {
        const QString name = p->objectName().isEmpty()
                                 ? QString::fromLatin1(p->metaObject()->className())
                                 : p->objectName();
        path.prepend(name);
    }
    return path.join(QLatin1Char('/'));
}

// The text a widget shows and the room it has for it, when the widget is one whose text can
// be cut: 0 room means "not applicable".
int overflow(const QWidget *w, QString *what)
{
    if (const auto *label = qobject_cast<const QLabel *>(w)) {
        if (label->wordWrap() || label->text().isEmpty() || !label->pixmap().isNull())
            return 0;
        QString text = label->text();
        if (Qt::mightBeRichText(text)) {
            QTextDocument doc;
            doc.setHtml(text);
            text = doc.toPlainText();
        }
        text.remove(QLatin1Char('&'));
        int widest = 0;
        for (const QString &line : text.split(QLatin1Char('\n')))
            widest = std::max(widest, label->fontMetrics().horizontalAdvance(line));
        *what = text;
        return widest - label->contentsRect().width();
    }
    if (const auto *combo = qobject_cast<const QComboBox *>(w)) {
        if (combo->isEditable() || combo->currentText().isEmpty())
            return 0;
        QStyleOptionComboBox option;
        option.initFrom(combo);
        option.editable = false;
        option.currentText = combo->currentText();
        const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &option,
                                                           QStyle::SC_ComboBoxEditField, combo);
        *what = combo->currentText();
        return combo->fontMetrics().horizontalAdvance(combo->currentText()) - field.width();
    }
    if (const auto *button = qobject_cast<const QAbstractButton *>(w)) {
        if (button->text().isEmpty() || qobject_cast<const QToolButton *>(w))
            return 0;
        *what = button->text();
        return button->sizeHint().width() - button->width();
    }
    return 0;
}

} // namespace

// What issue 19 has not fixed yet, named so that nothing else slips in: these are reported, every
// other problem fails the test. Take a line out when it is fixed.
const QStringList kKnownProblems = {};

class TestLayoutFit : public QObject
{
    Q_OBJECT
    QStringList m_problems;

    void problem(const QString &where, const QString &what)
    {
        const QString line = QStringLiteral("%1: %2").arg(where, what);
        for (const QString &known : kKnownProblems) {
            if (line.contains(known)) {
                qInfo("known, not fixed yet: %s", qPrintable(line));
                return;
            }
        }
        m_problems << line;
    }

    // Every visible widget of `top`: its text fits, it lies inside its parent, nothing
    // scrolls sideways.
    void checkTree(QWidget *top, const QString &context)
    {
        const QList<QWidget *> all = top->findChildren<QWidget *>();
        for (QWidget *w : all) {
            // Not shown at all: hidden, or a dock tabbed away behind another.
            if (!w->isVisibleTo(top) || w->isWindow() || w->visibleRegion().isEmpty())
                continue;
            QString text;
            if (const int over = overflow(w, &text); over > 1)
                problem(context, QStringLiteral("%1 \"%2\" cut by %3 px")
                                     .arg(describe(w), text.left(60))
                                     .arg(over));
            QWidget *parent = w->parentWidget();
            // Scroll areas' contents are larger than their viewports by design.
            const bool scrolled =
                qobject_cast<QScrollArea *>(parent ? parent->parentWidget() : nullptr) != nullptr;
            if (parent && !scrolled && !parent->rect().contains(w->geometry()) && w->width() > 0 &&
                w->height() > 0)
                problem(context, QStringLiteral("%1 lies outside its parent (%2 in %3×%4)")
                                     .arg(describe(w))
                                     .arg(QStringLiteral("%1,%2 %3×%4")
                                              .arg(w->x())
                                              .arg(w->y())
                                              .arg(w->width())
                                              .arg(w->height()))
                                     .arg(parent->width())
                                     .arg(parent->height()));
            // A page wider than its scroll area that does not scroll sideways is cut off.
            if (auto *area = qobject_cast<QScrollArea *>(w);
                area && area->widget() && area->widget()->isVisibleTo(area) &&
                area->horizontalScrollBarPolicy() == Qt::ScrollBarAlwaysOff &&
                area->widget()->width() > area->viewport()->width())
                problem(context, QStringLiteral("%1 is cut off at the right (%2 px of %3 shown)")
                                     .arg(describe(area->widget()))
                                     .arg(area->viewport()->width())
                                     .arg(area->widget()->width()));
            // Every scrolling view: pages, tables, lists, the guide's text.
            if (auto *area = qobject_cast<QAbstractScrollArea *>(w);
                area && area->horizontalScrollBar()->isVisible())
                problem(context, QStringLiteral("%1 scrolls sideways").arg(describe(w)));
        }
    }

    // `w` is shown and lies wholly inside the window (not scrolled away, not behind a tab).
    void checkOnScreen(const QWidget *w, const QWidget *window, const QString &context,
                       const QString &what)
    {
        if (!w || !w->isVisible() || w->visibleRegion().isEmpty()) {
            problem(context, QStringLiteral("%1 is not shown").arg(what));
            return;
        }
        const QRect rect(w->mapTo(window, QPoint(0, 0)), w->size());
        if (!window->rect().contains(rect) || w->visibleRegion().boundingRect() != w->rect())
            problem(context, QStringLiteral("%1 is not wholly on screen").arg(what));
    }

    // The machine strip (issue 25): both positions and its E-STOP on every page, no text cut.
    void checkStrip(MainWindow &window, const QString &context)
    {
        MachineStrip *strip = window.machineStrip();
        if (!strip) {
            problem(context, QStringLiteral("no machine strip"));
            return;
        }
        if (strip->motorCount() != 2)
            problem(context, QStringLiteral("the strip shows %1 motors").arg(strip->motorCount()));
        for (int m = 1; m <= strip->motorCount(); ++m)
            checkOnScreen(strip->positionLabel(m), &window, context,
                          QStringLiteral("the strip's motor %1 position").arg(m));
        checkOnScreen(strip->emergencyStopButton(), &window, context,
                      QStringLiteral("the strip's E-STOP"));
        // The sidebar (issue 25): every page's title whole beside its icon and marks.
        for (const QString &cut : window.sidebar()->cutEntries())
            problem(context, QStringLiteral("sidebar entry %1 is cut").arg(cut));
        for (QLabel *label : strip->findChildren<QLabel *>()) {
            QString text;
            if (label->isVisible() && overflow(label, &text) > 0)
                problem(context,
                        QStringLiteral("strip: %1 \"%2\" is cut").arg(describe(label), text));
        }
    }

    // A dialog or tool window shown over `window`: inside the screen, and its tree as above.
    void checkDialog(QWidget *dialog, const QString &name)
    {
        dialog->show();
        if (!QTest::qWaitForWindowExposed(dialog)) {
            problem(name, QStringLiteral("never shown"));
            return;
        }
        QCoreApplication::processEvents();
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        const QSize size = dialog->frameGeometry().size();
        if (size.width() > screen.width() || size.height() > screen.height())
            problem(name, QStringLiteral("%1×%2, larger than the screen %3×%4")
                              .arg(size.width())
                              .arg(size.height())
                              .arg(screen.width())
                              .arg(screen.height()));
        const QSize least = dialog->minimumSizeHint().expandedTo(dialog->minimumSize());
        if (least.width() > screen.width() || least.height() > screen.height())
            problem(
                name,
                QStringLiteral("cannot shrink below %1×%2").arg(least.width()).arg(least.height()));
        checkTree(dialog, name);
    }

    // A page shown for the first time lays itself out in rounds of posted layout requests
    // (its minimum grows, then its parents' layouts follow): judge the result, not a round.
    static void settle()
    {
        for (int round = 0; round < 5; ++round) {
            QCoreApplication::sendPostedEvents();
            QCoreApplication::processEvents();
        }
    }

    // `w` (a page's main action) can be seen without scrolling.
    void checkInView(QWidget *w, const QString &context)
    {
        if (!w) {
            problem(context, QStringLiteral("main action not found"));
            return;
        }
        for (QWidget *p = w->parentWidget(); p; p = p->parentWidget()) {
            if (auto *area = qobject_cast<QScrollArea *>(p)) {
                const QRect inViewport(w->mapTo(area->viewport(), QPoint(0, 0)), w->size());
                if (!area->viewport()->rect().contains(inViewport))
                    problem(context, QStringLiteral("%1 needs scrolling").arg(describe(w)));
                return;
            }
        }
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QApplication::setOrganizationName(QStringLiteral("StepComTest"));
        QSettings().clear(); // no window layout saved by another run
        qInfo("screen %dx%d (available %dx%d), scale %s",
              QGuiApplication::primaryScreen()->geometry().width(),
              QGuiApplication::primaryScreen()->geometry().height(),
              QGuiApplication::primaryScreen()->availableGeometry().width(),
              QGuiApplication::primaryScreen()->availableGeometry().height(),
              qgetenv("QT_SCALE_FACTOR").constData());
    }
    void cleanup() { m_problems.clear(); }

    void everyPageFits_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    // And once more connected: the values read (derived values, positions, the link status)
    // are longer than the dashes shown before.
    void everyPageFitsConnected_data() { everyPageFits_data(); }
    void everyPageFitsConnected() { everyPageFits(); }
    void everyPageFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        if (QTest::currentTestFunction() == QByteArrayLiteral("everyPageFitsConnected"))
            test::connectToSimulator(session);
        QCoreApplication::processEvents();
        // The window opens inside the screen and can be as small as the screen.
        const QRect frame = window.frameGeometry();
        if (!screen.contains(frame))
            problem(QStringLiteral("window"),
                    QStringLiteral("opens at %1,%2 %3×%4, outside the screen %5×%6")
                        .arg(frame.x())
                        .arg(frame.y())
                        .arg(frame.width())
                        .arg(frame.height())
                        .arg(screen.width())
                        .arg(screen.height()));
        const QSize least = window.minimumSizeHint().expandedTo(window.minimumSize());
        if (least.width() > screen.width() || least.height() > screen.height())
            problem(
                QStringLiteral("window"),
                QStringLiteral("cannot shrink below %1×%2").arg(least.width()).arg(least.height()));
        window.setGeometry(screen);
        for (int i = 0; i < window.pages().size(); ++i) {
            window.showPage(i);
            settle();
            Page *page = window.pages().at(i);
            const QString context = page->title();
            checkTree(&window, context);
            // What a page needs once shown (and its values read) stays the window's minimum.
            const QSize needs = window.minimumSizeHint().expandedTo(window.minimumSize());
            if (needs.width() > screen.width() || needs.height() > screen.height())
                problem(context, QStringLiteral("the window cannot shrink below %1×%2 now")
                                     .arg(needs.width())
                                     .arg(needs.height()));
            QToolButton *estop = window.emergencyStopButton();
            const QRect estopRect(estop->mapTo(&window, QPoint(0, 0)), estop->size());
            if (!estop->isVisible() || !window.rect().contains(estopRect))
                problem(context, QStringLiteral("the E-STOP is not on screen"));
            checkStrip(window, context);
            // The main action in view without scrolling: asked for at 1366×768 and up.
            if (screen.height() < 700)
                continue;
            if (qobject_cast<ConnectionPage *>(page))
                checkInView(page->findChild<QPushButton *>(QStringLiteral("connect")), context);
            if (QString::fromLatin1(page->metaObject()->className()) ==
                QLatin1String("stepcom::InterpolationPage"))
                checkInView(page->findChild<QPushButton *>(QStringLiteral("startButton")), context);
        }
        m_problems.removeDuplicates();
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }

    // The strip's readouts hold the widest value a position register can take ("-21474836.48
    // mm") whole, at the width they had before: digits never move their neighbours.
    void stripReadoutsHoldTheWidestValue_data() { everyPageFits_data(); }
    void stripReadoutsHoldTheWidestValue()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        test::connectToSimulator(session);
        QTRY_VERIFY(session.linkStats().answers > 0);
        MachineStrip *strip = window.machineStrip();
        QVERIFY(strip);
        QLabel *position = strip->positionLabel(1);
        QTRY_VERIFY(position->text() != QStringLiteral("—"));
        settle();
        const int width = position->width();
        const Parameter *p = session.map().find(QStringLiteral("motor1.position"));
        QVERIFY(p);
        session.setLive(false); // the poll would put the simulator's value back
        settle();
        for (qint64 raw : {p->rawMin, p->rawMax, qint64(0)}) {
            session.parameters()->setDeviceValues({{p->key, raw}});
            settle();
            QString text;
            QVERIFY2(overflow(position, &text) <= 0, qPrintable(position->text()));
            QCOMPARE(position->width(), width);
        }
        QVERIFY(position->text().contains(QStringLiteral("0")));
    }

    // A long message in the status bar stops short of the permanent link status ("Not saved to
    // flash"): cut with "…" inside its own room, the whole text in its tooltip and in the
    // messages dock.
    void statusMessageStopsShortOfTheIndicators_data() { everyPageFits_data(); }
    void statusMessageStopsShortOfTheIndicators()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        // Connected, so that every part of the link status shows (port, rate, errors).
        test::connectToSimulator(session);
        QTRY_VERIFY(session.linkStats().answers > 0);
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        window.setGeometry(screen);
        session.parameters()->setUnsavedToFlash(true); // the indicator the message must spare
        const QString text = QStringLiteral(
            "Motor 2 did not confirm the written speed: the controller answered 1200 "
            "while 1500 was sent; the value was not saved, check the wiring of the RS-485 "
            "line and the termination resistor, then write the changes again.");
        Q_EMIT session.message(DeviceSession::Severity::Warning, text);
        QCoreApplication::processEvents();
        auto *message = window.statusBar()->findChild<QLabel *>(QStringLiteral("statusMessage"));
        QVERIFY2(message && message->isVisible(), "no message in the status bar");
        bool indicator = false;
        for (auto *label : window.statusBar()->findChildren<QLabel *>())
            indicator = indicator || (label->isVisible() && label->text().contains(QChar(0x26a0)));
        QVERIFY2(indicator, "the \"Not saved to flash\" indicator is not shown");
        QVERIFY(window.messageView()->texts().join(QLatin1Char('\n')).contains(text));
        const QRect shown(message->mapTo(window.statusBar(), QPoint(0, 0)), message->size());
        for (QWidget *w : window.statusBar()->findChildren<QWidget *>()) {
            if (w == message || !w->isVisible() || w->isAncestorOf(message))
                continue;
            const QRect other(w->mapTo(window.statusBar(), QPoint(0, 0)), w->size());
            if (qobject_cast<QLabel *>(w) && !qobject_cast<QLabel *>(w)->text().isEmpty() &&
                shown.intersects(other))
                problem(QStringLiteral("status bar"), QStringLiteral("the message runs into \"%1\"")
                                                          .arg(qobject_cast<QLabel *>(w)->text()));
        }
        const int needed = message->fontMetrics().horizontalAdvance(message->text());
        if (needed > message->contentsRect().width())
            problem(QStringLiteral("status bar"), QStringLiteral("the message needs %1 px of %2")
                                                      .arg(needed)
                                                      .arg(message->contentsRect().width()));
        QVERIFY2(message->text() != text, "a message this long fits no laptop's status bar");
        QVERIFY(message->text().endsWith(QChar(0x2026)));
        QCOMPARE(message->toolTip(), text);
        checkTree(window.statusBar(), QStringLiteral("status bar"));
        const int least = window.minimumSizeHint().expandedTo(window.minimumSize()).width();
        if (least > screen.width())
            problem(QStringLiteral("status bar"),
                    QStringLiteral("the window cannot be narrower than %1 px").arg(least));
        if (window.statusBar()->width() > screen.width())
            problem(QStringLiteral("status bar"), QStringLiteral("%1 px wide on a screen of %2")
                                                      .arg(window.statusBar()->width())
                                                      .arg(screen.width()));
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }

    // The dialogs a technician meets most: comparing a profile with the controller or with
    // another file, and saving one.
    void profileDialogsFit_data() { everyPageFits_data(); }
    void profileDialogsFit()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        Profile profile;
        profile.values.insert(QStringLiteral("motor1.speed"), 300);
        ProfileCompareDialog compare(&session, profile, QStringLiteral("machine-a.json"), &window);
        ProfileSaveDialog save(true, QStringLiteral("Press 4 2026-11-24"), &window);
        Profile other = profile;
        other.values.insert(QStringLiteral("motor1.speed"), 450);
        other.values.insert(QStringLiteral("motor2.microsteps"), 16);
        ProfileFilesDialog files(
            session.map(), profile,
            QStringLiteral("/home/technician/profiles/press-4-machine-a.json"), other,
            QStringLiteral("/home/technician/profiles/press-4-machine-b.json"), &window);
        for (QDialog *dialog : {static_cast<QDialog *>(&compare), static_cast<QDialog *>(&save),
                                static_cast<QDialog *>(&files)}) {
            checkDialog(dialog, QString::fromLatin1(dialog->metaObject()->className()));
            dialog->close();
        }
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }

    void busScanDialogFits_data() { everyPageFits_data(); }
    void busScanDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        auto *page = qobject_cast<ConnectionPage *>(window.pages().first());
        BusScanDialog *dialog = page->openBusScan();
        QVERIFY(dialog);
        checkDialog(dialog, QStringLiteral("bus scan"));
        dialog->close();
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }

    // Write changes: a dozen edits with long names, and the problems the pages flag above them.
    void writeChangesDialogFits_data() { everyPageFits_data(); }
    void writeChangesDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        ParameterStore *store = session.parameters();
        int edits = 0;
        for (const Parameter &p : session.map().parameters()) {
            if (p.writable() && store->edit(p.key, p.rawMax).isEmpty() && ++edits == 12)
                break;
        }
        QVERIFY(edits >= 6);
        WriteChangesDialog dialog(*store, &window);
        QCOMPARE(dialog.writes().size(), edits);
        dialog.setProblems(
            {QStringLiteral(
                 "Motor 1: the travel limit (12000 steps) is beyond the soft limit the "
                 "machine's drawing gives for this axis, check the mechanics before writing"),
             QStringLiteral("Motor 2: home input and limit input are wired to the same terminal")});
        checkDialog(&dialog, QStringLiteral("write changes"));
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }

    // File → Backups with a few backups, one of them unreadable.
    void backupsDialogFits_data() { everyPageFits_data(); }
    void backupsDialogFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const BackupStore store(dir.path());
        const QHash<QString, qint64> values = FactoryValues::writable(session.map());
        const QDateTime at(QDate(2026, 11, 24), QTime(9, 30), Qt::UTC);
        for (auto op : {BackupStore::Operation::Apply, BackupStore::Operation::FactoryReset,
                        BackupStore::Operation::DeviceId}) {
            QVERIFY(store
                        .save(session.map(), values, op,
                              QStringLiteral("/dev/serial/by-id/usb-FTDI_FT232R_USB_UART_"
                                             "A50285BI-if00-port0 · 115200 8N1 · id 1"),
                              at.addSecs(60 * int(op)))
                        .ok());
        }
        QFile broken(dir.filePath(QStringLiteral("backup-20261124-100000-apply.json")));
        QVERIFY(broken.open(QIODevice::WriteOnly) && broken.write("{ not json") > 0);
        broken.close();
        BackupsDialog dialog(session.map(), dir.path(), &window);
        QVERIFY(dialog.list()->topLevelItemCount() >= 3);
        checkDialog(&dialog, QStringLiteral("backups"));
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }

    // Help → User guide at a section with pictures: nothing cut, no picture wider than the view.
    void guideWindowFits_data() { everyPageFits_data(); }
    void guideWindowFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        GuideWindow *guide = window.openGuide(QStringLiteral("stepcom::ConnectionPage"));
        QVERIFY(guide);
        QVERIFY2(!guide->file().isEmpty(), "the guide was not found");
        checkDialog(guide, QStringLiteral("guide"));
        QTextBrowser *browser = guide->browser();
        const QTextDocument *doc = browser->document();
        const qreal room = browser->viewport()->width() - 2 * doc->documentMargin();
        int images = 0;
        for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
            for (auto it = b.begin(); !it.atEnd(); ++it) {
                const QTextCharFormat f = it.fragment().charFormat();
                if (!f.isImageFormat())
                    continue;
                ++images;
                const QTextImageFormat image = f.toImageFormat();
                // Shown at the width the format asks for, else at the picture's own.
                qreal shown = image.width();
                if (!image.hasProperty(QTextFormat::ImageWidth)) {
                    const QVariant data =
                        doc->resource(QTextDocument::ImageResource, QUrl(image.name()));
                    QImage picture = data.value<QImage>();
                    if (picture.isNull())
                        picture.loadFromData(data.toByteArray());
                    shown = picture.width();
                }
                if (shown > room + 1)
                    problem(QStringLiteral("guide"),
                            QStringLiteral("picture %1 is %2 px wide in a view of %3 px")
                                .arg(image.name())
                                .arg(shown)
                                .arg(room));
            }
        }
        QVERIFY2(images > 0, "the guide shows no picture");
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }
};

#include "testregistry.h"
STEPCOM_TEST(TestLayoutFit, Gui)
#include "tst_layoutfit.moc"

// The window fits the laptops technicians carry: every page and the main dialogs at the screen
// the test runs on (ctest runs it at 1024×600 and 1366×768, at scale 1 and 1.5, see
// CMakeLists.txt), in English and Chinese. Fails when a text is clipped (a label's or button's
// text wider than the widget, a combo box's current text wider than its field), a widget lies
// outside its visible parent, a page scrolls sideways, the E-STOP is off screen, or a page's
// main action needs scrolling.
#include "device/devicesession.h"
#include "dialogs/busscandialog.h"
#include "dialogs/profilecomparedialog.h"
#include "dialogs/profilesavedialog.h"
#include "emergencystop.h"
#include "language.h"
#include "mainwindow.h"
#include "page.h"
#include "pages/connectionpage.h"

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
#include <QStyleOptionComboBox>
#include <QTest>
#include <QTextDocument>
#include <QToolBar>
#include <QToolButton>

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
            if (auto *area = qobject_cast<QScrollArea *>(w);
                area && area->horizontalScrollBar()->isVisible())
                problem(context, QStringLiteral("%1 scrolls sideways").arg(describe(w)));
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
    void everyPageFits()
    {
        QFETCH(QString, language);
        Language::instance().setLanguage(language);
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        DeviceSession session;
        MainWindow window(&session);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
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
            QCoreApplication::processEvents();
            Page *page = window.pages().at(i);
            const QString context = page->title();
            checkTree(&window, context);
            QToolButton *estop = window.emergencyStopButton();
            const QRect estopRect(estop->mapTo(&window, QPoint(0, 0)), estop->size());
            if (!estop->isVisible() || !window.rect().contains(estopRect))
                problem(context, QStringLiteral("the E-STOP is not on screen"));
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

    // The dialogs a technician meets most: comparing a profile and saving one.
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
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        ProfileCompareDialog compare(&session, profile, QStringLiteral("machine-a.json"), &window);
        ProfileSaveDialog save(true, QStringLiteral("Press 4 2026-11-24"), &window);
        for (QDialog *dialog : {static_cast<QDialog *>(&compare), static_cast<QDialog *>(&save)}) {
            dialog->show();
            QVERIFY(QTest::qWaitForWindowExposed(dialog));
            const QString name = QString::fromLatin1(dialog->metaObject()->className());
            if (dialog->width() > screen.width() || dialog->height() > screen.height())
                problem(name, QStringLiteral("larger than the screen"));
            checkTree(dialog, name);
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
        QVERIFY(QTest::qWaitForWindowExposed(dialog));
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        if (dialog->width() > screen.width() || dialog->height() > screen.height())
            problem(QStringLiteral("bus scan"), QStringLiteral("larger than the screen"));
        checkTree(dialog, QStringLiteral("bus scan"));
        dialog->close();
        QVERIFY2(m_problems.isEmpty(),
                 qPrintable(QStringLiteral("\n") + m_problems.join(QLatin1Char('\n'))));
    }
};

QTEST_MAIN(TestLayoutFit)
#include "tst_layoutfit.moc"

// MainWindow, its place on the screen: the docks arranged to the room there is, the window kept
// inside the screen, and the layout saved and restored (split from mainwindow.cpp).
#include "window/mainwindow.h"

#include "base/emergencystop.h"
#include "pages/checklistpage.h"
#include "pages/motionpage.h"
#include "pages/sequencepage.h"
#include "widgets/docks/devicelistdock.h"
#include "widgets/docks/machinestrip.h"
#include "widgets/docks/pagesidebar.h"
#include "widgets/docks/statusdock.h"
#include "widgets/motion/gamepadpanel.h"
#include "widgets/sequence/sequencerunpanel.h"

#include <QDockWidget>
#include <QScreen>
#include <QSettings>
#include <QStyle>
#include <QTimer>

#include <algorithm>

namespace stepcom {

void MainWindow::arrangeDocks()
{
    // A short window (1024×600) keeps the strip to one low row, a narrow one (1280×800) to
    // smaller digits. The screen decides too, before the window is fitted into it.
    const int high =
        screen() ? std::min(height(), screen()->availableGeometry().height()) : height();
    const int wide = screen() ? std::min(width(), screen()->availableGeometry().width()) : width();
    // Low as 1280×720 or lower, whatever the scale that made it so (1024×600, 1366×768 and
    // 1920×1080 at ×1.5): there the sidebar's full rows need scrolling beside the docks.
    const bool low = high <= std::max(720, fontMetrics().height() * 40);
    if (m_strip)
        m_strip->setCompact(low || wide < std::max(1440, fontMetrics().averageCharWidth() * 200));
    m_sidebar->setShortWindow(low); // low rows, small icons
    if (!m_statusDock || !centralWidget())
        return;
    const int needed = centralWidget()->minimumSizeHint().width() +
                       m_statusDock->minimumSizeHint().width() +
                       3 * style()->pixelMetric(QStyle::PM_DockWidgetSeparatorExtent);
    // The screen decides too: a window cannot get narrower than what its docks need, so on a
    // small screen the dock moves before the window would have to.
    const int room = screen() ? std::min(width(), screen()->availableGeometry().width()) : width();
    const bool narrow = room < needed;
    if (narrow && !m_statusDockMoved && dockWidgetArea(m_statusDock) == Qt::RightDockWidgetArea &&
        !m_statusDock->isFloating()) {
        m_statusDockMoved = true;
        tabifyDockWidget(m_messageDock, m_statusDock);
        // The machine strip shows the positions: the messages stay in front.
        m_messageDock->raise();
    } else if (!narrow && m_statusDockMoved) {
        m_statusDockMoved = false;
        addDockWidget(Qt::RightDockWidgetArea, m_statusDock);
    }
}

void MainWindow::fitIntoScreen()
{
    const QScreen *where = screen();
    if (!where)
        return;
    const QRect available = where->availableGeometry();
    const QMargins frame(geometry().left() - frameGeometry().left(),
                         geometry().top() - frameGeometry().top(),
                         frameGeometry().right() - geometry().right(),
                         frameGeometry().bottom() - geometry().bottom());
    const QRect room = available.marginsRemoved(frame);
    QRect g = geometry();
    g.setSize(g.size().boundedTo(room.size()));
    g.moveLeft(std::clamp(g.left(), room.left(), room.right() - g.width() + 1));
    g.moveTop(std::clamp(g.top(), room.top(), room.bottom() - g.height() + 1));
    setGeometry(g);
}

void MainWindow::restoreLayout()
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("window"));
    if (!restoreGeometry(settings.value(QStringLiteral("geometry")).toByteArray())) {
        firstStartLayout(); // the docks are where createDocks() placed them
    } else {
        m_firstStart = false;
        if (!restoreState(settings.value(QStringLiteral("state")).toByteArray()))
            resizeBottomDocks();
        // A layout saved on a larger screen still fits: the docks first (the saved state may
        // put the status dock beside the page), then the window.
        m_statusDockMoved = false;
        arrangeDocks();
        fitIntoScreen();
    }
    // Once every minimum size is known (after the layout requests): arrange and fit again.
    QTimer::singleShot(0, this, [this] {
        arrangeDocks();
        fitIntoScreen();
        if (m_firstStart)
            resizeBottomDocks();
    });
}

void MainWindow::useDefaultLayout()
{
    placeDocks();
    firstStartLayout();
}

void MainWindow::firstStartLayout()
{
    m_firstStart = true;
    // Room for a page beside the sidebar; showOnScreen() decides the size on the screen.
    const QFontMetrics fm = fontMetrics();
    resize(fm.horizontalAdvance(QLatin1Char('x')) * 185, fm.height() * 50);
    m_statusDockMoved = false;
    arrangeDocks();
    fitIntoScreen();
    resizeBottomDocks();
}

void MainWindow::placeDocks()
{
    for (QDockWidget *dock :
         {m_trafficDock, m_messageDock, static_cast<QDockWidget *>(m_deviceDock)}) {
        dock->setFloating(false);
        addDockWidget(Qt::BottomDockWidgetArea, dock);
    }
    tabifyDockWidget(m_trafficDock, m_messageDock);
    // A tab beside the messages: beside the pages it would widen the window past a laptop's.
    tabifyDockWidget(m_messageDock, m_deviceDock);
    m_statusDock->setFloating(false);
    addDockWidget(Qt::RightDockWidgetArea, m_statusDock);
    m_statusDockMoved = false;
    for (QDockWidget *dock : {m_trafficDock, m_messageDock})
        dock->show();
    // The machine strip shows the positions, states and lamps on every page: the status dock
    // would be a second place for them (View → Status brings it back).
    m_statusDock->hide();
    m_deviceDock->hide();
    m_messageDock->raise();
}

void MainWindow::resizeBottomDocks()
{
    const int line = fontMetrics().height();
    const int high = screen() ? screen()->availableGeometry().height() : height();
    const int lines = std::clamp(high / 6 / line, 4, 9);
    resizeDocks({m_trafficDock, m_messageDock}, {line * lines, line * lines}, Qt::Vertical);
}

void MainWindow::showOnScreen()
{
    const QScreen *where = screen();
    if (!m_firstStart || !where) {
        show();
        return;
    }
    const QRect available = where->availableGeometry();
    if (available.width() < 1440 || available.height() < 900) {
        showMaximized(); // a laptop's screen: every pixel for the page and the strip
        return;
    }
    // A large screen: most of it (a third of 1920×1080 left the page cramped), never less than
    // the window needs, in the middle.
    const QSize size = QSize(available.width() * 4 / 5, available.height() * 17 / 20)
                           .expandedTo(minimumSizeHint())
                           .boundedTo(available.size());
    resize(size);
    move(available.center() - QPoint(size.width() / 2, size.height() / 2));
    show();
}

void MainWindow::saveLayout()
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("window"));
    settings.setValue(QStringLiteral("geometry"), saveGeometry());
    settings.setValue(QStringLiteral("state"), saveState());
}

void MainWindow::watchProofs()
{
    connect(m_checklist, &ChecklistPage::stepsLost, this,
            [this](int motor, qint64 rpm, std::optional<qint64> recommended) {
                const QString action =
                    recommended ? tr("Use %1 rpm…").arg(*recommended) : tr("Find a safe speed…");
                m_strip->setProofWarning(tr("Motor %1 lost steps at %2 rpm").arg(motor).arg(rpm),
                                         action, [this, motor, recommended] {
                                             showPage(int(m_pages.indexOf(m_checklist)));
                                             if (recommended) {
                                                 m_checklist->writeRecommendation(motor);
                                                 return;
                                             }
                                             m_checklist->selectStep(Checklist::stepId(
                                                 ChecklistStep::Kind::KeepsSteps, motor));
                                         });
            });
    connect(m_checklist, &ChecklistPage::stepsKept, this,
            [this] { m_strip->setProofWarning({}, {}, {}); });
}

void MainWindow::watchSequence()
{
    // The pad's Back is the window's own E-STOP, ahead of everything queued.
    m_motion->gamepadPanel()->setEmergencyStop([this] { m_estop->trigger(); });
    connect(m_sequence, &SequencePage::runText, m_strip, &MachineStrip::setSequenceText);
    connect(m_sequence->runPanel(), &SequenceRunPanel::runInFinished, m_checklist,
            &ChecklistPage::recordRunIn);
    connect(m_checklist, &ChecklistPage::sequencePageWanted, this,
            [this] { showPage(int(m_pages.indexOf(m_sequence))); });
}

} // namespace stepcom

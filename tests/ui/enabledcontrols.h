#pragma once

#include "base/page.h"
#include "window/mainwindow.h"

#include <QAbstractButton>
#include <QAction>
#include <QCoreApplication>
#include <QMenu>
#include <QPushButton>
#include <QSet>
#include <QToolButton>

namespace stepcom::test {

// Every action and button of the window (every page shown in turn) that is enabled and could
// reach a controller: what must be none while a profile file is edited or a log is
// replayed. What stays on works on files, views or the language; E-STOP stays on
// and claims nothing. `alsoHarmless`: object names the caller's mode adds.
inline QStringList enabledControls(MainWindow *window, const QSet<QString> &alsoHarmless = {})
{
    // Reaches no controller: files, languages, editing, connecting (which ends the file editing
    // or the replay), finding controllers (a scan reads only; connecting from it ends them too),
    // and the views of what was recorded or logged.
    QSet<QString> harmless{
        "newProfile", "openProfile", "saveProfile", "saveProfileAs", "closeProfile",
        "compareProfiles", "reportFromProfile", "saveProfileFromEdited", "revert", "quit", "about",
        "userGuide", "whatsThis", "emergencyStopButton", "emergencyStop", "language_en",
        "language_zh_CN", "connect", "scan", "refresh", "pauseButton", "fitButton",
        "clearTraceButton", "exportPngButton", "exportCsvButton", "recordButton", "previewFit",
        "previewExport", "openSessionLog", "createSupportBundle",
        // listening beside another master sends nothing (its own test says what stays on)
        "listenOnly",
        // StepCom's own settings and the checklist file, not the controller:
        // travel limits, the profile beside the checklist, a step skipped
        "applyTravelLimits", "chooseChecklistProfile", "skipButton",
        // the built-in simulator's saved state, no machine's
        "resetSimulator"};
    harmless.unite(alsoHarmless);
    const QSet<QString> logViews{"stepcom::TrafficView", "stepcom::MessageView"};
    QStringList enabled;
    for (QAction *a : window->findChildren<QAction *>()) {
        if (!a->isEnabled() || a->isSeparator() || a->menu() || a->text().isEmpty())
            continue;
        if (a->objectName().isEmpty() && a->isCheckable())
            continue; // a dock's or toolbar's show/hide toggle
        if (auto *menu = qobject_cast<QMenu *>(a->parent());
            menu && menu->objectName() == QLatin1String("recentProfiles"))
            continue; // a recent profile: opened as a file too
        if (!harmless.contains(a->objectName()))
            enabled << QStringLiteral("action %1 \"%2\"").arg(a->objectName(), a->text());
    }
    const auto walk = [&](QWidget *root, const QString &where) {
        for (QAbstractButton *b : root->findChildren<QAbstractButton *>()) {
            if (!b->isEnabled() || !b->isVisibleTo(window))
                continue;
            auto *tool = qobject_cast<QToolButton *>(b);
            if (b->isCheckable() && !qobject_cast<QPushButton *>(b))
                continue; // check boxes and radio buttons choose, they do not act
            if (b->objectName().startsWith(u"qt_") ||
                (tool && !tool->defaultAction() && b->objectName().isEmpty()))
                continue; // scroll and tab arrows, a dock's float and close buttons
            if (tool && tool->defaultAction())
                continue; // a toolbar's action: walked above
            const auto inLogView = [&logViews](const QWidget *w) {
                for (; w; w = w->parentWidget()) {
                    if (logViews.contains(QString::fromLatin1(w->metaObject()->className())))
                        return true;
                }
                return false;
            };
            if (inLogView(b->parentWidget()))
                continue; // clear, copy or save a log (in a row of the log's view)
            if (!harmless.contains(b->objectName()))
                enabled << QStringLiteral("%1: button %2 \"%3\"")
                               .arg(where, b->objectName(), b->text());
        }
    };
    for (int i = 0; i < window->pages().size(); ++i) {
        window->showPage(i); // every page as the user sees it
        QCoreApplication::processEvents();
        walk(window->pages().at(i), window->pages().at(i)->title());
    }
    walk(window, QStringLiteral("window")); // docks, toolbar, the last page again
    return enabled;
}

} // namespace stepcom::test

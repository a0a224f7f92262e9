#pragma once

#include "base/page.h"
#include "widgets/fields/statetone.h"

#include <QListWidget>

class QToolButton;

namespace stepcom {

class DeviceSession;
class PageSidebarDelegate;

// The window's list of pages as the commissioning goes: group headers in order
// (connect; set up; move and run; check, save and report), each page with its icon and its
// state -- the edits on it not written (an amber dot and their number), the steps passed of a
// page that has steps ("3/15", "?" when the page cannot tell), and greyed while a page that
// needs the controller has none answering. Every state comes from the session's store, its
// link health and the pages' own signals. Headers cannot be selected and the arrow keys skip
// them; a page's accessible name is its title, its state the accessible description.
class PageSidebar : public QListWidget
{
    Q_OBJECT
public:
    enum Role {
        PageRole = Qt::UserRole + 1, // the page's index in the window; -1 on a header
        EditsRole,                   // int: edits on the page not written
        ProgressRole,                // QString: "3/15", "?" or empty
        ProgressToneRole,            // int: the StateTone of the progress
        OfflineRole,                 // bool: needs the controller, and none answers
        MostEditsRole,               // int: the most edits the page can have (its keys)
        StepsRole,                   // int: the steps the page counts
    };

    explicit PageSidebar(DeviceSession *session, QWidget *parent = nullptr);

    // Adds `page` (the window's page number `pages().size()`) under its stage's header.
    void addPage(Page *page);
    const QList<Page *> &pages() const { return m_pages; }
    void setCurrentPage(int index);
    int currentPage() const;
    QListWidgetItem *itemOf(int page) const;

    // What the entry of `page` shows beside its title, in words (also its tooltip and
    // accessible description): "2 edits not written", "3 of 15 steps passed", ...
    QString stateText(int page) const;
    int editCount(int page) const;
    bool isCompact() const;
    // The group headers drawn as thin lines: the low rows alone did not fit.
    bool hasThinHeaders() const;
    // The window is short (1024×600, 1366×768 at ×1.5): low rows from the start, before the
    // sidebar's own height is known, so the window opens at the width it will keep.
    void setShortWindow(bool isShort);
    // The titles of the entries shown narrower than they need (cut with "…"), for the layout
    // checks; each with the width it has and needs.
    QStringList cutEntries() const;
    // Entries scrolled out of view above or below: an arrow above or below the rows says so
    // (and scrolls when clicked); the arrows take rooms of their own, so no entry lies under one.
    bool hasMoreAbove() const;
    bool hasMoreBelow() const;
    QToolButton *moreAboveArrow() const { return m_up; }
    QToolButton *moreBelowArrow() const { return m_down; }
    // Where entries are drawn, in the viewport's coordinates: nothing covers this part.
    QRect clearArea() const;
    bool isOffline(int page) const;
    // The colours the marks are drawn in, on an entry not selected.
    QColor editColour() const;
    QColor progressColour(int page) const;
    // A page waiting for a controller: its title and icon in the "unknown" grey.
    QColor offlineColour() const;

Q_SIGNALS:
    // The user (or setCurrentPage) chose page number `index`.
    void pageChosen(int index);

protected:
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    // Over the headers: to the next page in the direction of the key.
    QModelIndex moveCursor(CursorAction action, Qt::KeyboardModifiers modifiers) override;

private:
    void retranslate();
    void refresh();
    void refreshIcons();
    void updateWidth();
    // Low rows when the full ones would need scrolling (a 1024×600 screen).
    void updateCompact();
    // The arrows' rooms above and below the rows when the rows need more height than there is.
    void updateArrows();
    int rowsHeight() const;
    static QString stageTitle(Page::Stage stage);

    DeviceSession *m_session;
    QList<Page *> m_pages;
    PageSidebarDelegate *m_delegate;
    bool m_shortWindow = false;
    QToolButton *m_up;
    QToolButton *m_down;
};

} // namespace stepcom

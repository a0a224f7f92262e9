#pragma once

#include <QStyledItemDelegate>

namespace stepcom {

// Draws PageSidebar's rows: a header as a small bold caption, a page as its icon, its title
// and, at the right, its marks (the edits' amber dot and count, the steps passed) in the
// state palette (statetone.h); greyed while the page waits for a controller.
class PageSidebarDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    // Small icons and little padding, for a sidebar too short for every row (1024×600).
    void setCompact(bool compact) { m_compact = compact; }
    bool isCompact() const { return m_compact; }
    // Headers as thin lines between the groups (their titles in the tooltips), for a sidebar
    // that the low rows alone do not fit (1366×768 at ×1.5 in Chinese).
    void setThinHeaders(bool thin) { m_thinHeaders = thin; }
    bool hasThinHeaders() const { return m_thinHeaders; }

    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override;
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    // The row's title is drawn whole in `option.rect` (not cut with "…").
    bool titleFits(const QStyleOptionViewItem &option, const QModelIndex &index) const;

    // The marks' text of a row ("● 2", "3/15"), as drawn.
    static QString editMark(int edits);
    // The room a row's marks may take (the most edits its page can have, its steps), so the
    // sidebar does not widen as they change; 0 for a page without either.
    static int marksWidth(const QFontMetrics &fm, const QModelIndex &index);
    int iconSize(const QFontMetrics &fm) const;
    static QFont headerFont(const QFont &font);
    QFont markFont(const QFont &font) const;

private:
    struct Geometry
    {
        QRect icon;
        QRect title;
        QRect marks;
    };
    Geometry geometry(const QStyleOptionViewItem &option, const QModelIndex &index) const;
    int padding(const QFontMetrics &fm) const;
    int gap(int pad) const;

    bool m_compact = false;
    bool m_thinHeaders = false;
};

} // namespace stepcom

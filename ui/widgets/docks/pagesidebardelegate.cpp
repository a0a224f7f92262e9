#include "widgets/docks/pagesidebardelegate.h"

#include "widgets/docks/pagesidebar.h"
#include "widgets/fields/statetone.h"

#include <QApplication>
#include <QPainter>

#include <cmath>

namespace stepcom {

namespace {

// A font set in pixels (some platforms' default) has no point size to scale.
void scaled(QFont &font, double factor)
{
    if (font.pointSizeF() > 0)
        font.setPointSizeF(font.pointSizeF() * factor);
    else
        font.setPixelSize(std::max(1, int(font.pixelSize() * factor)));
}

constexpr int kThinHeader = 5; // px: a line with room above and below

bool isHeader(const QModelIndex &index)
{
    return index.data(PageSidebar::PageRole).toInt() < 0;
}

} // namespace

QString PageSidebarDelegate::editMark(int edits)
{
    return edits > 0 ? QStringLiteral("\u25cf %1").arg(edits) : QString();
}

QFont PageSidebarDelegate::markFont(const QFont &font) const
{
    // Compact: a size smaller, so the widest title and its marks still fit a 911 px window.
    QFont f = font;
    if (m_compact)
        scaled(f, 0.85);
    return f;
}

int PageSidebarDelegate::marksWidth(const QFontMetrics &fm, const QModelIndex &index)
{
    const int edits = index.data(PageSidebar::MostEditsRole).toInt();
    const int steps = index.data(PageSidebar::StepsRole).toInt();
    int width = 0;
    if (edits > 0)
        width = fm.horizontalAdvance(editMark(edits));
    if (steps > 0)
        width = std::max(width, fm.horizontalAdvance(QStringLiteral("%1/%1").arg(steps)));
    return width;
}

int PageSidebarDelegate::padding(const QFontMetrics &fm) const
{
    // Compact: a pixel above and below, so every entry fits a 512 px high window (1366×768
    // at ×1.5) beside the docks.
    return m_compact ? 1 : std::max(3, fm.height() / 5);
}

int PageSidebarDelegate::gap(int pad) const
{
    // Between a title and its marks.
    return m_compact ? pad : 2 * pad;
}

int PageSidebarDelegate::iconSize(const QFontMetrics &fm) const
{
    // Drawn for 24 px; never smaller than the text beside it; 16 px when rows must be low.
    return std::max(m_compact ? 16 : 24, fm.ascent());
}

QFont PageSidebarDelegate::headerFont(const QFont &font)
{
    QFont f = font;
    f.setBold(true);
    scaled(f, 0.9);
    return f;
}

QSize PageSidebarDelegate::sizeHint(const QStyleOptionViewItem &option,
                                    const QModelIndex &index) const
{
    const QFontMetrics fm(option.font);
    const int pad = padding(fm);
    const QString title = index.data(Qt::DisplayRole).toString();
    if (isHeader(index)) {
        const QFontMetrics hm(headerFont(option.font));
        if (m_thinHeaders)
            return {2 * pad, kThinHeader};
        return {hm.horizontalAdvance(title) + 2 * pad, hm.height() + pad + (m_compact ? 0 : pad)};
    }
    const int icon = iconSize(fm);
    const int marks = marksWidth(QFontMetrics(markFont(option.font)), index);
    // The title's exact width rounded up: elidedText() cuts a title given its rounded width.
    const int text = int(std::ceil(QFontMetricsF(option.font).horizontalAdvance(title)));
    return {pad + icon + pad + text + (marks ? gap(pad) + marks : 0) + pad,
            std::max(icon, fm.height()) + 2 * pad};
}

PageSidebarDelegate::Geometry PageSidebarDelegate::geometry(const QStyleOptionViewItem &option,
                                                            const QModelIndex &index) const
{
    const QFontMetrics fm(option.font);
    const int pad = padding(fm);
    const QRect &row = option.rect;
    Geometry g;
    const int size = iconSize(fm);
    g.icon = QRect(row.left() + pad, row.top() + (row.height() - size) / 2, size, size);
    // The marks at the right, the title in the room left of them.
    const int room = marksWidth(QFontMetrics(markFont(option.font)), index);
    g.marks = row.adjusted(row.width() - pad - room, 0, -pad, 0);
    g.title = row;
    g.title.setLeft(g.icon.right() + 1 + pad);
    g.title.setRight(g.marks.left() - 1 - (room > 0 ? gap(pad) : 0));
    return g;
}

bool PageSidebarDelegate::titleFits(const QStyleOptionViewItem &option,
                                    const QModelIndex &index) const
{
    if (isHeader(index))
        return true;
    const QString title = index.data(Qt::DisplayRole).toString();
    return QFontMetrics(option.font)
               .elidedText(title, Qt::ElideRight, geometry(option, index).title.width()) == title;
}

void PageSidebarDelegate::paint(QPainter *painter, const QStyleOptionViewItem &option,
                                const QModelIndex &index) const
{
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    const QFontMetrics fm(opt.font);
    const int pad = padding(fm);
    const QString title = opt.text;
    painter->save();
    if (isHeader(index) && m_thinHeaders) {
        // The group's end, as a line; its title is the row's tooltip and accessible name.
        painter->setPen(opt.palette.color(QPalette::Active, QPalette::Mid));
        const int y = opt.rect.center().y();
        painter->drawLine(opt.rect.left() + pad, y, opt.rect.right() - pad, y);
        painter->restore();
        return;
    }
    if (isHeader(index)) {
        // Not a place to go: no selection, no focus, a caption over its pages.
        painter->setFont(headerFont(opt.font));
        painter->setPen(opt.palette.color(QPalette::Active, QPalette::Text));
        const QRect r = opt.rect.adjusted(pad, 0, -pad, -1);
        painter->drawText(r, Qt::AlignLeft | Qt::AlignBottom | Qt::TextSingleLine, title);
        painter->restore();
        return;
    }
    // The style's row: selection and focus, without its own text and icon.
    const QIcon icon = opt.icon;
    opt.text.clear();
    opt.icon = QIcon();
    const QWidget *view = opt.widget;
    QStyle *style = view ? view->style() : QApplication::style();
    style->drawControl(QStyle::CE_ItemViewItem, &opt, painter, view);

    const bool selected = opt.state & QStyle::State_Selected;
    const bool offline = index.data(PageSidebar::OfflineRole).toBool();
    const QPalette::ColorRole textRole = selected ? QPalette::HighlightedText : QPalette::Text;
    const QColor text = offline && !selected
                            ? stateColour(StateTone::Unknown, opt.palette, QPalette::Base)
                            : opt.palette.color(QPalette::Active, textRole);
    const Geometry g = geometry(opt, index);
    icon.paint(painter, g.icon, Qt::AlignCenter,
               selected  ? QIcon::Selected
               : offline ? QIcon::Disabled
                         : QIcon::Normal);

    const int edits = index.data(PageSidebar::EditsRole).toInt();
    const QString progress = index.data(PageSidebar::ProgressRole).toString();
    const auto markColour = [&](StateTone tone) {
        return selected ? opt.palette.color(QPalette::Active, QPalette::HighlightedText)
                        : stateColour(tone, opt.palette, QPalette::Base);
    };
    painter->setFont(markFont(opt.font));
    if (!progress.isEmpty()) {
        painter->setPen(
            markColour(static_cast<StateTone>(index.data(PageSidebar::ProgressToneRole).toInt())));
        painter->drawText(g.marks, Qt::AlignRight | Qt::AlignVCenter | Qt::TextSingleLine,
                          progress);
    } else if (edits > 0) {
        painter->setPen(markColour(StateTone::Warning));
        painter->drawText(g.marks, Qt::AlignRight | Qt::AlignVCenter | Qt::TextSingleLine,
                          editMark(edits));
    }
    painter->setFont(opt.font);
    painter->setPen(text);
    painter->drawText(g.title, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine,
                      fm.elidedText(title, Qt::ElideRight, g.title.width()));
    painter->restore();
}

} // namespace stepcom

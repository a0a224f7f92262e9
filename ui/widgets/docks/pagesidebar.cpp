#include "widgets/docks/pagesidebar.h"

#include "device/parameterstore.h"
#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/docks/pagesidebardelegate.h"
#include "widgets/fields/lineicon.h"

#include <QEvent>
#include <QResizeEvent>
#include <QScrollBar>
#include <QToolButton>

namespace stepcom {

PageSidebar::PageSidebar(DeviceSession *session, QWidget *parent)
    : QListWidget(parent)
    , m_session(session)
    , m_delegate(new PageSidebarDelegate(this))
    , m_up(new QToolButton(this))
    , m_down(new QToolButton(this))
{
    setObjectName(QStringLiteral("sidebar"));
    setItemDelegate(m_delegate);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // A scroll bar would take the titles' room on a short screen (1366×768 at ×1.5): the list
    // still scrolls by wheel and keys, and a fade with an arrow says that more is there.
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setVerticalScrollMode(QAbstractItemView::ScrollPerPixel);
    setUniformItemSizes(false);
    for (QToolButton *arrow : {m_up, m_down}) {
        arrow->setAutoRaise(true);
        arrow->setFocusPolicy(Qt::NoFocus); // the arrow keys scroll the list already
        arrow->setAutoRepeat(true);
        arrow->hide();
    }
    m_up->setObjectName(QStringLiteral("sidebarMoreAbove"));
    m_down->setObjectName(QStringLiteral("sidebarMoreBelow"));
    m_up->setArrowType(Qt::UpArrow);
    m_down->setArrowType(Qt::DownArrow);
    connect(m_up, &QToolButton::clicked, this,
            [this] { verticalScrollBar()->triggerAction(QAbstractSlider::SliderSingleStepSub); });
    connect(m_down, &QToolButton::clicked, this,
            [this] { verticalScrollBar()->triggerAction(QAbstractSlider::SliderSingleStepAdd); });
    connect(verticalScrollBar(), &QScrollBar::valueChanged, this, &PageSidebar::updateArrows);
    connect(verticalScrollBar(), &QScrollBar::rangeChanged, this, &PageSidebar::updateArrows);
    connect(this, &QListWidget::currentItemChanged, this, [this](QListWidgetItem *item) {
        const int page = item ? item->data(PageRole).toInt() : -1;
        if (page >= 0)
            Q_EMIT pageChosen(page);
    });
    // A screen reader chooses an entry through the accessibility interface (AT-SPI's Toggle
    // action, a table's row selection): that selects it without making it current.
    connect(this, &QListWidget::itemSelectionChanged, this, [this] {
        const QList<QListWidgetItem *> chosen = selectedItems();
        if (chosen.size() == 1 && chosen.first() != currentItem() &&
            chosen.first()->data(PageRole).toInt() >= 0)
            setCurrentItem(chosen.first());
    });
    connect(session->parameters()->store(), &ParameterStore::editsChanged, this,
            &PageSidebar::refresh);
    connect(session->connection()->health(), &LinkHealth::stateChanged, this,
            &PageSidebar::refresh);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &PageSidebar::refresh);
}

void PageSidebar::addPage(Page *page)
{
    const int number = int(m_pages.size());
    m_pages << page;
    // After the last page of its stage; its stage's header made when the first page of that
    // stage comes, so the stages stand in their order whatever the order of the pages.
    const Page::Stage stage = page->stage();
    int row = 0;
    for (; row < count(); ++row) {
        const int p = item(row)->data(PageRole).toInt();
        const Page::Stage rowStage =
            p >= 0 ? m_pages.at(p)->stage() : Page::Stage(item(row)->data(Qt::UserRole).toInt());
        if (rowStage > stage)
            break;
    }
    const bool hasHeader = [&] {
        for (int r = 0; r < count(); ++r) {
            if (item(r)->data(PageRole).toInt() < 0 &&
                Page::Stage(item(r)->data(Qt::UserRole).toInt()) == stage)
                return true;
        }
        return false;
    }();
    if (!hasHeader) {
        auto *header = new QListWidgetItem;
        header->setData(PageRole, -1);
        header->setData(Qt::UserRole, int(stage));
        // Neither selectable nor enabled: the arrow keys pass over it.
        header->setFlags(Qt::NoItemFlags);
        insertItem(row++, header);
    }
    auto *entry = new QListWidgetItem;
    entry->setData(PageRole, number);
    insertItem(row, entry);
    connect(page, &Page::progressChanged, this, &PageSidebar::refresh);
    retranslate();
}

QListWidgetItem *PageSidebar::itemOf(int page) const
{
    for (int r = 0; r < count(); ++r) {
        if (item(r)->data(PageRole).toInt() == page)
            return item(r);
    }
    return nullptr;
}

void PageSidebar::setCurrentPage(int index)
{
    if (QListWidgetItem *entry = itemOf(index))
        setCurrentItem(entry);
}

int PageSidebar::currentPage() const
{
    return currentItem() ? currentItem()->data(PageRole).toInt() : -1;
}

int PageSidebar::editCount(int page) const
{
    if (page < 0 || page >= m_pages.size())
        return 0;
    const QStringList keys = m_pages.at(page)->keys();
    int edits = 0;
    for (const QString &key : m_session->parameters()->store()->editedKeys())
        edits += keys.contains(key) ? 1 : 0;
    return edits;
}

bool PageSidebar::isOffline(int page) const
{
    return page >= 0 && page < m_pages.size() && m_pages.at(page)->needsDevice() &&
           !m_session->connection()->health()->isAnswering();
}

QString PageSidebar::stateText(int page) const
{
    QStringList parts;
    if (const int edits = editCount(page))
        parts << tr("%n edit(s) not written", nullptr, edits);
    if (page >= 0 && page < m_pages.size()) {
        const Page::Progress p = m_pages.at(page)->progress();
        if (p.total > 0)
            parts << (p.known ? tr("%1 of %2 steps passed").arg(p.passed).arg(p.total)
                              : tr("steps passed not known"));
    }
    if (isOffline(page))
        parts << tr("needs a controller that answers (%1)")
                     .arg(m_session->connection()->health()->stateText());
    return parts.join(QStringLiteral("; "));
}

QColor PageSidebar::editColour() const
{
    return stateColour(StateTone::Warning, viewport()->palette(), QPalette::Base);
}

QColor PageSidebar::progressColour(int page) const
{
    const QListWidgetItem *entry = itemOf(page);
    return stateColour(entry ? StateTone(entry->data(ProgressToneRole).toInt()) : StateTone::Normal,
                       viewport()->palette(), QPalette::Base);
}

QColor PageSidebar::offlineColour() const
{
    return stateColour(StateTone::Unknown, viewport()->palette(), QPalette::Base);
}

void PageSidebar::refresh()
{
    for (int page = 0; page < m_pages.size(); ++page) {
        QListWidgetItem *entry = itemOf(page);
        if (!entry)
            continue;
        entry->setData(EditsRole, editCount(page));
        const Page::Progress p = m_pages.at(page)->progress();
        entry->setData(MostEditsRole, int(m_pages.at(page)->keys().size()));
        entry->setData(StepsRole, p.total);
        QString progress;
        StateTone tone = StateTone::Normal;
        if (p.total > 0 && !p.known) {
            progress = QStringLiteral("?");
            tone = StateTone::Unknown;
        } else if (p.total > 0) {
            progress = QStringLiteral("%1/%2").arg(p.passed).arg(p.total);
            tone = p.passed == p.total ? StateTone::Good : StateTone::Normal;
        }
        entry->setData(ProgressRole, progress);
        entry->setData(ProgressToneRole, int(tone));
        entry->setData(OfflineRole, isOffline(page));
        const QString state = stateText(page);
        entry->setToolTip(state.isEmpty() ? entry->text()
                                          : QStringLiteral("%1: %2").arg(entry->text(), state));
        entry->setData(Qt::AccessibleDescriptionRole, state);
    }
}

void PageSidebar::refreshIcons()
{
    for (int page = 0; page < m_pages.size(); ++page) {
        if (QListWidgetItem *entry = itemOf(page))
            entry->setIcon(lineIcon(
                QStringLiteral(":/sidebar/%1.svg").arg(m_pages.at(page)->iconName()), palette()));
    }
}

QString PageSidebar::stageTitle(Page::Stage stage)
{
    switch (stage) {
    case Page::Stage::Connect:
        return tr("Connect");
    case Page::Stage::SetUp:
        return tr("Set up");
    case Page::Stage::MoveAndRun:
        return tr("Move and run");
    case Page::Stage::CheckAndReport:
        return tr("Check, save and report");
    }
    return {};
}

void PageSidebar::retranslate()
{
    for (int r = 0; r < count(); ++r) {
        QListWidgetItem *row = item(r);
        const int page = row->data(PageRole).toInt();
        row->setText(page >= 0 ? m_pages.at(page)->title()
                               : stageTitle(Page::Stage(row->data(Qt::UserRole).toInt())));
        if (page < 0)
            row->setToolTip(row->text());
    }
    m_up->setToolTip(tr("More pages above"));
    m_up->setAccessibleName(m_up->toolTip());
    m_down->setToolTip(tr("More pages below"));
    m_down->setAccessibleName(m_down->toolTip());
    refreshIcons();
    refresh();
    updateWidth();
    updateCompact();
}

bool PageSidebar::isCompact() const
{
    return m_delegate->isCompact();
}

bool PageSidebar::hasThinHeaders() const
{
    return m_delegate->hasThinHeaders();
}

QStringList PageSidebar::cutEntries() const
{
    QStyleOptionViewItem option;
    initViewItemOption(&option);
    QStringList cut;
    for (int r = 0; r < count(); ++r) {
        const QModelIndex index = indexFromItem(item(r));
        option.rect = visualRect(index);
        const int needs = m_delegate->sizeHint(option, index).width();
        const int has = option.rect.width();
        if (!m_delegate->titleFits(option, index))
            cut << QStringLiteral("%1 (%2 of %3 px)").arg(item(r)->text()).arg(has).arg(needs);
    }
    return cut;
}

void PageSidebar::updateCompact()
{
    const bool wasCompact = m_delegate->isCompact();
    const bool wasThin = m_delegate->hasThinHeaders();
    m_delegate->setThinHeaders(false);
    m_delegate->setCompact(false);
    // The room the rows have without the arrows (the viewport shrinks while they show).
    const int room = contentsRect().height();
    const bool compact = m_shortWindow || rowsHeight() > room;
    m_delegate->setCompact(compact);
    // Every page in view matters more than the groups' titles.
    const bool thin = compact && rowsHeight() > room;
    m_delegate->setThinHeaders(thin);
    if (compact != wasCompact || thin != wasThin) {
        updateWidth();
        // The rows' heights changed: lay them out now, so the scroll range and the rows a click
        // finds are those drawn.
        doItemsLayout();
    }
    updateArrows();
}

int PageSidebar::rowsHeight() const
{
    QStyleOptionViewItem option;
    initViewItemOption(&option);
    int height = 0;
    for (int r = 0; r < count(); ++r)
        height += m_delegate->sizeHint(option, indexFromItem(item(r))).height() + 2 * spacing();
    return height;
}

void PageSidebar::updateArrows()
{
    const QRect room = contentsRect();
    const bool scrolls = rowsHeight() > room.height();
    const int band = scrolls ? std::max(12, fontMetrics().height() * 3 / 4) : 0;
    if (viewportMargins() != QMargins(0, band, 0, band))
        setViewportMargins(0, band, 0, band);
    m_up->setVisible(scrolls);
    m_down->setVisible(scrolls);
    if (!scrolls)
        return;
    m_up->setGeometry(room.left(), room.top(), room.width(), band);
    m_down->setGeometry(room.left(), room.bottom() + 1 - band, room.width(), band);
    m_up->setEnabled(hasMoreAbove());
    m_down->setEnabled(hasMoreBelow());
}

QRect PageSidebar::clearArea() const
{
    return viewport()->rect();
}

void PageSidebar::setShortWindow(bool isShort)
{
    m_shortWindow = isShort;
    updateCompact();
}

void PageSidebar::resizeEvent(QResizeEvent *event)
{
    QListWidget::resizeEvent(event);
    updateCompact();
}

void PageSidebar::updateWidth()
{
    // As wide as its widest entry with its marks, never wider: the page takes the rest.
    int widest = 0;
    QStyleOptionViewItem option;
    initViewItemOption(&option);
    for (int r = 0; r < count(); ++r)
        widest = std::max(widest, itemDelegate()->sizeHint(option, indexFromItem(item(r))).width());
    setMinimumWidth(widest + 2 * frameWidth());
    setMaximumWidth(
        std::max(minimumWidth(), fontMetrics().horizontalAdvance(QLatin1Char('x')) * 40));
}

QModelIndex PageSidebar::moveCursor(CursorAction action, Qt::KeyboardModifiers modifiers)
{
    const QModelIndex to = QListWidget::moveCursor(action, modifiers);
    if (!to.isValid() || to.data(PageRole).toInt() >= 0)
        return to;
    const bool up = action == MoveUp || action == MovePageUp || action == MoveEnd ||
                    action == MovePrevious || action == MoveLeft;
    // Onwards in the key's direction; a header at the very end: back the other way.
    for (const int step : {up ? -1 : 1, up ? 1 : -1}) {
        for (int r = to.row() + step; r >= 0 && r < count(); r += step) {
            if (item(r)->data(PageRole).toInt() >= 0)
                return indexFromItem(item(r));
        }
    }
    return currentIndex();
}

bool PageSidebar::hasMoreAbove() const
{
    return verticalScrollBar()->value() > verticalScrollBar()->minimum();
}

bool PageSidebar::hasMoreBelow() const
{
    return verticalScrollBar()->value() < verticalScrollBar()->maximum();
}

void PageSidebar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange)
        retranslate(); // icons in the new colours, the width for the new font
    QListWidget::changeEvent(event);
}

} // namespace stepcom

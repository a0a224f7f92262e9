#include "widgets/fields/wrappingrow.h"

#include <QBoxLayout>
#include <QDockWidget>
#include <QEvent>

#include <algorithm>

namespace stepcom {

WrappingRow::WrappingRow(QWidget *parent)
    : QWidget(parent)
    , m_rows(new QBoxLayout(QBoxLayout::LeftToRight, this))
    , m_first(new QHBoxLayout)
    , m_second(new QHBoxLayout)
{
    m_rows->setContentsMargins(0, 0, 0, 0);
    m_rows->addLayout(m_first);
    m_rows->addLayout(m_second);
}

bool WrappingRow::isWrapped() const
{
    return m_rows->direction() == QBoxLayout::TopToBottom;
}

QSize WrappingRow::minimumSizeHint() const
{
    const QMargins m = m_rows->contentsMargins();
    const int width = std::max(m_first->minimumSize().width(), m_second->minimumSize().width());
    return {width + m.left() + m.right(), m_rows->minimumSize().height()};
}

void WrappingRow::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    arrange();
}

void WrappingRow::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // A dock behind another tab is moved out of view, not hidden, and its tab chosen moves it
    // back: nothing here is resized or moved, only the dock.
    for (QWidget *w = parentWidget(); w && !m_watchesDock; w = w->parentWidget()) {
        if (qobject_cast<QDockWidget *>(w)) {
            w->installEventFilter(this);
            m_watchesDock = true;
        }
    }
    arrange();
}

bool WrappingRow::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Move || event->type() == QEvent::Resize)
        QMetaObject::invokeMethod(this, &WrappingRow::arrange, Qt::QueuedConnection);
    return QWidget::eventFilter(watched, event);
}

bool WrappingRow::event(QEvent *event)
{
    // The words changed (a language, a state): side by side may fit now, or no longer.
    if (event->type() == QEvent::LayoutRequest)
        arrange();
    return QWidget::event(event);
}

void WrappingRow::arrange()
{
    const QMargins m = m_rows->contentsMargins();
    const int sideBySide = m_first->sizeHint().width() + m_rows->spacing() +
                           m_second->sizeHint().width() + m.left() + m.right();
    // Not seen (not shown yet, or in a dock behind another tab, which Qt moves out of view
    // rather than hiding): its width means nothing, its height still counts -- one row's.
    const bool seen = isVisible() && !visibleRegion().isEmpty();
    const auto direction =
        !seen || width() >= sideBySide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
    if (m_rows->direction() != direction) {
        m_rows->setDirection(direction);
        updateGeometry(); // the height it needs changed
    }
}

} // namespace stepcom

#include "base/page.h"

#include <QEvent>
#include <QScrollArea>
#include <QVBoxLayout>

namespace stepcom {

Page::Page(DeviceSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
{}

QWidget *Page::scrollableContent()
{
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    outer->addWidget(scroll);
    auto *content = new QWidget(scroll);
    scroll->setWidget(content);
    return content;
}

void Page::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace stepcom

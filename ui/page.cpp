#include "page.h"

#include <QEvent>

namespace stepcom {

Page::Page(DeviceSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
{}

void Page::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace stepcom

#include "widgets/fields/aboutbox.h"

#include <QAction>
#include <QEvent>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace stepcom {

AboutBox::AboutBox(QWidget *parent)
    : QWidget(parent)
    , m_button(new QToolButton(this))
    , m_text(new QLabel(this))
    , m_guide(new QToolButton(this))
{
    setObjectName(QStringLiteral("aboutBox"));
    m_button->setObjectName(QStringLiteral("aboutButton"));
    m_button->setCheckable(true);
    m_button->setAutoRaise(true);
    m_button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_button->setArrowType(Qt::RightArrow);
    m_text->setObjectName(QStringLiteral("aboutText"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_text->setVisible(false);
    m_guide->setObjectName(QStringLiteral("aboutGuideButton"));
    m_guide->setAutoRaise(true);
    m_guide->setVisible(false);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_button, 0, Qt::AlignLeft);
    layout->addWidget(m_text);
    layout->addWidget(m_guide, 0, Qt::AlignLeft);
    connect(m_button, &QToolButton::toggled, this, &AboutBox::setOpen);
    connect(m_guide, &QToolButton::clicked, this, [this] {
        if (QAction *f1 = window()->findChild<QAction *>(QStringLiteral("userGuide")))
            f1->trigger();
    });
    retranslate();
}

void AboutBox::setText(const QString &text)
{
    m_text->setText(text);
    setWhatsThis(text);
    m_button->setWhatsThis(text);
}

QString AboutBox::text() const
{
    return m_text->text();
}

bool AboutBox::isOpen() const
{
    return m_button->isChecked();
}

void AboutBox::setOpen(bool open)
{
    m_button->setChecked(open);
    m_button->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    m_text->setVisible(open);
    m_guide->setVisible(open && window()->findChild<QAction *>(QStringLiteral("userGuide")));
}

void AboutBox::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void AboutBox::retranslate()
{
    m_button->setText(tr("About this page"));
    m_button->setToolTip(tr("Show or hide what this page is for (F1: the user guide)"));
    m_button->setAccessibleName(m_button->text());
    m_guide->setText(tr("More in the user guide (F1)"));
}

} // namespace stepcom

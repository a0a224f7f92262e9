#include "widgets/fields/lineoptionsbox.h"

#include "line/linksettingsstore.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStyle>

#include <algorithm>

namespace stepcom {

namespace {

QSpinBox *newMsSpin(QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    spin->setRange(0, 1000);
    return spin;
}

} // namespace

LineOptionsBox::LineOptionsBox(QWidget *parent)
    : QGroupBox(parent)
    , m_answerDelayLabel(new QLabel(this))
    , m_answerDelay(newMsSpin(this))
    , m_turnaroundLabel(new QLabel(this))
    , m_turnaround(newMsSpin(this))
    , m_echo(new QCheckBox(this))
    , m_rs485Label(new QLabel(this))
    , m_rs485(new QComboBox(this))
    , m_offer(new QWidget(this))
    , m_offerText(new QLabel(m_offer))
    , m_acceptEcho(new QPushButton(m_offer))
{
    setObjectName(QStringLiteral("lineOptions"));
    m_answerDelay->setObjectName(QStringLiteral("answerDelay"));
    m_turnaround->setObjectName(QStringLiteral("turnaround"));
    m_echo->setObjectName(QStringLiteral("echo"));
    m_acceptEcho->setObjectName(QStringLiteral("acceptEcho"));
    m_rs485->setObjectName(QStringLiteral("rs485"));
    m_rs485Label->setBuddy(m_rs485);
    m_rs485->addItems({QString(), QString(), QString()}); // Auto, Kernel, Rts: texts below
    m_answerDelayLabel->setBuddy(m_answerDelay);
    m_turnaroundLabel->setBuddy(m_turnaround);

    // The offer: a warning icon, what was seen, and the one button that acts on it.
    auto *icon = new QLabel(m_offer);
    const int size = fontMetrics().height();
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(size));
    m_offerText->setWordWrap(true);
    auto *offerRow = new QHBoxLayout(m_offer);
    offerRow->setContentsMargins(0, 0, 0, 0);
    offerRow->addWidget(icon, 0, Qt::AlignTop);
    offerRow->addWidget(m_offerText, 1);
    offerRow->addWidget(m_acceptEcho, 0, Qt::AlignTop);
    m_offer->hide();

    auto *grid = new QGridLayout(this);
    grid->addWidget(m_answerDelayLabel, 0, 0);
    grid->addWidget(m_answerDelay, 0, 1);
    grid->addWidget(m_turnaroundLabel, 0, 2);
    grid->addWidget(m_turnaround, 0, 3);
    grid->setColumnStretch(4, 1);
    grid->addWidget(m_echo, 1, 0, 1, 5);
    grid->addWidget(m_offer, 2, 0, 1, 5);
    grid->addWidget(m_rs485Label, 3, 0);
    grid->addWidget(m_rs485, 3, 1, 1, 4, Qt::AlignLeft);

    connect(m_acceptEcho, &QPushButton::clicked, this, [this] {
        m_echo->setChecked(true);
        hideEchoOffer();
        Q_EMIT echoAccepted();
    });
    connect(m_echo, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            hideEchoOffer();
    });
    retranslate();
}

void LineOptionsBox::apply(const LinkSettings &settings)
{
    m_answerDelay->setValue(settings.answerDelayMs);
    m_turnaround->setValue(settings.turnaroundMs);
    m_echo->setChecked(settings.echo);
    m_rs485->setCurrentIndex(int(settings.rs485));
}

void LineOptionsBox::fillInto(LinkSettings &settings) const
{
    settings.answerDelayMs = m_answerDelay->value();
    settings.turnaroundMs = m_turnaround->value();
    settings.echo = m_echo->isChecked();
    settings.rs485 = LinkSettings::Rs485(std::max(0, m_rs485->currentIndex()));
}

void LineOptionsBox::offerEcho()
{
    if (!m_echo->isChecked())
        m_offer->show();
}

void LineOptionsBox::hideEchoOffer()
{
    m_offer->hide();
}

bool LineOptionsBox::echoOffered() const
{
    return !m_offer->isHidden();
}

void LineOptionsBox::retranslate()
{
    setTitle(tr("Line and adapter"));
    m_answerDelayLabel->setText(tr("&Answer delay:"));
    m_answerDelay->setToolTip(
        tr("How long the controller may take to answer (its manual: 35 ms): the least the "
           "timeout is fitted to. Answers are judged by what they say, however soon they "
           "come"));
    m_answerDelay->setSuffix(tr(" ms"));
    m_rs485Label->setText(tr("&RS-485 direction:"));
    m_rs485->setItemText(0, tr("the adapter switches by itself"));
    m_rs485->setItemText(1, tr("the driver's RS-485 mode (RTS on send)"));
    m_rs485->setItemText(2, tr("StepCom switches RTS"));
    m_rs485->setToolTip(tr("Who switches an RS-485 adapter between sending and receiving. Most "
                           "adapters do it themselves; some converters need RTS. A driver that "
                           "refuses is named when connecting, and nothing is sent"));
    m_turnaroundLabel->setText(tr("T&urnaround:"));
    m_turnaround->setToolTip(
        tr("Extra silence after an answer before the next request, for converters that need "
           "it"));
    m_turnaround->setSuffix(tr(" ms"));
    m_echo->setText(tr("The adapter &echoes what it sends"));
    m_echo->setToolTip(tr("For half-duplex USB-RS485 adapters without echo suppression: the "
                          "request's own bytes are skipped from the first request on. "
                          "Without it StepCom finds the echo on the first read"));
    m_offerText->setText(
        tr("This adapter echoes what it sends: StepCom found the request's own bytes before "
           "the answers and skips them. Remember it for this port?"));
    m_acceptEcho->setText(tr("Remember echo"));
}

} // namespace stepcom

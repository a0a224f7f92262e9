#include "replay/replaybar.h"

#include "replay/replayslider.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStandardItemModel>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace stepcom {

namespace {

QToolButton *button(const char *name, QWidget *parent)
{
    auto *b = new QToolButton(parent);
    b->setObjectName(QLatin1String(name));
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return b;
}

} // namespace

ReplayBar::ReplayBar(QWidget *parent)
    : QFrame(parent)
    , m_play(button("replayPlay", this))
    , m_speed(new QComboBox(this))
    , m_backFrame(button("replayBackFrame", this))
    , m_nextFrame(button("replayNextFrame", this))
    , m_slider(new ReplaySlider(this))
    , m_momentLabel(new QLabel(this))
    , m_backEvent(button("replayBackEvent", this))
    , m_events(new QComboBox(this))
    , m_nextEvent(button("replayNextEvent", this))
    , m_deviceCaption(new QLabel(this))
    , m_devices(new QComboBox(this))
    , m_close(button("closeReplayButton", this))
{
    setObjectName(QStringLiteral("replayBar"));
    setFrameShape(QFrame::StyledPanel);
    m_play->setCheckable(true);
    m_speed->setObjectName(QStringLiteral("replaySpeed"));
    for (const int factor : {1, 4, 16})
        m_speed->addItem(QStringLiteral("%1×").arg(factor), factor);
    m_momentLabel->setObjectName(QStringLiteral("replayMoment"));
    m_momentLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_momentLabel->setMinimumWidth(
        fontMetrics().horizontalAdvance(QStringLiteral("+00000.000 s (00:00:00.000)")));
    m_events->setObjectName(QStringLiteral("replayEvents"));
    m_events->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_events->setMinimumContentsLength(24);
    m_devices->setObjectName(QStringLiteral("replayDevices"));
    m_deviceCaption->setBuddy(m_devices);

    m_top = new QHBoxLayout;
    m_bottom = new QHBoxLayout;
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addLayout(m_top);
    layout->addLayout(m_bottom);
    place();

    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &ReplayBar::tick);
    connect(m_play, &QToolButton::toggled, this, &ReplayBar::setPlaying);
    connect(m_backFrame, &QToolButton::clicked, this, [this] { Q_EMIT stepFrame(-1); });
    connect(m_nextFrame, &QToolButton::clicked, this, [this] { Q_EMIT stepFrame(+1); });
    connect(m_slider, &QSlider::valueChanged, this, [this](int ms) {
        if (ms != m_moment)
            Q_EMIT seekRequested(ms);
    });
    connect(m_backEvent, &QToolButton::clicked, this, [this] { stepEvent(-1); });
    connect(m_nextEvent, &QToolButton::clicked, this, [this] { stepEvent(+1); });
    connect(m_events, &QComboBox::activated, this, [this](int index) {
        if (index >= 0 && index < m_eventList.size())
            Q_EMIT seekRequested(m_eventList.at(index).ms);
    });
    connect(m_devices, &QComboBox::activated, this,
            [this](int index) { Q_EMIT deviceChosen(m_devices->itemData(index).toInt()); });
    connect(m_close, &QToolButton::clicked, this, &ReplayBar::closeRequested);
    retranslate();
}

void ReplayBar::place()
{
    for (QHBoxLayout *row : {m_top, m_bottom}) {
        while (QLayoutItem *item = row->takeAt(0))
            delete item; // the widgets stay, only their places go
    }
    m_top->addWidget(m_play);
    m_top->addWidget(m_speed);
    m_top->addWidget(m_backFrame);
    m_top->addWidget(m_nextFrame);
    m_top->addWidget(m_slider, m_compact ? 2 : 1);
    m_top->addWidget(m_momentLabel);
    QHBoxLayout *events = m_compact ? m_top : m_bottom;
    events->addWidget(m_backEvent);
    events->addWidget(m_events, 1);
    events->addWidget(m_nextEvent);
    events->addWidget(m_deviceCaption);
    events->addWidget(m_devices);
    if (!m_compact)
        events->addStretch();
    events->addWidget(m_close);
    m_events->setMinimumContentsLength(m_compact ? 12 : 24);
}

void ReplayBar::setCompact(bool compact)
{
    if (compact == m_compact)
        return;
    m_compact = compact;
    place();
}

void ReplayBar::showEvent(QShowEvent *event)
{
    // The window's height decides, as it does for the machine strip.
    if (window() != this)
        window()->installEventFilter(this);
    setCompact(window()->height() < std::max(720, fontMetrics().height() * 40));
    QFrame::showEvent(event);
}

bool ReplayBar::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == window() && event->type() == QEvent::Resize)
        setCompact(window()->height() < std::max(720, fontMetrics().height() * 40));
    return QFrame::eventFilter(watched, event);
}

void ReplayBar::setLog(qint64 durationMs, const QList<ReplayEvent> &events,
                       const QList<int> &devices, std::function<QString(qint64)> momentText)
{
    setPlaying(false);
    m_duration = durationMs;
    m_eventList = events;
    m_momentText = std::move(momentText);
    {
        const QSignalBlocker blocker(m_slider);
        m_slider->setEvents(events, durationMs);
    }
    m_devices->clear();
    for (const int id : devices)
        m_devices->addItem(QString::number(id), id);
    m_devices->setVisible(devices.size() > 1);
    m_deviceCaption->setVisible(devices.size() > 1);
    fillEvents();
    m_moment = -1;
    setMoment(0);
}

void ReplayBar::fillEvents()
{
    m_events->clear();
    const int listed = int(std::min<qsizetype>(m_eventList.size(), kListedEvents));
    for (int i = 0; i < listed; ++i) {
        const ReplayEvent &e = m_eventList.at(i);
        const QString moment = QStringLiteral("%1 s").arg(double(e.ms) / 1000.0, 0, 'f', 3);
        const QString device = e.device > 0 ? tr("id %1").arg(e.device) : tr("line");
        m_events->addItem(QStringLiteral("%1  %2  %3").arg(moment, device, e.text));
        m_events->setItemData(i, QColor(ReplaySlider::colorOf(e.kind)), Qt::ForegroundRole);
    }
    if (m_eventList.size() > listed) {
        m_events->addItem(tr("… %n more event(s): Event ▶ reaches them", nullptr,
                             int(m_eventList.size() - listed)));
        if (auto *model = qobject_cast<QStandardItemModel *>(m_events->model()))
            model->item(listed)->setEnabled(false); // shown, not chosen
    }
    m_events->setEnabled(!m_eventList.isEmpty());
    m_backEvent->setEnabled(!m_eventList.isEmpty());
    m_nextEvent->setEnabled(!m_eventList.isEmpty());
}

void ReplayBar::setMoment(qint64 ms)
{
    ms = std::clamp<qint64>(ms, 0, m_duration);
    if (ms == m_moment)
        return;
    m_moment = ms;
    {
        const QSignalBlocker blocker(m_slider);
        m_slider->setValue(int(ms));
    }
    m_momentLabel->setText(m_momentText ? m_momentText(ms) : QString());
    // The list shows the last event at or before the moment.
    const auto after = std::upper_bound(m_eventList.cbegin(), m_eventList.cend(), ms,
                                        [](qint64 t, const ReplayEvent &e) { return t < e.ms; });
    const int index = int(after - m_eventList.cbegin()) - 1;
    if (index >= 0)
        m_events->setCurrentIndex(index < kListedEvents ? index : -1);
    if (ms >= m_duration)
        setPlaying(false);
}

void ReplayBar::setDevice(int id)
{
    const int index = m_devices->findData(id);
    if (index >= 0)
        m_devices->setCurrentIndex(index);
}

void ReplayBar::setPlaying(bool playing)
{
    // Playing from the end starts over.
    if (playing && m_moment >= m_duration)
        Q_EMIT seekRequested(0);
    if (playing)
        m_timer.start();
    else
        m_timer.stop();
    const QSignalBlocker blocker(m_play);
    m_play->setChecked(playing);
    retranslate();
}

int ReplayBar::speed() const
{
    return m_speed->currentData().toInt();
}

void ReplayBar::setSpeed(int factor)
{
    const int index = m_speed->findData(factor);
    if (index >= 0)
        m_speed->setCurrentIndex(index);
}

void ReplayBar::tick()
{
    Q_EMIT seekRequested(std::min(m_duration, m_moment + qint64(kTickMs) * speed()));
}

void ReplayBar::stepEvent(int direction)
{
    const ReplayEvent *to = nullptr;
    if (direction > 0) {
        const auto it = std::find_if(m_eventList.cbegin(), m_eventList.cend(),
                                     [this](const ReplayEvent &e) { return e.ms > m_moment; });
        to = it == m_eventList.cend() ? nullptr : &*it;
    } else {
        const auto it = std::find_if(m_eventList.crbegin(), m_eventList.crend(),
                                     [this](const ReplayEvent &e) { return e.ms < m_moment; });
        to = it == m_eventList.crend() ? nullptr : &*it;
    }
    if (to)
        Q_EMIT seekRequested(to->ms);
}

void ReplayBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        fillEvents();
    }
    QFrame::changeEvent(event);
}

void ReplayBar::retranslate()
{
    m_play->setText(isPlaying() ? tr("Pause") : tr("Play"));
    m_play->setToolTip(tr("Play the log at the chosen speed, or hold it at this moment"));
    m_speed->setToolTip(tr("Replay speed"));
    m_speed->setAccessibleName(tr("Replay speed"));
    m_backFrame->setText(tr("◀ Frame"));
    m_backFrame->setToolTip(tr("The frame before this moment"));
    m_nextFrame->setText(tr("Frame ▶"));
    m_nextFrame->setToolTip(tr("The next frame after this moment"));
    m_slider->setAccessibleName(tr("Moment of the log"));
    m_slider->setToolTip(QString()); // the markers say what they are
    m_momentLabel->setToolTip(tr("Time from the start of the log (clock time)"));
    m_backEvent->setText(tr("◀ Event"));
    m_backEvent->setToolTip(tr("The event before this moment"));
    m_nextEvent->setText(tr("Event ▶"));
    m_nextEvent->setToolTip(tr("The next event after this moment"));
    m_events->setAccessibleName(tr("Events of the log"));
    m_events->setToolTip(tr("Writes, commands, E-STOPs, errors, the link and restarts; choose "
                            "one to see that moment"));
    m_deviceCaption->setText(tr("&Device:"));
    m_devices->setToolTip(tr("The controller of the line shown on the pages"));
    m_close->setText(tr("Close replay"));
    m_close->setToolTip(tr("Leave the replay; the window is empty again, ready to connect"));
}

} // namespace stepcom

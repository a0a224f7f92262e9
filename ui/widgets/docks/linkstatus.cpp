#include "widgets/docks/linkstatus.h"

#include "widgets/fields/statetone.h"

#include "session/devicesession.h"
#include "session/linkhealth.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/reconnector.h"
#include "widgets/fields/elidedlabel.h"

#include <QDateTime>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace stepcom {

LinkStatus::LinkStatus(DeviceSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_state(new QLabel(this))
    , m_where(new ElidedLabel(this))
    , m_rate(new ElidedLabel(this))
    , m_errors(new ElidedLabel(this))
    , m_unsaved(new QLabel(this))
    , m_reconnect(new QLabel(this))
    , m_cancelReconnect(new QPushButton(this))
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    for (QLabel *l : {m_unsaved, m_state, m_reconnect})
        layout->addWidget(l);
    layout->addWidget(m_cancelReconnect);
    for (QLabel *l : {m_where, m_rate, m_errors})
        layout->addWidget(l);
    m_reconnect->setObjectName(QStringLiteral("reconnectText"));
    m_cancelReconnect->setObjectName(QStringLiteral("reconnectCancel"));
    m_reconnect->hide();
    m_cancelReconnect->hide();
    Reconnector *reconnector = session->connection()->reconnector();
    connect(m_cancelReconnect, &QPushButton::clicked, reconnector, &Reconnector::cancel);
    connect(reconnector, &Reconnector::stateChanged, this, &LinkStatus::refreshReconnect);
    connect(reconnector, &Reconnector::countdown, this, &LinkStatus::refreshReconnect);
    QFont bold = m_unsaved->font();
    bold.setBold(true);
    m_unsaved->setFont(bold);
    m_state->setFont(bold);
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &LinkStatus::refresh);
    connect(session->connection()->health(), &LinkHealth::stateChanged, this, &LinkStatus::refresh);
    connect(session->parameters()->store(), &ParameterStore::unsavedChanged, this,
            &LinkStatus::refresh);
    connect(&m_timer, &QTimer::timeout, this, &LinkStatus::refresh);
    m_timer.start(1000);
    refresh();
}

void LinkStatus::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        refresh();
        refreshReconnect();
    } else if (event->type() == QEvent::PaletteChange) {
        refresh(); // the state's colour for the new background
    }
    QWidget::changeEvent(event);
}

QString LinkStatus::stateText() const
{
    return m_state->text();
}

void LinkStatus::refresh()
{
    // Green "Connected" only once the controller answered; amber while it does not.
    const LinkHealth *health = m_session->connection()->health();
    // The state palette (statetone.h), as the machine strip says it.
    StateTone tone = StateTone::Normal;
    switch (health->state()) {
    case LinkHealth::State::Answering:
        m_state->setText(m_session->connection()->isSimulator() ? tr("Connected (simulator)")
                                                                : tr("Connected"));
        tone = StateTone::Good;
        break;
    case LinkHealth::State::NotAnswering:
        m_state->setText(tr("Not answering"));
        tone = StateTone::Warning;
        break;
    case LinkHealth::State::Asking:
        m_state->setText(tr("Port open, waiting for an answer…"));
        break;
    case LinkHealth::State::Opening:
        m_state->setText(tr("Connecting…"));
        break;
    case LinkHealth::State::Closed:
        m_state->setText(tr("Disconnected"));
        break;
    }
    QPalette pal = m_state->palette();
    pal.setColor(QPalette::WindowText, stateColour(tone, palette(), backgroundRole()));
    m_state->setPalette(pal);
    m_state->setToolTip(health->state() == LinkHealth::State::NotAnswering
                            ? LinkHealth::likelyCauses()
                            : QString());
    m_where->setFullText(m_session->connection()->linkState() ==
                                 SessionConnection::LinkState::Disconnected
                             ? QString()
                             : m_session->connection()->settings().describe());
    const LinkStats &s = m_session->connection()->linkStats();
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    if (m_lastMs > 0 && now > m_lastMs && s.answers >= m_lastAnswers)
        m_perSecond = double(s.answers - m_lastAnswers) * 1000.0 / double(now - m_lastMs);
    m_lastAnswers = s.answers;
    m_lastMs = now;
    // The status rate is the Connection page's, beside the choice of how often to read it.
    m_rate->setFullText(m_session->connection()->isConnected()
                            ? tr("%1 transactions/s").arg(m_perSecond, 0, 'f', 1)
                            : QString());
    // Counted from this connection's start (the session resets them on every connect).
    m_errors->setFullText(tr("errors: %1 (timeouts %2, CRC %3, exceptions %4, stale answers %5)")
                              .arg(s.errors())
                              .arg(s.timeouts)
                              .arg(s.crcErrors)
                              .arg(s.exceptions)
                              .arg(s.stale));
    // What the line showed: the controller's answer times, echo, the timeout in use.
    m_errors->setFullToolTip(
        s.answers == 0 ? QString()
                       : tr("Line: %1 (at most %2 ms)")
                             .arg(s.lineText(m_session->connection()->settings().deviceId))
                             .arg(m_session->connection()->settings().timeoutMs));
    m_unsaved->setText(m_session->parameters()->store()->unsavedToFlash()
                           ? tr("⚠ Not saved to flash")
                           : QString());
    m_unsaved->setToolTip(
        tr("Parameters were written but not saved to the controller's flash: they are lost "
           "when it loses power. Use Save to flash."));
}

void LinkStatus::refreshReconnect()
{
    const Reconnector *r = m_session->connection()->reconnector();
    m_reconnect->setVisible(r->isActive());
    m_cancelReconnect->setVisible(r->isActive());
    m_cancelReconnect->setText(tr("Cancel"));
    m_cancelReconnect->setToolTip(tr("Stop trying to reconnect; Connect tries again"));
    if (r->state() == Reconnector::State::Waiting)
        m_reconnect->setText(tr("Link lost — reconnecting in %1 s (attempt %2)")
                                 .arg(r->secondsLeft())
                                 .arg(r->attempt() + 1));
    else if (r->state() == Reconnector::State::Attempting)
        m_reconnect->setText(tr("Link lost — reconnecting… (attempt %1)").arg(r->attempt()));
    m_reconnect->setToolTip(r->lastError());
}

} // namespace stepcom

#include "widgets/fields/statuspollrow.h"

#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionstatus.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>

namespace stepcom {

StatusPollRow::StatusPollRow(DeviceSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_intervalCaption(new QLabel(this))
    , m_interval(new QComboBox(this))
    , m_rateCaption(new QLabel(this))
    , m_rate(new QLabel(this))
{
    // Two rows, so a narrow page (1366×768 at ×1.5) or a longer language never cuts them.
    auto *rows = new QFormLayout(this);
    rows->setContentsMargins(0, 0, 0, 0);
    rows->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    m_interval->setObjectName(QStringLiteral("pollInterval"));
    for (int ms : {0, 100, 250, 500, 1000})
        m_interval->addItem(QString(), ms);
    m_intervalCaption->setBuddy(m_interval);
    m_rate->setObjectName(QStringLiteral("statusRate"));
    rows->addRow(m_intervalCaption, m_interval);
    rows->addRow(m_rateCaption, m_rate);
    // STEPCOM_POLL_INTERVAL_MS (benchmarks, scripts) wins over the remembered choice.
    if (!qEnvironmentVariableIsSet("STEPCOM_POLL_INTERVAL_MS"))
        session->status()->setIntervalMs(
            QSettings()
                .value(QStringLiteral("monitor/pollIntervalMs"), session->status()->intervalMs())
                .toInt());
    const int current = m_interval->findData(session->status()->intervalMs());
    if (current < 0)
        m_interval->addItem(QString(), session->status()->intervalMs());
    m_interval->setCurrentIndex(current < 0 ? m_interval->count() - 1 : current);
    connect(m_interval, &QComboBox::activated, this, [this](int index) {
        const int ms = m_interval->itemData(index).toInt();
        m_session->status()->setIntervalMs(ms);
        QSettings().setValue(QStringLiteral("monitor/pollIntervalMs"), ms);
    });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &StatusPollRow::refreshRate);
    connect(&m_rateTimer, &QTimer::timeout, this, &StatusPollRow::refreshRate);
    m_rateTimer.start(1000);
    retranslate();
}

QString StatusPollRow::rateText() const
{
    return m_rate->text();
}

void StatusPollRow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void StatusPollRow::refreshRate()
{
    const double rate = m_session->status()->rate();
    if (!m_session->connection()->isConnected() || !m_session->status()->isActive())
        m_rate->setText(tr("unknown"));
    else if (rate <= 0.0)
        m_rate->setText(tr("measuring…"));
    else
        m_rate->setText(tr("%1 Hz").arg(rate, 0, 'f', 1));
    m_rate->setEnabled(m_session->connection()->isConnected());
    m_rate->setAccessibleName(tr("Status updates: %1").arg(m_rate->text()));
}

void StatusPollRow::retranslate()
{
    m_intervalCaption->setText(tr("&Read the status every:"));
    m_interval->setToolTip(tr("How often the status is read. Full rate reads again as soon as a "
                              "cycle ends; the link decides how fast that is."));
    for (int i = 0; i < m_interval->count(); ++i) {
        const int ms = m_interval->itemData(i).toInt();
        m_interval->setItemText(i, ms == 0 ? tr("full rate") : tr("%1 ms").arg(ms));
    }
    m_rateCaption->setText(tr("Achieved:"));
    const QString rateTip = tr("Status updates per second actually achieved by the poller "
                               "(complete read cycles, not the configured rate)");
    m_rateCaption->setToolTip(rateTip);
    m_rate->setToolTip(rateTip);
    refreshRate();
}

} // namespace stepcom

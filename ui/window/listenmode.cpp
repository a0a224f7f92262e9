#include "window/listenmode.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include "base/emergencystop.h"
#include "listen/linelistener.h"
#include "listen/listenlog.h"
#include "session/sessionlog.h"
#include "widgets/docks/machinestrip.h"

#include <QAction>
#include <QDateTime>
#include <QFrame>
#include <QGridLayout>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>

namespace stepcom {

namespace {

constexpr int kWritesKept = 500;

} // namespace

ListenMode::ListenMode(DeviceSession *session, EmergencyStop *estop, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_estop(estop)
    , m_window(window)
    , m_start(new QAction(this))
    , m_banner(new QFrame(window))
    , m_bannerText(new QLabel(m_banner))
    , m_writes(new QListWidget(m_banner))
    , m_stop(new QPushButton(m_banner))
{
    m_start->setObjectName(QStringLiteral("listenOnly"));
    connect(m_start, &QAction::triggered, this, [this] {
        if (isActive()) {
            stop();
            return;
        }
        QString why;
        if (!start(m_source ? m_source() : m_session->connection()->settings(), &why))
            Q_EMIT finished(false, why);
    });
    m_banner->setObjectName(QStringLiteral("listenBanner"));
    m_banner->setFrameShape(QFrame::StyledPanel);
    // Amber: the values are someone else's, seen on the line; not StepCom's, not a replay.
    m_banner->setStyleSheet(QStringLiteral("QFrame#listenBanner { background: #fff1c2; }"
                                           "QFrame#listenBanner QLabel { color: #3d2c00; }"));
    m_bannerText->setWordWrap(true);
    m_writes->setObjectName(QStringLiteral("heardWrites"));
    // Three rows: a small screen keeps its page; the list scrolls.
    m_writes->setMaximumHeight(m_writes->fontMetrics().height() * 3 + 2 * m_writes->frameWidth());
    m_stop->setObjectName(QStringLiteral("stopListening"));
    connect(m_stop, &QPushButton::clicked, this, &ListenMode::stop);
    auto *layout = new QGridLayout(m_banner);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->addWidget(m_bannerText, 0, 0);
    layout->addWidget(m_stop, 0, 1, Qt::AlignTop);
    layout->addWidget(m_writes, 1, 0, 1, 2);
    layout->setColumnStretch(0, 1);
    m_banner->hide();
    retranslate();
    // Connecting ends the listening first: the port is the link's then, and it drives the line.
    connect(m_session->connection(), &SessionConnection::linkStateChanged, this, [this] {
        if (isActive() &&
            m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
            stop();
    });
}

ListenMode::~ListenMode()
{
    stop();
}

bool ListenMode::start(const LinkSettings &settings, QString *why)
{
    if (isActive())
        return true;
    if (m_session->connection()->isConnected() || m_session->parameters()->store()->isFile() ||
        m_session->parameters()->store()->isReplay()) {
        *why = tr("Listening needs the window free: disconnect, and close any profile file or "
                  "replay first.");
        return false;
    }
    if (settings.isNetwork() || settings.portName.isEmpty()) {
        *why = tr("Listening hears a serial line: choose its port on the Connection page.");
        return false;
    }
    m_settings = settings;
    m_listener = new LineListener(&m_session->map(), this);
    // Opened for writing too, for the E-STOP only: nothing else is ever sent.
    m_listener->setMayTransmit(true);
    QString error;
    if (!m_listener->open(settings, &error)) {
        delete std::exchange(m_listener, nullptr);
        *why = tr("Cannot listen on %1: %2").arg(settings.portName, error);
        return false;
    }
    connect(m_listener, &LineListener::heard, this, &ListenMode::onHeard);
    connect(m_listener, &LineListener::lost, this, [this](const QString &reason) {
        const QString port = m_settings.portName;
        stop();
        Q_EMIT finished(false, tr("Listening ended: the port %1 was lost: %2").arg(port, reason));
    });
    connect(m_listener, &LineListener::frameSent, this,
            [this](const QByteArray &frame, bool estop, int n) {
                m_session->connection()->traffic()->add(TrafficEntry{
                    QDateTime::currentDateTime(), TrafficEntry::Direction::Sent,
                    estop ? TrafficEntry::Kind::Command : TrafficEntry::Kind::Read, frame,
                    estop ? tr("E-STOP into the other master's line (try %1)").arg(n)
                          : tr("the controller's motion state read back after the E-STOP (try "
                               "%1)")
                                .arg(n)});
            });
    connect(m_listener, &LineListener::emergencyStopSettled, this,
            [this](bool acknowledged, const QString &text) {
                if (m_log)
                    m_log->note(SessionLog::kUser, text, m_listener->now());
                Q_EMIT finished(acknowledged, text);
            });
    connect(m_listener, &LineListener::echoSuspected, this, [this] {
        const QString text =
            tr("The adapter on %1 returns what StepCom sends (an echo), but the line's echo "
               "option is off: StepCom's own E-STOP was not taken for the controller's answer. "
               "Tick \"The adapter echoes what it sends\" for this line on the Connection page.")
                .arg(m_settings.portName);
        if (m_log)
            m_log->note(SessionLog::kUser, text, m_listener->now());
        Q_EMIT finished(false, text);
    });
    m_log = std::make_unique<ListenLog>(m_session->map(), settings, QDateTime::currentDateTime());
    if (!m_log->open(ListenLog::fileIn(SessionLog::defaultDirectory(), settings.portName),
                     &error)) {
        Q_EMIT finished(false, error); // heard all the same, only not kept
        m_log.reset();
    }
    m_heardWrites = 0;
    m_writes->clear();
    m_estop->setHandler([this] { askEmergencyStop(); });
    m_session->connection()->traffic()->addEvent(
        tr("listening on %1 at %2 baud: another master drives the line, StepCom sends nothing")
            .arg(settings.portName)
            .arg(settings.baud));
    m_session->parameters()->store()->showReplay(tr("heard on %1").arg(settings.portName), {});
    m_start->setText(tr("Stop listening"));
    updateBanner();
    m_banner->show();
    Q_EMIT activeChanged(true);
    return true;
}

void ListenMode::stop()
{
    if (!m_listener)
        return;
    m_estop->setHandler({});
    m_listener->finish();
    m_listener->close();
    m_listener->deleteLater();
    m_listener = nullptr;
    m_log.reset();
    if (m_question)
        m_question->close();
    m_session->parameters()->store()->closeReplay();
    if (m_strip)
        m_strip->endReplay();
    m_session->connection()->traffic()->addEvent(tr("listening ended"));
    m_banner->hide();
    retranslate();
    Q_EMIT activeChanged(false);
}

void ListenMode::setStrip(MachineStrip *strip)
{
    m_strip = strip;
}

QString ListenMode::logFile() const
{
    return m_log ? m_log->fileName() : QString();
}

void ListenMode::onHeard(const HeardEvent &e)
{
    if (m_log)
        m_log->write(e);
    const QString text = e.text();
    const QDateTime now = QDateTime::currentDateTime();
    if (!e.request.isEmpty())
        m_session->connection()->traffic()->add(
            TrafficEntry{now.addMSecs(e.requestMs - e.ms), TrafficEntry::Direction::Sent,
                         TrafficEntry::Kind::Read, e.request, tr("PLC (heard)")});
    if (!e.answer.isEmpty() || e.request.isEmpty())
        m_session->connection()->traffic()->add(TrafficEntry{
            now, TrafficEntry::Direction::Received, TrafficEntry::Kind::Read, e.answer, text});
    else
        m_session->connection()->traffic()->addEvent(text);
    if (e.kind == HeardEvent::Kind::Write || e.kind == HeardEvent::Kind::Command) {
        ++m_heardWrites;
        m_writes->insertItem(
            0, QStringLiteral("%1  %2").arg(now.toString(QStringLiteral("HH:mm:ss.zzz")), text));
        while (m_writes->count() > kWritesKept)
            delete m_writes->takeItem(m_writes->count() - 1);
        updateBanner();
    }
    if (e.unit == m_settings.deviceId)
        showValues();
}

void ListenMode::showValues()
{
    const ReplayDevice device = m_listener->decoder().state().devices.value(m_settings.deviceId);
    m_session->parameters()->store()->showReplay(tr("heard on %1").arg(m_settings.portName),
                                                 device.values(m_session->map()));
    if (m_strip)
        m_strip->showReplayLink(true, device.answering,
                                tr("listening on %1").arg(m_settings.portName));
}

void ListenMode::askEmergencyStop()
{
    if (!isActive())
        return;
    if (m_question) {
        m_question->raise();
        return;
    }
    // Asked, not modal: the window and F12 stay live meanwhile.
    m_question = new QMessageBox(QMessageBox::Warning, tr("E-STOP"),
                                 tr("Another master drives this line. Send the E-STOP to id %1 "
                                    "into its traffic? It goes in the first silence and again "
                                    "until the controller answers it and its motors are read "
                                    "back stopped.")
                                     .arg(m_settings.deviceId),
                                 QMessageBox::Yes | QMessageBox::Cancel, m_window);
    m_question->setObjectName(QStringLiteral("listenEstopQuestion"));
    m_question->setAttribute(Qt::WA_DeleteOnClose);
    m_question->button(QMessageBox::Yes)->setText(tr("Send E-STOP"));
    connect(m_question, &QMessageBox::finished, this, [this](int result) {
        if (result == QMessageBox::Yes)
            sendEmergencyStop();
    });
    m_question->open();
}

void ListenMode::sendEmergencyStop()
{
    if (!m_listener || !m_listener->sendEmergencyStop(m_settings.deviceId)) {
        Q_EMIT finished(false, tr("The E-STOP could not be sent on %1").arg(m_settings.portName));
        return;
    }
    const QString text = tr("E-STOP sent into a line driven by another master");
    if (m_log)
        m_log->note(SessionLog::kUser, text, m_listener->now());
    Q_EMIT finished(true, text);
}

void ListenMode::updateBanner()
{
    m_bannerText->setText(
        tr("<b>Listening on %1</b> — another master drives the line. The values shown are the "
           "ones last heard in its traffic with id %2, not read by StepCom; a value never heard "
           "is unknown. Nothing is written, jogged or polled; the E-STOP asks first. The other "
           "master's writes (%3):")
            .arg(m_settings.portName.toHtmlEscaped())
            .arg(m_settings.deviceId)
            .arg(m_heardWrites));
}

void ListenMode::retranslate()
{
    m_start->setText(isActive() ? tr("Stop listening")
                                : tr("Listen only (another master drives the line)"));
    m_stop->setText(tr("Stop listening"));
    m_writes->setAccessibleName(tr("The other master's writes"));
    if (isActive())
        updateBanner();
}

} // namespace stepcom

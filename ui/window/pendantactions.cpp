#include "window/pendantactions.h"

#include "dialogs/pendantdialog.h"
#include "pendant/pendantcontrol.h"
#include "pendant/pendantserver.h"
#include "profile/profiledocument.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "session/sessionlog.h"
#include "widgets/docks/machinestrip.h"
#include "window/offlineactions.h"

#include <QAction>
#include <QEvent>
#include <QWidget>

namespace stepcom {

PendantActions::PendantActions(DeviceSession *session, MachineStrip *strip, SessionLog *log,
                               ReplayMode *replay, OfflineActions *offline, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_server(new PendantServer(session, this))
    , m_strip(strip)
    , m_replay(replay)
    , m_offline(offline)
    , m_window(window)
    , m_action(new QAction(window))
{
    m_action->setObjectName(QStringLiteral("pendant"));
    connect(m_action, &QAction::triggered, this, &PendantActions::openDialog);
    connect(m_server, &PendantServer::userAction, log, &SessionLog::noteUserAction);
    connect(m_server, &PendantServer::clientsChanged, this, &PendantActions::update);
    connect(m_server, &PendantServer::runningChanged, this, &PendantActions::update);
    connect(m_server->control(), &PendantControl::holderChanged, this, &PendantActions::update);
    connect(replay, &ReplayMode::activeChanged, this, &PendantActions::update);
    connect(offline->document(), &ProfileDocument::changed, this, &PendantActions::update);
    connect(session->parameters()->store(), &ParameterStore::originChanged, this,
            &PendantActions::update);
    window->installEventFilter(this); // its language changes are ours
    retranslate();
}

QString PendantActions::refusal() const
{
    if (m_replay->isActive())
        return tr("A replay serves no pendant: close the session log first");
    if (m_offline->document()->isOpen())
        return tr("A profile file edited without a controller serves no pendant");
    // Heard values stand in the store as a replay's do: listening beside another master.
    if (m_session->parameters()->store()->isReplay())
        return tr("Listening beside another master serves no pendant: stop listening first");
    return {};
}

PendantDialog *PendantActions::openDialog()
{
    if (!refusal().isEmpty())
        return nullptr;
    if (!m_dialog)
        m_dialog = new PendantDialog(m_server, m_window);
    m_dialog->show();
    m_dialog->raise();
    m_dialog->activateWindow();
    return m_dialog;
}

PendantDialog *PendantActions::dialog() const
{
    return m_dialog;
}

void PendantActions::update()
{
    const QString no = refusal();
    if (!no.isEmpty() && m_server->isRunning())
        m_server->stop(no);
    if (!no.isEmpty() && m_dialog)
        m_dialog->close();
    m_action->setEnabled(no.isEmpty());
    m_action->setStatusTip(no.isEmpty() ? tr("A phone or tablet as the pendant: watch, E-STOP, "
                                             "and jog when you allow it")
                                        : no);
    QString text;
    if (m_server->isRunning()) {
        const int phones = int(m_server->clients().size());
        const int holder = m_server->control()->holder();
        if (holder)
            text = tr("Pendant: jogging from %1").arg(m_server->describe(holder));
        else if (phones == 0)
            text = tr("Pendant: on, no phone yet");
        else if (phones == 1)
            text = tr("Pendant: 1 phone watching");
        else
            text = tr("Pendant: %1 phones watching").arg(phones);
    }
    if (m_strip)
        m_strip->setPendantText(text);
}

bool PendantActions::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_window && event->type() == QEvent::LanguageChange)
        retranslate();
    return QObject::eventFilter(watched, event);
}

void PendantActions::retranslate()
{
    m_action->setText(tr("Pendant…"));
    update();
}

} // namespace stepcom

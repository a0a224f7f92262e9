#include "window/busactions.h"

#include "dialogs/idassistantdialog.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/simulatorstarter.h"
#include "widgets/docks/devicelistdock.h"

#include <QAction>
#include <QEvent>
#include <QWidget>

namespace stepcom {

BusActions::BusActions(DeviceSession *session, DeviceListDock *dock, QWidget *window)
    : QObject(window)
    , m_session(session)
    , m_dock(dock)
    , m_window(window)
    , m_assignIds(new QAction(window))
    , m_resetSim(new QAction(window))
{
    m_resetSim->setObjectName(QStringLiteral("resetSimulator"));
    m_resetSim->setEnabled(m_session->simulatorStarter() != nullptr);
    connect(m_resetSim, &QAction::triggered, this, &BusActions::resetSimulator);
    m_assignIds->setObjectName(QStringLiteral("assignIds"));
    connect(m_assignIds, &QAction::triggered, this, &BusActions::openAssistant);
    // It writes ids: only with a line to write to (never while a file is edited offline).
    const auto update = [this] { m_assignIds->setEnabled(m_session->connection()->isConnected()); };
    connect(m_session->connection(), &SessionConnection::linkStateChanged, this, update);
    update();
    window->installEventFilter(this); // its language changes are ours
    retranslate();
}

IdAssistantDialog *BusActions::openAssistant()
{
    if (!m_assistant) {
        m_assistant = new IdAssistantDialog(m_session, m_window);
        connect(m_assistant, &IdAssistantDialog::deviceNamed, this,
                [this](int id, const QString &name) {
                    m_dock->setName(id, name);
                    m_dock->show(); // the list the controllers go on
                });
    }
    m_assistant->show();
    m_assistant->raise();
    m_assistant->activateWindow();
    return m_assistant;
}

void BusActions::resetSimulator()
{
    SimulatorStarter *sim = m_session->simulatorStarter();
    if (!sim)
        return;
    // Its controller goes away with the reset: a link to it would only be lost.
    if (m_session->connection()->isSimulator() &&
        m_session->connection()->linkState() != SessionConnection::LinkState::Disconnected)
        m_session->connection()->disconnectFrom(
            tr("the built-in simulator is reset to the factory"));
    QString error;
    if (!sim->resetToFactory(&error)) {
        Q_EMIT message(tr("The built-in simulator could not be reset: %1").arg(error));
        return;
    }
    Q_EMIT message(tr("The built-in simulator is back at the factory: id 1, 9600 baud, nothing "
                      "saved. Connect to it again to start it."));
}

IdAssistantDialog *BusActions::assistant() const
{
    return m_assistant;
}

bool BusActions::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_window && event->type() == QEvent::LanguageChange)
        retranslate();
    return QObject::eventFilter(watched, event);
}

void BusActions::retranslate()
{
    m_assignIds->setText(tr("Assign device ids…"));
    m_assignIds->setStatusTip(
        tr("Give each controller of a new line its own id, one controller at a time"));
    m_resetSim->setText(tr("Reset the built-in simulator to factory"));
    m_resetSim->setStatusTip(tr("Forget what the built-in simulator saved to flash: it starts "
                                "again as it leaves the factory"));
}

} // namespace stepcom

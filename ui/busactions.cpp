#include "busactions.h"

#include "dialogs/idassistantdialog.h"
#include "session/devicesession.h"
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
{
    m_assignIds->setObjectName(QStringLiteral("assignIds"));
    connect(m_assignIds, &QAction::triggered, this, &BusActions::openAssistant);
    // It writes ids: only with a line to write to (never while a file is edited offline).
    const auto update = [this] { m_assignIds->setEnabled(m_session->isConnected()); };
    connect(m_session, &DeviceSession::linkStateChanged, this, update);
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
}

} // namespace stepcom

#include "base/writeflow.h"

#include "base/writechangesdialog.h"
#include "device/writereview.h"
#include "map/parameter.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

namespace stepcom {

WriteFlow::WriteFlow(DeviceSession *session, QWidget *dialogParent)
    : QObject(dialogParent)
    , m_session(session)
    , m_dialogParent(dialogParent)
{}

bool WriteFlow::openFor(const QStringList &keys)
{
    if (!m_session->connection()->isConnected())
        return false;
    return show(new WriteChangesDialog(*m_session->parameters()->store(), keys, m_dialogParent));
}

bool WriteFlow::openAll()
{
    if (!m_session->connection()->isConnected() || !m_session->parameters()->store()->hasEdits())
        return false;
    return show(new WriteChangesDialog(*m_session->parameters()->store(), m_dialogParent));
}

bool WriteFlow::show(WriteChangesDialog *dialog)
{
    if (dialog->writes().isEmpty()) {
        dialog->deleteLater();
        return false;
    }
    // What the pages already flag in these values is said before anything goes out.
    dialog->setProblems(WriteReview::problems(*m_session->parameters()->store(), dialog->writes()));
    if (m_dialog)
        m_dialog->close();
    m_dialog = dialog;
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { send(dialog->writes()); });
    dialog->open();
    return true;
}

bool WriteFlow::writeConfirmed(const QList<ParameterWrite> &writes)
{
    if (!m_session->connection()->isConnected() || writes.isEmpty())
        return false;
    send(writes);
    return true;
}

void WriteFlow::send(const QList<ParameterWrite> &writes)
{
    QStringList what;
    for (const ParameterWrite &w : writes)
        what << QStringLiteral("%1 = %2").arg(w.parameter->key).arg(w.raw);
    Q_EMIT confirmed(what.join(QLatin1String(", ")));
    // The session verifies by read-back and says the outcome, a refusal too.
    m_session->parameters()->write(writes);
}

} // namespace stepcom

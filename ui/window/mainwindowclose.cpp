// MainWindow closing: edits never written are asked about first, and a jog still held is
// stopped and its stop let reach the wire before the window goes.
#include "window/mainwindow.h"

#include "profile/profiledocument.h"
#include "session/devicesession.h"
#include "session/jogcontroller.h"
#include "session/parts/sessionparameters.h"
#include "window/offlineactions.h"

#include <QCloseEvent>
#include <QMessageBox>
#include <QTimer>

namespace stepcom {

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_session->parameters()->store()->hasEdits() && !m_closeConfirmed) {
        event->ignore();
        if (m_closeQuestion)
            return;
        const int edits = int(m_session->parameters()->store()->editedKeys().size());
        m_closeQuestion = new QMessageBox(
            QMessageBox::Warning, tr("Unwritten changes"),
            m_offline->document()->isOpen()
                ? tr("%n edited value(s) of %1 are not saved in the file. Close anyway and lose "
                     "them?",
                     nullptr, edits)
                      .arg(m_offline->document()->displayName())
                : tr("%n edited value(s) were never written to the controller. Close anyway "
                     "and lose them?",
                     nullptr, edits),
            QMessageBox::Discard | QMessageBox::Cancel, this);
        m_closeQuestion->setAttribute(Qt::WA_DeleteOnClose);
        m_closeQuestion->setDefaultButton(QMessageBox::Cancel);
        connect(m_closeQuestion, &QMessageBox::finished, this, [this](int result) {
            if (result == QMessageBox::Discard) {
                m_closeConfirmed = true;
                close();
            }
        });
        m_closeQuestion->open();
        return;
    }
    // Stop what is held and let the stop reach the wire (at most 1 s).
    if (!m_jogStopAwaited && (m_session->stopJogging(DeviceSession::JogStop::WindowClosing) > 0 ||
                              m_session->jog()->isBusy())) {
        m_jogStopAwaited = true;
        event->ignore();
        const auto closeAgain = [this] {
            if (isVisible())
                close();
        };
        connect(m_session->jog(), &JogController::settled, this, closeAgain,
                Qt::SingleShotConnection);
        QTimer::singleShot(1000, this, closeAgain);
        return;
    }
    saveLayout();
    event->accept();
}

} // namespace stepcom

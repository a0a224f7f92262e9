// MainWindow, a file handed to it (`stepcom FILE`, a file manager's "Open with StepCom"): told
// apart by GivenFile, then opened as File → Open profile… or File → Open session log… would
// (split from mainwindow.cpp).
#include "window/mainwindow.h"

#include "pages/sequencepage.h"
#include "replay/replaymode.h"
#include "session/devicesession.h"
#include "widgets/docks/messageview.h"
#include "window/givenfile.h"
#include "window/profileactions.h"

#include <QMessageBox>

namespace stepcom {

bool MainWindow::openGivenFile(const QString &path)
{
    QString why;
    switch (GivenFile::classify(path, &why)) {
    case GivenFile::Kind::Profile:
        return m_profiles->openFile(path); // no controller connected: edited as a file
    case GivenFile::Kind::Sequence:
        showPage(int(m_pages.indexOf(m_sequence)));
        return m_sequence->openFile(path);
    case GivenFile::Kind::SessionLog:
    case GivenFile::Kind::SupportBundle:
        return m_replay->openPath(path);
    case GivenFile::Kind::Unreadable:
    case GivenFile::Kind::Unknown:
        break;
    }
    m_messages->add(DeviceSession::Severity::Error, why);
    if (m_givenFileError)
        m_givenFileError->deleteLater();
    m_givenFileError =
        new QMessageBox(QMessageBox::Warning, tr("Open a file"), why, QMessageBox::Ok, this);
    m_givenFileError->setAttribute(Qt::WA_DeleteOnClose);
    m_givenFileError->open();
    return false;
}

} // namespace stepcom

#pragma once

#include "base/writechangesdialog.h" // dialog() converts a QPointer to it

#include <QList>
#include <QObject>
#include <QPointer>
#include <QStringList>

namespace stepcom {

class DeviceSession;

// The window's one way to write: show exactly what will be written and the geometry and wiring
// problems the pages already flag in it (WriteReview), and on acceptance write it
// through the session (which verifies it and updates the store). Every page that writes uses
// one of these; the window hands its own to the pages, and its session log notes confirmed(). A
// second request replaces a dialog still open.
class WriteFlow : public QObject
{
    Q_OBJECT
public:
    // The dialogs open over `dialogParent`.
    WriteFlow(DeviceSession *session, QWidget *dialogParent);

    // The edits of `keys` only (a page's own parameters; the others stay held). Opens nothing
    // and returns false when not connected or none of them is edited.
    bool openFor(const QStringList &keys);
    // Every edit held.
    bool openAll();
    // Writes the caller has already asked about in a question of its own that said what
    // WriteReview::problems() finds in them (the mode page's): no second question, but
    // confirmed, written, verified and reported as the dialog's are. False, with nothing sent,
    // when not connected or `writes` is empty.
    bool writeConfirmed(const QList<ParameterWrite> &writes);
    WriteChangesDialog *dialog() const { return m_dialog; }

Q_SIGNALS:
    // The user confirmed the dialog (or the caller's own question): "motor1.speed = 222,
    // motor2.pitch = 500" (raw values, as they go out) is being written.
    void confirmed(const QString &writes);

private:
    bool show(WriteChangesDialog *dialog);
    void send(const QList<ParameterWrite> &writes);

    DeviceSession *m_session;
    QWidget *m_dialogParent;
    QPointer<WriteChangesDialog> m_dialog;
};

} // namespace stepcom

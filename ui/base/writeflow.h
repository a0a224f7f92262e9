#pragma once

#include <QObject>
#include <QPointer>
#include <QStringList>

class QWidget;

namespace stepcom {

class DeviceSession;
class WriteChangesDialog;

// The window's one way to write: show exactly what will be written and the geometry and wiring
// problems the pages already flag in it (WriteReview), and on acceptance write it
// through the session (which verifies it and updates the store). Every page that writes uses
// one of these; a second request replaces a dialog still open.
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
    WriteChangesDialog *dialog() const { return m_dialog; }

Q_SIGNALS:
    // The user confirmed the dialog: "motor1.speed = 222, motor2.pitch = 500" (raw values, as
    // they go out) is being written.
    void confirmed(const QString &writes);

private:
    bool show(WriteChangesDialog *dialog);

    DeviceSession *m_session;
    QWidget *m_dialogParent;
    QPointer<WriteChangesDialog> m_dialog;
};

} // namespace stepcom

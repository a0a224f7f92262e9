#pragma once

#include "commissioning/checkliststep.h"

#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;
class QVBoxLayout;

namespace stepcom {

class DeviceSession;
class WriteFlow;
struct Parameter;

// One step of the commissioning checklist on its page: the title, what to do, the step's own
// controls (a subclass adds them to body()), what happened, a note and "Skip". A subclass
// judges the step and calls finishStep(); the page records it. A fix it proposes is written
// through the window's WriteFlow (the usual write dialog, verified).
class ChecklistStepWidget : public QWidget
{
    Q_OBJECT
public:
    ChecklistStepWidget(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                        QWidget *parent = nullptr);

    QString stepId() const { return m_step.id; }
    QString statusText() const;
    QLineEdit *noteField() const { return m_note; }
    QPushButton *skipButton() const { return m_skip; }
    virtual void retranslate();

Q_SIGNALS:
    void recorded(const QString &id, stepcom::StepResult result,
                  const QList<stepcom::ChecklistMeasurement> &measurements, const QString &note);

protected:
    void changeEvent(QEvent *event) override;
    QVBoxLayout *body() const { return m_body; }
    DeviceSession *session() const { return m_session; }
    const ChecklistStep &step() const { return m_step; }
    void setStatus(const QString &text);
    // A button that moves or asks the machine: enabled only while a controller is connected
    // (offline, editing a file, nothing may reach one).
    void needsController(QPushButton *button);
    void finishStep(StepResult result, const QList<ChecklistMeasurement> &measurements);
    // The motor's parameter `local` (motorN.local), or nullptr.
    const Parameter *motorParameter(const char *local) const;
    // What the store holds from the device for `key`, as text with the unit ("5.00 mm").
    QString deviceText(const QString &key) const;
    // Puts these values in the store as edits and opens the write dialog for them; `done`
    // hears whether every one was written and verified.
    void proposeWrite(const QList<std::pair<QString, qint64>> &values,
                      std::function<void(bool ok)> done);

private:
    DeviceSession *m_session;
    WriteFlow *m_writes;
    ChecklistStep m_step;
    QLabel *m_title;
    QLabel *m_instruction;
    QVBoxLayout *m_body;
    QLabel *m_status;
    QLabel *m_noteLabel;
    QLineEdit *m_note;
    QPushButton *m_skip;
    QList<QPushButton *> m_needsController;
    QStringList m_pendingKeys;
    std::function<void(bool)> m_pendingDone;
};

} // namespace stepcom

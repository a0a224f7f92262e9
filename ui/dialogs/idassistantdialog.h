#pragma once

#include "line/idassigner.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace stepcom {

class DeviceSession;

// "Assign device ids…": the guided assistant for a new line. The technician connects the
// controllers one at a time (each arrives as id 1 at 9600 baud) and presses Next; each gets the
// next free id (and the common baud, if chosen), is proven to answer there and no longer at
// id 1, and goes on the device list with the name typed for it. Two controllers answering at
// id 1 are refused in words. The work is IdAssigner's (core); this only shows it. Non-modal.
class IdAssistantDialog : public QDialog
{
    Q_OBJECT
public:
    explicit IdAssistantDialog(DeviceSession *session, QWidget *parent = nullptr);
    ~IdAssistantDialog() override;

    IdAssigner *assigner() const { return m_assigner; }
    QString statusText() const;
    // The rows of the controllers given an id in this run: "id", "name".
    QStringList rowTexts(int row) const;
    int rowCount() const;

    // What the buttons do.
    void start();
    void next();
    void finish();
    // Closing while controllers wait for the end finishes the run (line at the common baud,
    // live status back); while one is being changed it waits.
    void reject() override;

Q_SIGNALS:
    // A controller answers at `id`; `name` is what the technician typed for it (maybe empty).
    void deviceNamed(int id, const QString &name);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateControls();
    void onDeviceAdded(int id);

    DeviceSession *m_session;
    IdAssigner *m_assigner;
    QLabel *m_intro = nullptr;
    QGroupBox *m_optionsBox = nullptr;
    QFormLayout *m_form = nullptr;
    QSpinBox *m_firstId = nullptr;
    QComboBox *m_baud = nullptr;
    QCheckBox *m_newLine = nullptr;
    QCheckBox *m_saveToFlash = nullptr;
    QLineEdit *m_name = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_step = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_next = nullptr;
    QPushButton *m_finish = nullptr;
    QPushButton *m_close = nullptr;
    QString m_pendingName;
    bool m_closeWhenFinished = false;
};

} // namespace stepcom

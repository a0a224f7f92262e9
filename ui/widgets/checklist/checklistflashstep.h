#pragma once

#include "widgets/checklist/checkliststepwidget.h"

#include <QHash>

class QPushButton;

namespace stepcom {

// "Machine: save to flash and read back": saves (the backup guard saves the settings first),
// then reads every setting back and passes only when the controller holds what it held before.
class ChecklistFlashStep : public ChecklistStepWidget
{
    Q_OBJECT
public:
    ChecklistFlashStep(DeviceSession *session, WriteFlow *writes, const ChecklistStep &step,
                       QWidget *parent = nullptr);

    QPushButton *saveButton() const { return m_save; }
    void retranslate() override;

private:
    void readBack();

    QPushButton *m_save;
    bool m_waiting = false;
    QHash<QString, qint64> m_before;
};

} // namespace stepcom

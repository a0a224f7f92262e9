#include "widgets/checklist/checklistruninstep.h"

#include <QHBoxLayout>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

ChecklistRunInStep::ChecklistRunInStep(DeviceSession *session, WriteFlow *writes,
                                       const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_open(new QPushButton(this))
{
    m_open->setObjectName(QStringLiteral("openSequenceButton"));
    m_open->setAutoDefault(false);
    auto *row = new QHBoxLayout;
    row->addWidget(m_open);
    row->addStretch(1);
    body()->addLayout(row);
    connect(m_open, &QPushButton::clicked, this, &ChecklistRunInStep::sequencePageWanted);
    retranslate();
}

void ChecklistRunInStep::record(StepResult result, const QList<ChecklistMeasurement> &measurements,
                                const QString &summary)
{
    finishStep(result, measurements);
    setStatus(summary);
}

void ChecklistRunInStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_open->setText(tr("Open the Sequence page"));
}

} // namespace stepcom

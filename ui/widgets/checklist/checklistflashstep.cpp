#include "widgets/checklist/checklistflashstep.h"

#include "profile/profile.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QHBoxLayout>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

ChecklistFlashStep::ChecklistFlashStep(DeviceSession *session, WriteFlow *writes,
                                       const ChecklistStep &step, QWidget *parent)
    : ChecklistStepWidget(session, writes, step, parent)
    , m_save(new QPushButton(this))
{
    m_save->setObjectName(QStringLiteral("saveButton"));
    m_save->setAutoDefault(false);
    auto *row = new QHBoxLayout;
    row->addWidget(m_save);
    row->addStretch(1);
    body()->addLayout(row);
    needsController(m_save);
    connect(m_save, &QPushButton::clicked, this, [this] {
        DeviceSession *s = this->session();
        if (!s->connection()->isConnected()) {
            setStatus(tr("Not connected: nothing was sent."));
            return;
        }
        m_before.clear();
        QStringList unknown;
        for (const Parameter *p : Profile::profileParameters(s->map(), false)) {
            if (const auto v = s->parameters()->store()->deviceValue(p->key))
                m_before.insert(p->key, *v);
            else
                unknown << p->key;
        }
        if (!unknown.isEmpty()) {
            setStatus(tr("Not every setting is read yet (%1): read all first.")
                          .arg(unknown.join(QLatin1String(", "))));
            return;
        }
        m_waiting = true;
        setStatus(tr("Saving to flash…"));
        s->saveToFlash();
    });
    connect(session, &DeviceSession::commandFinished, this, [this](const QString &key, bool ok) {
        if (!m_waiting || key != QLatin1String("save_to_flash"))
            return;
        m_waiting = false;
        if (!ok) {
            finishStep(StepResult::Failed, {});
            setStatus(tr("Failed: the save to flash was not done (see the messages)."));
            return;
        }
        readBack();
    });
    retranslate();
}

void ChecklistFlashStep::readBack()
{
    QList<const Parameter *> params = Profile::profileParameters(session()->map(), false);
    QPointer<ChecklistFlashStep> self(this);
    session()->parameters()->read(params, [self](const ReadOutcome &r) {
        if (!self)
            return;
        QStringList differ;
        for (auto it = self->m_before.cbegin(); it != self->m_before.cend(); ++it) {
            if (r.values.value(it.key(), it.value() + 1) != it.value())
                differ << it.key();
        }
        if (!r.ok || !differ.isEmpty()) {
            self->finishStep(
                StepResult::Failed,
                {{QStringLiteral("readback"),
                  tr("%n setting(s) differ", nullptr, int(differ.size())), QString()}});
            self->setStatus(r.ok ? tr("Failed: after the save these settings read back "
                                      "differently: %1")
                                       .arg(differ.join(QLatin1String(", ")))
                                 : tr("Failed: the settings could not be read back: %1")
                                       .arg(r.errors.join(QLatin1String("; "))));
            return;
        }
        self->session()->parameters()->store()->setDeviceValues(r.values);
        self->finishStep(StepResult::Passed, {{QStringLiteral("readback"),
                                               tr("%n setting(s) read back unchanged", nullptr,
                                                  int(self->m_before.size())),
                                               QString()}});
        self->setStatus(tr("Passed: saved to flash, and all %n setting(s) read back unchanged.",
                           nullptr, int(self->m_before.size())));
    });
}

void ChecklistFlashStep::retranslate()
{
    ChecklistStepWidget::retranslate();
    m_save->setText(tr("Save to flash and read back"));
}

} // namespace stepcom

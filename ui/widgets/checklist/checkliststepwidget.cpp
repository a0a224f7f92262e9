#include "widgets/checklist/checkliststepwidget.h"

#include "base/language.h"
#include "base/writechangesdialog.h"
#include "base/writeflow.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace stepcom {

ChecklistStepWidget::ChecklistStepWidget(DeviceSession *session, WriteFlow *writes,
                                         const ChecklistStep &step, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_writes(writes)
    , m_step(step)
    , m_title(new QLabel(this))
    , m_instruction(new QLabel(this))
    , m_body(new QVBoxLayout)
    , m_status(new QLabel(this))
    , m_noteLabel(new QLabel(this))
    , m_note(new QLineEdit(this))
    , m_skip(new QPushButton(this))
{
    setObjectName(QStringLiteral("step_") + step.id);
    m_step.attempts.clear();
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_title->setWordWrap(true);
    m_instruction->setWordWrap(true);
    m_status->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("stepStatus"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_note->setMaxLength(2000);
    m_noteLabel->setBuddy(m_note);
    m_skip->setObjectName(QStringLiteral("skipButton"));
    m_skip->setAutoDefault(false);
    auto *noteRow = new QHBoxLayout;
    noteRow->addWidget(m_noteLabel);
    noteRow->addWidget(m_note, 1);
    noteRow->addWidget(m_skip);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_instruction);
    layout->addLayout(m_body);
    layout->addWidget(m_status);
    layout->addLayout(noteRow);
    layout->addStretch(1);
    connect(session->connection(), &SessionConnection::linkStateChanged, this, [this] {
        for (QPushButton *b : std::as_const(m_needsController))
            b->setEnabled(m_session->connection()->isConnected());
    });
    connect(m_skip, &QPushButton::clicked, this, [this] {
        finishStep(StepResult::Skipped, {});
        setStatus(tr("Skipped."));
    });
    // A proposed fix: the write dialog's outcome decides.
    connect(session->parameters(), &SessionParameters::writeFinished, this,
            [this](const WriteOutcome &o) {
                if (m_pendingKeys.isEmpty())
                    return;
                bool all = true;
                bool any = false;
                for (const QString &k : std::as_const(m_pendingKeys)) {
                    all = all && o.verified(k);
                    any = any || o.written.contains(k); // a mismatch too: it was acknowledged
                }
                if (!any)
                    return; // another write (not ours)
                m_pendingKeys.clear();
                if (auto done = std::exchange(m_pendingDone, {}))
                    done(all);
            });
}

QString ChecklistStepWidget::statusText() const
{
    return m_status->text();
}

void ChecklistStepWidget::setStatus(const QString &text)
{
    m_status->setText(text);
}

void ChecklistStepWidget::finishStep(StepResult result,
                                     const QList<ChecklistMeasurement> &measurements)
{
    Q_EMIT recorded(m_step.id, result, measurements, m_note->text().trimmed());
    m_note->clear();
}

const Parameter *ChecklistStepWidget::motorParameter(const char *local) const
{
    return m_session->map().blockParameter(QStringLiteral("motor"), m_step.motor,
                                           QLatin1String(local));
}

QString ChecklistStepWidget::deviceText(const QString &key) const
{
    const Parameter *p = m_session->map().find(key);
    const auto v = p ? m_session->parameters()->store()->deviceValue(key) : std::nullopt;
    return v ? p->displayRaw(*v, Language::instance().current()) : QStringLiteral("—");
}

void ChecklistStepWidget::proposeWrite(const QList<std::pair<QString, qint64>> &values,
                                       std::function<void(bool ok)> done)
{
    QStringList keys;
    for (const auto &[key, raw] : values) {
        if (const QString e = m_session->parameters()->store()->edit(key, raw); !e.isEmpty()) {
            setStatus(e);
            return;
        }
        keys << key;
    }
    m_pendingKeys = keys;
    m_pendingDone = std::move(done);
    if (!m_writes->openFor(keys)) {
        m_pendingKeys.clear();
        m_pendingDone = {};
        setStatus(tr("Not connected: nothing was written."));
    }
}

void ChecklistStepWidget::retranslate()
{
    m_title->setText(m_step.title());
    m_instruction->setText(m_step.instruction());
    m_noteLabel->setText(tr("&Note:"));
    m_skip->setText(tr("S&kip this step"));
}

void ChecklistStepWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ChecklistStepWidget::needsController(QPushButton *button)
{
    m_needsController << button;
    button->setEnabled(m_session->connection()->isConnected());
}

} // namespace stepcom

#include "pages/motorpage.h"

#include "base/language.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/derivedvalues.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");

// The parameters of a motor, in the order of the manual's register table.
const char *const kParameters[] = {"step_angle", "microsteps", "start_frequency", "accel_frequency",
                                   "direction",  "speed",      "pitch",           "move_distance"};

} // namespace

MotorPage::MotorPage(DeviceSession *session, int motor, QWidget *parent)
    : Page(session, parent)
    , m_motor(motor)
{
    ParameterStore *store = session->parameters()->store();
    QWidget *content = scrollableContent();
    auto *columns = new QHBoxLayout(content);

    m_parameterBox = new QGroupBox(content);
    auto *parameterLayout = new QVBoxLayout(m_parameterBox);
    m_form = new ParameterForm(store, m_parameterBox);
    for (const char *local : kParameters) {
        if (const QString k = key(QLatin1String(local)); !k.isEmpty() && m_form->addParameter(k))
            m_keys << k;
    }
    parameterLayout->addWidget(m_form);
    // Top-aligned: the group keeps its own height instead of stretching down the page.
    columns->addWidget(m_parameterBox, 3, Qt::AlignTop);

    auto *right = new QVBoxLayout;
    m_derivedBox = new QGroupBox(content);
    auto *derivedLayout = new QVBoxLayout(m_derivedBox);
    m_derived = new DerivedValues(m_derivedBox);
    derivedLayout->addWidget(m_derived);
    m_derivedNote = new QLabel(m_derivedBox);
    m_derivedNote->setWordWrap(true);
    derivedLayout->addWidget(m_derivedNote);
    right->addWidget(m_derivedBox);

    m_motionBox = new QGroupBox(content);
    auto *motionLayout = new QVBoxLayout(m_motionBox);
    m_stop = new QPushButton(m_motionBox);
    m_stop->setIcon(style()->standardIcon(QStyle::SP_MediaStop));
    motionLayout->addWidget(m_stop);
    m_stopNote = new QLabel(m_motionBox);
    m_stopNote->setWordWrap(true);
    motionLayout->addWidget(m_stopNote);
    right->addWidget(m_motionBox);
    right->addStretch(1);
    columns->addLayout(right, 2);

    // Tab order: the parameters top to bottom, then the stop button.
    QWidget *previous = nullptr;
    for (ParameterField *f : m_form->fields()) {
        if (previous)
            setTabOrder(previous, f->editor());
        previous = f->editor();
    }
    if (previous)
        setTabOrder(previous, m_stop);

    connect(m_stop, &QPushButton::clicked, this, [this] {
        if (const QString k = key(QStringLiteral("stop")); !k.isEmpty())
            this->session()->command(k);
    });
    connect(store, &ParameterStore::valueChanged, this, [this](const QString &k) {
        if (m_keys.contains(k))
            updateDerived();
    });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &MotorPage::updateEnabled);
    connect(session->connection(), &SessionConnection::connected, this, &MotorPage::updateEnabled);
    connect(session->connection(), &SessionConnection::disconnected, this,
            &MotorPage::updateEnabled);
    updateEnabled();
    retranslate();
}

QString MotorPage::title() const
{
    return tr("Motor %1").arg(m_motor);
}

QStringList MotorPage::keys() const
{
    return m_keys;
}

QString MotorPage::key(const QString &localKey) const
{
    const Parameter *p = session()->map().blockParameter(kMotor, m_motor, localKey);
    return p ? p->key : QString();
}

std::optional<double> MotorPage::shown(const QString &localKey) const
{
    const Parameter *p = session()->map().blockParameter(kMotor, m_motor, localKey);
    if (!p)
        return std::nullopt;
    const std::optional<qint64> raw = session()->parameters()->store()->shownValue(p->key);
    if (!raw)
        return std::nullopt;
    return p->toEngineering(*raw);
}

MotorDerived MotorPage::derived() const
{
    MotorParameters p;
    p.stepAngle = shown(QStringLiteral("step_angle"));
    p.microsteps = shown(QStringLiteral("microsteps"));
    p.startHz = shown(QStringLiteral("start_frequency"));
    p.accelHzPerMs = shown(QStringLiteral("accel_frequency"));
    p.rpm = shown(QStringLiteral("speed"));
    p.pitch = shown(QStringLiteral("pitch"));
    p.distance = shown(QStringLiteral("move_distance"));
    return motorderived::derive(p);
}

void MotorPage::updateDerived()
{
    const Parameter *pitch =
        session()->map().blockParameter(kMotor, m_motor, QStringLiteral("pitch"));
    m_derived->setValues(derived(), pitch ? pitch->unit : QString());
    bool edited = false;
    for (const QString &k : std::as_const(m_keys))
        edited = edited || session()->parameters()->store()->entry(k).edited.has_value();
    m_derivedNote->setText(
        edited ? tr("Computed from the values shown, including edits not written yet.")
               : tr("Computed from the values shown."));
}

void MotorPage::updateEnabled()
{
    // Stopping must never depend on anything but the link: no state, no edits, no busy flag.
    m_stop->setEnabled(session()->connection()->isConnected() &&
                       !key(QStringLiteral("stop")).isEmpty());
}

void MotorPage::retranslate()
{
    m_parameterBox->setTitle(tr("Motor %1 parameters").arg(m_motor));
    m_derivedBox->setTitle(tr("Derived values"));
    m_motionBox->setTitle(tr("Motion"));
    m_stop->setText(tr("&Stop motor %1").arg(m_motor));
    const Parameter *stop =
        session()->map().blockParameter(kMotor, m_motor, QStringLiteral("stop"));
    const QString lang = Language::instance().current();
    m_stop->setToolTip(
        stop ? QStringLiteral("%1 — %2").arg(stop->label.text(lang), stop->registerName())
             : QString());
    m_stopNote->setText(
        tr("Stops the motor at once, without a ramp. The E-STOP under every page stops "
           "everything."));
    updateDerived();
}

} // namespace stepcom

#include "widgets/motion/travellimitseditor.h"

#include "motion/travellimits.h"
#include "session/devicesession.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "session/parts/sessionstatus.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QJsonDocument>
#include <QLabel>
#include <QPushButton>
#include <QSettings>

namespace stepcom {

namespace {

const QString kGroup = QStringLiteral("connection");
const QString kKey = QStringLiteral("travelLimits");

} // namespace

TravelLimitsEditor::TravelLimitsEditor(DeviceSession *session, QWidget *parent)
    : QGroupBox(parent)
    , m_session(session)
    , m_apply(new QPushButton(this))
    , m_problem(new QLabel(this))
    , m_note(new QLabel(this))
{
    setObjectName(QStringLiteral("travelLimitsEditor"));
    auto *grid = new QGridLayout(this);
    const RegisterMap &map = session->map();
    const int motors = map.blockCount(QStringLiteral("motor"));
    for (int n = 1; n <= motors; ++n) {
        const Parameter *pos = TravelLimits::positionParameter(map, n);
        Row r;
        r.name = new QLabel(this);
        r.minOn = new QCheckBox(this);
        r.min = new QDoubleSpinBox(this);
        r.maxOn = new QCheckBox(this);
        r.max = new QDoubleSpinBox(this);
        r.overrun = new QLabel(this);
        r.overrun->setWordWrap(true);
        for (QDoubleSpinBox *f : {r.min, r.max}) {
            f->setDecimals(2);
            if (pos)
                f->setRange(pos->toEngineering(pos->rawMin), pos->toEngineering(pos->rawMax));
            f->setSuffix(pos ? QLatin1Char(' ') + pos->unit : QString());
            f->setEnabled(false);
        }
        connect(r.minOn, &QCheckBox::toggled, r.min, &QWidget::setEnabled);
        connect(r.maxOn, &QCheckBox::toggled, r.max, &QWidget::setEnabled);
        const int row = (n - 1) * 2;
        grid->addWidget(r.name, row, 0);
        grid->addWidget(r.minOn, row, 1);
        grid->addWidget(r.min, row, 2);
        grid->addWidget(r.maxOn, row, 3);
        grid->addWidget(r.max, row, 4);
        grid->addWidget(r.overrun, row + 1, 1, 1, 4);
        m_rows << r;
    }
    grid->setColumnStretch(2, 1);
    grid->setColumnStretch(4, 1);
    m_problem->setWordWrap(true);
    m_problem->setObjectName(QStringLiteral("travelLimitsProblem"));
    m_note->setWordWrap(true);
    m_apply->setObjectName(QStringLiteral("applyTravelLimits"));
    m_apply->setAutoDefault(false);
    const int last = motors * 2;
    grid->addWidget(m_problem, last, 0, 1, 4);
    grid->addWidget(m_apply, last, 4);
    grid->addWidget(m_note, last + 1, 0, 1, 5);
    connect(m_apply, &QPushButton::clicked, this, &TravelLimitsEditor::apply);
    connect(session, &DeviceSession::travelLimitsChanged, this, &TravelLimitsEditor::showLimits);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &k) {
                if (k.endsWith(QLatin1String(".speed")) || k.endsWith(QLatin1String(".pitch")))
                    refreshOverrun();
            });
    connect(session->connection(), &SessionConnection::linkStatsChanged, this,
            &TravelLimitsEditor::refreshOverrun);
    retranslate();
    showLimits();
}

void TravelLimitsEditor::restoreSaved(DeviceSession *session)
{
    QSettings settings;
    settings.beginGroup(kGroup);
    const QByteArray json = settings.value(kKey).toByteArray();
    if (json.isEmpty())
        return;
    QStringList errors;
    const auto limits =
        TravelLimits::fromJson(QJsonDocument::fromJson(json).object(), session->map(), &errors);
    if (limits)
        session->setTravelLimits(*limits);
    else
        Q_EMIT session->message(DeviceSession::Severity::Warning,
                                tr("The saved software travel limits were not used: %1")
                                    .arg(errors.join(QLatin1String("; "))));
}

void TravelLimitsEditor::showLimits()
{
    const TravelLimits &limits = m_session->travelLimits();
    for (int n = 1; n <= m_rows.size(); ++n) {
        const Row &r = m_rows.at(n - 1);
        const AxisTravel t = limits.axis(n);
        const Parameter *pos = TravelLimits::positionParameter(m_session->map(), n);
        r.minOn->setChecked(t.min.has_value());
        r.maxOn->setChecked(t.max.has_value());
        if (t.min && pos)
            r.min->setValue(pos->toEngineering(*t.min));
        if (t.max && pos)
            r.max->setValue(pos->toEngineering(*t.max));
    }
    refreshOverrun();
}

void TravelLimitsEditor::apply()
{
    TravelLimits limits;
    QStringList problems;
    for (int n = 1; n <= m_rows.size(); ++n) {
        const Row &r = m_rows.at(n - 1);
        const std::optional<double> min =
            r.minOn->isChecked() ? std::optional<double>(r.min->value()) : std::nullopt;
        const std::optional<double> max =
            r.maxOn->isChecked() ? std::optional<double>(r.max->value()) : std::nullopt;
        if (min || max) {
            if (const QString e = limits.setAxis(m_session->map(), n, min, max); !e.isEmpty())
                problems << e;
        }
    }
    m_problem->setText(problems.join(QLatin1Char('\n')));
    if (!problems.isEmpty())
        return; // nothing half-applied
    m_session->setTravelLimits(limits);
    QSettings settings;
    settings.beginGroup(kGroup);
    settings.setValue(
        kKey, QJsonDocument(limits.toJson(m_session->map())).toJson(QJsonDocument::Compact));
    refreshOverrun();
}

QString TravelLimitsEditor::problemText() const
{
    return m_problem->text();
}

QString TravelLimitsEditor::overrunText(int motor) const
{
    const RegisterMap &map = m_session->map();
    const Parameter *pos = TravelLimits::positionParameter(map, motor);
    const Parameter *speed =
        map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("speed"));
    const Parameter *pitch =
        map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("pitch"));
    if (!pos || !speed || !pitch)
        return {};
    const auto rpm = m_session->parameters()->store()->deviceValue(speed->key);
    const auto p = m_session->parameters()->store()->deviceValue(pitch->key);
    const qint64 roundTrip = m_session->connection()->linkStats().maxRoundTripMs;
    if (!rpm || !p || roundTrip < 0)
        return tr("How far a jog can overrun a limit is worked out once the speed and pitch are "
                  "read and the link has answered.");
    OverrunInputs in;
    in.unitsPerSecond = speed->toEngineering(*rpm) * pitch->toEngineering(*p) / 60.0;
    // A cycle starts when the last ended, at most every interval: the slower of the two.
    in.pollIntervalMs = double(
        std::max<qint64>(m_session->status()->intervalMs(), m_session->status()->stats().maxMs));
    in.readMs = double(roundTrip);
    in.stopMs = 2.0 * double(roundTrip); // a transaction in flight, then the stop's own
    return tr("A hold-to-move jog can run past a limit by %1.")
        .arg(TravelLimits::describeOverrun(in, pos->unit));
}

void TravelLimitsEditor::refreshOverrun()
{
    for (int n = 1; n <= m_rows.size(); ++n)
        m_rows.at(n - 1).overrun->setText(overrunText(n));
}

void TravelLimitsEditor::retranslate()
{
    setTitle(tr("Software travel limits"));
    for (int n = 1; n <= m_rows.size(); ++n) {
        const Row &r = m_rows.at(n - 1);
        r.name->setText(tr("Motor %1").arg(n));
        r.minOn->setText(tr("Min"));
        r.maxOn->setText(tr("Max"));
    }
    m_apply->setText(tr("Apply limits"));
    // What a technician must not miss stays on the page; the rest is on demand.
    m_note->setText(tr("StepCom's limits, not the controller's: if the link dies during a jog, "
                       "only the limit switches stop the axis."));
    m_note->setToolTip(explanation());
    m_note->setWhatsThis(explanation());
    refreshOverrun();
}

QString TravelLimitsEditor::explanation() const
{
    return tr("StepCom's limits, not the controller's: a step or move-to beyond them is "
              "refused and a jog is stopped when the polled position crosses them. "
              "Saved with the connection settings and in profiles. If the link dies "
              "during a jog, only the limit switches stop the axis.");
}

void TravelLimitsEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QGroupBox::changeEvent(event);
}

} // namespace stepcom

#include "widgets/motion/patheditor.h"

#include "base/writechangesdialog.h"
#include "motion/motionjudge.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/parameterform.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

#include <cmath>

namespace stepcom {

using interpolation::Geometry;
using interpolation::Point;

namespace {

const char *const kArcFields[] = {"enabled",  "mode",     "start_x",   "start_y",
                                  "end_x",    "end_y",    "center_x",  "center_y",
                                  "middle_x", "middle_y", "direction", "speed"};
const char *const kLineFields[] = {"enabled", "start_x", "start_y", "end_x", "end_y", "speed"};

QString number(double v)
{
    return QString::number(v, 'f', 2);
}

QString duration(double ms)
{
    if (ms < 60000)
        return PathEditor::tr("%1 s").arg(QString::number(ms / 1000.0, 'f', 2));
    const qint64 s = qint64(std::llround(ms / 1000.0));
    return PathEditor::tr("%1 min %2 s").arg(s / 60).arg(s % 60);
}

} // namespace

PathEditor::PathEditor(DeviceSession *session, Kind kind, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_kind(kind)
    , m_prefix(kind == Kind::Arc ? QStringLiteral("arc.") : QStringLiteral("line."))
{
    setObjectName(kind == Kind::Arc ? QStringLiteral("arcEditor") : QStringLiteral("lineEditor"));
    m_writeFlow = new WriteFlow(session, this);
    ParameterStore *store = session->parameters()->store();
    auto *layout = new QVBoxLayout(this);

    m_parameterBox = new QGroupBox(this);
    auto *parameterLayout = new QVBoxLayout(m_parameterBox);
    m_form = new ParameterForm(store, m_parameterBox);
    auto addFields = [this](const auto &locals) {
        for (const char *local : locals) {
            if (m_form->addParameter(key(local)))
                m_keys << key(local);
        }
    };
    if (kind == Kind::Arc)
        addFields(kArcFields);
    else
        addFields(kLineFields);
    parameterLayout->addWidget(m_form);
    layout->addWidget(m_parameterBox);

    m_resultBox = new QGroupBox(this);
    m_results = new QFormLayout(m_resultBox);
    auto addResult = [this](const char *label) {
        auto *name = new QLabel(m_resultBox);
        auto *value = new QLabel(m_resultBox);
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // "0.000 / 0.002 (difference 0.002, at most 0.010)" wraps rather than widening the
        // page past a 1366×768 screen at 150 %.
        value->setWordWrap(true);
        m_rowLabels << qMakePair(name, label);
        m_results->addRow(name, value);
        return value;
    };
    if (kind == Kind::Arc) {
        m_radius = addResult(QT_TR_NOOP("Radius"));
        m_centre = addResult(QT_TR_NOOP("Centre"));
        m_radii = addResult(QT_TR_NOOP("Start / end radius"));
        m_sweep = addResult(QT_TR_NOOP("Sweep"));
    }
    m_length = addResult(QT_TR_NOOP("Path length"));
    m_speed = addResult(QT_TR_NOOP("Path speed"));
    m_time = addResult(QT_TR_NOOP("Estimated time"));
    m_problem = new QLabel(m_resultBox);
    m_problem->setObjectName(QStringLiteral("geometryProblem"));
    m_problem->setWordWrap(true);
    m_results->addRow(m_problem);
    m_assumes = new QLabel(m_resultBox);
    m_assumes->setWordWrap(true);
    m_results->addRow(m_assumes);
    layout->addWidget(m_resultBox);

    m_runBox = new QGroupBox(this);
    auto *runLayout = new QVBoxLayout(m_runBox);
    auto *buttons = new QHBoxLayout;
    m_write = new QPushButton(m_runBox);
    m_write->setObjectName(QStringLiteral("writeButton"));
    m_start = new QPushButton(m_runBox);
    m_start->setObjectName(QStringLiteral("startButton"));
    m_start->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    m_stop = new QPushButton(m_runBox);
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_stop->setIcon(style()->standardIcon(QStyle::SP_MediaStop));
    buttons->addWidget(m_write);
    buttons->addWidget(m_start);
    buttons->addWidget(m_stop);
    runLayout->addLayout(buttons);
    m_reason = new QLabel(m_runBox);
    m_reason->setObjectName(QStringLiteral("startReason"));
    m_reason->setWordWrap(true);
    runLayout->addWidget(m_reason);
    m_outcome = new QLabel(m_runBox);
    m_outcome->setObjectName(QStringLiteral("outcome"));
    m_outcome->setWordWrap(true);
    m_outcome->setTextInteractionFlags(Qt::TextSelectableByMouse);
    runLayout->addWidget(m_outcome);
    layout->addWidget(m_runBox);
    layout->addStretch(1);

    for (ParameterField *f : m_form->fields())
        connect(f, &ParameterField::typing, this, &PathEditor::update);
    connect(store, &ParameterStore::valueChanged, this, [this](const QString &k) {
        // The start warning reads the limit inputs and the mode too, not only the axes.
        if (m_keys.contains(k) || k.startsWith(QLatin1String("motor")) ||
            k.startsWith(QLatin1String("io.in")) || k == QLatin1String("mode.system"))
            update();
    });
    connect(store, &ParameterStore::editsChanged, this, &PathEditor::update);
    connect(session->connection(), &SessionConnection::linkStateChanged, this, &PathEditor::update);
    connect(session->connection(), &SessionConnection::connected, this, &PathEditor::update);
    connect(session->connection(), &SessionConnection::disconnected, this, &PathEditor::update);
    connect(session->motion(), &MotionSupervisor::changed, this, &PathEditor::update);
    connect(session->motion(), &MotionSupervisor::emergencyStopSent, this, [this] {
        m_startSent.stop(); // nothing waits for a start any more
        update();
    });
    connect(m_write, &QPushButton::clicked, this, &PathEditor::openWriteDialog);
    m_startSent.setSingleShot(true);
    m_startSent.setInterval(1500);
    connect(&m_startSent, &QTimer::timeout, this, &PathEditor::update);
    connect(m_start, &QPushButton::clicked, this, [this] {
        // Checked again at the click: nothing but what is shown and held by the controller.
        if (!startBlockedReason().isEmpty())
            return;
        m_session->command(m_prefix + QStringLiteral("start"));
        // Until the poll shows the motors running, a second click must not start it again.
        m_startSent.start();
        update();
        Q_EMIT started();
    });
    connect(m_stop, &QPushButton::clicked, this,
            [this] { m_session->command(m_prefix + QStringLiteral("stop")); });
    retranslate();
}

QString PathEditor::key(const char *local) const
{
    return m_prefix + QLatin1String(local);
}

std::optional<double> PathEditor::typed(const char *local) const
{
    const ParameterField *f = m_form->field(key(local));
    if (!f)
        return std::nullopt;
    const std::optional<qint64> raw = f->typedRaw();
    if (!raw)
        return std::nullopt;
    return f->parameter().toEngineering(*raw);
}

Point PathEditor::typedPoint(const char *name) const
{
    const QByteArray n(name);
    return {typed((n + "_x").constData()).value_or(0), typed((n + "_y").constData()).value_or(0)};
}

MotorParameters PathEditor::motor(int n) const
{
    // What the controller holds: it runs with those, not with edits on the motor pages.
    const ParameterStore *store = m_session->parameters()->store();
    return interpolation::motorParameters(
        m_session->map(), n, [store](const QString &k) { return store->deviceValue(k); });
}

Geometry PathEditor::geometry() const
{
    if (m_kind == Kind::Line)
        return interpolation::line(typedPoint("start"), typedPoint("end"));
    interpolation::ArcSetup in;
    in.mode = typed("mode").value_or(0) == 1 ? interpolation::ArcMode::ThreePoints
                                             : interpolation::ArcMode::Centre;
    in.start = typedPoint("start");
    in.end = typedPoint("end");
    in.centre = typedPoint("center");
    in.middle = typedPoint("middle");
    in.counterClockwise = typed("direction").value_or(0) == 1;
    return interpolation::arc(in);
}

std::optional<QPointF> PathEditor::position() const
{
    const RegisterMap &map = m_session->map();
    const Parameter *x = map.blockParameter(QStringLiteral("motor"), 1, QStringLiteral("position"));
    const Parameter *y = map.blockParameter(QStringLiteral("motor"), 2, QStringLiteral("position"));
    if (!x || !y || !m_session->connection()->isConnected())
        return std::nullopt;
    const auto rx = m_session->parameters()->store()->deviceValue(x->key);
    const auto ry = m_session->parameters()->store()->deviceValue(y->key);
    if (!rx || !ry)
        return std::nullopt;
    return QPointF(x->toEngineering(*rx), y->toEngineering(*ry));
}

bool PathEditor::anyMotorRunning() const
{
    for (int n = 1; n <= 2; ++n) {
        const Parameter *p =
            m_session->map().blockParameter(QStringLiteral("motor"), n, QStringLiteral("running"));
        if (p && m_session->parameters()->store()->deviceValue(p->key).value_or(0) != 0)
            return true;
    }
    return false;
}

std::optional<interpolation::Approach> PathEditor::approach(const Geometry &g) const
{
    const std::optional<QPointF> from = position();
    if (!from || anyMotorRunning())
        return std::nullopt;
    return interpolation::approach({from->x(), from->y()}, g.start, motor(1), motor(2));
}

QString PathEditor::startBlockedReason() const
{
    if (!m_session->connection()->isConnected())
        return tr("Not connected.");
    const ParameterStore *store = m_session->parameters()->store();
    for (const ParameterField *f : m_form->fields()) {
        if (f->isTyping())
            return tr("A value is being typed: press Enter to keep it, then write it.");
    }
    for (const QString &k : m_keys) {
        if (store->entry(k).edited)
            return tr("Changes not written yet: write them first, so the controller runs what "
                      "the preview shows.");
    }
    for (const QString &k : m_keys) {
        if (!store->deviceValue(k))
            return tr("Not read from the controller yet.");
    }
    const Geometry g = geometry();
    if (!g.valid)
        return tr("The geometry is invalid: %1").arg(g.error);
    if (store->deviceValue(key("enabled")).value_or(0) != 1)
        return m_kind == Kind::Arc
                   ? tr("Arc interpolation is off (40182): choose “Motors 1+2 interpolate” and "
                        "write it.")
                   : tr("Line interpolation is off (40202): choose “Motors 1+2 interpolate” and "
                        "write it.");
    if (anyMotorRunning())
        return tr("A motor is moving: wait until it stops, or stop it.");
    if (m_startSent.isActive())
        return tr("Starting…");
    return {};
}

void PathEditor::update()
{
    const Geometry g = geometry();
    const QString unit = [this] {
        const ParameterField *f = m_form->field(key("start_x"));
        return f ? f->parameter().unit : QString();
    }();
    auto withUnit = [&unit](double v) { return QStringLiteral("%1 %2").arg(number(v), unit); };
    const QString none = QStringLiteral("—");
    if (m_kind == Kind::Arc) {
        const bool radiiKnown = g.centre && g.startRadius > 0;
        m_radius->setText(g.valid ? withUnit(g.radius()) : none);
        m_centre->setText(
            g.centre ? QStringLiteral("(%1, %2)%3")
                           .arg(number(g.centre->x), number(g.centre->y),
                                g.middle ? tr(" — computed from the three points") : QString())
                     : none);
        m_radii->setText(radiiKnown ? tr("%1 / %2 (difference %3, at most %4)")
                                          .arg(withUnit(g.startRadius), withUnit(g.endRadius),
                                               number(g.radiusDifference),
                                               number(interpolation::kRadiusTolerance))
                                    : none);
        m_sweep->setText(!g.valid ? none
                         : g.fullCircle
                             ? tr("%1° (full circle)").arg(QString::number(g.sweepDegrees, 'f', 1))
                             : tr("%1°").arg(QString::number(g.sweepDegrees, 'f', 1)));
    }
    m_length->setText(g.valid ? withUnit(g.length) : none);
    const std::optional<double> rpm = typed("speed");
    const MotorParameters m1 = motor(1);
    const std::optional<double> ups =
        rpm ? interpolation::pathUnitsPerSecond(*rpm, m1) : std::nullopt;
    m_speed->setText(rpm && ups ? tr("%1 rpm = %2 %3/s").arg(*rpm).arg(number(*ups), unit) : none);
    const std::optional<double> pathMs =
        g.valid && rpm ? interpolation::pathTimeMs(g.length, *rpm, m1) : std::nullopt;
    const std::optional<interpolation::Approach> a = g.valid ? approach(g) : std::nullopt;
    const double approachMs = a && a->timeMs ? *a->timeMs : 0.0;
    const double pathTimeMs = pathMs.value_or(0.0);
    if (!pathMs)
        m_time->setText(none);
    else if (approachMs > 0)
        m_time->setText(tr("%1 (approach %2 + path %3)")
                            .arg(duration(approachMs + pathTimeMs), duration(approachMs),
                                 duration(pathTimeMs)));
    else
        m_time->setText(duration(pathTimeMs));
    QPalette pal = m_problem->palette();
    pal.setColor(QPalette::WindowText,
                 g.valid ? palette().color(QPalette::WindowText) : QColor(220, 40, 40));
    m_problem->setPalette(pal);
    m_problem->setText(g.valid ? g.notes.join(QLatin1Char(' ')) : g.error);
    m_problem->setVisible(!m_problem->text().isEmpty());

    if (m_kind == Kind::Arc) {
        // Only the point the chosen mode uses.
        const bool threePoints = typed("mode").value_or(0) == 1;
        for (const char *local : {"center_x", "center_y"}) {
            if (ParameterField *f = m_form->field(key(local)))
                m_form->formLayout()->setRowVisible(f, !threePoints);
        }
        for (const char *local : {"middle_x", "middle_y"}) {
            if (ParameterField *f = m_form->field(key(local)))
                m_form->formLayout()->setRowVisible(f, threePoints);
        }
    }

    const bool connected = m_session->connection()->isConnected();
    if (anyMotorRunning() || !connected)
        m_startSent.stop(); // the poll saw it start
    const QString reason = startBlockedReason();
    m_start->setEnabled(reason.isEmpty());
    // Said before Start, not found out after it: an axis driven into a limit already ON.
    const QString warning =
        reason.isEmpty() ? m_session->motion()->startWarning(m_prefix + QStringLiteral("start"))
                         : QString();
    m_reason->setText(!reason.isEmpty()   ? reason
                      : warning.isEmpty() ? tr("Ready: Start runs the path shown, as written.")
                                          : tr("⚠ Start is possible, but: %1").arg(warning));
    const MotionKind kind = m_kind == Kind::Arc ? MotionKind::Arc : MotionKind::Line;
    const MotionSupervisor *motion = m_session->motion();
    if (const auto active = motion->active(kind))
        m_outcome->setText(tr("%1: running…").arg(MotionJudge::name(*active)));
    else if (const auto last = motion->lastOutcome(kind))
        m_outcome->setText(tr("Last run: %1").arg(motion->text(*last)));
    else
        m_outcome->clear();
    m_outcome->setVisible(!m_outcome->text().isEmpty());
    bool edited = false;
    for (const QString &k : std::as_const(m_keys))
        edited = edited || m_session->parameters()->store()->entry(k).edited.has_value();
    m_write->setEnabled(connected && edited);
    // Stopping depends on nothing but the link.
    m_stop->setEnabled(connected);
    Q_EMIT changed();
}

void PathEditor::openWriteDialog()
{
    m_writeFlow->openFor(m_keys);
}

QString PathEditor::assumptions()
{
    return tr("Estimated time: the approach from where the axes are now (each axis on its own at "
              "its own speed) plus the path, driven at the set speed as motor 1 revolutions per "
              "minute with motor 1's start frequency, acceleration and pitch, as the simulator "
              "runs it. A real controller may differ.");
}

void PathEditor::retranslate()
{
    const bool arc = m_kind == Kind::Arc;
    m_parameterBox->setTitle(arc ? tr("Arc parameters") : tr("Line parameters"));
    m_resultBox->setTitle(tr("What the controller will do"));
    m_runBox->setTitle(arc ? tr("Run the arc") : tr("Run the line"));
    for (const auto &[label, text] : std::as_const(m_rowLabels))
        label->setText(tr(text));
    // The one line a technician needs; how the estimate is made is on demand.
    m_assumes->setText(tr("Times as the simulator runs the path; a real controller may differ."));
    m_assumes->setToolTip(assumptions());
    m_assumes->setWhatsThis(assumptions());
    m_write->setText(tr("&Write changes…"));
    m_write->setToolTip(tr("Write this editor's changes to the controller and read them back"));
    m_start->setText(arc ? tr("Start arc") : tr("Start line"));
    m_start->setToolTip(arc ? tr("Coil 00100: each axis first moves to the start point on its "
                                 "own, then both follow the arc")
                            : tr("Coil 00102: each axis first moves to the start point on its "
                                 "own, then both follow the line"));
    m_stop->setText(arc ? tr("Stop arc") : tr("Stop line"));
    m_stop->setToolTip(arc ? tr("Coil 00101, sent ahead of everything queued")
                           : tr("Coil 00103, sent ahead of everything queued"));
    update();
}

} // namespace stepcom

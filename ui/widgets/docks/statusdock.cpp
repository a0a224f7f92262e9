#include "widgets/docks/statusdock.h"

#include "base/language.h"
#include "motion/referencetracker.h"
#include "session/devicesession.h"
#include "session/motionsupervisor.h"
#include "session/parts/sessionconnection.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/led.h"

#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");
constexpr int kLampsPerRow = 4;

Led::State lampState(std::optional<qint64> value)
{
    if (!value)
        return Led::State::Unknown;
    return *value ? Led::State::On : Led::State::Off;
}

// A lamp with its caption beside it, in a grid that wraps after kLampsPerRow.
void addLamp(QGridLayout *grid, int index, int firstRow, Led *led, QLabel *name)
{
    auto *cell = new QHBoxLayout;
    cell->setSpacing(grid->spacing() > 0 ? grid->spacing() / 2 : 3);
    cell->addWidget(led);
    cell->addWidget(name);
    cell->addStretch(1);
    grid->addLayout(cell, firstRow + index / kLampsPerRow, 1 + index % kLampsPerRow);
}

} // namespace

StatusDock::StatusDock(DeviceSession *session, QWidget *parent)
    : QDockWidget(parent)
    , m_session(session)
{
    setObjectName(QStringLiteral("statusDock"));
    setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                QDockWidget::DockWidgetFloatable);
    const RegisterMap &map = session->map();

    // No scroll area: the dock is never narrower than what it shows, so nothing is cut off.
    auto *content = new QWidget(this);
    auto *rows = new QVBoxLayout(content);

    // Fixed-width digits: a changing position does not make its neighbours jump.
    QFont big = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    big.setPointSizeF(font().pointSizeF() * 2.0);
    big.setBold(true);
    for (int n = 1; n <= map.blockCount(kMotor); ++n) {
        const Parameter *pos = map.blockParameter(kMotor, n, QStringLiteral("position"));
        if (!pos)
            break;
        const Parameter *run = map.blockParameter(kMotor, n, QStringLiteral("running"));
        m_positionKeys << pos->key;
        m_runningKeys << (run ? run->key : QString());
        auto *box = new QGroupBox(content);
        auto *grid = new QGridLayout(box);
        auto *position = new QLabel(box);
        position->setFont(big);
        position->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        position->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // Room for the widest value the register holds, so the dock never resizes on the go.
        const QString widest = pos->displayRaw(std::max<qint64>(pos->rawMin, -9999999));
        position->setMinimumWidth(QFontMetrics(big).horizontalAdvance(widest + QLatin1Char(' ')));
        grid->addWidget(position, 0, 0, 1, 3);
        auto *led = new Led(box);
        led->setEnabled(run != nullptr);
        auto *state = new QLabel(box);
        grid->addWidget(led, 1, 0);
        grid->addWidget(state, 1, 1);
        auto *reference = new QLabel(box);
        reference->setWordWrap(true);
        grid->addWidget(reference, 2, 0, 1, 3);
        m_references << reference;
        grid->setColumnStretch(2, 1);
        rows->addWidget(box);
        m_motorBoxes << box;
        m_positions << position;
        m_runningLeds << led;
        m_running << state;
    }

    m_ioBox = new QGroupBox(content);
    auto *io = new QGridLayout(m_ioBox);
    m_inputsCaption = new QLabel(m_ioBox);
    io->addWidget(m_inputsCaption, 0, 0, Qt::AlignLeft | Qt::AlignTop);
    for (int n = 1; map.find(QStringLiteral("io.in%1").arg(n)); ++n) {
        m_inputKeys << QStringLiteral("io.in%1").arg(n);
        auto *led = new Led(m_ioBox);
        auto *name = new QLabel(m_ioBox);
        addLamp(io, n - 1, 0, led, name);
        m_inputLeds << led;
        m_inputNames << name;
    }
    const int outputRow = 1 + (std::max<int>(1, int(m_inputLeds.size())) - 1) / kLampsPerRow;
    m_outputsCaption = new QLabel(m_ioBox);
    io->addWidget(m_outputsCaption, outputRow, 0, Qt::AlignLeft | Qt::AlignTop);
    for (int n = 1; map.find(QStringLiteral("io.out%1").arg(n)); ++n) {
        m_outputKeys << QStringLiteral("io.out%1").arg(n);
        auto *led = new Led(m_ioBox);
        auto *name = new QLabel(m_ioBox);
        addLamp(io, n - 1, outputRow, led, name);
        m_outputLeds << led;
        m_outputNames << name;
    }
    io->setColumnStretch(kLampsPerRow + 1, 1);
    rows->addWidget(m_ioBox);

    rows->addStretch(1);
    setWidget(content);

    m_refresh.setSingleShot(true);
    m_refresh.setInterval(0);
    connect(&m_refresh, &QTimer::timeout, this, &StatusDock::refresh);
    connect(session->parameters()->store(), &ParameterStore::valueChanged, this,
            [this](const QString &key) {
                if (key.startsWith(QLatin1String("io.")) || m_positionKeys.contains(key) ||
                    m_runningKeys.contains(key))
                    scheduleRefresh();
            });
    connect(session->connection(), &SessionConnection::linkStateChanged, this,
            &StatusDock::scheduleRefresh);
    connect(session->motion()->references(), &ReferenceTracker::changed, this,
            &StatusDock::scheduleRefresh);
    retranslate();
}

QString StatusDock::positionText(int motor) const
{
    const QLabel *l = m_positions.value(motor - 1);
    return l ? l->text() : QString();
}

QString StatusDock::runningText(int motor) const
{
    const QLabel *l = m_running.value(motor - 1);
    return l ? l->text() : QString();
}

void StatusDock::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void StatusDock::scheduleRefresh()
{
    if (!m_refresh.isActive())
        m_refresh.start();
}

QString StatusDock::referenceText(int motor) const
{
    return m_session->motion()->references()->text(motor);
}

void StatusDock::refresh()
{
    const ParameterStore *store = m_session->parameters()->store();
    const RegisterMap &map = m_session->map();
    const QString lang = Language::instance().current();
    for (int m = 0; m < m_positions.size(); ++m) {
        QLabel *label = m_positions.at(m);
        const auto raw = store->deviceValue(m_positionKeys.at(m));
        const Parameter *p = map.find(m_positionKeys.at(m));
        label->setText(raw && p ? p->displayRaw(*raw, lang) : tr("unknown"));
        label->setEnabled(raw.has_value()); // the palette's disabled text: dimmed, any theme
        const auto running =
            m_runningKeys.at(m).isEmpty() ? std::nullopt : store->deviceValue(m_runningKeys.at(m));
        m_runningLeds.at(m)->setState(lampState(running));
        m_references.at(m)->setText(referenceText(m + 1));
        m_running.at(m)->setText(!running ? tr("unknown")
                                          : (*running ? tr("Running") : tr("Stopped")));
        m_running.at(m)->setEnabled(running.has_value());
    }
    const auto lamp = [lang, &map, store](Led *led, const QString &key) {
        const auto value = store->deviceValue(key);
        led->setState(lampState(value));
        const Parameter *p = map.find(key);
        const QString state = !value ? tr("unknown") : (*value ? tr("on") : tr("off"));
        led->setToolTip(QStringLiteral("%1: %2").arg(p ? p->label.text(lang) : key, state));
        led->setAccessibleName(led->toolTip());
    };
    for (int i = 0; i < m_inputLeds.size(); ++i)
        lamp(m_inputLeds.at(i), m_inputKeys.at(i));
    for (int i = 0; i < m_outputLeds.size(); ++i)
        lamp(m_outputLeds.at(i), m_outputKeys.at(i));
}

void StatusDock::retranslate()
{
    setWindowTitle(tr("Status"));
    const QString lang = Language::instance().current();
    const RegisterMap &map = m_session->map();
    for (int m = 0; m < m_motorBoxes.size(); ++m) {
        m_motorBoxes.at(m)->setTitle(tr("Motor %1").arg(m + 1));
        if (const Parameter *p = map.find(m_positionKeys.at(m)))
            m_positions.at(m)->setToolTip(p->label.text(lang));
    }
    m_ioBox->setTitle(tr("Inputs and outputs"));
    m_inputsCaption->setText(tr("In"));
    m_outputsCaption->setText(tr("Out"));
    for (int i = 0; i < m_inputNames.size(); ++i)
        m_inputNames.at(i)->setText(tr("IN%1").arg(i + 1));
    for (int i = 0; i < m_outputNames.size(); ++i)
        m_outputNames.at(i)->setText(tr("OUT%1").arg(i + 1));
    refresh();
}

} // namespace stepcom

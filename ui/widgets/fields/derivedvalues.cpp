#include "widgets/fields/derivedvalues.h"

#include <QEvent>
#include <QFormLayout>
#include <QLabel>

#include <cmath>

namespace stepcom {

namespace {

constexpr int kRows = 8;
const QString kDash = QStringLiteral("—");

} // namespace

DerivedValues::DerivedValues(QWidget *parent)
    : QWidget(parent)
    , m_layout(new QFormLayout(this))
{
    m_layout->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (int i = 0; i < kRows; ++i) {
        auto *name = new QLabel(this);
        auto *value = new QLabel(kDash, this);
        // Technicians copy these into reports; selectable text, never focusable editors.
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        QFont bold = value->font();
        bold.setBold(true);
        value->setFont(bold);
        m_layout->addRow(name, value);
        m_names << name;
        m_texts << value;
    }
    retranslate();
}

void DerivedValues::setValues(const MotorDerived &values, const QString &unit)
{
    m_values = values;
    m_unit = unit;
    refresh();
}

QString DerivedValues::text(Row row) const
{
    return m_texts.at(int(row))->text();
}

QString DerivedValues::number(double value, int decimals)
{
    QString s = QString::number(value, 'f', decimals);
    if (s.contains(QLatin1Char('.'))) {
        while (s.endsWith(QLatin1Char('0')))
            s.chop(1);
        if (s.endsWith(QLatin1Char('.')))
            s.chop(1);
    }
    return s;
}

QString DerivedValues::duration(double ms)
{
    if (ms < 1000)
        return tr("%1 ms").arg(number(std::round(ms), 0));
    const double s = ms / 1000.0;
    if (s < 60)
        return tr("%1 s").arg(number(s, 3));
    if (s < 3600) {
        const int minutes = int(s / 60);
        return tr("%1 min %2 s").arg(minutes).arg(number(s - minutes * 60.0, 1));
    }
    const int hours = int(s / 3600);
    return tr("%1 h %2 min").arg(hours).arg(int((s - hours * 3600.0) / 60));
}

void DerivedValues::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void DerivedValues::retranslate()
{
    const QString names[kRows] = {tr("Pulses per revolution:"), tr("Pulse rate at the set speed:"),
                                  tr("Linear speed:"),          QString(),
                                  tr("Revolutions per move:"),  tr("Pulses per move:"),
                                  tr("Ramp to the set speed:"), tr("Estimated move time:")};
    const QString tips[kRows] = {
        tr("360 / step angle × microsteps"),
        tr("Speed (rpm) × pulses per revolution / 60: what the driver must accept"),
        tr("Speed (rpm) × pitch / 60"),
        tr("Speed (rpm) × pitch"),
        tr("Move distance / pitch"),
        tr("Move distance / pitch × pulses per revolution, in whole pulses as the controller sends "
           "them"),
        tr("(Pulse rate − start frequency) / accel/decel frequency: the rate rises by the "
           "accel/decel "
           "frequency every millisecond; braking takes as long"),
        tr("A single move with its ramps up and down, as the simulator runs it (start frequency, "
           "accel/decel frequency per millisecond, speed)")};
    for (int i = 0; i < kRows; ++i) {
        m_names.at(i)->setText(names[i]);
        m_names.at(i)->setToolTip(tips[i]);
        m_texts.at(i)->setToolTip(tips[i]);
    }
    refresh();
}

void DerivedValues::refresh()
{
    const MotorDerived &v = m_values;
    const QString unit = m_unit.isEmpty() ? tr("units") : m_unit;
    auto show = [this](Row row, const QString &text) {
        QLabel *label = m_texts.at(int(row));
        label->setText(text);
        // The per-minute row continues "Linear speed:" and has no name of its own.
        const int named = m_names.at(int(row))->text().isEmpty() ? int(row) - 1 : int(row);
        label->setAccessibleName(m_names.at(named)->text() + QLatin1Char(' ') + text);
    };
    show(Row::PulsesPerRev,
         v.pulsesPerRev ? tr("%1 pulses/rev").arg(number(*v.pulsesPerRev, 2)) : kDash);
    show(Row::PulseRate, v.pulseRateHz ? tr("%1 Hz").arg(number(*v.pulseRateHz, 1)) : kDash);
    show(Row::SpeedPerSecond,
         v.unitsPerSecond ? tr("%1 %2/s").arg(number(*v.unitsPerSecond, 3), unit) : kDash);
    show(Row::SpeedPerMinute,
         v.unitsPerMinute ? tr("%1 %2/min").arg(number(*v.unitsPerMinute, 2), unit) : kDash);
    show(Row::RevolutionsPerMove,
         v.revolutionsPerMove ? tr("%1 rev").arg(number(*v.revolutionsPerMove, 3)) : kDash);
    show(Row::PulsesPerMove, v.pulsesPerMove ? tr("%1 pulses").arg(*v.pulsesPerMove) : kDash);
    if (!v.rampMs)
        show(Row::Ramp, kDash);
    else if (*v.rampMs <= 0)
        show(Row::Ramp, tr("none (start frequency ≥ pulse rate)"));
    else
        show(Row::Ramp, duration(*v.rampMs));
    show(Row::MoveTime, v.moveTimeMs && *v.moveTimeMs > 0 ? duration(*v.moveTimeMs) : kDash);
}

} // namespace stepcom

#include "widgets/sequence/sequencestepform.h"

#include "map/parameter.h"
#include "map/registermap.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>

namespace stepcom {

namespace {

using StepKind = SequenceStep::Kind;

const QList<StepKind> kKinds{StepKind::Home,      StepKind::MoveTo, StepKind::MoveBy,
                             StepKind::WaitInput, StepKind::Output, StepKind::Outputs,
                             StepKind::Dwell,     StepKind::Repeat, StepKind::Speed};

enum Label { HomeRow, PointRow, NumberRow, OnRow, TimeoutRow, OutputsRow, DwellRow, CountRow };

} // namespace

SequenceStepForm::SequenceStepForm(const RegisterMap &map, QWidget *parent)
    : QWidget(parent)
    , m_map(map)
    , m_form(new QFormLayout(this))
    , m_kind(new QComboBox(this))
    , m_home(new QComboBox(this))
    , m_point(new QComboBox(this))
    , m_number(new QSpinBox(this))
    , m_on(new QCheckBox(this))
    , m_timeout(new QDoubleSpinBox(this))
    , m_outputs(new QComboBox(this))
    , m_dwell(new QSpinBox(this))
    , m_count(new QSpinBox(this))
{
    m_form->setContentsMargins(0, 0, 0, 0);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_kind->setObjectName(QStringLiteral("stepKind"));
    for (StepKind k : kKinds)
        m_kind->addItem(QString(), int(k));
    auto *kindCaption = new QLabel(this);
    kindCaption->setBuddy(m_kind);
    m_form->addRow(kindCaption, m_kind);
    m_home->setObjectName(QStringLiteral("stepHome"));
    m_home->addItem(QString(), 0);
    const int motors = map.blockCount(QStringLiteral("motor"));
    for (int n = 1; n <= motors; ++n)
        m_home->addItem(QString(), n);
    m_point->setObjectName(QStringLiteral("stepPoint"));
    m_number->setObjectName(QStringLiteral("stepNumber"));
    m_number->setRange(1, 99);
    m_on->setObjectName(QStringLiteral("stepOn"));
    m_timeout->setObjectName(QStringLiteral("stepTimeout"));
    m_timeout->setRange(0, 86400);
    m_timeout->setDecimals(1);
    m_outputs->setObjectName(QStringLiteral("stepOutputs"));
    m_outputs->addItem(QString(), true);
    m_outputs->addItem(QString(), false);
    m_dwell->setObjectName(QStringLiteral("stepDwell"));
    m_dwell->setRange(0, 86400000);
    m_dwell->setSingleStep(100);
    m_count->setObjectName(QStringLiteral("stepCount"));
    m_count->setRange(1, 1000000);
    const QList<QWidget *> fields{m_home,    m_point,   m_number, m_on,
                                  m_timeout, m_outputs, m_dwell,  m_count};
    for (int i = 0; i < fields.size(); ++i) {
        m_labels[i] = new QLabel(this);
        m_labels[i]->setBuddy(fields[i]);
        m_form->addRow(m_labels[i], fields[i]);
    }
    // One row per motor after the point: a move or speed names the axes it sets.
    for (int n = 1; n <= motors; ++n) {
        auto *on = new QCheckBox(this);
        on->setObjectName(QStringLiteral("stepAxis%1").arg(n));
        auto *value = new QDoubleSpinBox(this);
        value->setObjectName(QStringLiteral("stepAxisValue%1").arg(n));
        value->setRange(-1e7, 1e7);
        auto *row = new QWidget(this);
        auto *h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        h->addWidget(on);
        h->addWidget(value, 1);
        m_axisOn << on;
        m_axisValue << value;
        m_axisLabel << new QLabel(this);
        m_axisLabel.last()->setBuddy(value);
        m_form->insertRow(3 + n - 1, m_axisLabel.last(), row);
        connect(on, &QCheckBox::toggled, this, [this, value](bool checked) {
            value->setEnabled(checked);
            changed();
        });
        connect(value, &QDoubleSpinBox::valueChanged, this, &SequenceStepForm::changed);
    }
    connect(m_kind, &QComboBox::currentIndexChanged, this, [this] {
        if (m_filling)
            return;
        // A new kind starts from its own defaults; the path and place stay.
        const SequenceStep old = m_step;
        m_step = defaultStep(StepKind(m_kind->currentData().toInt()), m_points);
        m_step.path = old.path;
        setStep(m_step, m_points);
        Q_EMIT edited();
    });
    for (QComboBox *box : {m_home, m_point, m_outputs})
        connect(box, &QComboBox::currentIndexChanged, this, &SequenceStepForm::changed);
    connect(m_on, &QCheckBox::toggled, this, &SequenceStepForm::changed);
    for (QSpinBox *box : {m_number, m_dwell, m_count})
        connect(box, &QSpinBox::valueChanged, this, &SequenceStepForm::changed);
    connect(m_timeout, &QDoubleSpinBox::valueChanged, this, &SequenceStepForm::changed);
    retranslate();
    clear();
}

QString SequenceStepForm::kindLabel(StepKind kind)
{
    switch (kind) {
    case StepKind::Home:
        return tr("Home");
    case StepKind::MoveTo:
        return tr("Move to");
    case StepKind::MoveBy:
        return tr("Move by");
    case StepKind::WaitInput:
        return tr("Wait for an input");
    case StepKind::Output:
        return tr("Switch output 1");
    case StepKind::Outputs:
        return tr("Switch all outputs");
    case StepKind::Dwell:
        return tr("Dwell");
    case StepKind::Repeat:
        return tr("Repeat (a loop)");
    case StepKind::Speed:
        return tr("Set the speed");
    }
    return {};
}

SequenceStep SequenceStepForm::defaultStep(StepKind kind, const QStringList &points)
{
    SequenceStep s;
    s.kind = kind;
    switch (kind) {
    case StepKind::Home:
        s.homeInOrder = true;
        break;
    case StepKind::MoveTo:
        if (!points.isEmpty())
            s.point = points.first();
        else
            s.axes.insert(1, 0.0);
        break;
    case StepKind::MoveBy:
        s.axes.insert(1, 1.0);
        break;
    case StepKind::WaitInput:
        s.number = 1;
        s.on = true;
        s.timeoutMs = 10000;
        break;
    case StepKind::Output:
        s.number = 1;
        s.on = true;
        break;
    case StepKind::Outputs:
        s.on = false;
        break;
    case StepKind::Dwell:
        s.dwellMs = 500;
        break;
    case StepKind::Repeat:
        s.count = 2;
        break;
    case StepKind::Speed:
        s.axes.insert(1, 100);
        break;
    }
    return s;
}

void SequenceStepForm::setStep(const SequenceStep &step, const QStringList &points)
{
    m_filling = true;
    m_step = step;
    m_points = points;
    m_has = true;
    setEnabled(true);
    m_kind->setCurrentIndex(m_kind->findData(int(step.kind)));
    m_home->setCurrentIndex(step.homeInOrder || step.homeMotors.isEmpty()
                                ? 0
                                : m_home->findData(step.homeMotors.first()));
    m_point->clear();
    for (const QString &p : points)
        m_point->addItem(p, p);
    if (!step.point.isEmpty() && !points.contains(step.point))
        m_point->addItem(step.point, step.point); // a point no longer there: the check says so
    m_point->addItem(tr("(a position of its own)"), QString());
    m_point->setCurrentIndex(m_point->findData(step.point));
    for (int i = 0; i < m_axisOn.size(); ++i) {
        const int motor = i + 1;
        const bool on = step.axes.contains(motor);
        m_axisOn[i]->setChecked(on);
        m_axisValue[i]->setEnabled(on);
        const QString local = step.kind == StepKind::Speed    ? QStringLiteral("speed")
                              : step.kind == StepKind::MoveBy ? QStringLiteral("move_distance")
                                                              : QStringLiteral("position");
        const Parameter *p = m_map.blockParameter(QStringLiteral("motor"), motor, local);
        m_axisValue[i]->setDecimals(p ? p->decimals() : 2);
        m_axisValue[i]->setSuffix(p && !p->unit.isEmpty() ? QLatin1Char(' ') + p->unit : QString());
        m_axisValue[i]->setValue(step.axes.value(motor));
    }
    m_number->setValue(std::max(1, step.number));
    m_on->setChecked(step.on);
    m_timeout->setValue(step.timeoutMs / 1000.0);
    m_outputs->setCurrentIndex(step.on ? 0 : 1);
    m_dwell->setValue(step.dwellMs);
    m_count->setValue(step.count);
    m_filling = false;
    showRows();
    retranslate();
}

void SequenceStepForm::clear()
{
    m_has = false;
    m_step = {};
    setEnabled(false);
    showRows();
}

SequenceStep SequenceStepForm::step() const
{
    SequenceStep s = m_step;
    switch (s.kind) {
    case StepKind::Home:
        s.homeMotors.clear();
        s.homeInOrder = m_home->currentData().toInt() == 0;
        if (!s.homeInOrder)
            s.homeMotors << m_home->currentData().toInt();
        break;
    case StepKind::MoveTo:
        s.point = m_point->currentData().toString();
        [[fallthrough]];
    case StepKind::MoveBy:
    case StepKind::Speed:
        if (s.kind != StepKind::MoveTo || s.point.isEmpty()) {
            s.axes.clear();
            for (int i = 0; i < m_axisOn.size(); ++i) {
                if (m_axisOn[i]->isChecked())
                    s.axes.insert(i + 1, m_axisValue[i]->value());
            }
        }
        break;
    case StepKind::WaitInput:
        s.timeoutMs = int(std::lround(m_timeout->value() * 1000));
        [[fallthrough]];
    case StepKind::Output:
        s.number = m_number->value();
        s.on = m_on->isChecked();
        break;
    case StepKind::Outputs:
        s.on = m_outputs->currentData().toBool();
        break;
    case StepKind::Dwell:
        s.dwellMs = m_dwell->value();
        break;
    case StepKind::Repeat:
        s.count = m_count->value();
        break;
    }
    return s;
}

void SequenceStepForm::changed()
{
    if (m_filling || !m_has)
        return;
    m_step = step();
    showRows();
    Q_EMIT edited();
}

void SequenceStepForm::showRows()
{
    const StepKind k = m_step.kind;
    const bool has = m_has;
    const auto show = [this](QWidget *field, bool visible) {
        m_form->setRowVisible(field, visible);
    };
    show(m_kind, has);
    show(m_home, has && k == StepKind::Home);
    show(m_point, has && k == StepKind::MoveTo);
    const bool axes = has && (k == StepKind::MoveBy || k == StepKind::Speed ||
                              (k == StepKind::MoveTo && m_step.point.isEmpty()));
    for (QCheckBox *box : m_axisOn)
        show(box->parentWidget(), axes); // the row holding the tick and the value
    show(m_number, has && (k == StepKind::WaitInput || k == StepKind::Output));
    show(m_on, has && (k == StepKind::WaitInput || k == StepKind::Output));
    show(m_timeout, has && k == StepKind::WaitInput);
    show(m_outputs, has && k == StepKind::Outputs);
    show(m_dwell, has && k == StepKind::Dwell);
    show(m_count, has && k == StepKind::Repeat);
}

void SequenceStepForm::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SequenceStepForm::retranslate()
{
    static_cast<QLabel *>(m_form->labelForField(m_kind))->setText(tr("&Step:"));
    for (int i = 0; i < m_kind->count(); ++i)
        m_kind->setItemText(i, kindLabel(StepKind(m_kind->itemData(i).toInt())));
    m_home->setItemText(0, tr("In the set homing order"));
    for (int i = 1; i < m_home->count(); ++i)
        m_home->setItemText(i, tr("Motor %1").arg(i));
    m_outputs->setItemText(0, tr("All ON"));
    m_outputs->setItemText(1, tr("All OFF"));
    const bool input = m_step.kind == StepKind::WaitInput;
    m_labels[HomeRow]->setText(tr("&Home:"));
    m_labels[PointRow]->setText(tr("&Point:"));
    m_labels[NumberRow]->setText(input ? tr("&Input (IN):") : tr("&Output:"));
    m_labels[OnRow]->setText(tr("State:"));
    m_on->setText(input ? tr("Wait for ON (unticked: for OFF)") : tr("ON (unticked: OFF)"));
    m_labels[TimeoutRow]->setText(tr("&Timeout (0: none):"));
    m_timeout->setSuffix(tr(" s"));
    m_labels[OutputsRow]->setText(tr("O&utputs:"));
    m_labels[DwellRow]->setText(tr("&Dwell:"));
    m_dwell->setSuffix(tr(" ms"));
    m_labels[CountRow]->setText(tr("&Times:"));
    for (int i = 0; i < m_axisOn.size(); ++i) {
        m_axisLabel[i]->setText(tr("Motor %1:").arg(i + 1));
        m_axisOn[i]->setText(m_step.kind == StepKind::Speed ? tr("set") : tr("moves"));
    }
    const int outputs = [this] {
        int n = 0;
        while (m_map.find(QStringLiteral("io.out%1").arg(n + 1)))
            ++n;
        return n;
    }();
    m_number->setToolTip(input ? QString()
                               : tr("The controller switches output 1 alone; all %1 "
                                    "outputs together with \"Switch all outputs\".")
                                     .arg(outputs));
}

} // namespace stepcom

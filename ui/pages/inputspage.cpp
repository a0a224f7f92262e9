#include "pages/inputspage.h"

#include "base/language.h"
#include "i18n/translators.h"
#include "session/devicesession.h"
#include "session/parts/sessionparameters.h"
#include "widgets/fields/led.h"
#include "widgets/fields/parameterfield.h"
#include "widgets/fields/wiringwarnings.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace stepcom {

namespace {

const QString kMotor = QStringLiteral("motor");
const QString kMode = QStringLiteral("mode.system");
const QString kRoles[] = {QStringLiteral("limit_positive"), QStringLiteral("limit_negative"),
                          QStringLiteral("home_input")};

QString inputKey(int n)
{
    return QStringLiteral("io.in%1").arg(n);
}

QString outputKey(int n)
{
    return QStringLiteral("io.out%1").arg(n);
}

Led::State lampState(std::optional<qint64> value)
{
    if (!value)
        return Led::State::Unknown;
    return *value ? Led::State::On : Led::State::Off;
}

} // namespace

InputsPage::InputsPage(DeviceSession *session, QWidget *parent)
    : Page(session, parent)
{
    ParameterStore *store = session->parameters()->store();
    const RegisterMap &map = session->map();
    m_motors = map.blockCount(kMotor);

    QWidget *content = scrollableContent();
    auto *rows = new QVBoxLayout(content);

    // Motors as rows, roles as columns: a wrong input stands out against its neighbours.
    m_wiringBox = new QGroupBox(content);
    auto *wiringLayout = new QVBoxLayout(m_wiringBox);
    auto *grid = new QGridLayout;
    for (int c = 0; c < 3; ++c) {
        auto *head = new QLabel(m_wiringBox);
        grid->addWidget(head, 0, c + 1);
        m_columnHeads << head;
    }
    for (int n = 1; n <= m_motors; ++n) {
        auto *label = new QLabel(m_wiringBox);
        grid->addWidget(label, n, 0, Qt::AlignRight | Qt::AlignVCenter);
        m_motorLabels << label;
        for (int c = 0; c < 3; ++c) {
            const Parameter *p = map.blockParameter(kMotor, n, kRoles[c]);
            if (!p)
                continue;
            auto *field = new ParameterField(store, *p, m_wiringBox);
            grid->addWidget(field, n, c + 1);
            m_fields.insert(p->key, field);
            m_keys << p->key;
            if (c == 0)
                label->setBuddy(field->editor());
        }
    }
    for (int c = 1; c <= 3; ++c)
        grid->setColumnStretch(c, 1);
    wiringLayout->addLayout(grid);
    m_homeNote = new QLabel(m_wiringBox);
    m_homeNote->setWordWrap(true);
    wiringLayout->addWidget(m_homeNote);
    m_modeLine = new QLabel(m_wiringBox);
    m_modeLine->setObjectName(QStringLiteral("systemModeLine"));
    m_modeLine->setWordWrap(true);
    wiringLayout->addWidget(m_modeLine);
    rows->addWidget(m_wiringBox);

    m_checkBox = new QGroupBox(content);
    auto *checkLayout = new QVBoxLayout(m_checkBox);
    m_warnings = new WiringWarnings(m_checkBox);
    checkLayout->addWidget(m_warnings);
    rows->addWidget(m_checkBox);

    auto *lamps = new QHBoxLayout;
    m_inputsBox = new QGroupBox(content);
    auto *inputGrid = new QGridLayout(m_inputsBox);
    inputGrid->setColumnStretch(2, 1);
    for (int n = 1; map.find(inputKey(n)); ++n) {
        auto *led = new Led(m_inputsBox);
        auto *name = new QLabel(m_inputsBox);
        auto *use = new QLabel(m_inputsBox);
        use->setWordWrap(true);
        inputGrid->addWidget(led, n - 1, 0);
        inputGrid->addWidget(name, n - 1, 1);
        inputGrid->addWidget(use, n - 1, 2);
        m_inputLeds << led;
        m_inputNames << name;
        m_inputUses << use;
    }
    lamps->addWidget(m_inputsBox, 2);
    m_outputsBox = new QGroupBox(content);
    auto *outputGrid = new QGridLayout(m_outputsBox);
    outputGrid->setColumnStretch(1, 1);
    for (int n = 1; map.find(outputKey(n)); ++n) {
        auto *led = new Led(m_outputsBox);
        led->setOnColor(QColor(255, 170, 0)); // amber: an output, not an input
        auto *name = new QLabel(m_outputsBox);
        outputGrid->addWidget(led, n - 1, 0);
        outputGrid->addWidget(name, n - 1, 1);
        m_outputLeds << led;
        m_outputNames << name;
    }
    lamps->addWidget(m_outputsBox, 1);
    rows->addLayout(lamps);
    rows->addStretch(1);

    // Tab order: motor by motor, positive, negative, home.
    QWidget *previous = nullptr;
    for (const QString &k : std::as_const(m_keys)) {
        QWidget *editor = m_fields.value(k)->editor();
        if (previous)
            setTabOrder(previous, editor);
        previous = editor;
    }

    m_watchedKeys = m_keys;
    m_watchedKeys << kMode;
    connect(store, &ParameterStore::valueChanged, this, [this](const QString &k) {
        if (m_watchedKeys.contains(k))
            updateWiring();
        else if (k.startsWith(QLatin1String("io.")))
            updateLamps();
    });
    retranslate();
}

QString InputsPage::title() const
{
    return tr("Inputs and limits");
}

QStringList InputsPage::keys() const
{
    return m_keys;
}

ParameterField *InputsPage::field(int motor, const QString &localKey) const
{
    const Parameter *p = session()->map().blockParameter(kMotor, motor, localKey);
    return p ? m_fields.value(p->key) : nullptr;
}

QList<MotorWiring> InputsPage::wiring() const
{
    QList<MotorWiring> out;
    const ParameterStore *store = session()->parameters()->store();
    for (int n = 1; n <= m_motors; ++n) {
        MotorWiring w;
        w.motor = n;
        std::optional<int> *targets[] = {&w.positive, &w.negative, &w.home};
        for (int c = 0; c < 3; ++c) {
            if (const Parameter *p = session()->map().blockParameter(kMotor, n, kRoles[c])) {
                if (const auto v = store->shownValue(p->key))
                    *targets[c] = int(*v);
            }
        }
        out << w;
    }
    return out;
}

QList<WiringWarning> InputsPage::warnings() const
{
    const auto mode = session()->parameters()->store()->shownValue(kMode);
    return checkWiring(wiring(), mode ? std::optional<int>(int(*mode)) : std::nullopt);
}

void InputsPage::updateWiring()
{
    const QList<MotorWiring> w = wiring();
    bool known = !w.isEmpty();
    for (const MotorWiring &m : w)
        known = known && m.positive && m.negative && m.home;
    m_warnings->setWarnings(known ? warnings() : QList<WiringWarning>(), known);

    const Parameter *mode = session()->map().find(kMode);
    const auto value = session()->parameters()->store()->shownValue(kMode);
    const QString lang = Language::instance().current();
    if (!mode || !value) {
        m_modeLine->setText(tr("System mode: not known yet."));
    } else {
        const QString name = mode->displayRaw(*value, lang);
        if (*value == 0)
            m_modeLine->setText(
                tr("System mode: %1. The limit and home settings apply.").arg(name));
        else if (*value == 1)
            m_modeLine->setText(
                tr("System mode: %1. Motor 1 uses IN1 and IN2 as its limits, IN3 stops "
                   "it and IN4 starts it.")
                    .arg(name));
        else
            m_modeLine->setText(
                tr("System mode: %1. The limit settings are ignored: the inputs do what "
                   "the mode says.")
                    .arg(name));
    }

    // Beside each lamp: what the settings wire to that input.
    for (int i = 0; i < m_inputUses.size(); ++i) {
        QStringList uses;
        for (const MotorWiring &m : w) {
            if (m.positive == i + 1)
                uses << tr("motor %1 positive limit").arg(m.motor);
            if (m.negative == i + 1)
                uses << tr("motor %1 negative limit").arg(m.motor);
            if (m.home == i + 1)
                uses << tr("motor %1 home").arg(m.motor);
        }
        m_inputUses.at(i)->setText(uses.isEmpty() ? tr("not used as a limit or home")
                                                  : Translators::joinList(uses));
    }
}

void InputsPage::updateLamps()
{
    const ParameterStore *store = session()->parameters()->store();
    const auto show = [](Led *led, QLabel *name, std::optional<qint64> value) {
        led->setState(lampState(value));
        const QString state = !value ? tr("unknown") : (*value ? tr("on") : tr("off"));
        led->setToolTip(QStringLiteral("%1: %2").arg(name->text(), state));
        led->setAccessibleName(led->toolTip());
    };
    for (int i = 0; i < m_inputLeds.size(); ++i)
        show(m_inputLeds.at(i), m_inputNames.at(i), store->deviceValue(inputKey(i + 1)));
    for (int i = 0; i < m_outputLeds.size(); ++i)
        show(m_outputLeds.at(i), m_outputNames.at(i), store->deviceValue(outputKey(i + 1)));
}

void InputsPage::retranslate()
{
    m_wiringBox->setTitle(tr("Limit and home inputs"));
    m_checkBox->setTitle(tr("Wiring check"));
    m_inputsBox->setTitle(tr("Inputs (live)"));
    m_outputsBox->setTitle(tr("Outputs (live)"));
    const QString heads[] = {tr("Positive limit"), tr("Negative limit"), tr("Home input")};
    for (int c = 0; c < m_columnHeads.size(); ++c)
        m_columnHeads.at(c)->setText(heads[c]);
    for (int n = 1; n <= m_motorLabels.size(); ++n)
        m_motorLabels.at(n - 1)->setText(tr("Motor &%1:").arg(n));
    m_homeNote->setText(
        tr("Homing runs in reverse until the home input is on, so the home input is "
           "usually the negative limit's input. Inputs are on with a 24 V negative "
           "(NPN) signal."));
    const ParameterStore *store = session()->parameters()->store();
    const QString lang = Language::instance().current();
    for (int i = 0; i < m_inputNames.size(); ++i) {
        const Parameter *p = store->map().find(inputKey(i + 1));
        m_inputNames.at(i)->setText(QStringLiteral("IN%1").arg(i + 1));
        m_inputNames.at(i)->setToolTip(
            p ? QStringLiteral("%1 — %2").arg(p->label.text(lang), p->registerName()) : QString());
    }
    for (int i = 0; i < m_outputNames.size(); ++i) {
        const Parameter *p = store->map().find(outputKey(i + 1));
        m_outputNames.at(i)->setText(p ? p->label.text(lang) : tr("Output %1").arg(i + 1));
        m_outputNames.at(i)->setToolTip(p ? p->registerName() : QString());
    }
    updateWiring();
    updateLamps();
}

} // namespace stepcom

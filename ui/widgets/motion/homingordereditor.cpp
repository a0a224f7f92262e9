#include "widgets/motion/homingordereditor.h"

#include "base/language.h"
#include "device/parameterstore.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>

namespace stepcom {

namespace {

const char *const kKeys[HomingOrderEditor::kSlots] = {"homing.first", "homing.second"};

} // namespace

HomingOrderEditor::HomingOrderEditor(ParameterStore *store, QWidget *parent)
    : QWidget(parent)
    , m_store(store)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    for (int slot = 0; slot < kSlots; ++slot) {
        m_params[slot] = store->map().find(QLatin1String(kKeys[slot]));
        m_labels[slot] = new QLabel(this);
        m_combos[slot] = new QComboBox(this);
        m_states[slot] = new QLabel(this);
        m_states[slot]->setMinimumWidth(
            m_states[slot]->fontMetrics().horizontalAdvance(QStringLiteral("●●")));
        m_states[slot]->setAlignment(Qt::AlignCenter);
        m_labels[slot]->setBuddy(m_combos[slot]);
        grid->addWidget(m_labels[slot], slot, 0);
        grid->addWidget(m_combos[slot], slot, 1);
        grid->addWidget(m_states[slot], slot, 2);
        if (const Parameter *p = m_params[slot]) {
            for (const EnumValue &v : p->values)
                m_combos[slot]->addItem(QString(), QVariant::fromValue(v.value));
        }
        m_combos[slot]->setEnabled(m_params[slot] != nullptr);
        connect(m_combos[slot], &QComboBox::activated, this, [this, slot](int index) {
            if (index >= 0)
                choose(slot, m_combos[slot]->itemData(index).toLongLong());
        });
    }
    grid->setColumnStretch(1, 1);
    connect(store, &ParameterStore::valueChanged, this, [this](const QString &k) {
        if (k == key(0) || k == key(1))
            refresh();
    });
    retranslate();
}

QString HomingOrderEditor::key(int slot) const
{
    return m_params.at(slot) ? m_params.at(slot)->key : QString();
}

bool HomingOrderEditor::choose(int slot, qint64 value)
{
    if (!m_params.at(slot))
        return false;
    const int other = 1 - slot;
    const std::optional<qint64> otherValue = m_store->shownValue(key(other));
    if (value != 0 && otherValue == value) {
        const QString why = tr("%1 is already the %2 in the homing order: a motor homes once. "
                               "Set the %2 to %3 first.")
                                .arg(valueText(slot, value), slotName(other), valueText(other, 0));
        refresh(); // the choice shows what the store holds, not the refused value
        Q_EMIT rejected(why);
        return false;
    }
    const QString error = m_store->edit(key(slot), value);
    refresh();
    if (!error.isEmpty()) {
        Q_EMIT rejected(error);
        return false;
    }
    return true;
}

QList<ParameterWrite> HomingOrderEditor::pendingWrites() const
{
    QList<ParameterWrite> writes;
    for (int slot = 0; slot < kSlots; ++slot) {
        if (!m_params.at(slot))
            continue;
        if (const auto edited = m_store->entry(key(slot)).edited)
            writes.append({m_params.at(slot), *edited});
    }
    return writes;
}

bool HomingOrderEditor::isEdited() const
{
    return !pendingWrites().isEmpty();
}

bool HomingOrderEditor::isKnown() const
{
    return isValid() && m_store->deviceValue(key(0)) && m_store->deviceValue(key(1));
}

QString HomingOrderEditor::deviceOrderText() const
{
    if (!isKnown())
        return {};
    QStringList motors;
    for (int slot = 0; slot < kSlots; ++slot) {
        const qint64 v = *m_store->deviceValue(key(slot));
        if (v != 0 && !(slot == 1 && v == *m_store->deviceValue(key(0))))
            motors << valueText(slot, v);
    }
    if (motors.isEmpty())
        return tr("no motor");
    return motors.size() == 1 ? motors.first() : tr("%1, then %2").arg(motors.at(0), motors.at(1));
}

QString HomingOrderEditor::slotName(int slot) const
{
    return slot == 0 ? tr("1st") : tr("2nd");
}

QString HomingOrderEditor::valueText(int slot, qint64 value) const
{
    const Parameter *p = m_params.at(slot);
    return p ? p->displayRaw(value, Language::instance().current()) : QString::number(value);
}

void HomingOrderEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void HomingOrderEditor::retranslate()
{
    const QString lang = Language::instance().current();
    for (int slot = 0; slot < kSlots; ++slot) {
        const Parameter *p = m_params.at(slot);
        if (!p)
            continue;
        m_labels[slot]->setText(slot == 0 ? tr("1st to home:") : tr("2nd to home:"));
        for (int i = 0; i < p->values.size(); ++i)
            m_combos[slot]->setItemText(i, p->values.at(i).label.text(lang));
        m_combos[slot]->setToolTip(QStringLiteral("<b>%1</b> — %2<br>%3")
                                       .arg(p->label.text(lang).toHtmlEscaped(), p->registerName(),
                                            p->help.text(lang).toHtmlEscaped()));
        m_combos[slot]->setAccessibleName(p->label.text(lang));
    }
    refresh();
}

void HomingOrderEditor::refresh()
{
    for (int slot = 0; slot < kSlots; ++slot) {
        if (!m_params.at(slot))
            continue;
        const ParameterStore::Entry e = m_store->entry(key(slot));
        const std::optional<qint64> shown = m_store->shownValue(key(slot));
        m_combos[slot]->setCurrentIndex(
            shown ? m_combos[slot]->findData(QVariant::fromValue(*shown)) : -1);
        QString mark;
        QString tip;
        switch (e.state) {
        case ParameterStore::State::Unknown:
            mark = QStringLiteral("?");
            tip = tr("Not read from the controller yet");
            break;
        case ParameterStore::State::InSync:
            mark = QStringLiteral("✓");
            tip = tr("The controller holds this order");
            break;
        case ParameterStore::State::Edited:
            mark = QStringLiteral("●");
            tip = tr("Edited, not written yet: apply the order");
            break;
        case ParameterStore::State::WriteFailed:
            mark = QStringLiteral("✗");
            tip = tr("Write failed: %1").arg(e.error);
            break;
        case ParameterStore::State::Unsupported:
            mark = QStringLiteral("—");
            tip = tr("Not supported by this controller");
            break;
        }
        m_states[slot]->setText(mark);
        m_states[slot]->setToolTip(tip);
    }
}

} // namespace stepcom

#include "widgets/fields/parameterform.h"

#include "base/language.h"
#include "device/parameterstore.h"
#include "widgets/fields/parameterfield.h"

#include <QEvent>
#include <QFormLayout>
#include <QLabel>

namespace stepcom {

ParameterForm::ParameterForm(ParameterStore *store, QWidget *parent)
    : QWidget(parent)
    , m_store(store)
    , m_layout(new QFormLayout(this))
{
    m_layout->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_layout->setLabelAlignment(Qt::AlignRight | Qt::AlignVCenter);
}

ParameterField *ParameterForm::addParameter(const QString &key)
{
    const Parameter *p = m_store->map().find(key);
    if (!p)
        return nullptr;
    auto *field = new ParameterField(m_store, *p, this);
    auto *label = new QLabel(this);
    label->setBuddy(field->editor());
    label->setProperty("parameterKey", key);
    connect(field, &ParameterField::rejected, this, &ParameterForm::rejected);
    m_layout->addRow(label, field);
    m_fields << field;
    m_labels << label;
    retranslate();
    return field;
}

void ParameterForm::addRow(QLabel *label, QWidget *widget)
{
    m_layout->addRow(label, widget);
}

ParameterField *ParameterForm::field(const QString &key) const
{
    for (ParameterField *f : m_fields) {
        if (f->parameter().key == key)
            return f;
    }
    return nullptr;
}

QStringList ParameterForm::keys() const
{
    QStringList out;
    for (ParameterField *f : m_fields)
        out << f->parameter().key;
    return out;
}

void ParameterForm::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ParameterForm::retranslate()
{
    const QString lang = Language::instance().current();
    for (int i = 0; i < m_fields.size(); ++i) {
        const Parameter &p = m_fields.at(i)->parameter();
        m_labels.at(i)->setText(p.label.text(lang) + QLatin1Char(':'));
        m_labels.at(i)->setToolTip(QStringLiteral("%1 · %2").arg(p.registerName(), p.key));
        // Help → What's this (Shift+F1), then a click on the label or the field: the map's help.
        const QString whatsThis =
            QStringLiteral("<p><b>%1</b> — %2</p><p>%3</p><p><small>%4 · %5</small></p>")
                .arg(p.label.text(lang).toHtmlEscaped(), p.registerName(),
                     p.help.text(lang).toHtmlEscaped(), p.key, p.rangeText().toHtmlEscaped());
        m_labels.at(i)->setWhatsThis(whatsThis);
        m_fields.at(i)->setWhatsThis(whatsThis);
    }
}

} // namespace stepcom

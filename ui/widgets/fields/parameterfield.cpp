#include "widgets/fields/parameterfield.h"

#include "base/language.h"
#include "device/parameterstore.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace stepcom {

namespace {

QColor blend(const QColor &base, const QColor &tint, double amount)
{
    return QColor::fromRgbF(float(base.redF() * (1 - amount) + tint.redF() * amount),
                            float(base.greenF() * (1 - amount) + tint.greenF() * amount),
                            float(base.blueF() * (1 - amount) + tint.blueF() * amount));
}

} // namespace

ParameterField::ParameterField(ParameterStore *store, const Parameter &parameter, QWidget *parent)
    : QWidget(parent)
    , m_store(store)
    , m_parameter(parameter)
{
    auto *column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    auto *layout = new QHBoxLayout;
    column->addLayout(layout);
    m_reason = new QLabel(this);
    m_reason->setWordWrap(true);
    m_reason->setObjectName(QStringLiteral("rejection"));
    m_reason->hide();
    column->addWidget(m_reason);
    if (!parameter.values.isEmpty()) {
        m_combo = new QComboBox(this);
        for (const EnumValue &v : parameter.values)
            m_combo->addItem(QString(), QVariant::fromValue(v.value));
        connect(m_combo, &QComboBox::activated, this, &ParameterField::commitIndex);
        layout->addWidget(m_combo, 1);
    } else {
        m_line = new QLineEdit(this);
        m_line->setAlignment(Qt::AlignRight);
        m_line->setPlaceholderText(QStringLiteral("—"));
        // Wide enough for the largest value the parameter can hold, at any font size.
        const QString widest = parameter.formatRaw(parameter.rawMin).size() >
                                       parameter.formatRaw(parameter.rawMax).size()
                                   ? parameter.formatRaw(parameter.rawMin)
                                   : parameter.formatRaw(parameter.rawMax);
        m_line->setMinimumWidth(
            m_line->fontMetrics().horizontalAdvance(widest + QStringLiteral("00")));
        connect(m_line, &QLineEdit::editingFinished, this, &ParameterField::commitText);
        connect(m_line, &QLineEdit::textEdited, this, &ParameterField::typing);
        connect(m_line, &QLineEdit::textEdited, this, [this](const QString &text) {
            // The red goes as soon as what is typed is allowed, or back to the held value.
            if (m_problem == ValueCheck::Problem::None)
                return;
            const auto shown = m_store->shownValue(m_parameter.key);
            if (ValueCheck::check(m_parameter, text, nullptr) ||
                (shown && text == m_parameter.formatRaw(*shown)))
                clearRejection();
        });
        layout->addWidget(m_line, 1);
        m_unit = new QLabel(parameter.unit, this);
        m_unit->setMinimumWidth(m_unit->fontMetrics().horizontalAdvance(QStringLiteral("rpm__")));
        layout->addWidget(m_unit);
    }
    editor()->setEnabled(parameter.writable());
    m_state = new QLabel(this);
    m_state->setMinimumWidth(m_state->fontMetrics().horizontalAdvance(QStringLiteral("●●")));
    m_state->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_state);
    setFocusProxy(editor());
    connect(m_store, &ParameterStore::valueChanged, this, [this](const QString &key) {
        if (key != m_parameter.key)
            return;
        // A verified write, a read, an apply or a lost link: the refused text is stale now.
        if (m_problem != ValueCheck::Problem::None) {
            clearRejection();
            if (m_line)
                m_line->setModified(false);
        }
        refresh();
    });
    connect(m_store, &ParameterStore::reverted, this, [this] {
        if (m_problem == ValueCheck::Problem::None)
            return;
        clearRejection();
        if (m_line)
            m_line->setModified(false);
        refresh();
    });
    retranslate();
}

QWidget *ParameterField::editor() const
{
    return m_combo ? static_cast<QWidget *>(m_combo) : static_cast<QWidget *>(m_line);
}

void ParameterField::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    else if (event->type() == QEvent::PaletteChange)
        applyStateLook();
    QWidget::changeEvent(event);
}

void ParameterField::retranslate()
{
    const QString lang = Language::instance().current();
    if (m_combo) {
        for (int i = 0; i < m_parameter.values.size(); ++i)
            m_combo->setItemText(i, m_parameter.values.at(i).label.text(lang));
    }
    refresh();
}

void ParameterField::refresh()
{
    const std::optional<qint64> shown = m_store->shownValue(m_parameter.key);
    if (m_combo) {
        int index = -1;
        if (shown)
            index = m_combo->findData(QVariant::fromValue(*shown));
        m_combo->setCurrentIndex(index);
    } else if (m_problem == ValueCheck::Problem::None &&
               (!m_line->hasFocus() || !m_line->isModified())) {
        m_line->setText(shown ? m_parameter.formatRaw(*shown) : QString());
        m_line->setModified(false);
    }
    applyStateLook();
}

void ParameterField::enterText(const QString &text)
{
    if (m_combo) {
        const auto raw = m_parameter.parse(text, nullptr);
        const int index = raw ? m_combo->findData(QVariant::fromValue(*raw)) : -1;
        if (index < 0) {
            reject(ValueCheck::Problem::NotAChoice, text);
            return;
        }
        m_combo->setCurrentIndex(index);
        commitIndex(index);
        return;
    }
    m_line->setText(text);
    m_line->setModified(true);
    commitText();
}

std::optional<qint64> ParameterField::typedRaw() const
{
    if (isTyping()) {
        if (const auto raw = m_parameter.parse(m_line->text(), nullptr))
            return raw;
    }
    return m_store->shownValue(m_parameter.key);
}

bool ParameterField::isTyping() const
{
    return m_line && m_line->isModified();
}

void ParameterField::commitText()
{
    if (!m_line->isModified())
        return;
    ValueCheck::Problem problem = ValueCheck::Problem::None;
    const QString typed = m_line->text();
    const auto raw = ValueCheck::check(m_parameter, typed, &problem);
    if (!raw) {
        reject(problem, typed); // the typed text stays for correction
        return;
    }
    m_line->setModified(false);
    clearRejection();
    if (const QString error = m_store->edit(m_parameter.key, *raw); !error.isEmpty())
        reject(ValueCheck::Problem::OutOfRange, typed);
    refresh();
}

void ParameterField::commitIndex(int index)
{
    if (index < 0)
        return;
    clearRejection();
    if (!m_store->edit(m_parameter.key, m_combo->itemData(index).toLongLong()).isEmpty())
        reject(ValueCheck::Problem::NotAChoice, m_combo->itemText(index));
    refresh();
}

QString ParameterField::rejectionText() const
{
    return ValueCheck::text(m_parameter, m_problem, m_rejected);
}

void ParameterField::reject(ValueCheck::Problem problem, const QString &typed)
{
    m_problem = problem;
    m_rejected = typed;
    Q_EMIT rejected(rejectionText());
    applyStateLook();
}

void ParameterField::clearRejection()
{
    if (m_problem == ValueCheck::Problem::None)
        return;
    m_problem = ValueCheck::Problem::None;
    m_rejected.clear();
    applyStateLook();
}

void ParameterField::applyStateLook()
{
    const ParameterStore::Entry e = m_store->entry(m_parameter.key);
    const QString lang = Language::instance().current();
    // A register this controller lacks cannot be edited: nothing could ever be written to it.
    editor()->setEnabled(m_parameter.writable() && !e.unsupported);
    QString stateText;
    QString stateTip;
    QColor tint;
    switch (e.state) {
    case ParameterStore::State::Unknown:
        stateText = QStringLiteral("?");
        stateTip = tr("Not read from the controller yet");
        break;
    case ParameterStore::State::InSync:
        stateText = QStringLiteral("✓");
        stateTip = tr("The controller holds this value");
        break;
    case ParameterStore::State::Edited:
        stateText = QStringLiteral("●");
        tint = QColor(255, 170, 0);
        stateTip = e.device ? tr("Edited, not written yet (the controller holds %1)")
                                  .arg(m_parameter.displayRaw(*e.device, lang))
                            : tr("Edited, not written yet");
        break;
    case ParameterStore::State::WriteFailed:
        stateText = QStringLiteral("✗");
        tint = QColor(230, 40, 40);
        stateTip = tr("Write failed: %1").arg(e.error);
        break;
    case ParameterStore::State::Unsupported:
        stateText = QStringLiteral("—");
        tint = QColor(160, 160, 160);
        stateTip = tr("Not supported by this controller: it refuses to read this register");
        break;
    }
    // Editing a profile file: the values are the file's, nothing reaches a controller.
    if (m_store->isFile() && e.state != ParameterStore::State::WriteFailed)
        stateTip =
            e.state == ParameterStore::State::Unknown  ? tr("The profile file lacks this value")
            : e.state == ParameterStore::State::InSync ? tr("The profile file holds this value")
            : e.device ? tr("Edited, not saved yet (the file holds %1)")
                             .arg(m_parameter.displayRaw(*e.device, lang))
                       : tr("Edited, not saved yet");
    const QString rejection = rejectionText();
    if (!rejection.isEmpty()) {
        tint = QColor(230, 40, 40);
        stateTip = rejection;
        stateText = QStringLiteral("✗");
    }
    m_reason->setText(rejection);
    m_reason->setVisible(!rejection.isEmpty());
    QPalette reasonPalette = m_reason->palette();
    reasonPalette.setColor(QPalette::WindowText, QColor(200, 30, 30));
    m_reason->setPalette(reasonPalette);
    m_state->setText(stateText);
    m_state->setToolTip(stateTip);
    QPalette pal = editor()->parentWidget()->palette();
    if (tint.isValid()) {
        pal.setColor(QPalette::Base, blend(pal.color(QPalette::Base), tint, 0.35));
        pal.setColor(QPalette::Button, blend(pal.color(QPalette::Button), tint, 0.35));
    }
    editor()->setPalette(pal);
    QFont font = editor()->font();
    font.setItalic(e.state == ParameterStore::State::Unknown);
    editor()->setFont(font);
    const QString tip =
        QStringLiteral("<b>%1</b> — %2<br>%3<br><small>%4 · %5</small>")
            .arg(m_parameter.label.text(lang).toHtmlEscaped(), m_parameter.registerName(),
                 m_parameter.help.text(lang).toHtmlEscaped(), m_parameter.key,
                 m_parameter.rangeText().toHtmlEscaped());
    editor()->setToolTip(tip + QStringLiteral("<br>") + stateTip.toHtmlEscaped());
    editor()->setAccessibleName(m_parameter.label.text(lang));
}

} // namespace stepcom

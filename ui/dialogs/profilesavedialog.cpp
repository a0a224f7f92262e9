#include "dialogs/profilesavedialog.h"

#include <QDate>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace stepcom {

ProfileSaveDialog::ProfileSaveDialog(bool fromDevice, const QString &suggestedName, QWidget *parent)
    : QDialog(parent)
    , m_fromDevice(fromDevice)
    , m_what(new QLabel(this))
    , m_nameLabel(new QLabel(this))
    , m_notesLabel(new QLabel(this))
    , m_name(new QLineEdit(suggestedName, this))
    , m_notes(new QPlainTextEdit(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("profileSaveDialog"));
    m_name->setObjectName(QStringLiteral("profileName"));
    m_notes->setObjectName(QStringLiteral("profileNotes"));
    m_what->setWordWrap(true);
    m_name->selectAll();
    m_nameLabel->setBuddy(m_name);
    m_notesLabel->setBuddy(m_notes);
    m_notes->setTabChangesFocus(true);
    m_notes->setMinimumHeight(fontMetrics().height() * 4);
    auto *form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->addRow(m_nameLabel, m_name);
    form->addRow(m_notesLabel, m_notes);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_what);
    layout->addLayout(form, 1);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // A profile without a name cannot be told apart in the recent list or the report.
    connect(m_name, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_buttons->button(QDialogButtonBox::Save)->setEnabled(!text.trimmed().isEmpty());
    });
    m_buttons->button(QDialogButtonBox::Save)->setEnabled(!name().isEmpty());
    resize(fontMetrics().averageCharWidth() * 60, sizeHint().height());
    retranslate();
}

QString ProfileSaveDialog::name() const
{
    return m_name->text().trimmed();
}

QString ProfileSaveDialog::notes() const
{
    return m_notes->toPlainText().trimmed();
}

QString ProfileSaveDialog::suggestName(const QString &machine, int deviceId, const QDate &date)
{
    static const QRegularExpression trailingDate(QStringLiteral("[\\s_-]*\\d{4}-\\d{2}-\\d{2}$"));
    QString base = machine.trimmed();
    base.remove(trailingDate);
    if (base.isEmpty())
        base = deviceId > 0 ? tr("Controller id %1").arg(deviceId) : tr("Profile");
    return QStringLiteral("%1 %2").arg(base, date.toString(Qt::ISODate));
}

QString ProfileSaveDialog::fileNameFor(const QString &name)
{
    static const QRegularExpression unsafe(QStringLiteral("[/\\\\:*?\"<>|\\x00-\\x1f]+"));
    QString file = name.trimmed();
    file.replace(unsafe, QStringLiteral("-"));
    if (file.isEmpty() || file.startsWith(QLatin1Char('.')))
        file.prepend(QStringLiteral("profile"));
    return file + QStringLiteral(".json");
}

void ProfileSaveDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ProfileSaveDialog::retranslate()
{
    setWindowTitle(tr("Save profile"));
    m_what->setText(m_fromDevice ? tr("Every parameter is read from the controller, then saved "
                                      "with this name and notes.")
                                 : tr("The values the pages show (edits included) are saved "
                                      "with this name and notes."));
    m_nameLabel->setText(tr("&Name:"));
    m_notesLabel->setText(tr("N&otes:"));
    m_notes->setPlaceholderText(tr("Machine, place, who set it up, what was changed"));
}

} // namespace stepcom

#include "dialogs/supportbundledialog.h"

#include "support/supportbundle.h"

#include <QCheckBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace stepcom {

SupportBundleDialog::SupportBundleDialog(const QString &profilePath, QWidget *parent)
    : QDialog(parent)
    , m_profilePath(profilePath)
    , m_logDirectory(SupportBundle::defaultLogDirectory())
    , m_days(new QSpinBox(this))
    , m_logs(new QLabel(this))
    , m_profile(new QCheckBox(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this))
{
    setObjectName(QStringLiteral("supportBundleDialog"));
    setWindowTitle(tr("Create support bundle"));
    auto *intro = new QLabel(
        tr("One .zip file to send to support: the session logs (every frame of every "
           "connection), the profile and its checklist, StepCom's settings (there are no "
           "passwords in them), the versions of StepCom, Qt and the system, and the serial "
           "adapters seen. A README inside lists it all."),
        this);
    intro->setWordWrap(true);
    m_days->setObjectName(QStringLiteral("bundleDays"));
    m_days->setRange(1, 365);
    m_days->setValue(7);
    m_logs->setObjectName(QStringLiteral("bundleLogs"));
    m_profile->setObjectName(QStringLiteral("bundleProfile"));
    const bool haveProfile = !profilePath.isEmpty() && QFileInfo::exists(profilePath);
    m_profile->setText(
        haveProfile
            ? tr("The profile %1 and its checklist").arg(QDir::toNativeSeparators(profilePath))
            : tr("No profile is open"));
    m_profile->setEnabled(haveProfile);
    m_profile->setChecked(haveProfile);
    m_buttons->button(QDialogButtonBox::Save)->setText(tr("&Save bundle…"));
    auto *form = new QFormLayout;
    form->addRow(tr("Session logs of the last days:"), m_days);
    form->addRow(QString(), m_logs);
    form->addRow(tr("Profile:"), m_profile);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_buttons);
    connect(m_days, &QSpinBox::valueChanged, this, &SupportBundleDialog::refresh);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &SupportBundleDialog::chooseFile);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    refresh();
}

void SupportBundleDialog::setLogDirectory(const QString &directory)
{
    m_logDirectory = directory;
    refresh();
}

void SupportBundleDialog::setDays(int days)
{
    m_days->setValue(days);
}

int SupportBundleDialog::days() const
{
    return m_days->value();
}

void SupportBundleDialog::setProfileIncluded(bool included)
{
    m_profile->setChecked(included && m_profile->isEnabled());
}

BundleInput SupportBundleDialog::input() const
{
    BundleInput in;
    in.logDirectory = m_logDirectory;
    in.days = m_days->value();
    in.profilePath = m_profile->isChecked() ? m_profilePath : QString();
    in.settingsFiles = SupportBundle::defaultSettingsFiles();
    return in;
}

QString SupportBundleDialog::logsText() const
{
    qint64 bytes = 0;
    const QFileInfoList logs = SupportBundle::logsFor(input());
    for (const QFileInfo &log : logs)
        bytes += log.size();
    return tr("%n session log(s), %1", nullptr, int(logs.size()))
        .arg(QLocale().formattedDataSize(bytes));
}

void SupportBundleDialog::refresh()
{
    m_logs->setText(logsText());
}

void SupportBundleDialog::chooseFile()
{
    const QString name =
        QStringLiteral("stepcom-support-%1.zip")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")));
    auto *dialog = new QFileDialog(this, tr("Save support bundle"), QDir::home().filePath(name),
                                   tr("Zip files (*.zip)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("zip"));
    connect(dialog, &QFileDialog::fileSelected, this, &SupportBundleDialog::createFile);
    dialog->open();
}

bool SupportBundleDialog::createFile(const QString &zipPath)
{
    QStringList contents;
    QString error;
    const bool ok = SupportBundle::create(zipPath, input(), &contents, &error);
    const QString message =
        ok ? tr("Support bundle written: %1 (%2). It holds:")
                     .arg(QDir::toNativeSeparators(zipPath),
                          QLocale().formattedDataSize(QFileInfo(zipPath).size())) +
                 QStringLiteral("\n• ") + contents.join(QStringLiteral("\n• "))
           : tr("The support bundle was not written: %1").arg(error);
    if (m_result)
        m_result->deleteLater();
    m_result = new QMessageBox(ok ? QMessageBox::Information : QMessageBox::Warning,
                               tr("Create support bundle"), message, QMessageBox::Ok,
                               parentWidget() ? parentWidget() : this);
    m_result->setAttribute(Qt::WA_DeleteOnClose);
    m_result->open();
    Q_EMIT written(ok, message);
    if (ok)
        accept();
    return ok;
}

QMessageBox *SupportBundleDialog::resultBox() const
{
    return m_result;
}

} // namespace stepcom

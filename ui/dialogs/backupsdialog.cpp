#include "dialogs/backupsdialog.h"

#include "base/fittoscreen.h"
#include "profile/backupstore.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace stepcom {

BackupsDialog::BackupsDialog(const RegisterMap &map, const QString &directory, QWidget *parent)
    : QDialog(parent)
    , m_map(map)
    , m_dir(directory)
    , m_where(new QLabel(this))
    , m_list(new QTreeWidget(this))
    , m_restore(new QPushButton(this))
    , m_close(new QPushButton(this))
{
    setObjectName(QStringLiteral("backupsDialog"));
    m_where->setWordWrap(true);
    m_where->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_list->setRootIsDecorated(false);
    m_list->setColumnCount(3);
    // The time as wide as it needs; the device (a long /dev/serial/by-id name) and what
    // happened share the rest, cut in the middle where the window is narrow, whole in the
    // tooltip: no sideways scrolling on a small screen.
    m_list->header()->setStretchLastSection(false);
    m_list->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_list->header()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_list->header()->setSectionResizeMode(2, QHeaderView::Stretch);
    m_list->setTextElideMode(Qt::ElideMiddle);
    m_restore->setObjectName(QStringLiteral("restoreButton"));
    m_restore->setAutoDefault(false);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_restore);
    buttons->addWidget(m_close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_where);
    layout->addWidget(m_list, 1);
    layout->addLayout(buttons);
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(m_list, &QTreeWidget::currentItemChanged, this, [this] {
        const QTreeWidgetItem *i = m_list->currentItem();
        m_restore->setEnabled(i && i->data(0, Qt::UserRole + 1).toString().isEmpty());
    });
    connect(m_restore, &QPushButton::clicked, this, [this] {
        if (const QTreeWidgetItem *i = m_list->currentItem())
            Q_EMIT restoreRequested(i->data(0, Qt::UserRole).toString());
    });
    retranslate();
    reload();
    // Room for the time, a /dev/serial/by-id name and what happened, within the screen.
    resize(fitToScreen(this,
                       QSize(fontMetrics().averageCharWidth() * 110, fontMetrics().height() * 24)));
}

void BackupsDialog::reload()
{
    m_list->clear();
    const QLocale locale;
    for (const BackupEntry &e : BackupStore(m_dir).list(m_map)) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setText(0, locale.toString(e.time.toLocalTime(), QLocale::ShortFormat));
        item->setText(1, e.error.isEmpty() ? e.device : QString());
        item->setText(2, e.error.isEmpty() ? BackupStore::operationLabel(e.operation)
                                           : tr("cannot be read: %1").arg(e.error));
        item->setToolTip(1, item->text(1));
        item->setToolTip(2, QStringLiteral("%1\n%2").arg(item->text(2), e.path));
        item->setData(0, Qt::UserRole, e.path);
        item->setData(0, Qt::UserRole + 1, e.error);
    }
    if (m_list->topLevelItemCount() > 0)
        m_list->setCurrentItem(m_list->topLevelItem(0));
    m_restore->setEnabled(m_list->currentItem() &&
                          m_list->currentItem()->data(0, Qt::UserRole + 1).toString().isEmpty());
}

void BackupsDialog::retranslate()
{
    setWindowTitle(tr("Backups"));
    m_where->setText(tr("StepCom saves the controller's settings here before every apply, "
                        "factory reset, save to flash and id or baud change: %1")
                         .arg(m_dir));
    m_list->setHeaderLabels({tr("Time"), tr("Device"), tr("What happened after")});
    m_restore->setText(tr("Restore…"));
    m_restore->setToolTip(tr("Compare the backup with the controller and apply what you check"));
    m_close->setText(tr("Close"));
}

} // namespace stepcom

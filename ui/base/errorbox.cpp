#include "base/errorbox.h"

#include <QMessageBox>

namespace stepcom {

void showErrorBox(QPointer<QMessageBox> &slot, QWidget *parent, const QString &objectName,
                  const QString &title, const QStringList &errors, const QString &informative)
{
    if (slot)
        slot->close();
    slot =
        new QMessageBox(QMessageBox::Warning, title,
                        errors.value(0) + (errors.size() > 1 ? QStringLiteral("\n…") : QString()),
                        QMessageBox::Close, parent);
    slot->setObjectName(objectName);
    slot->setDetailedText(errors.join(QLatin1Char('\n')));
    if (!informative.isEmpty())
        slot->setInformativeText(informative);
    slot->setAttribute(Qt::WA_DeleteOnClose);
    slot->open();
}

} // namespace stepcom

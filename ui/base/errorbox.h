#pragma once

#include <QPointer>
#include <QStringList>

class QMessageBox;
class QWidget;

namespace stepcom {

// What went wrong, said in one warning box that does not block: the first error in the box,
// every error in its details, `informative` under it. The box in `slot` (one a caller keeps
// open at a time) is closed first and replaced.
void showErrorBox(QPointer<QMessageBox> &slot, QWidget *parent, const QString &objectName,
                  const QString &title, const QStringList &errors,
                  const QString &informative = QString());

} // namespace stepcom

#include "testpaths.h"

#include <QDir>

namespace stepcom::test {

QString sourcePath(const QString &relative)
{
    return QDir(QStringLiteral(STEPCOM_SOURCE_DIR)).filePath(relative);
}

QString programPath(const QString &name)
{
    return QDir(QStringLiteral(STEPCOM_BINARY_DIR)).filePath(QStringLiteral("app/") + name);
}

} // namespace stepcom::test

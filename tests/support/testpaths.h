#pragma once

#include <QString>

namespace stepcom::test {

// Absolute path of a file in the source tree ("tests/data/x.json").
QString sourcePath(const QString &relative);
// Absolute path of a built program ("stepcomctl"), next to the test executables' build tree.
QString programPath(const QString &name);

} // namespace stepcom::test

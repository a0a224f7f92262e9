#pragma once

#include "device/writeplanner.h"

#include <QCoreApplication>
#include <QStringList>

namespace stepcom {

class ParameterStore;

// What the pages already know to be wrong with a set of writes, said before they go out: an
// arc or line whose geometry the controller cannot run, limit and home wiring the wiring check
// flags. Judged on what the controller will hold once the writes are done.
class WriteReview
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::WriteReview)
public:
    static QStringList problems(const ParameterStore &store, const QList<ParameterWrite> &writes);
};

} // namespace stepcom

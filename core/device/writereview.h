#pragma once

#include "device/writeplanner.h"

#include <QCoreApplication>
#include <QStringList>

#include <functional>
#include <optional>

namespace stepcom {

class ParameterStore;
class RegisterMap;

// The one review of a set of writes, said before they go out, for every front-end: an arc or
// line whose geometry the controller cannot run, limit and home wiring the wiring check flags,
// a change of the system mode (it changes what the inputs do, at once; modes 2-5 ignore the
// limit settings). Judged on what the controller will hold once the writes are done. The
// window shows these in its write dialog; stepcomctl prints them and writes only with --yes.
class WriteReview
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::WriteReview)
public:
    // What the controller holds, by key (nullopt: not known).
    using Held = std::function<std::optional<qint64>(const QString &key)>;

    static QStringList problems(const ParameterStore &store, const QList<ParameterWrite> &writes);
    static QStringList problems(const RegisterMap &map, const Held &held,
                                const QList<ParameterWrite> &writes);
    // The registers besides the written ones that problems() judges `writes` with: what a
    // front-end without a full store reads first.
    static QStringList keysRead(const RegisterMap &map, const QList<ParameterWrite> &writes);
    // The system modes that ignore the limit settings (the manual's modes 2-5).
    static bool modeIgnoresLimits(qint64 mode) { return mode >= 2 && mode <= 5; }
};

} // namespace stepcom

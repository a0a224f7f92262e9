#pragma once

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace stepcom {

// A list of device ids as people type it: "1,2,3", "1-3", "1,4-6" (1-255, in the order given).
class IdList
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::IdList)
public:
    // The ids in order; nullopt and a reason naming the bad part. Repeats are refused unless
    // `allowRepeats` (the simulator's collision mode).
    static std::optional<QList<int>> parse(const QString &text, QString *error,
                                           bool allowRepeats = false);
    static QString format(const QList<int> &ids);
};

} // namespace stepcom

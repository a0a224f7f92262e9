#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>

namespace stepcom {

class RegisterMap;

// What "did the axis move toward + ?" asks for, per the register map.
struct DirectionAnswer
{
    QString key;              // motor1.direction
    std::optional<qint64> to; // the new value on "No"; nullopt on "Yes" or when there is none
    QString error;            // why no value can be proposed
};

// The direction step: a small step forward; on "No" the direction register is flipped to the
// map's other allowed value (0 forward ↔ 1 reverse). Pure. On this controller the register
// sets the direction of a single move (40005/40015); forward and reverse jogs are fixed.
class DirectionCheck
{
    Q_DECLARE_TR_FUNCTIONS(stepcom::DirectionCheck)
public:
    static DirectionAnswer answer(const RegisterMap &map, int motor, qint64 current,
                                  bool movedTowardPlus);
};

} // namespace stepcom

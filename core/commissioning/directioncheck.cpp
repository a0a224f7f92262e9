#include "commissioning/directioncheck.h"

#include "map/registermap.h"

namespace stepcom {

DirectionAnswer DirectionCheck::answer(const RegisterMap &map, int motor, qint64 current,
                                       bool movedTowardPlus)
{
    DirectionAnswer a;
    const Parameter *p =
        map.blockParameter(QStringLiteral("motor"), motor, QStringLiteral("direction"));
    if (!p) {
        a.error = tr("motor %1 has no direction register in this register map").arg(motor);
        return a;
    }
    a.key = p->key;
    if (const QString why = p->checkRaw(current); !why.isEmpty()) {
        a.error = why;
        return a;
    }
    if (movedTowardPlus)
        return a;
    // Exactly two allowed values: the other one. Anything else has no single "flip".
    if (p->values.size() != 2) {
        a.error = tr("%1 does not have exactly two values: StepCom cannot flip it").arg(p->key);
        return a;
    }
    a.to = p->values.at(0).value == current ? p->values.at(1).value : p->values.at(0).value;
    return a;
}

} // namespace stepcom

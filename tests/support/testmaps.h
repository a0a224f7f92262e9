#pragma once

#include "map/registermap.h"

#include <optional>

namespace stepcom::test {

// The built-in map with its motor block repeated `count` times: a larger model of the family
// is a change of data only, and tests prove it with this. Errors name what went wrong.
std::optional<RegisterMap> builtinMapWithMotors(int count, QStringList *errors);

} // namespace stepcom::test

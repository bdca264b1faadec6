// RADIANCE's rule for which definition a modifier name stands for (common/modobject.c
// insertobject, eqobjects, lastmod): the latest definition, except that a redefinition
// equal to the one the name stands for (same type, arguments within FTINY, equal
// modifiers down the chain) leaves the name with the earlier one. Renderers see no
// difference; the object numbers in a frozen octree do, so oconv follows it.
#pragma once

#include <string>
#include <unordered_map>

#include "scene/primitive.h"

namespace rp {

// True if records a and b of `prims` are equal as RADIANCE's eqobjects() decides.
// `table` maps names to the definitions they stand for (RADIANCE's modifier table), used
// for modifiers named in string arguments (alias, illum, mirror, mixtures, antimatter).
bool radianceEqualObjects(const std::vector<Primitive>& prims,
                          const std::unordered_map<std::string, int32_t>& table, int32_t a,
                          int32_t b);

}  // namespace rp

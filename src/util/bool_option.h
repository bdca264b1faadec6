// RADIANCE's boolean option suffixes (check_bool), shared by every tool's option parser.
#pragma once

#include <cstddef>
#include <string>

namespace rp {

// The value of boolean option `opt` whose name is its first `len` characters (e.g. "-bv"
// in "-bv+"): no suffix toggles `current`; + y Y t T 1 set; - n N f F 0 clear. Anything
// else throws InputError("unknown option '...'").
bool boolSuffix(const std::string& opt, size_t len, bool current);

}  // namespace rp

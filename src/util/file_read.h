// Reading an input file whole (or its first bytes), with the one-line error every reader
// gives for a file it cannot open.
#pragma once

#include <cstddef>
#include <string>

namespace rp {

// The file's bytes, or at most `limit` of them (all when 0). InputError
// "<path>: cannot open file (<reason>)" when it cannot be opened.
std::string readFileBytes(const std::string& path, size_t limit = 0);

}  // namespace rp

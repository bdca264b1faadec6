// cnt, RADIANCE's index counter (cnt(1)): "cnt 3 5" writes the 15 lines 0 0 .. 2 4, the
// last counter turning fastest, for rcalc to make arrays from.
#pragma once

#include <ostream>
#include <span>

namespace rp::data {

// Writes every combination of 0 <= i_k < counts[k], one line each, every value preceded
// by a tab (RADIANCE cnt.c prints its buffer "\t0\t1"). RADIANCE compat: a zero count
// ends the list (cnt 2 0 3 is cnt 2; no counts at all give one empty line), and a
// negative count before it gives no lines.
void writeCounts(std::span<const int> counts, std::ostream& out);

}  // namespace rp::data

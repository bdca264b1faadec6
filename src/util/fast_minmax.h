// std::fmin / std::fmax without the libm call they compile to at -O2 (a visible cost per
// photon and per ray in hit completion, emission and the intersect callbacks). The same
// result for every input, NaN included (the other argument is returned), except that a
// tie between +0 and -0 may return either; callers compare distances or magnitudes, where
// that tie does not arise.
#pragma once

namespace rp {

inline double fastMin(double a, double b) { return a < b ? a : (b != b ? a : b); }
inline double fastMax(double a, double b) { return a > b ? a : (b != b ? a : b); }

}  // namespace rp

// std::fmin / std::fmax without the libm call they compile to at -O2 (a visible cost per
// photon and per ray in hit completion, emission and the intersect callbacks). The same
// result for every input, NaN included (the other argument is returned), except that a
// tie between +0 and -0 may return either; callers compare distances or magnitudes, where
// that tie does not arise.
//
// Branch-free on x86-64 (SSE2 min/max plus a NaN mask): GCC compiles the plain ternary
// form to conditional jumps, and the comparisons in maxAbs (which coordinate of a hit
// point is largest) are random, so they mispredicted (bench/README_profile.md).
#pragma once

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rp {

#if defined(__SSE2__)
// minpd/maxpd return their second operand when either is NaN, so (b, a) gives a unless
// b is the smaller/larger; unlessANan then puts b in when a is NaN. Both lanes hold the
// same value (set1: _mm_set_sd's zeroing move is an encoding valgrind cannot run).
inline double unlessANan(__m128d va, __m128d vb, __m128d m) {
    const __m128d aNan = _mm_cmpunord_pd(va, va);
    return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(aNan, vb), _mm_andnot_pd(aNan, m)));
}
inline double fastMin(double a, double b) {
    const __m128d va = _mm_set1_pd(a), vb = _mm_set1_pd(b);
    return unlessANan(va, vb, _mm_min_pd(vb, va));  // b < a ? b : a
}
inline double fastMax(double a, double b) {
    const __m128d va = _mm_set1_pd(a), vb = _mm_set1_pd(b);
    return unlessANan(va, vb, _mm_max_pd(vb, va));  // b > a ? b : a
}
#else
inline double fastMin(double a, double b) { return a < b ? a : (b != b ? a : b); }
inline double fastMax(double a, double b) { return a > b ? a : (b != b ? a : b); }
#endif

}  // namespace rp

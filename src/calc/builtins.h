// The .cal library functions that are built in rather than defined in rayinit.cal:
// calc's math library (sqrt ... rand, erf, erfc) and the renderer's additions (noise3,
// noise3a/b/c with aliases noise3x/y/z, fnoise3, hermite). if, select and arg are
// special forms handled by the compiler, not listed here.
#pragma once

#include <span>
#include <string_view>

namespace rp::calc {

// An argument or select() index: RADIANCE rounds, n = value + .5 truncated. Beyond int's
// range (or NaN) it saturates, to an index every check refuses, instead of converting
// out of range (undefined behaviour, found by fuzz_cal).
inline int roundedIndex(double v) {
    const double r = v + 0.5;
    if (!(r > -2147483648.0)) return -2147483647 - 1;  // NaN too
    if (r >= 2147483647.0) return 2147483647;
    return static_cast<int>(r);
}

struct Builtin {
    std::string_view name;
    int minArgs;
    int maxArgs;
    double (*f1)(double) = nullptr;                     // one-argument math function, or
    double (*fn)(const double* args, int n) = nullptr;  // general form
};

std::span<const Builtin> builtins();
// nullptr when `name` is not a builtin.
const Builtin* findBuiltin(std::string_view name);

// Pseudo-random value in [0,1) that depends only on x: calc's rand(x), RADIANCE's values.
double randOf(double x);

}  // namespace rp::calc

// Built-in library functions. rand and the noise functions give RADIANCE's values (the
// same formula for rand, noise.cpp for the noise family), so that patterns built on them
// match RADIANCE's pictures point for point.
#include "calc/builtins.h"

#include <array>
#include <cmath>

#include "calc/noise.h"

namespace rp::calc {
namespace {

double bRand(const double* a, int) { return randOf(a[0]); }
double bAtan2(const double* a, int) { return std::atan2(a[0], a[1]); }
double bNoise(const double* a, int) { return noise3(a[0], a[1], a[2]); }
double bNoiseX(const double* a, int) { return noise3Partial(a[0], a[1], a[2], 0); }
double bNoiseY(const double* a, int) { return noise3Partial(a[0], a[1], a[2], 1); }
double bNoiseZ(const double* a, int) { return noise3Partial(a[0], a[1], a[2], 2); }
double bFnoise(const double* a, int) { return fnoise3(a[0], a[1], a[2]); }
// hermite(p0, p1, r0, r1, t): cubic with values p0, p1 and slopes r0, r1 at t = 0, 1.
double bHermite(const double* a, int) {
    double t = a[4], t2 = t * t, t3 = t2 * t;
    return a[0] * (2 * t3 - 3 * t2 + 1) + a[1] * (3 * t2 - 2 * t3) + a[2] * (t3 - 2 * t2 + t) +
           a[3] * (t3 - t2);
}

// RADIANCE compat (calfunc.c l_max, l_min): the first argument, then the others from
// the last down, replacing it only when strictly greater (smaller), so NaN in the first
// place survives and NaN elsewhere never wins.
double bMax(const double* a, int n) {
    double m = a[0];
    for (int i = n - 1; i >= 1; --i)
        if (m < a[i]) m = a[i];
    return m;
}
double bMin(const double* a, int n) {
    double m = a[0];
    for (int i = n - 1; i >= 1; --i)
        if (m > a[i]) m = a[i];
    return m;
}

double fSqrt(double x) { return std::sqrt(x); }
double fSin(double x) { return std::sin(x); }
double fCos(double x) { return std::cos(x); }
double fTan(double x) { return std::tan(x); }
double fAsin(double x) { return std::asin(x); }
double fAcos(double x) { return std::acos(x); }
double fAtan(double x) { return std::atan(x); }
double fExp(double x) { return std::exp(x); }
double fLog(double x) { return std::log(x); }
double fLog10(double x) { return std::log10(x); }
double fFloor(double x) { return std::floor(x); }
double fCeil(double x) { return std::ceil(x); }
double fErf(double x) { return std::erf(x); }
double fErfc(double x) { return std::erfc(x); }

const std::array kBuiltins = {
    Builtin{"acos", 1, 1, fAcos},
    Builtin{"asin", 1, 1, fAsin},
    Builtin{"atan", 1, 1, fAtan},
    Builtin{"atan2", 2, 2, nullptr, bAtan2},
    Builtin{"ceil", 1, 1, fCeil},
    Builtin{"cos", 1, 1, fCos},
    Builtin{"erf", 1, 1, fErf},
    Builtin{"erfc", 1, 1, fErfc},
    Builtin{"exp", 1, 1, fExp},
    Builtin{"floor", 1, 1, fFloor},
    Builtin{"log", 1, 1, fLog},
    Builtin{"log10", 1, 1, fLog10},
    Builtin{"rand", 1, 1, nullptr, bRand},
    Builtin{"sin", 1, 1, fSin},
    Builtin{"sqrt", 1, 1, fSqrt},
    Builtin{"tan", 1, 1, fTan},
    Builtin{"noise3", 3, 3, nullptr, bNoise},
    Builtin{"noise3a", 3, 3, nullptr, bNoiseX},
    Builtin{"noise3b", 3, 3, nullptr, bNoiseY},
    Builtin{"noise3c", 3, 3, nullptr, bNoiseZ},
    Builtin{"noise3x", 3, 3, nullptr, bNoiseX},
    Builtin{"noise3y", 3, 3, nullptr, bNoiseY},
    Builtin{"noise3z", 3, 3, nullptr, bNoiseZ},
    Builtin{"fnoise3", 3, 3, nullptr, bFnoise},
    Builtin{"hermite", 5, 5, nullptr, bHermite},
    Builtin{"max", 1, 255, nullptr, bMax},
    Builtin{"min", 1, 255, nullptr, bMin},
};

}  // namespace

std::span<const Builtin> builtins() { return kBuiltins; }

const Builtin* findBuiltin(std::string_view name) {
    for (const Builtin& b : kBuiltins)
        if (b.name == name) return &b;
    return nullptr;
}

double randOf(double x) {
    // RADIANCE compat: calc's rand is a fixed chaotic map of its argument (calc manual,
    // "rand(x): pseudo-random function between 0 and 1"); the same steps give the same values.
    x *= 1.0 / (1.0 + x * x) + 2.71828182845904;
    x += 0.785398163397447 - std::floor(x);
    x = 1e5 / x;
    return x - std::floor(x);
}

}  // namespace rp::calc

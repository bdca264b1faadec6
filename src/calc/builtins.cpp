// Built-in library functions. Our own implementations: noise3/fnoise3 are Perlin-style
// gradient noise with a quintic fade and rand is a bit hash, so patterns built on them
// have RADIANCE's ranges and smoothness but not its exact values (RADIANCE's noise3.c
// tables are not reproduced).
#include "calc/builtins.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace rp::calc {
namespace {

std::uint64_t mix(std::uint64_t z) {  // splitmix64 finaliser
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// The 12 edge directions of a cube (Perlin 2002), picked by a lattice hash.
constexpr double kGrad[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                 {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                 {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

const double* latticeGradient(std::int64_t i, std::int64_t j, std::int64_t k) {
    std::uint64_t h = mix(static_cast<std::uint64_t>(i) * 0x8da6b343ull ^
                          mix(static_cast<std::uint64_t>(j) * 0xd8163841ull ^
                              mix(static_cast<std::uint64_t>(k) * 0xcb1ab31full)));
    return kGrad[h % 12];
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double fadeDeriv(double t) { return 30 * t * t * (t * (t - 2) + 1); }

double bRand(const double* a, int) { return randOf(a[0]); }
double bAtan2(const double* a, int) { return std::atan2(a[0], a[1]); }
double bNoise(const double* a, int) { return noise3(a[0], a[1], a[2], nullptr); }
double bNoiseA(const double* a, int) {
    double g[3];
    noise3(a[0], a[1], a[2], g);
    return g[0];
}
double bNoiseB(const double* a, int) {
    double g[3];
    noise3(a[0], a[1], a[2], g);
    return g[1];
}
double bNoiseC(const double* a, int) {
    double g[3];
    noise3(a[0], a[1], a[2], g);
    return g[2];
}
double bFnoise(const double* a, int) { return fnoise3(a[0], a[1], a[2]); }
// hermite(p0, p1, r0, r1, t): cubic with values p0, p1 and slopes r0, r1 at t = 0, 1.
double bHermite(const double* a, int) {
    double t = a[4], t2 = t * t, t3 = t2 * t;
    return a[0] * (2 * t3 - 3 * t2 + 1) + a[1] * (3 * t2 - 2 * t3) + a[2] * (t3 - 2 * t2 + t) +
           a[3] * (t3 - t2);
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
    Builtin{"acos", 1, 1, fAcos},       Builtin{"asin", 1, 1, fAsin},
    Builtin{"atan", 1, 1, fAtan},       Builtin{"atan2", 2, 2, nullptr, bAtan2},
    Builtin{"ceil", 1, 1, fCeil},       Builtin{"cos", 1, 1, fCos},
    Builtin{"erf", 1, 1, fErf},         Builtin{"erfc", 1, 1, fErfc},
    Builtin{"exp", 1, 1, fExp},         Builtin{"floor", 1, 1, fFloor},
    Builtin{"log", 1, 1, fLog},         Builtin{"log10", 1, 1, fLog10},
    Builtin{"rand", 1, 1, nullptr, bRand}, Builtin{"sin", 1, 1, fSin},
    Builtin{"sqrt", 1, 1, fSqrt},       Builtin{"tan", 1, 1, fTan},
    Builtin{"noise3", 3, 3, nullptr, bNoise},   Builtin{"noise3a", 3, 3, nullptr, bNoiseA},
    Builtin{"noise3b", 3, 3, nullptr, bNoiseB}, Builtin{"noise3c", 3, 3, nullptr, bNoiseC},
    Builtin{"noise3x", 3, 3, nullptr, bNoiseA}, Builtin{"noise3y", 3, 3, nullptr, bNoiseB},
    Builtin{"noise3z", 3, 3, nullptr, bNoiseC}, Builtin{"fnoise3", 3, 3, nullptr, bFnoise},
    Builtin{"hermite", 5, 5, nullptr, bHermite},
};

}  // namespace

std::span<const Builtin> builtins() { return kBuiltins; }

const Builtin* findBuiltin(std::string_view name) {
    for (const Builtin& b : kBuiltins)
        if (b.name == name) return &b;
    return nullptr;
}

double randOf(double x) {
    std::uint64_t h = mix(std::bit_cast<std::uint64_t>(x + 0.0));  // -0 and +0 agree
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

double noise3(double x, double y, double z, double grad[3]) {
    double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    double u[3] = {x - fx, y - fy, z - fz};
    double w1[3], dw[3];
    for (int d = 0; d < 3; ++d) {
        w1[d] = fade(u[d]);
        dw[d] = fadeDeriv(u[d]);
    }
    auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy),
         iz = static_cast<std::int64_t>(fz);
    double value = 0, g[3] = {0, 0, 0};
    for (int corner = 0; corner < 8; ++corner) {
        int c[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
        const double* gr = latticeGradient(ix + c[0], iy + c[1], iz + c[2]);
        double off[3] = {u[0] - c[0], u[1] - c[1], u[2] - c[2]};
        double dotv = gr[0] * off[0] + gr[1] * off[1] + gr[2] * off[2];
        double w[3], dwd[3];
        for (int d = 0; d < 3; ++d) {
            w[d] = c[d] ? w1[d] : 1 - w1[d];
            dwd[d] = c[d] ? dw[d] : -dw[d];
        }
        double weight = w[0] * w[1] * w[2];
        value += weight * dotv;
        g[0] += dwd[0] * w[1] * w[2] * dotv + weight * gr[0];
        g[1] += w[0] * dwd[1] * w[2] * dotv + weight * gr[1];
        g[2] += w[0] * w[1] * dwd[2] * dotv + weight * gr[2];
    }
    if (grad) {
        grad[0] = g[0];
        grad[1] = g[1];
        grad[2] = g[2];
    }
    return value;
}

double fnoise3(double x, double y, double z) {
    constexpr int kOctaves = 6;
    double sum = 0, amp = 1, total = 0, scale = 1;
    for (int i = 0; i < kOctaves; ++i) {
        sum += amp * noise3(x * scale, y * scale, z * scale, nullptr);
        total += amp;
        amp *= 0.5;
        scale *= 2;
    }
    return sum / total;
}

}  // namespace rp::calc

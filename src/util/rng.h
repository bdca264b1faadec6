// Random number streams. Each stream is a value keyed by (seed, domain, index) so that
// results never depend on which thread draws them: photon i's emission stream is the
// same with -n 1 and -n 16. RADIANCE's lesson (pmaprand.h: one stream per sampling
// domain) is kept; its process-seeded erand48 state is not.
#pragma once

#include <cstdint>

namespace rp {

// Sampling domains: separate streams so that e.g. changing the scattering code does not
// change emission positions.
enum class RngDomain : uint32_t {
    Emission = 1,
    Scattering = 2,
    Roulette = 3,
    Ambient = 4,
    Pixel = 5,
    Sampling = 6,
    Test = 99
};

// SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mixer.
constexpr uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// Murmur3's 64-bit finaliser (Appleby): a second bijective mixer, with constants unlike
// mix64's, for turning (seed, domain, index) into a stream's start.
constexpr uint64_t fmix64(uint64_t z) {
    z = (z ^ (z >> 33)) * 0xff51afd7ed558ccdULL;
    z = (z ^ (z >> 33)) * 0xc4ceb9fe1a85ec53ULL;
    return z ^ (z >> 33);
}

// SplitMix64 (Steele, Lea & Flood 2014; passes BigCrush): the state steps by the golden
// gamma and each output is mix64 of it. Hand-written rather than <random> because std
// engines are either slow (mt19937: 2.5 kB state per stream) or weak (minstd), and we
// create one per work item: mkpmap makes three per photon. Why not xoshiro256+ (used
// before): seeding its 256-bit state took six mixes per stream, a SplitMix stream starts
// with two (bench/README_profile.md). A stream starts at a pseudo-random
// point of the one 2^64 Weyl sequence: two streams of L draws overlap with probability
// about 2L / 2^64 (for a million streams of a thousand draws, ~5e-5 that any pair
// does), and an overlap would only make two work items share some of their draws.
class Rng {
public:
    Rng(uint64_t seed, RngDomain domain, uint64_t index)
        : state_(fmix64(fmix64(seed ^ uint64_t(domain) * 0xd1b54a32d192ed03ULL) ^ index)) {}

    uint64_t next() {
        state_ += 0x9e3779b97f4a7c15ULL;
        return mix64(state_);
    }

    // Uniform in [0, 1) with 53 random bits.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    // Uniform integer in [0, n) (n > 0), Lemire's multiply-shift (bias < n / 2^64).
    uint64_t below(uint64_t n) {
        __extension__ using U128 = unsigned __int128;  // GCC/Clang; -Wpedantic-clean
        return uint64_t(U128(next()) * n >> 64);
    }

private:
    uint64_t state_;
};

// A point uniform in the disc of `radius` about the origin, drawn by rejection from the
// enclosing square (no trigonometry); returns x^2 + y^2. Projected up onto the unit
// hemisphere (z = sqrt(1 - x^2 - y^2)) such points are cosine-distributed directions
// (Malley's method).
inline double uniformDiscPoint(Rng& rng, double radius, double& x, double& y) {
    double r2;
    do {
        x = radius * (2 * rng.uniform() - 1);
        y = radius * (2 * rng.uniform() - 1);
        r2 = x * x + y * y;
    } while (r2 >= radius * radius);
    return r2;
}

}  // namespace rp

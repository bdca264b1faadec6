// Fake HemisphereTracers for the ambient tests: radiance as a function of the sample
// ray, with a call counter. Test code only.
#pragma once

#include <atomic>
#include <functional>

#include "render/ambient.h"

namespace rp::render::testing {

class FunctionTracer : public HemisphereTracer {
public:
    using Fn = std::function<Sample(const Vec3& origin, const Vec3& dir)>;
    explicit FunctionTracer(Fn fn) : fn_(std::move(fn)) {}
    Sample trace(const Vec3& origin, const Vec3& dir, int level, double weight,
                 double /*share*/) override {
        calls.fetch_add(1, std::memory_order_relaxed);
        lastLevel = level;
        lastWeight = weight;
        return fn_(origin, dir);
    }
    std::atomic<long> calls{0};
    std::atomic<int> lastLevel{-1};  // atomics: the tracer is shared by threads
    std::atomic<double> lastWeight{0};

private:
    Fn fn_;
};

// The same radiance from every direction, surfaces at distance `distance`.
inline FunctionTracer::Fn constantRadiance(Color L, double distance = 1) {
    return [L, distance](const Vec3&, const Vec3&) {
        return HemisphereTracer::Sample{L, distance, {}};
    };
}

// An infinite ceiling at height z = h above the origin whose radiance is `lo` where the
// hit point has x < 0 and `hi` where x >= 0 (nothing below the horizon).
inline FunctionTracer::Fn ceilingStep(double h, double lo, double hi) {
    return [=](const Vec3& o, const Vec3& d) {
        if (d.z <= 0) return HemisphereTracer::Sample{Color{}, 1e10, {}};
        double t = (h - o.z) / d.z;
        double x = o.x + t * d.x;
        double L = x < 0 ? lo : hi;
        return HemisphereTracer::Sample{Color::grey(L), t, {}};
    };
}

}  // namespace rp::render::testing

// Sampling a surface's outgoing light for mkillum (see illum_sample.h). Where we differ
// from RADIANCE, and why:
//  - points and directions within a bin are Latin-hypercube strata drawn from our own
//    streams (RADIANCE: its urand table through multisamp): a stream per bin, so the
//    result does not depend on the number of threads;
//  - a flat surface's frame, where no edge is long enough to follow, and the frames of
//    the disks that sphere rays start from, are fixed functions of the normal
//    (RADIANCE mkaxes picks a random perpendicular);
//  - l+ sends one shadow ray to each whole source from each point (RADIANCE: one per
//    -ds subdivision of it); both estimate the same light.
#include "illum/illum_sample.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>

#include "util/rng.h"

namespace rp::illum {

namespace {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

// Latin hypercube strata for `n` samples in `dims` dimensions: sample i draws dimension
// d from stratum perm[d][i] of n, so each dimension is evenly covered.
class Strata {
public:
    Strata(int n, int dims, Rng& rng) : n_(n), perm_(size_t(n) * size_t(dims)) {
        for (int d = 0; d < dims; ++d) {
            int* p = &perm_[size_t(d) * size_t(n)];
            for (int i = 0; i < n; ++i) p[i] = i;
            for (int i = n - 1; i > 0; --i) std::swap(p[i], p[rng.below(uint64_t(i) + 1)]);
        }
    }
    double at(int dim, int i, Rng& rng) const {
        return (perm_[size_t(dim) * size_t(n_) + size_t(i)] + rng.uniform()) / n_;
    }

private:
    int n_;
    std::vector<int> perm_;
};

Distribution emptyDistribution(int altitudes, int azimuths, int samples) {
    Distribution d;
    d.altitudes = altitudes;
    d.azimuths = azimuths;
    d.samples = samples;
    d.sums.assign(size_t(altitudes) * size_t(azimuths), Color{});
    return d;
}

Distribution flatDistribution(const IllumSettings& s) {
    int nalt, nazi;
    flatGrid(s.density, nalt, nazi);
    return emptyDistribution(nalt, nazi, s.samples);
}

// The world direction of a sample ray for bin `bin` of a flat surface: it travels into
// the surface, against the direction in which the light it measures leaves.
Vec3 binRay(const FlatFrame& f, const Distribution& d, int bin, double a, double b) {
    const int alt = bin / d.azimuths;
    const Vec3 out =
        flatDirection((alt + a) / d.altitudes, (bin - alt * d.azimuths + b - .5) / d.azimuths);
    return -(f.u * out.x + f.v * out.y + f.w * out.z);
}

// Traces every bin of `d` in parallel: `ray(rng, strata, i, bin, org, dir)` places
// sample i of the bin and returns false to give up on the surface; the sums are taken in
// sample order, so they do not depend on the threads. Returns false if one gave up.
template <class RayFn>
bool traceBins(Distribution& d, const IllumTracer& tracer, uint64_t base, RayFn ray) {
    std::atomic<bool> gaveUp{false};
    const int bins = int(d.sums.size());
    tbb::parallel_for(tbb::blocked_range<int>(0, bins), [&](const tbb::blocked_range<int>& r) {
        for (int bin = r.begin(); bin != r.end() && !gaveUp.load(); ++bin) {
            Rng rng(tracer.seed(), RngDomain::Pixel, base + uint64_t(bin));
            const Strata strata(d.samples, 4, rng);
            Color sum;
            for (int i = 0; i < d.samples; ++i) {
                Vec3 org, dir;
                if (!ray(rng, strata, i, bin, org, dir)) {
                    gaveUp = true;
                    return;
                }
                sum += tracer.radiance(org, dir, base + uint64_t(bin) * d.samples + i);
            }
            d.sums[size_t(bin)] = sum;
        }
    });
    return !gaveUp.load();
}

// l+ (RADIANCE srcsamps): through each of `points`, from `eps` in front of the surface,
// the sources behind it, each added to the bin of the direction its light leaves in,
// weighted to a radiance: omega cos / (pi / bins), the bin's projected solid angle.
void addSources(const std::vector<Vec3>& points, double eps, const FlatFrame& f, Distribution& d,
                const IllumTracer& tracer, uint64_t base) {
    std::vector<std::vector<std::pair<int, Color>>> found(points.size());
    const double binsPerPi = double(d.sums.size()) / kPi;
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
        tracer.sourceSamples(points[i], eps, base + i, [&](const Vec3& toSource, const Color& c) {
            const Vec3 out{-dot(toSource, f.u), -dot(toSource, f.v), -dot(toSource, f.w)};
            if (out.z <= kFtiny) return;  // in front: not through us
            const int bin = flatIndex(out, d.altitudes, d.azimuths);
            found[i].emplace_back(bin, c * (binsPerPi * out.z));
        });
    });
    for (const auto& list : found)
        for (const auto& [bin, c] : list) d.sums[size_t(bin)] += c;
}

// The frame of a polygon: along its first edge at least sqrt(area) long (RADIANCE
// my_face), which keeps a rectangle's bounding box tight.
FlatFrame faceFrame(const Face& face) {
    const size_t n = face.vertices.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const Vec3 e = face.vertices[i] - face.vertices[j];
        if (lengthSquared(e) >= face.area - kFtiny) {
            FlatFrame f;
            f.w = face.normal;
            f.u = normalize(e);
            f.v = cross(face.normal, f.u);
            return f;
        }
    }
    return frameAbout(face.normal);
}

}  // namespace

std::optional<Distribution> sampleFace(const Face& face, const IllumSettings& s,
                                       const IllumTracer& tracer, uint64_t& nextRay,
                                       FlatFrame& frame) {
    frame = faceFrame(face);
    double u0 = HUGE_VAL, u1 = -HUGE_VAL, v0 = HUGE_VAL, v1 = -HUGE_VAL;
    for (const Vec3& p : face.vertices) {
        u0 = std::fmin(u0, dot(p, frame.u));
        u1 = std::fmax(u1, dot(p, frame.u));
        v0 = std::fmin(v0, dot(p, frame.v));
        v1 = std::fmax(v1, dot(p, frame.v));
    }
    const FlatFrame f = frame;
    auto at = [&](double a, double b) {
        return f.u * (u0 + (u1 - u0) * a) + f.v * (v0 + (v1 - v0) * b) + f.w * face.offset;
    };
    Distribution d = flatDistribution(s);
    const double eps = kOriginEpsilon * std::sqrt(face.area);
    const uint64_t base = nextRay;
    nextRay += d.sums.size() * uint64_t(d.samples) + (s.light ? uint64_t(s.samples) : 0);
    // RADIANCE compat: rejection sampling in the bounding rectangle, with 5 misses per
    // sample allowed over the whole surface before it is given up as too thin.
    const long budget = 5L * long(d.sums.size()) * d.samples;
    std::atomic<long> misses{0};
    auto ray = [&](Rng& rng, const Strata& st, int i, int bin, Vec3& org, Vec3& dir) {
        dir = binRay(f, d, bin, st.at(0, i, rng), st.at(1, i, rng));
        org = at(st.at(2, i, rng), st.at(3, i, rng));
        while (!face.contains(org)) {
            if (misses.fetch_add(1) >= budget) return false;
            org = at(rng.uniform(), rng.uniform());
        }
        org -= dir * eps;
        return true;
    };
    if (!traceBins(d, tracer, base, ray)) return std::nullopt;
    if (!s.light) return d;
    // The points the sources are seen from: 10 misses per point allowed.
    Rng rng(tracer.seed(), RngDomain::Pixel, base + d.sums.size());
    long allowed = 10L * s.samples;
    std::vector<Vec3> points;
    for (int i = 0; i < s.samples; ++i) {
        Vec3 p = at(rng.uniform(), rng.uniform());
        while (!face.contains(p)) {
            if (allowed-- <= 0) return std::nullopt;
            p = at(rng.uniform(), rng.uniform());
        }
        points.push_back(p);
    }
    addSources(points, eps, f, d, tracer, base + d.sums.size() * uint64_t(d.samples));
    return d;
}

Distribution sampleRing(const Ring& ring, const IllumSettings& s, const IllumTracer& tracer,
                        uint64_t& nextRay, FlatFrame& frame) {
    frame = frameAbout(ring.normal);
    const FlatFrame f = frame;
    // A uniform point of the annulus.
    auto at = [&](double a, double b) {
        const double r = std::sqrt(ring.inner * ring.inner +
                                   a * (ring.outer * ring.outer - ring.inner * ring.inner));
        const double phi = 2 * kPi * b;
        return ring.centre + f.u * (r * std::cos(phi)) + f.v * (r * std::sin(phi));
    };
    Distribution d = flatDistribution(s);
    const double eps = kOriginEpsilon * ring.outer;
    const uint64_t base = nextRay;
    nextRay += d.sums.size() * uint64_t(d.samples) + (s.light ? uint64_t(s.samples) : 0);
    auto ray = [&](Rng& rng, const Strata& st, int i, int bin, Vec3& org, Vec3& dir) {
        dir = binRay(f, d, bin, st.at(0, i, rng), st.at(1, i, rng));
        org = at(st.at(2, i, rng), st.at(3, i, rng)) + f.w * eps;
        return true;
    };
    traceBins(d, tracer, base, ray);
    if (!s.light) return d;
    Rng rng(tracer.seed(), RngDomain::Pixel, base + d.sums.size());
    std::vector<Vec3> points;
    for (int i = 0; i < s.samples; ++i) points.push_back(at(rng.uniform(), rng.uniform()));
    addSources(points, eps, f, d, tracer, base + d.sums.size() * uint64_t(d.samples));
    return d;
}

Distribution sampleSphere(const Sphere& sphere, const IllumSettings& s, const IllumTracer& tracer,
                          uint64_t& nextRay) {
    int nalt, nazi;
    roundGrid(s.density, nalt, nazi);
    Distribution d = emptyDistribution(nalt, nazi, s.samples);
    const uint64_t base = nextRay;
    nextRay += d.sums.size() * uint64_t(d.samples);
    // Each ray starts on a disk through the centre facing the direction the light it
    // measures leaves in, 1.01 radii out, and travels back through the sphere.
    auto ray = [&](Rng& rng, const Strata& st, int i, int bin, Vec3& org, Vec3& dir) {
        const int alt = bin / nazi, azi = bin % nazi;
        const Vec3 out =
            roundDirection((alt + st.at(0, i, rng)) / nalt, (azi + st.at(1, i, rng) - .5) / nazi);
        Vec3 e1, e2;
        orthonormalFrame(out, e1, e2);
        const double r = std::sqrt(st.at(2, i, rng));
        const double phi = 2 * kPi * st.at(3, i, rng);
        const double R = sphere.radius;
        org = sphere.centre + e1 * (r * R * std::cos(phi)) + e2 * (r * R * std::sin(phi)) +
              out * (R * std::sqrt(1.01 - r * r));
        dir = -out;
        return true;
    };
    traceBins(d, tracer, base, ray);
    return d;
}

}  // namespace rp::illum

// The direct calculation: candidate samples of every source, RADIANCE's sorted shadow
// test with the -dt threshold and -dc certainty, and shadow paths through transmitting
// surfaces and relaying mirrors (see direct.h). The source list is source_list.h and
// the subdivision source_sampling.h.
#include "render/direct.h"

#include <algorithm>
#include <cmath>

#include "render/source_sampling.h"
#include "util/small_sort.h"

namespace rp::render {

namespace {

// One source sample that may contribute: RADIANCE's CONTRIB record.
struct Candidate {
    int32_t source = -1;  // index into SourceList::sources
    SourceSample sample;  // toward the real source, from the apparent origin
    Vec3 toLight;         // unit direction leaving the shaded point
    Color coef;           // coefficient(toLight, omega) * omega
    Color estimate;       // coef * unoccluded radiance (mirrors included)
    double brt = 0;       // brightness of estimate (sort key)
    uint32_t crossings = 0;  // first index into the mirror crossing points
};

constexpr int kMaxShadowSurfaces = 64;  // transmitting surfaces crossed per leg at most

}  // namespace

struct DirectLighting::Impl {
    const SceneGeometry& geometry;
    DirectOptions options;
    SourceList list;

    // Radiance reaching the shaded point along candidate `c`'s shadow path, zero if
    // blocked. `crossings` are the points where the path meets the mirrors (virtual).
    Color trace(const DirectPoint& at, const Candidate& c, const Vec3* crossings,
                ShadowOracle& oracle) const;
};

DirectLighting::DirectLighting(const Scene& scene, const SceneGeometry& geometry,
                               const DirectOptions& options, bool virtualSources)
    : impl_(std::make_unique<Impl>(
          Impl{geometry, options, buildSourceList(scene, geometry, options, virtualSources)})) {}

DirectLighting::~DirectLighting() = default;

size_t DirectLighting::sourceCount() const { return impl_->list.realCount; }
size_t DirectLighting::virtualSourceCount() const {
    return impl_->list.sources.size() - impl_->list.realCount;
}
const SourceList& DirectLighting::sourceList() const { return impl_->list; }

bool DirectLighting::isSourceSurface(int32_t prim, const Vec3& from) const {
    if (prim < 0 || size_t(prim) >= impl_->list.sourceOfPrim.size()) return false;
    int32_t s = impl_->list.sourceOfPrim[size_t(prim)];
    if (s < 0) return false;
    const DirectSource& src = impl_->list.sources[size_t(s)];
    // A local glow is a source only near it; farther away the ambient calculation sees
    // it (RADIANCE distglow). Distance to the surface's centre stands in for the
    // distance to the surface.
    if (src.proximity > 0) return length(from - src.centre) < src.proximity;
    return true;
}

bool DirectLighting::isDistantSource(int32_t source) const {
    return source >= 0 && size_t(source) < impl_->list.distantInList.size() &&
           impl_->list.distantInList[size_t(source)];
}

Color DirectLighting::Impl::trace(const DirectPoint& at, const Candidate& c,
                                  const Vec3* crossings, ShadowOracle& oracle) const {
    const DirectSource& src = list.sources[size_t(c.source)];
    const size_t legs = src.mirrors.size() + 1;
    Vec3 dir = c.toLight;
    Ray ray = at.hit ? spawnRay(*at.hit, dir) : Ray{at.point, dir, HUGE_VAL};
    // How far spawn offsets may have moved the ray off the straight line to the goal.
    double shift = at.hit ? at.hit->offset : 0;
    Color through{1, 1, 1};
    for (size_t leg = 0; leg < legs; ++leg) {
        const bool last = leg + 1 == legs;
        const bool escape = last && src.distant();
        const Vec3& goal = last ? c.sample.target : crossings[leg];
        bool advanced = false;
        for (int guard = 0; guard < kMaxShadowSurfaces && !advanced; ++guard) {
            double remaining = escape ? HUGE_VAL : length(goal - ray.origin);
            // Slightly past the goal: the source (or mirror) itself is the last thing
            // the ray may reach; what lies behind it must not count. A mirror is reached
            // where the ray meets its plane, wherever offsets moved the origin.
            if (!last) {
                const MirrorPlane& m = list.mirrors[size_t(src.mirrors[leg])];
                double denom = dot(m.region.normal, ray.dir);
                if (denom != 0) remaining = -m.region.signedDistance(ray.origin) / denom;
                if (!(remaining > 0)) return {};
            }
            ray.tmax = escape ? HUGE_VAL
                              : remaining * (1 + 1e-6) + 2 * shift + 1e-9 * maxAbs(goal);
            std::optional<Hit> hit = oracle.closestHit(ray);
            if (!hit) {
                if (!last) return {};  // grazed past the mirror's edge
                if (escape) return through * oracle.distantRadiance(src.light.shapeIndex, dir);
                // Reached the target although the accelerator did not report the
                // (grazed) source surface: it is there by construction.
                ShadowEvent ev = oracle.event(
                    sourceSurfaceHit(src, geometry.shapes(), list.regions, goal, dir, remaining),
                    dir);
                return ev.kind == ShadowEvent::Kind::Emit ? through * ev.colour : Color{};
            }
            if (!last && hit->prim == list.mirrors[size_t(src.mirrors[leg])].prim) {
                ShadowEvent ev = oracle.event(*hit, dir);
                if (ev.kind != ShadowEvent::Kind::Reflect) return {};
                through *= ev.colour;
                dir = list.mirrors[size_t(src.mirrors[leg])].reflectDir(dir);
                ray = spawnRay(*hit, dir);
                shift = hit->offset;
                advanced = true;
                continue;
            }
            ShadowEvent ev = oracle.event(*hit, dir);
            if (last && !escape && hit->prim == src.light.prim)
                return ev.kind == ShadowEvent::Kind::Emit ? through * ev.colour : Color{};
            // Glass and trans pass light on; anything else (an opaque surface, another
            // source, a mirror not on this path) blocks it.
            if (ev.kind != ShadowEvent::Kind::Transmit) return {};
            through *= ev.colour;
            if (through.isBlack()) return {};
            ray = spawnRay(*hit, dir);
            shift = std::fmax(shift, hit->offset);
        }
        if (!advanced) return {};
    }
    return {};
}

Color DirectLighting::compute(const DirectPoint& at, const DirectCoefficient& coefficient,
                              ShadowOracle& oracle, Rng& rng) const {
    const Impl& im = *impl_;
    const SourceList& list = im.list;
    const ShapeSet& shapes = im.geometry.shapes();
    // Scratch kept per thread (compute is not re-entered: shadow rays do not shade).
    thread_local std::vector<Candidate> cands;
    thread_local std::vector<Vec3> crossings;
    thread_local std::vector<SourceSample> samples;
    thread_local std::vector<double> tail;
    cands.clear();
    crossings.clear();
    samples.clear();

    for (size_t si = 0; si < list.sources.size(); ++si) {
        const DirectSource& src = list.sources[si];
        // Virtual sources: the point must be on the mirror's reflecting side, and the
        // source is sampled from the point's mirror image (virtuals.c).
        Vec3 from = at.point;
        if (src.isVirtual()) {
            const MirrorPlane& m1 = list.mirrors[size_t(src.mirrors.front())];
            if (m1.region.signedDistance(at.point) * src.mirrorSide <= 0) continue;
            for (int32_t mi : src.mirrors) from = list.mirrors[size_t(mi)].reflectPoint(from);
        }
        samples.clear();
        sampleSource(list, src, shapes, from, im.options, at.weight, rng, samples);
        for (const SourceSample& s : samples) {
            // Direction leaving the point: the sample direction reflected back through
            // the mirrors, last to first.
            Vec3 d = s.dir;
            for (size_t k = src.mirrors.size(); k-- > 0;)
                d = list.mirrors[size_t(src.mirrors[k])].reflectDir(d);
            if (!at.transmits && dot(d, at.normal) <= 0) continue;
            Candidate c;
            c.source = int32_t(si);
            c.sample = s;
            c.toLight = d;
            c.crossings = uint32_t(crossings.size());
            // The path must cross each mirror inside its polygon (RADIANCE checks the
            // virtual source's ray against the mirror object).
            Color mirrorColour{1, 1, 1};
            Vec3 p = at.point, dir = d;
            bool ok = true;
            for (int32_t mi : src.mirrors) {
                const MirrorPlane& m = list.mirrors[size_t(mi)];
                double denom = dot(m.region.normal, dir);
                double t = denom != 0 ? -m.region.signedDistance(p) / denom : -1;
                if (!(t > 0)) {
                    ok = false;
                    break;
                }
                Vec3 x = p + dir * t;
                Vec3 rel = x - m.region.origin;
                if (!m.region.contains(dot(rel, m.region.uAxis), dot(rel, m.region.vAxis))) {
                    ok = false;
                    break;
                }
                ShadowEvent ev = oracle.event(mirrorSurfaceHit(m, x, dir, t), dir);
                if (ev.kind != ShadowEvent::Kind::Reflect) {
                    ok = false;
                    break;
                }
                mirrorColour *= ev.colour;
                crossings.push_back(x);
                p = x;
                dir = m.reflectDir(dir);
            }
            if (!ok) {
                crossings.resize(c.crossings);
                continue;
            }
            // The coefficient is per unit solid angle (BRDF x cos, material::evaluate):
            // the sample's solid angle makes it RADIANCE's coef.
            c.coef = coefficient(d, s.omega) * s.omega;
            if (c.coef.brightness() <= 0) {
                crossings.resize(c.crossings);
                continue;
            }
            // Unoccluded value (RADIANCE srcvalue): the source's radiance toward us.
            Color radiance;
            if (src.distant()) {
                radiance = oracle.distantRadiance(src.light.shapeIndex, s.dir);
            } else {
                ShadowEvent ev = oracle.event(
                    sourceSurfaceHit(src, shapes, list.regions, s.target, s.dir, s.dist), s.dir);
                if (ev.kind == ShadowEvent::Kind::Emit) radiance = ev.colour;
            }
            c.estimate = c.coef * radiance * mirrorColour;
            c.brt = c.estimate.brightness();
            if (c.brt <= 0) {
                crossings.resize(c.crossings);
                continue;
            }
            cands.push_back(c);
        }
    }
    if (cands.empty()) return {};

    // RADIANCE compat (source.c direct): test the brightest first; stop when the next
    // nshadcheck = n^dc estimates together fall below dt/weight times what has been
    // found so far. Stable sort: ties keep source order, so results are reproducible.
    // A handful of candidates is usual (stableSortSmall: no buffer allocated per call).
    stableSortSmall(cands.begin(), cands.end(),
                    [](const Candidate& a, const Candidate& b) { return a.brt > b.brt; });
    const size_t n = cands.size();
    tail.assign(n + 1, 0.0);
    for (size_t i = n; i-- > 0;) tail[i] = tail[i + 1] + cands[i].brt;
    // n^dc for the last n seen (the same few counts recur at every shaded point).
    thread_local size_t powN = 0;
    thread_local double powCertainty = -1, powValue = 0;
    const double certainty = std::clamp(im.options.certainty, 0.0, 1.0);
    if (n != powN || certainty != powCertainty) {
        powN = n;
        powCertainty = certainty;
        powValue = std::pow(double(n), certainty);
    }
    const size_t nshadcheck = size_t(powValue + 0.5);
    const double threshold = im.options.threshold / std::fmax(at.weight, 1e-9);

    Color total;
    double testedEstimate = 0, testedFound = 0;
    size_t sn = 0;
    for (; sn < n; ++sn) {
        double window = sn + nshadcheck >= n ? tail[sn] : tail[sn] - tail[sn + nshadcheck];
        if (window < threshold * total.brightness()) break;
        const Candidate& c = cands[sn];
        Color value = c.coef * im.trace(at, c, crossings.data() + c.crossings, oracle);
        total += value;
        testedEstimate += c.brt;
        testedFound += value.brightness();
    }
    // Untested samples: their estimates scaled by the fraction of the tested estimate
    // that was found unshadowed. RADIANCE scales by its hit rate times per-source hit
    // statistics gathered over the whole run; those depend on the order rays are
    // traced in (threads), so we use this call's own ratio instead (0.5 if none tested,
    // as RADIANCE).
    if (sn < n) {
        double prob = testedEstimate > 0 ? std::min(1.0, testedFound / testedEstimate) : 0.5;
        for (; sn < n; ++sn) total += cands[sn].estimate * prob;
    }
    return total;
}

}  // namespace rp::render

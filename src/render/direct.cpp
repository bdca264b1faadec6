// The direct calculation: candidate samples of every source, RADIANCE's sorted shadow
// test with the -dt threshold and -dc certainty, and shadow paths through transmitting
// surfaces and relaying mirrors and prisms (see direct.h). The source list is source_list.h and
// the subdivision source_sampling.h.
#include "render/direct.h"

#include <algorithm>
#include <cmath>

#include "render/source_polygon.h"
#include "render/source_sampling.h"
#include "util/small_sort.h"

namespace rp::render {

namespace {

// One source sample that may contribute: RADIANCE's CONTRIB record.
struct Candidate {
    int32_t source = -1;     // index into SourceList::sources
    SourceSample sample;     // toward the real source, from the apparent origin
    Vec3 toLight;            // unit direction leaving the shaded point
    Color coef;              // coefficient(toLight, omega) * omega
    Color estimate;          // coef * unoccluded radiance (relays included)
    double brt = 0;          // brightness of estimate (sort key)
    uint32_t crossings = 0;  // first index into the relay crossing points
    // Aimed at the source as a whole, through no sample point (traceToward): the ray
    // meets it wherever it does, as after a prism.
    bool unaimed = false;
};

// Where a shadow path that reached its source ended, for contributions.
struct ShadowEnd {
    Color through;          // what the path transmits (glass, mirrors, prisms, medium)
    Color radiance;         // the source's radiance toward the point
    int32_t modifier = -1;  // of the source surface (distant: of the `source`)
    Vec3 point, dir;        // where it met the source, travelling dir
};

constexpr int kMaxShadowSurfaces = 64;  // transmitting surfaces crossed per leg at most

}  // namespace

struct DirectScratch::Buffers {
    std::vector<Candidate> cands;
    std::vector<Vec3> crossings;  // where candidates' paths cross their relays
    std::vector<SourceSample> samples;
    std::vector<double> tail;  // suffix sums of the candidates' estimates
    PolygonScratch polygon;
    // n^dc for the last n seen: the same few candidate counts recur at every shaded
    // point, and pow was a visible share of the direct calculation (bench/README_profile.md).
    size_t powN = 0;
    double powCertainty = -1, powValue = 0;
};

DirectScratch::DirectScratch() : b_(std::make_unique<Buffers>()) {}
DirectScratch::~DirectScratch() = default;

struct DirectLighting::Impl {
    const SceneGeometry& geometry;
    DirectOptions options;
    SourceList list;
    material::Medium globalMedium;

    // Radiance reaching the shaded point along candidate `c`'s shadow path, zero if
    // blocked. `crossings` are the points where the path meets the relays (virtual).
    // `end` (may be null) receives how it ended when it reached the source. With `tree`
    // the path is shown in the ray tree as the oracle asks (ShadowTree).
    Color trace(const DirectPoint& at, const Candidate& c, const Vec3* crossings,
                ShadowOracle& oracle, ShadowEnd* end = nullptr, bool tree = false) const;
    // trace's path, its pieces appended to `pieces` if not null.
    Color traceLegs(const DirectPoint& at, const Candidate& c, const Vec3* crossings,
                    ShadowOracle& oracle, ShadowEnd* end, std::vector<ShadowPiece>* pieces) const;

    // compute's phases: every source's samples as candidates (with their coefficient and,
    // unless every sample is tested, their unoccluded estimate), then RADIANCE's sorted
    // shadow test of them.
    void collect(const DirectPoint& at, const DirectCoefficient& coefficient, ShadowOracle& oracle,
                 Rng& rng, DirectScratch::Buffers& b) const;
    // Candidate `c` toward virtual source `src`: the path must cross each relay inside its
    // polygon; false if it does not. Appends the crossings and sets `colour` to what the
    // relays pass.
    bool crossRelays(const DirectPoint& at, const DirectSource& src, const Candidate& c,
                     ShadowOracle& oracle, std::vector<Vec3>& crossings, Color& colour) const;
    Color test(const DirectPoint& at, ShadowOracle& oracle, DirectScratch::Buffers& b) const;
    bool testAll() const { return !(options.threshold > 0); }
};

DirectLighting::DirectLighting(const Scene& scene, const SceneGeometry& geometry,
                               const DirectOptions& options, bool virtualSources,
                               const RedirectFunction& redirect,
                               const material::Medium& globalMedium)
    : impl_(std::make_unique<Impl>(Impl{
          geometry, options, buildSourceList(scene, geometry, options, virtualSources, redirect),
          globalMedium})) {}

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

// RADIANCE source.c passillum/illumblock: a shadow ray aimed at another source passes an
// illum it meets, except from the illum's front toward a real illum or glow (one
// secondary source must not relay another's light twice).
namespace {
bool passesIllum(const DirectSource& src, const Hit& hit) {
    return !src.relays.empty() || !src.light.params.secondary() || !hit.front;
}
}  // namespace

Color DirectLighting::Impl::trace(const DirectPoint& at, const Candidate& c, const Vec3* crossings,
                                  ShadowOracle& oracle, ShadowEnd* end, bool tree) const {
    const ShadowTree shown = tree && list.sources[size_t(c.source)].relays.empty()
                                 ? oracle.shadowTree()
                                 : ShadowTree::None;
    if (shown == ShadowTree::None) return traceLegs(at, c, crossings, oracle, end, nullptr);
    std::vector<ShadowPiece> pieces;  // only for the ray tree, a debugging output
    ShadowEnd ended;
    const Color value = traceLegs(at, c, crossings, oracle, &ended, &pieces);
    if (end) *end = ended;
    const bool reached = ended.modifier >= 0;
    // RADIANCE compat (source.c direct): a shadow ray that met another surface first is
    // followed and reported; one that met its source only under -oT.
    if (pieces.size() > 1 || (shown == ShadowTree::All && reached && !pieces.empty())) {
        // Each piece brings what the next one brings, times what its end surface passed.
        Color arriving = reached ? ended.radiance : Color{};
        for (size_t i = pieces.size(); i-- > 0;) {
            pieces[i].value = arriving;
            arriving *= pieces[i].coefficient;
        }
        pieces.front().coefficient = c.coef;
        oracle.reportShadowRay(at, pieces);
    }
    return value;
}

Color DirectLighting::Impl::traceLegs(const DirectPoint& at, const Candidate& c,
                                      const Vec3* crossings, ShadowOracle& oracle, ShadowEnd* end,
                                      std::vector<ShadowPiece>* pieces) const {
    const DirectSource& src = list.sources[size_t(c.source)];
    const size_t legs = src.relays.size() + 1;
    Vec3 dir = c.toLight;
    ShadowPath path = at.shadow;
    Ray ray = at.hit ? spawnRay(*at.hit, dir) : Ray{at.point, dir, HUGE_VAL};
    // How far spawn offsets may have moved the ray off the straight line to the goal.
    double shift = at.hit ? at.hit->offset : 0;
    Color through{1, 1, 1};
    Color passed{1, 1, 1};  // by the last surface passed (the tree's pieces)
    // After a prism the ray goes where the prism's functions send it (m_direct.c), not
    // necessarily through the sample: it must meet the source itself (a distant one
    // within its disk, RADIANCE sourcehit), wherever that is.
    bool redirected = c.unaimed;
    material::Medium medium = at.medium ? *at.medium : material::Medium{};
    // Loss over `t` in the current medium (DirectPoint::scatterLoss).
    auto absorb = [&](double t) {
        if (medium.active()) through *= medium.transmittance(t, !at.scatterLoss);
    };
    auto reached = [&](const Color& radiance, int32_t modifier, const Vec3& point) {
        if (end) *end = ShadowEnd{through, radiance, modifier, point, dir};
        return through * radiance;
    };
    for (size_t leg = 0; leg < legs; ++leg) {
        const bool last = leg + 1 == legs;
        const bool escape = last && src.distant();
        const bool anywhere = last && redirected;
        const Vec3& goal = last ? c.sample.target : crossings[leg];
        const RelayPlane* relay = last ? nullptr : &list.relays[size_t(src.relays[leg].relay)];
        bool advanced = false;
        for (int guard = 0; guard < kMaxShadowSurfaces && !advanced; ++guard) {
            double remaining = escape || anywhere ? HUGE_VAL : length(goal - ray.origin);
            // Slightly past the goal: the source (or relay) itself is the last thing
            // the ray may reach; what lies behind it must not count. A relay is reached
            // where the ray meets its plane, wherever offsets moved the origin.
            if (relay) {
                double denom = dot(relay->region.normal, ray.dir);
                if (denom != 0) remaining = -relay->region.signedDistance(ray.origin) / denom;
                if (!(remaining > 0)) return {};
            }
            ray.tmax = escape || anywhere
                           ? HUGE_VAL
                           : remaining * (1 + 1e-6) + 2 * shift + 1e-9 * maxAbs(goal);
            std::optional<Hit> hit = oracle.closestHit(ray);
            // The tree's piece: its coefficient is for now what the surface before it
            // passed (trace puts them in their places).
            if (pieces) pieces->push_back({ray.origin, dir, hit, -1, {}, passed});
            if (!hit) {
                if (!last) return {};  // grazed past the relay's edge
                if (escape) {
                    absorb(HUGE_VAL);
                    const DistantSource& d = geometry.sources()[size_t(src.light.shapeIndex)];
                    if (redirected && 2 * kPi * (1 - dot(d.dir, dir)) > d.solidAngle) return {};
                    if (pieces) pieces->back().distant = src.light.shapeIndex;
                    return reached(oracle.distantRadiance(src.light.shapeIndex, dir), d.modifier,
                                   ray.origin + dir * 1e10);
                }
                if (anywhere) return {};
                // Reached the target although the accelerator did not report the
                // (grazed) source surface: it is there by construction.
                absorb(remaining);
                const Hit h =
                    sourceSurfaceHit(src, geometry.shapes(), list.regions, goal, dir, remaining);
                if (pieces) pieces->back().hit = h;
                ShadowEvent ev = oracle.event(h, dir, path);
                return ev.kind == ShadowEvent::Kind::Emit ? reached(ev.colour, h.modifier, h.point)
                                                          : Color{};
            }
            absorb(hit->t);
            if (relay && hit->prim == relay->prim) {
                const RelayStep& step = src.relays[leg];
                if (relay->isPrism()) {
                    material::Redirection r =
                        oracle.redirect(*hit, dir, step.projection, step.toTarget(hit->point));
                    if (!r.ok || !(r.coef > 0)) return {};
                    through *= Color::grey(r.coef);
                    dir = r.dir;
                    redirected = true;
                } else {
                    ShadowEvent ev = oracle.event(*hit, dir, path);
                    if (ev.kind != ShadowEvent::Kind::Reflect) return {};
                    through *= ev.colour;
                    dir = relay->reflectDir(dir);
                }
                ray = spawnRay(*hit, dir);
                shift = hit->offset;
                advanced = true;
                continue;
            }
            const bool target = last && !escape && hit->prim == src.light.prim;
            ShadowEvent ev = oracle.event(*hit, dir, path, !target && passesIllum(src, *hit));
            if (target)
                return ev.kind == ShadowEvent::Kind::Emit
                           ? reached(ev.colour, hit->modifier, hit->point)
                           : Color{};
            // Glass and trans pass light on; anything else (an opaque surface, another
            // source, a relay not on this path) blocks it.
            if (ev.kind != ShadowEvent::Kind::Transmit) return {};
            through *= ev.colour;
            passed = ev.colour;
            if (through.isBlack()) return {};
            medium = material::changeMedium(medium, ev.medium, globalMedium, ev.mist);
            if (lengthSquared(ev.bent) > 0) {
                // Refracted: only a distant source can still be met, within its disk.
                if (!escape) return {};
                dir = ev.bent;
                redirected = true;
            }
            ray = spawnRay(*hit, dir);
            shift = std::fmax(shift, hit->offset);
        }
        if (!advanced) return {};
    }
    return {};
}

Color DirectLighting::sampleWhole(size_t source, const DirectPoint& at, ShadowOracle& oracle,
                                  Rng& rng, Vec3& toLight) const {
    const Impl& im = *impl_;
    const DirectSource& src = im.list.sources[source];
    DirectOptions whole = im.options;
    whole.sampling = 0;  // RADIANCE nopart: the whole source is one sample
    std::vector<SourceSample> samples;
    PolygonScratch unused;  // no subdivision
    sampleSource(im.list, src, im.geometry.shapes(), at.point, whole, 1, rng, unused, samples);
    if (samples.empty()) return {};
    Candidate c;
    c.source = int32_t(source);
    c.sample = samples.front();
    c.toLight = c.sample.dir;
    toLight = c.toLight;
    return im.trace(at, c, nullptr, oracle) * c.sample.omega;
}

Color DirectLighting::traceToward(size_t source, const DirectPoint& at, const Vec3& dir,
                                  ShadowOracle& oracle, double* distance) const {
    const Impl& im = *impl_;
    const DirectSource& src = im.list.sources[source];
    if (src.isVirtual()) return {};  // its path through the relays needs a sample point
    // RADIANCE compat (srcdraw.c, m_light spotout): no light outside a spotlight's cone.
    const material::LightParams& lp = src.light.params;
    if (lp.spotlight() && lp.spotSolidAngle < 2 * kPi * (1 + dot(lp.spotAim, dir))) return {};
    Candidate c;
    c.source = int32_t(source);
    c.sample.dir = c.toLight = dir;
    c.unaimed = true;
    ShadowEnd end;
    const Color value = im.trace(at, c, nullptr, oracle, &end);
    if (distance) *distance = value.isBlack() ? HUGE_VAL : length(end.point - at.point);
    return value;
}

Color DirectLighting::compute(const DirectPoint& at, const DirectCoefficient& coefficient,
                              ShadowOracle& oracle, Rng& rng, DirectScratch& scratch) const {
    DirectScratch::Buffers& b = *scratch.b_;
    b.cands.clear();
    b.crossings.clear();
    impl_->collect(at, coefficient, oracle, rng, b);
    if (b.cands.empty()) return {};
    return impl_->test(at, oracle, b);
}

void DirectLighting::Impl::collect(const DirectPoint& at, const DirectCoefficient& coefficient,
                                   ShadowOracle& oracle, Rng& rng,
                                   DirectScratch::Buffers& b) const {
    const ShapeSet& shapes = geometry.shapes();
    for (size_t si = 0; si < list.sources.size(); ++si) {
        const DirectSource& src = list.sources[si];
        // Virtual sources: the point must be on a mirror's reflecting side, and the
        // source is sampled from the point's preimage through the relays (virtuals.c).
        Vec3 from = at.point;
        if (src.isVirtual()) {
            const RelayPlane& m1 = list.relays[size_t(src.relays.front().relay)];
            if (src.mirrorSide != 0 && m1.region.signedDistance(at.point) * src.mirrorSide <= 0)
                continue;
            for (const RelayStep& st : src.relays)
                from = st.unproject(list.relays[size_t(st.relay)].region, from);
        }
        b.samples.clear();
        sampleSource(list, src, shapes, from, options, at.weight, rng, b.polygon, b.samples);
        for (SourceSample& s : b.samples) {
            // Direction leaving the point: the sample direction through the relays'
            // maps, last to first. A local sample's solid angle changes by the maps'
            // Jacobian |det L| / |L u|^3 (1 for mirrors); a distant source keeps its
            // solid angle, as RADIANCE's virtual sources keep ss2.
            Vec3 d = s.dir;
            for (size_t k = src.relays.size(); k-- > 0;) {
                const RelayStep& st = src.relays[k];
                const PlanarRegion& r = list.relays[size_t(st.relay)].region;
                Vec3 w = st.projectDir(r, d);
                double len = length(w);
                if (!(len > 0)) break;
                if (!src.distant()) s.omega *= std::fabs(st.det(r)) / (len * len * len);
                d = w / len;
            }
            if (!at.transmits && dot(d, at.normal) <= 0) continue;
            Candidate c;
            c.source = int32_t(si);
            c.sample = s;
            c.toLight = d;
            c.crossings = uint32_t(b.crossings.size());
            Color relayColour{1, 1, 1};
            // The coefficient is per unit solid angle (BRDF x cos, material::evaluate):
            // the sample's solid angle makes it RADIANCE's coef.
            if (crossRelays(at, src, c, oracle, b.crossings, relayColour))
                c.coef = coefficient(d, s.omega) * s.omega;
            if (c.coef.brightness() <= 0) {
                b.crossings.resize(c.crossings);
                continue;
            }
            if (testAll()) {
                c.estimate = c.coef * relayColour;
                c.brt = 1;
                b.cands.push_back(c);
                continue;
            }
            // Unoccluded value (RADIANCE srcvalue): the source's radiance toward us.
            Color radiance;
            if (src.distant()) {
                radiance = oracle.distantRadiance(src.light.shapeIndex, s.dir);
            } else {
                ShadowPath probe = at.shadow;
                ShadowEvent ev = oracle.event(
                    sourceSurfaceHit(src, shapes, list.regions, s.target, s.dir, s.dist), s.dir,
                    probe);
                if (ev.kind == ShadowEvent::Kind::Emit) radiance = ev.colour;
            }
            c.estimate = c.coef * radiance * relayColour;
            c.brt = c.estimate.brightness();
            if (c.brt <= 0) {
                b.crossings.resize(c.crossings);
                continue;
            }
            b.cands.push_back(c);
        }
    }
}

bool DirectLighting::Impl::crossRelays(const DirectPoint& at, const DirectSource& src,
                                       const Candidate& c, ShadowOracle& oracle,
                                       std::vector<Vec3>& crossings, Color& colour) const {
    // RADIANCE traces the virtual source's ray into the relay object.
    Vec3 p = at.point, dir = c.toLight;
    for (const RelayStep& st : src.relays) {
        const RelayPlane& m = list.relays[size_t(st.relay)];
        double denom = dot(m.region.normal, dir);
        double t = denom != 0 ? -m.region.signedDistance(p) / denom : -1;
        if (!(t > 0)) return false;
        Vec3 x = p + dir * t;
        Vec3 rel = x - m.region.origin;
        if (!m.region.contains(dot(rel, m.region.uAxis), dot(rel, m.region.vAxis))) return false;
        Hit h = relaySurfaceHit(m, x, dir, t);
        if (m.isPrism()) {
            material::Redirection r = oracle.redirect(h, dir, st.projection, st.toTarget(x));
            if (!r.ok || !(r.coef > 0)) return false;
            colour *= Color::grey(r.coef);
            dir = r.dir;
        } else {
            ShadowPath probe = at.shadow;
            ShadowEvent ev = oracle.event(h, dir, probe);
            if (ev.kind != ShadowEvent::Kind::Reflect) return false;
            colour *= ev.colour;
            dir = m.reflectDir(dir);
        }
        crossings.push_back(x);
        p = x;
    }
    return true;
}

Color DirectLighting::Impl::test(const DirectPoint& at, ShadowOracle& oracle,
                                 DirectScratch::Buffers& b) const {
    std::vector<Candidate>& cands = b.cands;
    // RADIANCE compat (source.c direct): test the brightest first; stop when the next
    // nshadcheck = n^dc estimates together fall below dt/weight times what has been
    // found so far. Stable sort: ties keep source order, so results are reproducible.
    // A handful of candidates is usual (stableSortSmall: no buffer allocated per call).
    if (!testAll())
        stableSortSmall(cands.begin(), cands.end(),
                        [](const Candidate& a, const Candidate& b) { return a.brt > b.brt; });
    const size_t n = cands.size();
    b.tail.assign(n + 1, 0.0);
    for (size_t i = n; i-- > 0;) b.tail[i] = b.tail[i + 1] + cands[i].brt;
    const double certainty = std::clamp(options.certainty, 0.0, 1.0);
    if (n != b.powN || certainty != b.powCertainty) {
        b.powN = n;
        b.powCertainty = certainty;
        b.powValue = std::pow(double(n), certainty);
    }
    const size_t nshadcheck = size_t(b.powValue + 0.5);
    const double threshold = options.threshold / std::fmax(at.weight, 1e-9);

    Color total;
    double testedEstimate = 0, testedFound = 0;
    size_t sn = 0;
    for (; sn < n; ++sn) {
        double window = sn + nshadcheck >= n ? b.tail[sn] : b.tail[sn] - b.tail[sn + nshadcheck];
        if (window < threshold * total.brightness()) break;
        const Candidate& c = cands[sn];
        ShadowEnd end;
        Color value = c.coef * trace(at, c, b.crossings.data() + c.crossings, oracle,
                                     at.contrib ? &end : nullptr, /*tree=*/true);
        // RADIANCE compat (source.c direct, rcontrib.c trace_contrib): the shadow ray that
        // reached its source tells rcontrib its coefficient and the source's radiance.
        if (at.contrib && end.modifier >= 0 && at.contrib->tracks(end.modifier))
            at.contrib->add(end.modifier, end.point, end.dir, at.contribCoef * c.coef * end.through,
                            end.radiance);
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

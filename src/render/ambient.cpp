// The ambient calculation's option logic (see ambient.h): which points get -av, the
// division counts and sample weights per level, record radii, the cache and the -af file.
// Sampling is in ambient_hemisphere.cpp, record storage in irradiance_cache.cpp.
#include "render/ambient.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <optional>
#include <unordered_set>
#include <vector>

#include "render/ambient_file.h"
#include "render/ambient_hemisphere.h"
#include "render/irradiance_cache.h"
#include "util/warnings.h"

namespace rp::render {

namespace {
constexpr double kTiny = 1e-6;  // RADIANCE's FTINY
}  // namespace

struct Ambient::Impl {
    AmbientOptions opt;
    double sceneSize = 0;
    double minRadius = 0;  // RADIANCE minarad: scene size / -ar
    double maxRadius = 0;  // RADIANCE maxarad
    double minWeight = 2e-3;
    std::vector<char> excluded;  // per Scene::prims index: 1 = gets -av
    bool voidExcluded = false;
    std::unique_ptr<IrradianceCache> cache;  // null with -aa 0
    // Log-brightness sum and count of stored records, for -aw (RADIANCE avsum, navsum).
    std::atomic<double> logSum{0};
    std::atomic<long> logCount{0};
    std::mutex saveMutex;
    size_t saved = 0;  // new records already appended to the -af file

    bool isExcluded(int32_t modifier) const {
        if (modifier < 0 || size_t(modifier) >= excluded.size()) return voidExcluded;
        return excluded[size_t(modifier)] != 0;
    }

    void countValue(const Color& v) {
        double b = v.brightness();
        if (b > kTiny) {
            logSum.fetch_add(std::log(b), std::memory_order_relaxed);
            logCount.fetch_add(1, std::memory_order_relaxed);
        }
    }

    // Both give nothing when no sample could be traced (RADIANCE then uses -av).
    std::optional<Color> fresh(const AmbientPoint& at, HemisphereTracer& tracer, Rng& rng) const;
    std::optional<Color> makeRecord(const AmbientPoint& at, HemisphereTracer& tracer, Rng& rng);
    uint32_t corralFlags(const HemisphereEstimate& est, double reach, int columns) const;
    // Ward radius R of a new record (its reach is aa R); may cap the relative gradient.
    double recordRadius(const HemisphereEstimate& est, double brightness, double wt,
                        Vec3& gradPosition) const;
};

Ambient::Ambient(const AmbientOptions& options, double sceneSize, const Scene& scene,
                 double minWeight)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.opt = options;
    m.sceneSize = sceneSize;
    m.minWeight = minWeight;
    // RADIANCE compat (ambient.c setambres): records are at least size/ar apart and
    // reach at most 64 times that (half the scene without -ar), never over half the scene
    // (RADIANCE: a fifth; the curvature bounds our records' reach long before).
    m.minRadius = options.resolution > 0 ? sceneSize / options.resolution : 0;
    m.maxRadius = m.minRadius > kTiny ? 64 * m.minRadius : sceneSize / 2;
    if (sceneSize > 0) m.maxRadius = std::min(m.maxRadius, sceneSize / 2);
    if (m.maxRadius <= 0) m.maxRadius = 1e10;

    // -ae/-ai: the list names modifiers; the last of the two options sets its meaning.
    std::unordered_set<std::string> names(options.modifiers.begin(), options.modifiers.end());
    m.excluded.resize(scene.prims.size());
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        bool listed = names.count(scene.prims[i].name) != 0;
        m.excluded[i] = options.includeList ? !listed : listed;
    }
    // RADIANCE compat (multambient): a point without an object (rtrace -I) is never
    // excluded.
    m.voidExcluded = false;

    if (options.accuracy > kTiny)
        m.cache = std::make_unique<IrradianceCache>(options.accuracy, m.minRadius, sceneSize);

    if (options.file.empty()) return;
    if (!m.cache) {
        // RADIANCE compat (ambient.c setambient): -aa 0 leaves the ambient file alone.
        warn(fmt::format("zero ambient accuracy so \"{}\" not opened", options.file));
        return;
    }
    if (!std::filesystem::exists(options.file)) return;
    AmbientFileContents f = readAmbientFile(options.file);
    if (f.bands != options.bands)
        throw InputError(SourceLoc{options.file, 0}, bandsProblem(f.bands, options.bands));
    std::string mine = ambientFileOptions(options);
    // RADIANCE reuses ambient files whatever the options; records from other settings are
    // still valid irradiance estimates, only of other quality, so we warn, not refuse.
    if (f.options != mine)
        warn(fmt::format("ambient file {} was made with {}, now using {}", options.file,
                         f.options.empty() ? "unknown options" : f.options, mine));
    for (const AmbientRecord& r : f.records) {
        m.cache->insert(r, false);
        m.countValue(r.value);
    }
}

Ambient::~Ambient() = default;

Color Ambient::ambientValue() const {
    // RADIANCE compat (ambient.c multambient, "dumbamb"): the geometric mean of the
    // computed brightnesses, with -av counted -aw times, in the colour of -av.
    const AmbientOptions& o = impl_->opt;
    long n = impl_->logCount.load(std::memory_order_relaxed);
    if (o.valueWeight <= 0 || n == 0) return o.value;
    double sum = impl_->logSum.load(std::memory_order_relaxed);
    double l = o.value.brightness();
    if (l > kTiny) {
        double d = std::exp((std::log(l) * o.valueWeight + sum) / double(o.valueWeight + n));
        return o.value * (d / l);
    }
    return Color::grey(std::exp(sum / double(n)));
}

std::optional<Color> Ambient::Impl::fresh(const AmbientPoint& at, HemisphereTracer& tracer,
                                          Rng& rng) const {
    // RADIANCE compat (ambcomp.c samp_hemi): without the cache the division count follows
    // the ray weight, lowered so that samples stay above -lw; each sample carries its
    // share of the weight times the material's ambient coefficient.
    double wt = at.weight;
    if (minWeight > 0) {
        double cap = 0.8 * at.coefficient * at.weight / (opt.divisions * minWeight);
        wt = std::min(wt, cap);
    }
    HemisphereParams p = hemisphereDivisions(opt.divisions, opt.supersamples, wt, false);
    p.sampleLevel = at.ambientLevel + 1;
    p.sampleWeight =
        at.weight * std::min(1.0, at.coefficient / (double(p.thetaDivisions) * p.phiDivisions));
    p.gradients = false;
    if (p.superSamples <= 8) p.superSamples = 0;  // RADIANCE 5: not worth it below 9
    const HemisphereEstimate est = sampleHemisphere(at.offsetOrigin, at.normal, p, tracer, rng);
    if (est.untraced == est.divisions) return std::nullopt;
    return est.value;
}

// The curvature term may use this share of -aa: the rest is left to the records' Monte
// Carlo noise and the normal test. Measured on the Cornell box with the README's -ab 8
// -aa 0.05 options against RADIANCE's ref_classic_ab8: share 1: 12k records, MARE 1.9 %;
// 1/2: 38k records, 1.5 %; 1/4: 197k records, 1.4 % (three points lit through the mirror
// differ by 25-37 % in every run; without them 1.0, 0.6 and 0.5 %). 1/2 keeps the
// accuracy at a fifth of the work of 1/4.
constexpr double kCurvatureShare = 0.5;
// The curvature never counts as less than this over the squared harmonic mean distance
// R_h of the surfaces hit (at most maxarad): the second-order analogue of Ward's split
// sphere, whose first-order bound E/R_h RADIANCE 3 used. Our Hessian (sampleHemisphere)
// sees how the light from the surfaces in view changes, not how their visibility does;
// R_h does. Rays that escape (sky through a window) do not lengthen R_h, and a record
// that hits nothing counts as curved on the maxarad scale: without these two rules the
// daylight room's classic -ab 5 read 10-20 % high away from the sun patch (MARE 9.8 %
// against RADIANCE; with them 1.9 %), records near the window reaching far past it.
constexpr double kSplitSphereCurvature = 2.0;

double Ambient::Impl::recordRadius(const HemisphereEstimate& est, double brightness, double wt,
                                   Vec3& gradPosition) const {
    // The reach of a record (how far lookups may use it) follows from its second-order
    // error, as in RADIANCE 5's Hessian-based records, though by our own derivation:
    // extrapolation with the gradients leaves the curvature term 1/2 k x^2 (k: largest
    // |eigenvalue| of the value's Hessian relative to the value, from sampleHemisphere,
    // at least kSplitSphereCurvature / R_h^2), so the relative error stays within tol out to
    //     reach = sqrt(2 tol / k),   tol = kCurvatureShare * aa / sqrt(wt),
    // deeper levels being allowed more error as RADIANCE's 1/sqrt(wt) radius growth allows.
    // The reach grows as sqrt(aa) (RADIANCE 3's Ward-Heckbert reach aa R grows as aa), so
    // halving -aa doubles the records instead of quadrupling them, and in smooth light
    // (small k) records reach far. Bounds: at least aa * minarad (RADIANCE 3's smallest
    // reach), at most maxarad, and at most aa * maxarad (RADIANCE's own bound, ambcomp.c)
    // for a record whose samples mostly escaped: they tell nothing of the surfaces around
    // it, and R_h knows only the few that were hit (issue 43: records on an open ground
    // plane 400 m across reached 70 m, into the room beside them, where the walls had no
    // sample; LBNL's tutorial room read 60 % high; capping every record so made the
    // Cornell box 4x slower for nothing). Where the first-order change over the reach
    // would exceed the value itself (|g| reach > 1) the reach shrinks to 1/|g| (if the
    // floor keeps it larger, the relative gradient `gradPosition` is capped instead).
    // Stored as the Ward radius R = reach / aa, so lookups, the grid and the -af file
    // work unchanged.
    const double aa = opt.accuracy;
    const double tol = kCurvatureShare * aa / std::sqrt(wt);
    double k = brightness > kTiny ? est.maxCurvature() / brightness : 0;
    const double rh = est.sumInverseDistance > kTiny ? est.hits / est.sumInverseDistance : 0;
    const double rSplit = rh > 0 ? std::min(rh, maxRadius) : maxRadius;
    k = std::max(k, kSplitSphereCurvature / (rSplit * rSplit));
    const bool mostlyEscaped = 2 * est.hits < est.samples;
    const double maxReach = std::max(aa * minRadius, (mostlyEscaped ? aa : 1.0) * maxRadius);
    double reach = k > 0 ? std::sqrt(2 * tol / k) : maxReach;
    const double g = length(gradPosition);
    if (g * reach > 1) reach = 1 / g;
    reach = std::clamp(reach, aa * minRadius, maxReach);
    if (g * reach > 1) gradPosition *= 1 / (g * reach);
    return std::max(reach / aa, 1e-12);
}

// RADIANCE compat (ambcomp.c ambcorral): the azimuth sectors in which a surface near the
// horizon lies within the record's reach, so that lookups from there test for a leak
// through it. Not for coarse hemispheres (RADIANCE: fewer than 8 divisions), nor under a
// ceiling within the reach (the mean inverse distance overhead times the reach reaches 1),
// nor for occluders nearer than the smallest reach plus a millimetre.
uint32_t Ambient::Impl::corralFlags(const HemisphereEstimate& est, double reach,
                                    int columns) const {
    if (columns < 8 || est.horizonDistance.size() != size_t(columns)) return 0;
    if (est.overheadInverseDistance * reach >= 1) return 0;
    const double nearest = opt.accuracy * minRadius + 1e-3;
    if (est.overheadInverseDistance >= 1 / nearest) return 0;
    uint32_t flags = 0;
    const double width = 2 * kPi / columns;
    for (int k = 0; k < columns; ++k) {
        const double d = est.horizonDistance[size_t(k)];
        if (!(d < reach) || d <= nearest) continue;
        // The column's span and half a column either side, as RADIANCE's +-ang_res.
        const double lo = (k - 0.5) * width, hi = (k + 1.5) * width;
        for (int s = int(std::floor(lo * 16 / kPi)); s <= int(std::floor(hi * 16 / kPi)); ++s)
            flags |= 1u << ((s % 32 + 32) % 32);
    }
    return flags;
}

std::optional<Color> Ambient::Impl::makeRecord(const AmbientPoint& at, HemisphereTracer& tracer,
                                               Rng& rng) {
    // RADIANCE compat (ambient.c makeambient): a record's weight is AVGREFL per level,
    // unless the ray is much lighter already; it sets the division count and radius.
    double wt = std::pow(kAverageReflectance, at.ambientLevel);
    if (at.weight < 0.1 * wt) wt = 1.25 * at.weight;
    HemisphereParams p = hemisphereDivisions(opt.divisions, opt.supersamples, wt, true);
    p.sampleLevel = at.ambientLevel + 1;
    // Cached values are reused by many rays, so samples carry the full AVGREFL share
    // (ambcomp.c: rcoef = AVGREFL with -aa > 0).
    p.sampleWeight = at.weight * kAverageReflectance;
    if (p.superSamples <= 8) p.superSamples = 0;
    HemisphereEstimate est = sampleHemisphere(at.offsetOrigin, at.normal, p, tracer, rng);
    // RADIANCE compat (ambient.c makeambient): a value some of whose samples were lost
    // (the ray was lighter than -lw allows for them) is used here but not cached, where
    // every later ray would reuse its shortfall; with none traced there is no value.
    if (est.untraced == est.divisions) return std::nullopt;
    if (est.untraced > 0) return est.value;

    AmbientRecord rec;
    rec.position = at.point;
    rec.normal = at.normal;
    rec.value = est.value;
    rec.level = at.ambientLevel;
    rec.weight = wt;
    double b = est.value.brightness();
    if (b > kTiny) {  // gradients are stored relative to the value (ambcomp.c)
        rec.gradPosition = est.gradPosition / b;
        rec.gradDirection = est.gradDirection / b;
    }
    rec.radius = recordRadius(est, b, wt, rec.gradPosition);
    rec.corral = corralFlags(est, opt.accuracy * rec.radius, p.phiDivisions);
    cache->insert(rec, true);
    countValue(rec.value);
    return rec.value;
}

Color Ambient::indirect(const AmbientPoint& at, HemisphereTracer& tracer, Rng& rng) const {
    const Impl& m = *impl_;
    if (at.ambientLevel >= m.opt.bounces || m.opt.divisions <= 0 || m.isExcluded(at.modifier))
        return ambientValue();
    if (!m.cache) return m.fresh(at, tracer, rng).value_or(ambientValue());
    CacheQuery q{at.point, at.normal, at.ambientLevel, at.weight, at.offsetOrigin, at.leaks};
    Color c;
    if (m.cache->lookup(q, c)) return c;
    // Inserting is thread-safe; the Impl is logically the shared cache.
    return const_cast<Impl&>(m).makeRecord(at, tracer, rng).value_or(ambientValue());
}

void Ambient::save() const {
    Impl& m = *impl_;
    if (m.opt.file.empty() || !m.cache) return;
    std::lock_guard<std::mutex> lock(m.saveMutex);
    std::vector<AmbientRecord> recs = m.cache->newRecords();
    if (m.saved >= recs.size() && std::filesystem::exists(m.opt.file)) return;
    std::vector<AmbientRecord> todo(recs.begin() + long(std::min(m.saved, recs.size())),
                                    recs.end());
    appendAmbientFile(m.opt.file, ambientFileOptions(m.opt), todo, m.opt.bands);
    m.saved = recs.size();
}

long Ambient::recordCount() const { return impl_->cache ? impl_->cache->size() : 0; }

}  // namespace rp::render

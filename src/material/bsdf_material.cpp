// BSDF and aBSDF (RADIANCE m_bsdf.c, pmapmat.c bsdfPhotonScatter): scattering from XML
// data in the BSDF's local frame (+Z the unperturbed-side normal, +Y the up vector).
//
// Backward: the non-diffuse part of reflection and of transmission is each sampled with
// one ray per data component (several above -ss 1.5), weighted by its directional-
// hemispherical value (below -st it goes to the ambient instead); the Lambertian parts
// (the data's and the arguments') take ambient light; direct light is the BSDF averaged
// over the view direction jittered within the data's resolution, minus the Lambertian
// part counted separately. A thick BSDF is a proxy: only scattered rays see it, others
// pass to the geometry behind it. aBSDF looks for a strong "through" peak, which passes
// view and shadow rays unscattered.
#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>

#include "bsdf/bsdf.h"
#include "material/detail.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/warnings.h"

namespace rp::material::detail {

namespace {

// The BSDF's frame at a hit (bsdf.c SDcompXform); orthonormal, so its inverse is its
// transpose.
struct Frame {
    Vec3 x, y, z;
    Vec3 toLocal(const Vec3& v) const { return {dot(x, v), dot(y, v), dot(z, v)}; }
    Vec3 toWorld(const Vec3& l) const { return x * l.x + y * l.y + z * l.z; }
};

bool makeFrame(const Vec3& normal, const Vec3& up, Frame& f) {
    f.z = normalize(normal);
    const Vec3 x = cross(up, f.z);
    if (lengthSquared(x) <= 1e-24) return false;
    f.x = normalize(x);
    f.y = cross(f.z, f.x);
    return true;
}

// m_bsdf.c BSDFDAT: everything one hit needs.
struct BsdfHit {
    const bsdf::BsdfData* sd = nullptr;
    Frame frame;
    Vec3 vray;                          // local direction back along the ray
    double srPsa[2] = {0, 0};           // sqrt of the data's smallest and largest cells at vray
    Color rdiff, tdiff;                 // Lambertian parts (data + arguments) times the pattern
    Color cthru, cthruSurround;         // aBSDF: the through peak and the BTDF around it
    std::array<int, 3> bands{0, 1, 2};  // BsdfParams::dataBands

    // A colour of the data in the pass's bands. Choices (peaks, thresholds) are made on
    // the data's own colours, so that every pass makes the same ones.
    Color inBands(const Color& c) const { return {c[bands[0]], c[bands[1]], c[bands[2]]}; }
};

// What a hit needs beyond the frame and the Lambertian parts: the data's resolution at
// the view (for sampling) and aBSDF's through peak. Direct light needs neither, except
// the peak for sources behind an aBSDF, so setupBsdf leaves them to the callers.
void setResolution(BsdfHit& h) {
    h.sd->size(h.vray, nullptr, bsdf::SizeQuery::MinMax, h.srPsa);
    h.srPsa[0] = std::sqrt(h.srPsa[0]);
    h.srPsa[1] = std::sqrt(h.srPsa[1]);
}

Vec3 jitter(const BsdfHit& h, double srPsa, double dx, double dy) {
    if (srPsa <= kFtiny) return h.vray;
    return normalize(Vec3{h.vray.x + srPsa * dx, h.vray.y + srPsa * dy, h.vray.z});
}

Vec3 jitterRandom(const BsdfHit& h, double srPsa, double specJitter, Rng& rng) {
    if (specJitter < 1) srPsa *= specJitter;
    const double dx = .5 - rng.uniform(), dy = .5 - rng.uniform();
    return jitter(h, srPsa, dx, dy);
}

void computeThrough(BsdfHit& h, const SurfacePoint& sp);

bool setupBsdf(const BsdfParams& m, const SurfacePoint& sp, BsdfHit& h) {
    RP_CHECK(sp.bsdf);  // the renderer fills it from MaterialCalc
    h.sd = sp.bsdf;
    const Vec3 unflipped = sp.front ? sp.normal : -sp.normal;
    if (!makeFrame(unflipped, sp.uDir, h.frame)) {
        static std::atomic<bool> warned{false};  // RADIANCE warns per hit; once is enough
        if (!warned.exchange(true))
            warn("BSDF: illegal orientation vector (up vector along the normal)");
        return false;
    }
    h.vray = h.frame.toLocal(-sp.dir);
    h.bands = m.dataBands;
    const bsdf::BsdfData& sd = *h.sd;
    h.rdiff = h.inBands(sp.front ? sd.rLambFront : sd.rLambBack) +
              (sp.front ? m.frontDiffuse : m.backDiffuse);
    h.tdiff = h.inBands(sp.front ? sd.tLambFront : sd.tLambBack) + m.diffuseTransmittance;
    h.rdiff = h.rdiff * sp.pattern;
    h.tdiff = h.tdiff * sp.pattern;
    return true;
}

// aBSDF (m_bsdf.c compute_through): the BTDF near the straight-through direction, at 29
// points of a grid one data cell apart. The highest values that come from cells of the
// smallest size form the peak (as a transmittance: value times cell size); the rest is
// its surround. No peak where the top value is not among the smallest cells, where
// there is no surround, or where it transmits under 0.05 %.
void computeThrough(BsdfHit& h, const SurfacePoint& sp) {
    static constexpr double kGrid[29][2] = {
        {0, 0},      {-.6, 0},    {0, .6},      {0, -.6},    {.6, 0},      {-.6, .6},
        {-.6, -.6},  {.6, .6},    {.6, -.6},    {-1.2, 0},   {0, 1.2},     {0, -1.2},
        {1.2, 0},    {-1.2, 1.2}, {-1.2, -1.2}, {1.2, 1.2},  {1.2, -1.2},  {-1.8, 0},
        {0, 1.8},    {0, -1.8},   {1.8, 0},     {-1.8, 1.8}, {-1.8, -1.8}, {1.8, 1.8},
        {1.8, -1.8}, {-2.4, 0},   {0, 2.4},     {0, -2.4},   {2.4, 0}};
    const bsdf::ScatteringSet* t = h.sd->transmission(h.vray.z > 0);
    if (!t || sp.pattern.brightness() <= kFtiny) return;
    const double r = std::sqrt(t->minProjSA);
    struct Sample {
        double y;
        Vec3 dir;
        Color c;
    } s[29];
    for (int i = 0; i < 29; ++i) {
        s[i].dir =
            normalize(Vec3{-h.vray.x + kGrid[i][0] * r, -h.vray.y + kGrid[i][1] * r, -h.vray.z});
        s[i].c = h.sd->evaluate(h.vray, s[i].dir);
        s[i].y = s[i].c.brightness();
    }
    std::stable_sort(std::begin(s), std::end(s),
                     [](const Sample& a, const Sample& b) { return a.y > b.y; });
    if (s[0].y <= kFtiny) return;
    Color peak, surround;
    double ypeak = 0, omPeak = 0, omSurround = 0;
    int ns = 0;
    for (int i = 0; i < 29; ++i) {
        if (i && s[i].y == s[i - 1].y) continue;  // the same cell again
        double psa[2];
        h.sd->size(h.vray, &s[i].dir, bsdf::SizeQuery::Min, psa);
        const Color c = s[i].c * psa[0];
        if (psa[0] > 1.5 * t->minProjSA || ypeak > 8 * s[i].y * ns) {
            if (i == 0) return;
            surround += c;
            omSurround += psa[0];
            continue;
        }
        peak += c;
        omPeak += psa[0];
        ypeak += s[i].y;
        ++ns;
    }
    if (omSurround <= kFtiny) return;
    const double lamb = (h.vray.z > 0 ? h.sd->tLambFront : h.sd->tLambBack).brightness() / kPi;
    if ((ypeak / ns - lamb) * omPeak < .0005) return;
    h.cthru = h.inBands(peak) * sp.pattern;
    h.cthruSurround = h.inBands(surround) * (1 / omSurround) * sp.pattern;
}

// The non-diffuse part of the BSDF for light from world direction `l` (m_bsdf.c
// direct_specular_OK), black where there is none, averaged over jitter points in the
// view direction's cell.
Color directSpecular(BsdfHit& h, const BsdfParams& m, const SurfacePoint& sp, const Vec3& l,
                     double omega, double specJitter) {
    const bsdf::BsdfData& sd = *h.sd;
    const Vec3 vsrc = h.frame.toLocal(l);
    const bool srcFront = vsrc.z > 0, viewFront = h.vray.z > 0;
    Color diff;
    if (srcFront == viewFront) {
        if (!sd.reflection(viewFront)) return {};
        diff = viewFront ? sd.rLambFront : sd.rLambBack;
    } else {
        if (!sd.hasTransmission()) return {};
        diff = viewFront ? sd.tLambFront : sd.tLambBack;
    }
    diff = diff * (1 / kPi);
    const double diffY = diff.brightness();
    if (m.absdf && srcFront != viewFront) computeThrough(h, sp);
    if (srcFront != viewFront && h.cthru.brightness() > kFtiny) {
        // aBSDF: a source near the through direction is already seen through the peak.
        const double dx = vsrc.x + h.vray.x, dy = vsrc.y + h.vray.y;
        const double tom = omega * std::abs(vsrc.z);
        const double mps = sd.transmission(sp.front)->minProjSA;
        if (dx * dx + dy * dy <= (2.5 * 4 / kPi) * (tom + mps + 2 * std::sqrt(tom * mps)))
            return h.cthruSurround;
    }
    double tomega[2];
    sd.size(h.vray, &vsrc, bsdf::SizeQuery::Min, tomega);
    const double tsr = std::sqrt(tomega[0]);
    int nsamp = 1;
    if (tsr > 0) nsamp = std::max(1, static_cast<int>(4 * specJitter * sp.rayWeight + .5));
    // The jitter points: a low-discrepancy set over the cell (the R2 sequence), shifted by
    // a hash of the ray and light directions. RADIANCE draws them at random; a fixed set
    // with a point at the cell's centre read a BSDF's peak cell up to 2-400 times high.
    const uint64_t hash =
        mix64(std::bit_cast<uint64_t>(sp.dir.x) ^
              mix64(std::bit_cast<uint64_t>(sp.dir.y) ^
                    mix64(std::bit_cast<uint64_t>(l.x) ^ std::bit_cast<uint64_t>(l.y))));
    const double u0 = double(hash >> 11) * 0x1.0p-53, v0 = double(mix64(hash) >> 11) * 0x1.0p-53;
    Color sum;
    int count = 0;
    for (int k = 0; k < nsamp; ++k) {
        const double u = std::fmod(u0 + k * .7548776662466927, 1.0);
        const double v = std::fmod(v0 + k * .5698402909980532, 1.0);
        const Vec3 vj = jitter(h, tsr * std::min(specJitter, 1.0), .5 - u, .5 - v);
        const Color c = sd.evaluate(vj, vsrc);
        if (c.brightness() - diffY <= kFtiny) continue;
        double t2[2];
        sd.size(vj, &vsrc, bsdf::SizeQuery::Min, t2);
        if (t2[0] < .12 * tomega[0]) continue;  // a finer cell of a tree: not safe
        sum += c;
        ++count;
    }
    if (!count) return {};
    Color c = sum * (1.0 / count);
    if (diffY > kFtiny)
        for (int i = 0; i < 3; ++i) c[i] = std::max(0.0, c[i] - diff[i]);
    return h.inBands(c);
}

}  // namespace

Color evaluateBsdf(const BsdfParams& m, const SurfacePoint& sp, const Vec3& l, double omega) {
    BsdfHit h;
    if (!setupBsdf(m, sp, h)) return {};
    const double ldot = dot(sp.normal, l);
    if (std::abs(ldot) <= kFtiny) return {};
    const bool reflectOnly = h.tdiff.brightness() <= kFtiny && !h.sd->hasTransmission();
    if (reflectOnly && ldot <= kFtiny) return {};
    Color c;
    if (ldot > 0 && h.rdiff.brightness() > kFtiny) c += h.rdiff * (ldot / kPi);
    if (ldot < 0 && h.tdiff.brightness() > kFtiny) c += h.tdiff * (-ldot / kPi);
    if (sp.specularInPhotons) return c;
    Color s = directSpecular(h, m, sp, l, omega, sp.specJitter);
    if (ldot < 0) s = s * sp.pattern;
    return c + s * std::abs(ldot);
}

namespace {

// m_bsdf.c sample_sdcomp: the samples per data component, 1 up to -ss 1.5, above it -ss
// times the ray's weight rounded to the nearest (at least 1; at most kMaxRoughSamples).
int bsdfSampleCount(double specJitter, double rayWeight) {
    if (!(specJitter > 1.5)) return 1;
    const double n = std::floor(specJitter * rayWeight + .5);
    return n > 1 ? int(std::min(n, double(kMaxRoughSamples))) : 1;
}

// A sampled direction's weight: the component's hemispherical value, in the colour of
// the data there (RADIANCE: the sample's chromaticity with the cumulative total as Y).
Color sampleColour(const bsdf::Distribution& d, const Vec3& in, const Vec3& out, double total) {
    const Color v = d.value(in, out);
    const double y = v.brightness();
    return y > 0 ? v * (total / y) : Color::grey(total);
}

// m_bsdf.c sample_sdf: the non-diffuse reflection or transmission, sampled (bsdfSampleCount
// rays per component) or, at or below -st, returned as an ambient coefficient.
Color sampleSet(const BsdfHit& h, const SurfacePoint& sp, bool transmit, const ShadeOptions& opt,
                Rng& rng, BackwardResult& r) {
    const bsdf::ScatteringSet* set =
        transmit ? h.sd->transmission(sp.front) : h.sd->reflection(sp.front);
    if (!set) return {};
    const bool hasThrough = transmit && !sp.scatteredRay && h.cthru.brightness() > kFtiny;
    double b = 0;
    if (hasThrough) {
        r.add(makeRay(sp.dir, h.cthru, ScatterKind::SpecularTransmission));
        b = h.cthru.brightness();
    }
    if (set->maxHemi - b <= kFtiny) {
        b = 0;
    } else {
        const Vec3 vj = jitterRandom(h, h.srPsa[1], opt.specJitter, rng);
        b = std::max(0.0, h.sd->nonDiffuseHemispherical(vj, transmit) - b);
    }
    if (b <= opt.specThreshold + kFtiny) {
        if (b <= kFtiny) return {};
        return transmit ? sp.pattern * b : Color::grey(b);  // no pattern on reflection
    }
    for (const auto& comp : set->components) {
        int n = bsdfSampleCount(opt.specJitter, sp.rayWeight);
        for (int k = 0; k < n; ++k) {
            // One sample: its stratum's variable narrowed by -ss below 1; several: one
            // stratum of the component's cumulative distribution each.
            double x = rng.uniform();
            if (n == 1 && opt.specJitter < 1) x = .5 + opt.specJitter * (x - .5);
            if (n > 1) x = (k + x) / n;
            const Vec3 vin = jitterRandom(h, h.srPsa[0], opt.specJitter, rng);
            const double total = comp->hemispherical(vin);
            Vec3 out;
            if (total <= kFtiny || !comp->sample(vin, x, rng.uniform(), out)) break;
            if (hasThrough) {  // leave the through direction to the through ray
                const double dx = vin.x + out.x, dy = vin.y + out.y;
                if (dx * dx + dy * dy <= h.srPsa[0] * h.srPsa[0]) continue;
            }
            Color w = h.inBands(sampleColour(*comp, vin, out, n > 1 ? total / n : total));
            if (transmit) w = w * sp.pattern;
            const double childWeight = sp.rayWeight * spawnedWeight(w);
            if (k == 0 && n > 1 && childWeight < opt.minWeight) {
                // RADIANCE compat (m_bsdf.c sample_sdcomp): where the first of several
                // samples falls below -lw, start again with as many as keep each above it
                // (none where that is still n). RADIANCE tests the first ray's rayorigin;
                // we its weight, as the renderer drops it (under -lr < 0 RADIANCE's
                // roulette sometimes keeps it instead).
                const int fewer = int(n * childWeight / opt.minWeight);
                if (fewer == n) break;
                n = fewer;
                k = -1;
                continue;
            }
            r.add(makeRay(
                normalize(h.frame.toWorld(out)), w,
                transmit ? ScatterKind::SpecularTransmission : ScatterKind::SpecularReflection,
                true));
        }
    }
    return {};
}

}  // namespace

BackwardResult shadeBsdf(const BsdfParams& m, const SurfacePoint& sp, const ShadeOptions& opt,
                         Rng& rng) {
    BackwardResult r;
    const double thick = sp.bsdfThickness;
    // Hidden from the back without -bv; a thick BSDF shows its proxied geometry to every
    // ray but scattered ones on the side it faces (positive: front, negative: back).
    if ((!sp.front && !opt.backVisible) ||
        (thick != 0 && (!sp.scatteredRay || (thick > 0) != sp.front))) {
        r.transparent = true;
        return r;
    }
    BsdfHit h;
    if (!setupBsdf(m, sp, h)) return r;
    setResolution(h);
    if (m.absdf) computeThrough(h, sp);
    r.directFromBehind = h.sd->hasTransmission();
    const Color runsamp = sampleSet(h, sp, false, opt, rng, r);
    const Color tunsamp = sampleSet(h, sp, true, opt, rng, r);
    r.transmitOffset = -thick;
    r.ambientReflect = h.rdiff + runsamp;
    r.ambientTransmit = h.tdiff + tunsamp;
    if (r.ambientReflect.brightness() <= kFtiny) r.ambientReflect = {};
    if (r.ambientTransmit.brightness() <= kFtiny) r.ambientTransmit = {};
    return r;
}

PhotonScatter scatterBsdf(const BsdfParams& m, const SurfacePoint& sp, Rng& rng) {
    RP_CHECK(sp.bsdf);  // the data comes through prepareHit (a MaterialCalc is needed)
    PhotonScatter s;
    if (!sp.front && !sp.backVisible && !m.hasBackDiffuse && !sp.bsdf->rb && !sp.bsdf->tf) {
        // pmapmat.c: without -bv the back of a BSDF with nothing there absorbs.
        return s;
    }
    BsdfHit h;
    if (!setupBsdf(m, sp, h)) return s;
    const bsdf::BsdfData& sd = *h.sd;
    const double patAlb = sp.pattern.brightness();
    const bool vf = h.vray.z > 0;
    // The data's Lambertian parts, with the pattern's brightness as pmapmat.c uses it,
    // plus the arguments' (setupBsdf already gave both the pattern's colour).
    const Color extraR = (sp.front ? m.frontDiffuse : m.backDiffuse) * sp.pattern;
    const Color extraT = m.diffuseTransmittance * sp.pattern;
    const Color lambR = h.inBands(vf ? sd.rLambFront : sd.rLambBack) * patAlb;
    const Color lambT = h.inBands(vf ? sd.tLambFront : sd.tLambBack) * patAlb;
    const Component c[4] = {
        {ScatterKind::DiffuseReflection, extraR + lambR},
        {ScatterKind::DiffuseTransmission, extraT + lambT},
        {ScatterKind::SpecularReflection, Color::grey(sd.nonDiffuseHemispherical(h.vray, false))},
        {ScatterKind::SpecularTransmission, sp.pattern * sd.nonDiffuseHemispherical(h.vray, true)}};
    s.store = (c[0].coef + c[1].coef).average() > kFtiny;
    Color factor;
    const int i = roulette(c, 4, rng, factor);
    if (i < 0) return s;
    if (i < 2) {
        s.dir = sampleCosine(i == 0 ? sp.normal : -sp.normal, rng);
    } else {
        // One component, chosen by its share of the set's hemispherical value.
        const bsdf::ScatteringSet* set = i == 3 ? sd.transmission(vf) : sd.reflection(vf);
        if (!set) return s;
        double x = rng.uniform() * sd.nonDiffuseHemispherical(h.vray, i == 3);
        const bsdf::Distribution* pick = nullptr;
        for (const auto& comp : set->components) {
            pick = comp.get();
            const double hc = comp->hemispherical(h.vray);
            if (x < hc) break;
            x -= hc;
        }
        Vec3 out;
        if (!pick || !pick->sample(h.vray, rng.uniform(), rng.uniform(), out)) return s;
        s.dir = normalize(h.frame.toWorld(out));
        factor = factor * h.inBands(sampleColour(*pick, h.vray, out, 1));  // its colour there
    }
    s.kind = c[i].kind;
    s.fluxFactor = factor;
    if (i == 1 || i == 3) s.originOffset = static_cast<float>(-sp.bsdfThickness);
    return s;
}

}  // namespace rp::material::detail

namespace rp::material {

bool bsdfShadowPass(const BsdfParams& m, const SurfacePoint& sp, bool backVisible, Color& colour) {
    colour = {1, 1, 1};
    if (!sp.front && !backVisible) return true;
    if (!m.absdf) return sp.bsdfThickness != 0;  // a thick BSDF is a proxy
    detail::BsdfHit h;
    if (!detail::setupBsdf(m, sp, h)) return false;
    detail::computeThrough(h, sp);
    if (h.cthru.brightness() <= detail::kFtiny) return false;
    colour = h.cthru;
    return true;
}

}  // namespace rp::material

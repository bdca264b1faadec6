// SurfaceChainEvaluator: walks a surface's modifier chain at a hit point in RADIANCE's
// order (raytrace.c rayshade, raytexture, raymixture) and returns the material layers
// with their pattern colours and normal perturbations.
#include <algorithm>
#include <cmath>

#include "material/function_space.h"
#include "material/surface_chain.h"
#include "material/surface_chain_impl.h"

namespace rp::material {

namespace {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY: mixture sides below this are skipped
constexpr int kBufferLayers = 64;
constexpr int kMaxDepth = 200;

// What the chain has done so far to the ray (RADIANCE r->pcol, r->pert).
struct WalkState {
    Color pcol{1, 1, 1};
    Vec3 pert;
};

}  // namespace

struct SurfaceChainEvaluator::Impl {
    const SurfaceChains::Impl& chains;
    calc::Evaluator eval;
    calc::RayContext ctx;
    const PatternPoint* at = nullptr;
    Rng* rng = nullptr;
    std::array<ShadingLayer, kBufferLayers> buf{};
    int count = 0;

    explicit Impl(const SurfaceChains::Impl& c) : chains(c), eval(c.program) {}

    const Primitive& prim(int32_t m) const { return chains.scene->prims[m]; }

    // The ray variables as the record's function space sees them (functionSpace).
    void setRay(const ChainRecord& r, const Primitive& p) {
        ctx = functionSpace(*at, r.toObject);
        ctx.args = p.rargs;
        eval.setRay(ctx);
    }

    double expr(const ChainRecord& r, int k) { return eval.eval(r.exprs[size_t(k)]); }

    double call1(const NamedFunction& f, double v) {
        return eval.call(f.fn, std::span<const double>(&v, 1));
    }
    double call3(const NamedFunction& f, const double* v) {
        return eval.call(f.fn, std::span<const double>(v, 3));
    }

    // Interpolated table values at the record's coordinates (one per table).
    std::array<double, 3> dataValues(const ChainRecord& r) {
        std::array<double, calc::DataFile::kMaxDimensions> pt{};
        size_t nd = r.exprs.size();
        for (size_t k = 0; k < nd && k < pt.size(); ++k) pt[k] = eval.eval(r.exprs[k]);
        std::array<double, 3> v{};
        for (int k = 0; k < 3; ++k)
            if (r.data[k]) v[k] = r.data[k]->value(std::span<const double>(pt.data(), nd));
        return v;
    }

    // colordata / colorpict: each channel's function gets its own value, or all three.
    Color channelFunctions(const ChainRecord& r, const std::array<double, 3>& v) {
        Color c;
        for (int k = 0; k < 3; ++k)
            c[k] = r.funcs[k].threeArgs ? call3(r.funcs[k], v.data()) : call1(r.funcs[k], v[k]);
        return c;
    }

    std::array<double, 3> pictValues(const ChainRecord& r) {
        double u = expr(r, 0), v = expr(r, 1);
        Color c = r.pict->value(u, v);
        return {c.r, c.g, c.b};
    }

    Color specFunc(const ChainRecord& r);
    Color specData(const ChainRecord& r);
    Color specPict(const ChainRecord& r);

    bool inText(const ChainRecord& r) {
        // Text records have no transform arguments: the text lies in world space.
        return r.text->inText(at->point);
    }

    void addPerturbation(const ChainRecord& r, WalkState& st, Vec3 disp) {
        // RADIANCE compat (t_func.c): the perturbation is computed in function space and
        // carried to world space by the forward transform's rotation: the scale is
        // divided out (a texfunc under "-s 0.2" perturbs as much as without it).
        st.pert += functionToWorld(*at, r.hasTransform ? &r.forward : nullptr, disp);
    }

    void push(int32_t material, double weight, const WalkState& st) {
        if (count >= kBufferLayers) {
            // Only reachable with mixtures nested far deeper than anyone writes: keep
            // the heavier of the last layer and this one (biased, but bounded memory).
            ShadingLayer& last = buf[count - 1];
            if (last.weight >= weight) return;
            last = ShadingLayer{material, weight, st.pcol, st.pert};
            return;
        }
        buf[count++] = ShadingLayer{material, weight, st.pcol, st.pert};
    }

    bool shade(int32_t mod, WalkState& st, double weight, bool inTexture, int depth);
    bool mix(int32_t m, int32_t fore, int32_t back, double coef, WalkState& st, double weight,
             bool inTexture, int depth);
};

// specfunc: the function of wavelength sampled in bands of a 24th of its range (no
// finer than a quarter of a working band), each at a jittered wavelength within its
// band, as RADIANCE's p_specfunc.
Color SurfaceChainEvaluator::Impl::specFunc(const ChainRecord& r) {
    const spectral::Sampling& s = chains.pass.sampling;
    const double lo = std::max(r.wlMin, s.wl[3]), hi = std::min(r.wlMax, s.wl[0]);
    if (!(lo < hi)) return {1, 1, 1};  // outside the working range: no effect
    const double step =
        std::max((hi - lo) / spectral::kMaxSamples, 0.25 / s.n * (s.wl[0] - s.wl[3]));
    const int n = std::min(static_cast<int>((hi - lo) / step + .1), spectral::kMaxSamples);
    double buf[spectral::kMaxSamples];
    const std::span<double> samples(buf, size_t(n));
    double wl = hi - 0.5 * step;
    for (int i = n; i-- > 0; wl -= step)
        samples[size_t(i)] = call1(r.funcs[0], wl + 0.9 * (0.5 - rng->uniform()) * step);
    double out[spectral::kMaxSamples];
    const std::span<double> working(out, size_t(s.n));
    spectral::toWorking(samples, lo, hi, s, working);
    return chains.pass.ofSamples(working);
}

// specdata: the table interpolated at the record's coordinates at each wavelength of its
// last axis, each value through the record's function f(value, wavelength).
Color SurfaceChainEvaluator::Impl::specData(const ChainRecord& r) {
    const calc::DataFile& d = *r.data[0];
    const int nd = d.dimensions();
    std::array<double, calc::DataFile::kMaxDimensions> pt{};
    for (int k = 0; k + 1 < nd; ++k) pt[size_t(k)] = eval.eval(r.exprs[size_t(k)]);
    const calc::DataFile::Axis& ax = d.axis(nd - 1);
    const bool listed = !ax.points.empty();
    const double first = listed ? ax.points.front() : ax.begin;
    const double range = (listed ? ax.points.back() : ax.end) - first;
    if (ax.count < 2 || range == 0) return {1, 1, 1};
    const double step = range / (ax.count - 1);
    std::vector<double> samples(static_cast<size_t>(ax.count));
    for (int i = 0; i < ax.count; ++i) {
        const double wl = first + i * step;
        pt[size_t(nd - 1)] = wl;
        const double args[2] = {d.value(std::span<const double>(pt.data(), size_t(nd))), wl};
        samples[size_t(i)] = eval.call(r.funcs[0].fn, std::span<const double>(args, 2));
    }
    double out[spectral::kMaxSamples];
    const std::span<double> working(out, size_t(chains.pass.sampling.n));
    spectral::toWorking(samples, first - 0.5 * step, first + range + 0.5 * step,
                        chains.pass.sampling, working);
    return chains.pass.ofSamples(working);
}

// specpict: the picture's samples at (u, v), each through the record's function
// f(value, wavelength) at its band's centre.
Color SurfaceChainEvaluator::Impl::specPict(const ChainRecord& r) {
    const PictTable& pict = *r.pict;
    const spectral::Sampling& ps = pict.sampling();
    double buf[spectral::kMaxSamples];  // a spectral picture has at most kMaxSamples
    const std::span<double> samples(buf, size_t(ps.n));
    pict.values(expr(r, 0), expr(r, 1), samples);
    for (int i = 0; i < ps.n; ++i) {
        const double args[2] = {samples[size_t(i)], ps.centre(i)};
        samples[size_t(i)] = eval.call(r.funcs[0].fn, std::span<const double>(args, 2));
    }
    double out[spectral::kMaxSamples];
    const std::span<double> working(out, size_t(chains.pass.sampling.n));
    spectral::toWorking(samples, ps.wl[0], ps.wl[3], chains.pass.sampling, working);
    return chains.pass.ofSamples(working);
}

// RADIANCE raymixture: both sides shaded with their share; a side that reaches no
// material is transparent if the other reaches one; if neither does, the pattern colours
// and perturbations blend and the walk goes on.
bool SurfaceChainEvaluator::Impl::mix(int32_t m, int32_t fore, int32_t back, double coef,
                                      WalkState& st, double weight, bool inTexture, int depth) {
    if (!(coef > 0)) coef = 0;  // NaN too
    if (coef > 1) coef = 1;
    WalkState fs = st, bs = st;
    int start = count;
    bool foreMat = false, backMat = false;
    bool doFore = coef > kFtiny, doBack = coef < 1 - kFtiny;
    if (doFore) {
        foreMat = shade(fore, fs, weight * coef, inTexture, depth + 1);
        // Transparent if the background turns out to reach a material (removed below
        // otherwise); kept beside its own side's layers for the random choice.
        if (!foreMat) push(kVoid, weight * coef, fs);
    }
    int mid = count;
    if (doBack) backMat = shade(back, bs, weight * (1 - coef), inTexture, depth + 1);
    if (!foreMat && !backMat) {
        count = start;
        st.pcol = fs.pcol * coef + bs.pcol * (1 - coef);
        st.pert = fs.pert * coef + bs.pert * (1 - coef);
        return false;
    }
    if (doBack && !backMat) push(kVoid, weight * (1 - coef), bs);
    if (count - start > ChainResult::kMaxLayers && doFore && doBack) {
        // Too many layers: keep one side, chosen with the mixture's probability, its
        // weights divided by that probability (the expectation is raymixture's).
        bool keepFore = rng->uniform() < coef;
        int from = keepFore ? start : mid, to = keepFore ? mid : count;
        double scale = keepFore ? 1 / coef : 1 / (1 - coef);
        int out = start;
        for (int i = from; i < to; ++i) {
            buf[out] = buf[i];
            buf[out++].weight *= scale;
        }
        count = out;
    }
    return true;
}

bool SurfaceChainEvaluator::Impl::shade(int32_t mod, WalkState& st, double weight, bool inTexture,
                                        int depth) {
    for (int32_t m = mod; m != kVoid; m = prim(m).modifier) {
        const Primitive& p = prim(m);
        const ChainRecord& r = chains.records[m];
        if (depth > kMaxDepth) throw InputError(p.loc, "modifier chain too deep");
        switch (r.kind) {
            case ChainKind::NotModifier:
            case ChainKind::Unsupported:
                throw notSupportedYet(p.loc, std::string(primTypeName(p.type)) + " '" + p.name +
                                                 "' in a modifier chain");
            case ChainKind::Material:
                if (inTexture)
                    throw InputError(p.loc, std::string(primTypeName(p.type)) + " '" + p.name +
                                                "': conflicting material in a modifier chain");
                // RADIANCE raytexture: the material's own modifiers apply before shading.
                shade(p.modifier, st, weight, true, depth + 1);
                push(m, weight, st);
                return true;
            case ChainKind::Func:
                setRay(r, p);
                if (r.colour)
                    st.pcol *= chains.pass.ofRgb({expr(r, 0), expr(r, 1), expr(r, 2)});
                else
                    st.pcol *= expr(r, 0);
                break;
            case ChainKind::Data: {
                setRay(r, p);
                auto v = dataValues(r);
                if (r.colour)
                    st.pcol *= chains.pass.ofRgb(channelFunctions(r, v));
                else
                    st.pcol *= call1(r.funcs[0], v[0]);
                break;
            }
            case ChainKind::Pict:
                setRay(r, p);
                st.pcol *= chains.pass.ofRgb(channelFunctions(r, pictValues(r)));
                break;
            case ChainKind::Text:
                st.pcol *= inText(r) ? r.textFore : r.textBack;
                break;
            case ChainKind::Spectrum:
                st.pcol *= r.constant;
                break;
            case ChainKind::SpecFunc:
                setRay(r, p);
                st.pcol *= specFunc(r);
                break;
            case ChainKind::SpecData:
                setRay(r, p);
                st.pcol *= specData(r);
                break;
            case ChainKind::SpecPict:
                setRay(r, p);
                st.pcol *= specPict(r);
                break;
            case ChainKind::TexFunc:
                setRay(r, p);
                addPerturbation(r, st, {expr(r, 0), expr(r, 1), expr(r, 2)});
                break;
            case ChainKind::TexData: {
                setRay(r, p);
                auto v = dataValues(r);
                addPerturbation(r, st,
                                {call3(r.funcs[0], v.data()), call3(r.funcs[1], v.data()),
                                 call3(r.funcs[2], v.data())});
                break;
            }
            case ChainKind::MixFunc:
                setRay(r, p);
                if (mix(m, r.foreMod, r.backMod, expr(r, 0), st, weight, inTexture, depth))
                    return true;
                break;
            case ChainKind::MixData: {
                setRay(r, p);
                double c = call1(r.funcs[0], dataValues(r)[0]);
                if (mix(m, r.foreMod, r.backMod, c, st, weight, inTexture, depth)) return true;
                break;
            }
            case ChainKind::MixPict: {
                setRay(r, p);
                auto v = pictValues(r);
                double c = call3(r.funcs[0], v.data());
                if (mix(m, r.foreMod, r.backMod, c, st, weight, inTexture, depth)) return true;
                break;
            }
            case ChainKind::MixText:
                // RADIANCE compat (text.c): not a blend, the point picks one modifier.
                if (shade(inText(r) ? r.foreMod : r.backMod, st, weight, inTexture, depth + 1)) {
                    if (p.modifier != kVoid)
                        throw InputError(p.loc, "mixtext '" + p.name + "': inappropriate modifier");
                    return true;
                }
                break;
        }
    }
    return false;
}

SurfaceChainEvaluator::SurfaceChainEvaluator(const SurfaceChains& chains)
    : impl_(std::make_unique<Impl>(*chains.impl_)) {}

SurfaceChainEvaluator::~SurfaceChainEvaluator() = default;

ChainResult SurfaceChainEvaluator::resolve(int32_t modifier, const PatternPoint& at, Rng& rng) {
    const SurfaceChains::Impl& c = impl_->chains;
    if (modifier == kVoid || c.plainMaterial[modifier] >= 0)
        return ChainResult::plain(modifier == kVoid ? kVoid : modifier);
    ChainResult res;
    Impl& im = *impl_;
    im.at = &at;
    im.rng = &rng;
    im.count = 0;
    WalkState st;
    // RADIANCE compat (raytrace.c): a chain that reaches no material leaves the surface
    // transparent.
    if (!im.shade(modifier, st, 1.0, false, 0)) im.push(kVoid, 1.0, st);
    res.count = std::min(im.count, ChainResult::kMaxLayers);
    std::copy(im.buf.begin(), im.buf.begin() + res.count, res.layers.begin());
    return res;
}

}  // namespace rp::material

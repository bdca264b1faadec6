// SurfaceChains: compiles every pattern, texture and mixture record of a scene once
// (function files into one calc Program, data files, pictures and fonts read), and the
// static questions about a chain (checkChain, isPlain). Evaluation is in
// surface_chain_eval.cpp.
#include "material/surface_chain.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

#include "calc/search_path.h"
#include "material/surface_chain_impl.h"

namespace rp::material {

namespace {

std::string what(const Primitive& p) {
    return std::string(primTypeName(p.type)) + " '" + p.name + "'";
}

[[noreturn]] void fail(const Primitive& p, const std::string& msg) {
    throw InputError(p.loc, what(p) + ": " + msg);
}

ChainKind kindOf(PrimType t) {
    switch (primCategory(t)) {
        case PrimCategory::Surface:
            return ChainKind::NotModifier;
        case PrimCategory::Material:
            return ChainKind::Material;
        case PrimCategory::Alias:
            return ChainKind::Unsupported;
        default:
            break;
    }
    switch (t) {
        case PrimType::Colorfunc:
        case PrimType::Brightfunc:
            return ChainKind::Func;
        case PrimType::Colordata:
        case PrimType::Brightdata:
            return ChainKind::Data;
        case PrimType::Colorpict:
            return ChainKind::Pict;
        case PrimType::Colortext:
        case PrimType::Brighttext:
            return ChainKind::Text;
        case PrimType::Texfunc:
            return ChainKind::TexFunc;
        case PrimType::Texdata:
            return ChainKind::TexData;
        case PrimType::Mixfunc:
            return ChainKind::MixFunc;
        case PrimType::Mixdata:
            return ChainKind::MixData;
        case PrimType::Mixpict:
            return ChainKind::MixPict;
        case PrimType::Mixtext:
            return ChainKind::MixText;
        case PrimType::Spectrum:
        case PrimType::Specfile:
            return ChainKind::Spectrum;
        case PrimType::Specfunc:
            return ChainKind::SpecFunc;
        case PrimType::Specdata:
            return ChainKind::SpecData;
        case PrimType::Specpict:
            return ChainKind::SpecPict;
        default:
            return ChainKind::Unsupported;
    }
}

// Loads files and tables once per name; everything found along the search path.
class Loader {
public:
    explicit Loader(std::vector<std::string> path) : builder(path), path_(std::move(path)) {
        builder.loadFile("rayinit.cal");
    }

    std::string find(const Primitive& p, const std::string& name, const char* kind) {
        auto found = calc::findFile(name, path_);
        if (!found) fail(p, std::string("cannot find ") + kind + " '" + name + "'");
        return *found;
    }

    // RADIANCE compat: function files share one context, each loaded once in order of
    // first use after rayinit.cal.
    void loadFunctionFile(const Primitive& p, const std::string& file) {
        if (file == "." || loadedFiles_.count(file)) return;
        try {
            builder.loadFile(file);
        } catch (const InputError& e) {
            if (e.loc().line > 0) throw;  // a syntax error names its own file:line
            fail(p, e.what());
        }
        loadedFiles_[file] = true;
    }

    std::shared_ptr<const calc::DataFile> data(const Primitive& p, const std::string& name) {
        return cached(data_, p, name, "data file",
                      [](const std::string& path) { return calc::DataFile::load(path); });
    }

    std::shared_ptr<const PictTable> pict(const Primitive& p, const std::string& name) {
        return cached(picts_, p, name, "picture file",
                      [](const std::string& path) { return PictTable::load(path); });
    }

    std::shared_ptr<const PictTable> spectralPict(const Primitive& p, const std::string& name) {
        return cached(spectralPicts_, p, name, "hyperspectral image",
                      [](const std::string& path) { return PictTable::loadSpectral(path); });
    }

    std::shared_ptr<const Font> font(const Primitive& p, const std::string& name) {
        auto it = fonts_.find(name);
        if (it != fonts_.end()) return it->second;
        std::string path = find(p, name, "font file");
        std::shared_ptr<const Font> f = Font::load(path);
        return fonts_[name] = f;
    }

    std::vector<std::string> textLines(const Primitive& p, const std::string& name) {
        std::ifstream in(find(p, name, "text file"));
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            lines.push_back(line);
        }
        return lines;
    }

    calc::Builder builder;

private:
    // Each file loaded once per name, found along the search path; its errors name the
    // record (a file's own syntax errors keep their file:line).
    template <class T, class Load>
    std::shared_ptr<const T> cached(std::map<std::string, std::shared_ptr<const T>>& cache,
                                    const Primitive& p, const std::string& name, const char* kind,
                                    const Load& load) {
        auto it = cache.find(name);
        if (it != cache.end()) return it->second;
        const std::string path = find(p, name, kind);
        std::shared_ptr<const T> t;
        try {
            t = std::make_shared<const T>(load(path));
        } catch (const InputError& e) {
            if (e.loc().line > 0) throw;
            fail(p, e.what());
        }
        return cache[name] = t;
    }

    std::vector<std::string> path_;
    std::map<std::string, bool> loadedFiles_;
    std::map<std::string, std::shared_ptr<const calc::DataFile>> data_;
    std::map<std::string, std::shared_ptr<const PictTable>> picts_, spectralPicts_;
    std::map<std::string, std::shared_ptr<const Font>> fonts_;
};

// RADIANCE compat (modobject.c lastmod): a mixture's foreground and background are the
// latest modifiers of those names defined before the mixture itself.
int32_t lookupModifier(const Scene& s, int32_t before, const std::string& name) {
    if (name == "void") return kVoid;
    for (int32_t i = before; i-- > 0;)
        if (isModifier(s.prims[i].type) && s.prims[i].name == name) return i;
    fail(s.prims[before], "undefined modifier '" + name + "'");
}

// Whether an expression's text names a ray variable that depends on the point rather
// than only the direction. Only meaningful when no function file is loaded.

// Function file at `fileAt`, then `nexpr` expressions at `exprAt`, then the transform.
void compileFunctions(Loader& ld, const Primitive& p, ChainRecord& r, size_t fileAt, size_t exprAt,
                      size_t nexpr, size_t xfAt) {
    if (p.sargs.size() < xfAt)
        fail(p, "expected at least " + std::to_string(xfAt) + " string arguments, got " +
                    std::to_string(p.sargs.size()));
    ld.loadFunctionFile(p, p.sargs[fileAt]);
    r.directional = true;  // judged once the program is built (directionOnly)
    for (size_t k = 0; k < nexpr; ++k)
        r.exprIds.push_back(ld.builder.addExpression(p.sargs[exprAt + k], p.loc));
    r.forward = parseTransform(p.sargs, xfAt, p.loc);
    r.toObject = r.forward.inverse();
    r.hasTransform = !r.forward.isIdentity();
}

// Data records: `ndata` tables from `dataAt`, function file, then one coordinate
// expression per dimension of the tables, then the transform.
void compileData(Loader& ld, const Primitive& p, ChainRecord& r, size_t dataAt, size_t ndata,
                 size_t fileAt) {
    for (size_t k = 0; k < ndata; ++k) {
        r.data[k] = ld.data(p, p.sargs.at(dataAt + k));
        if (r.data[k]->dimensions() != r.data[0]->dimensions())
            fail(p, "dimension error: data files '" + p.sargs[dataAt] + "' and '" +
                        p.sargs[dataAt + k] + "' differ in dimensions");
    }
    size_t nd = size_t(r.data[0]->dimensions());
    size_t coordsAt = fileAt + 1;
    if (p.sargs.size() < coordsAt + nd ||
        (p.sargs.size() > coordsAt + nd && !isTransformOption(p.sargs[coordsAt + nd])))
        fail(p, "dimension error: data file '" + p.sargs[dataAt] + "' has " + std::to_string(nd) +
                    " dimension(s), the record gives " +
                    std::to_string(p.sargs.size() > coordsAt ? p.sargs.size() - coordsAt : 0) +
                    " coordinate(s) and transform argument(s)");
    compileFunctions(ld, p, r, fileAt, coordsAt, nd, coordsAt + nd);
}

void compileText(Loader& ld, const Primitive& p, ChainRecord& r, size_t fontAt, size_t spacingAt) {
    size_t textAt = fontAt + 1;
    if (p.sargs.size() <= textAt) fail(p, "missing text file or text");
    std::vector<std::string> lines;
    if (p.sargs.size() > textAt + 1) {  // "fontfile . words ...": one line of text
        std::string line;
        for (size_t k = textAt + 1; k < p.sargs.size(); ++k)
            line += (line.empty() ? "" : " ") + p.sargs[k];
        lines.push_back(line);
    } else {
        lines = ld.textLines(p, p.sargs[textAt]);
    }
    auto font = ld.font(p, p.sargs[fontAt]);
    const auto& a = p.rargs;
    if (a.size() < spacingAt)
        fail(p, "expected at least " + std::to_string(spacingAt) + " real arguments");
    bool hasSpacing = a.size() > spacingAt;
    try {
        r.text = std::make_shared<const TextBlock>(font, std::move(lines), Vec3(a[0], a[1], a[2]),
                                                   Vec3(a[3], a[4], a[5]), Vec3(a[6], a[7], a[8]),
                                                   hasSpacing, hasSpacing ? a[spacingAt] : 0.0);
    } catch (const InputError& e) {
        fail(p, e.what());
    }
}

// A spectrum (bands from wl0 to wl1) as the pass renders it.
Color workingColour(const std::vector<double>& samples, double wl0, double wl1,
                    const spectral::Pass& pass) {
    double out[spectral::kMaxSamples];
    const std::span<double> working(out, size_t(pass.sampling.n));
    spectral::toWorking(samples, wl0, wl1, pass.sampling, working);
    return pass.ofSamples(working);
}

// spectrum: "nmA nmB s1 s2 ...", samples at evenly spaced wavelengths from nmA to nmB
// (each the centre of its band).
Color compileSpectrum(const Primitive& p, const spectral::Pass& s) {
    const auto& a = p.rargs;
    const size_t n = a.size() - 2;
    const double half = 0.5 * (a[1] - a[0]) / double(n - 1);
    if (!(std::fabs(a[1] - a[0]) > 0)) fail(p, "the wavelength range is empty");
    return workingColour(std::vector<double>(a.begin() + 2, a.end()), a[0] - half, a[1] + half, s);
}

// specfile: a 1-D data file over wavelength. RADIANCE compat (p_data.c): listed
// wavelengths are sampled twice as densely as there are points. RADIANCE then spreads
// only the first half of those samples over the range; all of them are used here.
Color compileSpecfile(Loader& ld, const Primitive& p, const spectral::Pass& s) {
    auto d = ld.data(p, p.sargs.at(0));
    if (d->dimensions() != 1) fail(p, "data file must be 1-dimensional");
    const calc::DataFile::Axis& ax = d->axis(0);
    const bool listed = !ax.points.empty();
    const double first = listed ? ax.points.front() : ax.begin;
    const double range = (listed ? ax.points.back() : ax.end) - first;
    const int n = listed ? 2 * ax.count : ax.count;
    if (n < 2 || range == 0) fail(p, "data file must span a range of wavelengths");
    const double step = range / (n - 1);
    std::vector<double> samples(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) {
        const double wl = first + k * step;
        samples[size_t(k)] = d->value(std::span<const double>(&wl, 1));
    }
    return workingColour(samples, first - 0.5 * step, first + range + 0.5 * step, s);
}

void compileRecord(Loader& ld, const Scene& s, int32_t index, ChainRecord& r,
                   const spectral::Pass& pass) {
    const Primitive& p = s.prims[index];
    const auto& sa = p.sargs;
    switch (p.type) {
        case PrimType::Colorfunc:
            r.colour = true;
            compileFunctions(ld, p, r, 3, 0, 3, 4);
            break;
        case PrimType::Brightfunc:
            compileFunctions(ld, p, r, 1, 0, 1, 2);
            break;
        case PrimType::Texfunc:
            compileFunctions(ld, p, r, 3, 0, 3, 4);
            break;
        case PrimType::Colordata:
            r.colour = true;
            r.funcNames = {sa.at(0), sa.at(1), sa.at(2)};
            compileData(ld, p, r, 3, 3, 6);
            break;
        case PrimType::Brightdata:
            r.funcNames = {sa.at(0)};
            compileData(ld, p, r, 1, 1, 2);
            break;
        case PrimType::Texdata:
            r.funcNames = {sa.at(0), sa.at(1), sa.at(2)};
            compileData(ld, p, r, 3, 3, 6);
            break;
        case PrimType::Colorpict:
            r.colour = true;
            r.funcNames = {sa.at(0), sa.at(1), sa.at(2)};
            r.pict = ld.pict(p, sa.at(3));
            compileFunctions(ld, p, r, 4, 5, 2, 7);
            break;
        case PrimType::Colortext:
            r.colour = true;
            compileText(ld, p, r, 0, 15);
            r.textFore = pass.ofRgb({p.rargs[9], p.rargs[10], p.rargs[11]});
            r.textBack = pass.ofRgb({p.rargs[12], p.rargs[13], p.rargs[14]});
            break;
        case PrimType::Brighttext:
            compileText(ld, p, r, 0, 11);
            r.textFore = Color::grey(p.rargs[9]);
            r.textBack = Color::grey(p.rargs[10]);
            break;
        case PrimType::Mixfunc:
            r.foreMod = lookupModifier(s, index, sa.at(0));
            r.backMod = lookupModifier(s, index, sa.at(1));
            compileFunctions(ld, p, r, 3, 2, 1, 4);
            break;
        case PrimType::Mixdata:
            r.foreMod = lookupModifier(s, index, sa.at(0));
            r.backMod = lookupModifier(s, index, sa.at(1));
            r.funcNames = {sa.at(2)};
            compileData(ld, p, r, 3, 1, 4);
            break;
        case PrimType::Mixpict:
            r.foreMod = lookupModifier(s, index, sa.at(0));
            r.backMod = lookupModifier(s, index, sa.at(1));
            r.funcNames = {sa.at(2)};
            r.pict = ld.pict(p, sa.at(3));
            compileFunctions(ld, p, r, 4, 5, 2, 7);
            break;
        case PrimType::Mixtext:
            r.foreMod = lookupModifier(s, index, sa.at(0));
            r.backMod = lookupModifier(s, index, sa.at(1));
            compileText(ld, p, r, 2, 9);
            break;
        case PrimType::Spectrum:
            r.constant = compileSpectrum(p, pass);
            break;
        case PrimType::Specfile:
            r.constant = compileSpecfile(ld, p, pass);
            break;
        case PrimType::Specfunc:
            r.funcNames = {sa.at(0)};
            r.wlMin = std::min(p.rargs[0], p.rargs[1]);
            r.wlMax = std::max(p.rargs[0], p.rargs[1]);
            compileFunctions(ld, p, r, 1, 2, 0, 2);
            break;
        case PrimType::Specpict:  // sfunc specfile funcfile u v transform
            r.funcNames = {sa.at(0)};
            r.pict = ld.spectralPict(p, sa.at(1));
            compileFunctions(ld, p, r, 2, 3, 2, 5);
            break;
        case PrimType::Specdata: {
            // The data's last dimension is wavelength; one coordinate per other one.
            r.funcNames = {sa.at(0)};
            r.data[0] = ld.data(p, sa.at(1));
            const size_t nd = size_t(r.data[0]->dimensions());
            if (nd < 2) fail(p, "need at least 2-dimensional data");
            if (sa.size() < 3 + nd - 1 || (sa.size() > 2 + nd && !isTransformOption(sa[2 + nd])))
                fail(p, "dimension error: data file '" + sa[1] + "' has " + std::to_string(nd) +
                            " dimensions, so the record needs " + std::to_string(nd - 1) +
                            " coordinate(s) before its transform");
            compileFunctions(ld, p, r, 2, 3, nd - 1, 2 + nd);
            break;
        }
        default:
            break;
    }
}

// How many values each named function of a record is called with (ray.html).
bool callsWithThree(PrimType t, const calc::Function& f) {
    switch (t) {
        case PrimType::Texdata:
        case PrimType::Mixpict:
            return true;
        case PrimType::Colordata:
        case PrimType::Colorpict:
            return f.nparams >= 3;
        default:
            return false;  // brightdata, mixdata
    }
}

// Whether a record's expressions and functions read the ray's direction only (and the
// record's own transform), so that a source's emission through it is one table for
// every point (light/emitter.cpp). skybright.cal's sky qualifies.
bool directionOnly(const calc::Program& prog, const ChainRecord& r) {
    static constexpr std::string_view kAllowed[] = {"Dx", "Dy", "Dz", "S",  "Tx", "Ty", "Tz", "Ix",
                                                    "Iy", "Iz", "Jx", "Jy", "Jz", "Kx", "Ky", "Kz"};
    for (int id : r.exprIds)
        if (!prog.readsOnly(id, kAllowed)) return false;
    for (const auto& f : r.funcs)
        if (!prog.readsOnly(f.fn, kAllowed)) return false;
    return true;
}

}  // namespace

SurfaceChains::SurfaceChains(const Scene& scene, std::vector<std::string> searchPath,
                             const spectral::Pass& pass)
    : impl_(std::make_unique<Impl>(scene, pass)) {
    size_t n = scene.prims.size();
    impl_->records.resize(n);
    impl_->plainMaterial.assign(n, -2);
    Loader ld(std::move(searchPath));
    for (size_t i = 0; i < n; ++i) {
        ChainRecord& r = impl_->records[i];
        r.kind = kindOf(scene.prims[i].type);
        compileRecord(ld, scene, int32_t(i), r, impl_->pass);
    }
    impl_->program = ld.builder.build();
    const calc::Program& prog = *impl_->program;
    for (size_t i = 0; i < n; ++i) {
        ChainRecord& r = impl_->records[i];
        const Primitive& p = scene.prims[i];
        for (int id : r.exprIds) r.exprs.push_back(prog.expression(id));
        for (const std::string& name : r.funcNames) {
            auto f = prog.function(name);
            if (!f) fail(p, "undefined function '" + name + "'");
            r.funcs.push_back({*f, callsWithThree(p.type, *f)});
        }
        r.directional = r.directional && directionOnly(prog, r);
        if (r.kind == ChainKind::Material && p.modifier == kVoid)
            impl_->plainMaterial[i] = int32_t(i);
    }
}

SurfaceChains::~SurfaceChains() = default;

const Scene& SurfaceChains::scene() const { return *impl_->scene; }

const MaterialTable& SurfaceChains::materials() const { return impl_->materials; }

namespace {

void checkFrom(const Scene& s, const std::vector<ChainRecord>& records, int32_t mod, bool inTexture,
               int depth) {
    for (int32_t m = mod; m != kVoid; m = s.prims[m].modifier) {
        const Primitive& p = s.prims[m];
        const ChainRecord& r = records[m];
        // Modifiers refer to earlier records only, so chains cannot loop; the bound is
        // against pathological nesting.
        if (depth > 200) fail(p, "modifier chain too deep");
        switch (r.kind) {
            case ChainKind::NotModifier:
                fail(p, "a surface cannot modify another primitive");
            case ChainKind::Unsupported:
                throw notSupportedYet(p.loc, what(p) + " in a modifier chain");
            case ChainKind::Material:
                // RADIANCE compat (raytrace.c raytexture): a material's own chain may hold
                // only patterns, textures and mixtures of them.
                if (inTexture) fail(p, "conflicting material in a modifier chain");
                checkFrom(s, records, p.modifier, true, depth + 1);
                return;
            default:
                if (isMixtureKind(r.kind)) {
                    checkFrom(s, records, r.foreMod, inTexture, depth + 1);
                    checkFrom(s, records, r.backMod, inTexture, depth + 1);
                }
                break;
        }
    }
}

}  // namespace

void SurfaceChains::checkChain(int32_t modifier) const {
    checkFrom(*impl_->scene, impl_->records, modifier, false, 0);
}

bool SurfaceChains::isPlain(int32_t modifier) const {
    return modifier == kVoid || impl_->plainMaterial[modifier] >= 0;
}

bool SurfaceChains::directionalOnly(int32_t modifier) const {
    for (int32_t m = modifier; m != kVoid; m = impl_->scene->prims[m].modifier) {
        const ChainRecord& r = impl_->records[m];
        if (r.kind == ChainKind::Spectrum) continue;  // a constant
        // Patterns whose value follows from their expressions (pictures and data are
        // fixed tables); textures and mixtures are not judged.
        const bool judged = r.kind == ChainKind::Func || r.kind == ChainKind::Data ||
                            r.kind == ChainKind::Pict || r.kind == ChainKind::SpecFunc ||
                            r.kind == ChainKind::SpecData || r.kind == ChainKind::SpecPict;
        if (!judged || !r.directional) return false;
    }
    return true;
}

int32_t SurfaceChains::plainMaterial(int32_t modifier) const {
    if (modifier == kVoid) return kVoid;
    int32_t m = impl_->plainMaterial[modifier];
    return m >= 0 ? m : kVoid;
}

}  // namespace rp::material

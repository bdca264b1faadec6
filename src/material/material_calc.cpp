#include "material/material_calc.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include "calc/search_path.h"
#include "material/function_space.h"
#include "material/material_table.h"
#include "material/surface_chain.h"
#include "util/error.h"

namespace rp::material {

namespace {

Vec3 toVec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
std::array<double, 3> toArr(const Vec3& v) { return {v.x, v.y, v.z}; }

std::optional<double> number(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return v;
}

std::string what(const Primitive& p) {
    return std::string(primTypeName(p.type)) + " '" + p.name + "'";
}

[[noreturn]] void fail(const Primitive& p, const std::string& msg) {
    throw InputError(p.loc, what(p) + ": " + msg);
}

// Where the function file sits in each family's string arguments (ray.html).
size_t funcFileIndex(PrimType t) {
    switch (t) {
        case PrimType::Plastic2:
        case PrimType::Metal2:
        case PrimType::Trans2:
        case PrimType::Ashik2:
            return 3;  // ux uy uz funcfile transform
        case PrimType::Plasdata:
        case PrimType::Metdata:
        case PrimType::Transdata:
            return 2;  // func datafile funcfile x1 .. xN transform
        case PrimType::BRTDfunc:
            return 9;  // 6 colours, 3 brtd functions, funcfile
        case PrimType::Prism1:
            return 4;  // coef dx dy dz funcfile transform
        case PrimType::Prism2:
            return 8;  // coef1 dx1 dy1 dz1 coef2 dx2 dy2 dz2 funcfile
        case PrimType::BSDF:
            return 5;  // thick file ux uy uz funcfile transform
        case PrimType::ABSDF:
            return 4;  // file ux uy uz funcfile transform
        case PrimType::WGMDfunc:
            return 12;  // 3 modifiers, 6 coefficients, ux uy uz, funcfile
        default:
            return 1;  // func funcfile transform
    }
}

// Function files (RADIANCE compat: one global context, each file loaded once in order of
// first use after rayinit.cal) and data files, found along the search path.
class Loader {
public:
    explicit Loader(std::vector<std::string> path) : builder(path), path_(std::move(path)) {
        builder.loadFile("rayinit.cal");
    }

    void functionFile(const Primitive& p, const std::string& file) {
        if (file == "." || std::find(loaded_.begin(), loaded_.end(), file) != loaded_.end()) return;
        try {
            builder.loadFile(file);
        } catch (const InputError& e) {
            if (e.loc().line > 0) throw;  // a syntax error names its own file:line
            fail(p, e.what());
        }
        loaded_.push_back(file);
    }

    std::shared_ptr<const calc::DataFile> data(const Primitive& p, const std::string& name) {
        if (auto it = data_.find(name); it != data_.end()) return it->second;
        auto found = calc::findFile(name, path_);
        if (!found) fail(p, "cannot find data file '" + name + "'");
        std::shared_ptr<const calc::DataFile> d;
        try {
            d = std::make_shared<const calc::DataFile>(calc::DataFile::load(*found));
        } catch (const InputError& e) {
            if (e.loc().line > 0) throw;
            fail(p, e.what());
        }
        return data_[name] = d;
    }

    std::shared_ptr<const bsdf::BsdfData> bsdf(const Primitive& p, const std::string& name) {
        if (auto it = bsdf_.find(name); it != bsdf_.end()) return it->second;
        auto found = calc::findFile(name, path_);
        if (!found) fail(p, "cannot find BSDF file '" + name + "'");
        return bsdf_[name] = bsdf::loadBsdfFile(*found);  // its errors name the XML's line
    }

    calc::Builder builder;

private:
    std::vector<std::string> path_;
    std::vector<std::string> loaded_;
    std::map<std::string, std::shared_ptr<const calc::DataFile>> data_;
    std::map<std::string, std::shared_ptr<const bsdf::BsdfData>> bsdf_;
};

// BSDF/aBSDF: the data and the expressions of the up vector and thickness (a template
// only to reach MaterialCalc's private Record type).
template <class Record>
void addBsdf(const Primitive& p, Loader& loader, Record& r, const spectral::Pass& pass) {
    const bool thick = p.type == PrimType::BSDF;
    r.bsdf = loader.bsdf(p, p.sargs[thick ? 1 : 0]);
    // Expressions: the up vector's three, then the thickness (aBSDF: the constant 0).
    const int at[4] = {thick ? 2 : 1, thick ? 3 : 2, thick ? 4 : 3, thick ? 0 : -1};
    for (int k = 0; k < 4; ++k) {
        if (at[k] < 0) {
            r.exprConstant[k] = true;
            continue;
        }
        const std::string& e = p.sargs[size_t(at[k])];
        if (auto v = number(e)) {
            r.exprConstant[k] = true;
            r.exprValue[k] = *v;
        } else {
            r.expr[k] = loader.builder.addExpression(e, p.loc);
        }
    }
}

// WGMDfunc's component modifiers other than "void", "inherit" and the material's own
// (m_wgmdf.c fill_modval; RADIANCE finds them when first shaded, we at load).
void setWgmdModifiers(const Scene& scene, int32_t material, int32_t (&out)[3]) {
    const Primitive& p = scene.prims[size_t(material)];
    const WgmdParams m = std::get<WgmdParams>(makeMaterial(p));
    static const char* const kWhat[3] = {"specular reflection", "specular transmission",
                                         "diffuse transmission"};
    for (int c = 0; c < 3; ++c) {
        if (m.mod[size_t(c)] != WgmdParams::Mod::Named) continue;
        out[c] = lastModifier(scene, material, m.modName[size_t(c)]);
        if (out[c] == kVoid)
            fail(p,
                 std::string("unknown ") + kWhat[c] + " modifier '" + m.modName[size_t(c)] + "'");
    }
}

}  // namespace

MaterialCalc::MaterialCalc(const Scene& scene, std::vector<std::string> searchPath,
                           const spectral::Pass& pass)
    : recordOf_(scene.prims.size(), -1), pass_(pass) {
    Loader loader(std::move(searchPath));
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        const Primitive& p = scene.prims[i];
        Record r;
        switch (p.type) {
            case PrimType::Plastic2:
            case PrimType::Metal2:
            case PrimType::Trans2:
            case PrimType::Ashik2:
                r.kind = Kind::Aniso;
                break;
            case PrimType::Plasfunc:
            case PrimType::Metfunc:
            case PrimType::Transfunc:
                r.kind = Kind::Func;
                break;
            case PrimType::Plasdata:
            case PrimType::Metdata:
            case PrimType::Transdata:
                r.kind = Kind::Data;
                break;
            case PrimType::BRTDfunc:
                r.kind = Kind::Brtd;
                break;
            case PrimType::Prism1:
            case PrimType::Prism2:
                r.kind = Kind::Prism;
                break;
            case PrimType::BSDF:
            case PrimType::ABSDF:
                r.kind = Kind::Bsdf;
                break;
            case PrimType::WGMDfunc:
                r.kind = Kind::Wgmd;
                break;
            default:
                continue;
        }
        r.prim = int32_t(i);
        r.type = p.type;
        r.rargs = p.rargs;
        size_t ff = funcFileIndex(p.type);
        if (p.sargs.size() <= ff) fail(p, "too few string arguments");  // reader checks this
        size_t xfFirst = ff + 1;
        if (r.kind == Kind::Data) {
            r.data = loader.data(p, p.sargs[1]);
            size_t nd = size_t(r.data->dimensions());
            if (p.sargs.size() < xfFirst + nd)
                fail(p, "data file '" + p.sargs[1] + "' has " + std::to_string(nd) +
                            " dimensions but fewer coordinate functions are given");
            r.coords.resize(nd);
            for (size_t k = 0; k < nd; ++k) r.coords[k].name = p.sargs[xfFirst + k];
            xfFirst += nd;
        }
        loader.functionFile(p, p.sargs[ff]);
        r.forward = parseTransform(p.sargs, xfFirst, p.loc);
        r.toObject = r.forward.inverse();
        if (r.kind == Kind::Bsdf) {
            addBsdf(p, loader, r, pass);
            recordOf_[i] = int32_t(records_.size());
            records_.push_back(std::move(r));
            continue;
        }

        int nexpr = r.kind == Kind::Aniso   ? 3
                    : r.kind == Kind::Brtd  ? 6
                    : r.kind == Kind::Prism ? int(ff)
                    : r.kind == Kind::Wgmd  ? 9
                                            : 0;
        // WGMDfunc's expressions sit between its modifier names (ray.html).
        constexpr size_t kWgmdExpr[9] = {1, 2, 3, 5, 6, 7, 9, 10, 11};
        bool allConstant = true;
        for (int k = 0; k < nexpr; ++k) {
            const std::string& e = p.sargs[r.kind == Kind::Wgmd ? kWgmdExpr[k] : size_t(k)];
            if (auto v = number(e)) {
                r.exprConstant[k] = true;
                r.exprValue[k] = *v;
            } else {
                r.expr[k] = loader.builder.addExpression(e, p.loc);
                allConstant = false;
            }
        }
        if (r.kind == Kind::Wgmd) {
            r.needed = !allConstant;
            setWgmdModifiers(scene, int32_t(i), r.wgmdMod);
        }
        if (r.kind == Kind::Func || r.kind == Kind::Data) r.fn[0].name = p.sargs[0];
        if (r.kind == Kind::Brtd) {
            bool allConstant = true;
            for (int k = 0; k < 6; ++k) allConstant = allConstant && r.exprConstant[k];
            bool anyBrtd = false;
            for (int k = 0; k < 3; ++k) {
                // RADIANCE compat (m_brdf.c): a name starting with '0' means no function.
                const std::string& s = p.sargs[6 + k];
                r.fn[k].name = s.empty() || s[0] == '0' ? "0" : s;
                anyBrtd = anyBrtd || r.fn[k].name != "0";
            }
            r.needed = !allConstant || anyBrtd;
        }
        recordOf_[i] = int32_t(records_.size());
        records_.push_back(std::move(r));
    }
    program_ = loader.builder.build();

    // Resolve the named functions now so that a misspelt name is an error at its line.
    for (Record& r : records_) {
        const Primitive& p = scene.prims[r.prim];
        auto resolve = [&](Callable& c) {
            if (auto v = number(c.name)) {
                c.how = Callable::How::Constant;
                c.value = *v;
            } else if (auto f = program_->function(c.name)) {
                c.how = Callable::How::Function;
                c.function = *f;
            } else if (auto e = program_->variable(c.name)) {
                c.how = Callable::How::Variable;
                c.variable = *e;
            } else {
                fail(p, "unknown function '" + c.name + "'");
            }
        };
        if (r.kind != Kind::Aniso && r.kind != Kind::Prism && r.kind != Kind::Bsdf &&
            r.kind != Kind::Wgmd)
            for (int k = 0; k < (r.kind == Kind::Brtd ? 3 : 1); ++k) resolve(r.fn[k]);
        for (Callable& c : r.coords) resolve(c);
    }
}

MaterialCalc::~MaterialCalc() = default;

bool MaterialCalc::uses(int32_t material) const {
    if (material < 0 || size_t(material) >= recordOf_.size()) return false;
    int32_t r = recordOf_[material];
    return r >= 0 && records_[r].needed;
}

int32_t MaterialCalc::wgmdModifier(int32_t material, int component) const {
    if (material < 0 || size_t(material) >= recordOf_.size() || recordOf_[material] < 0)
        return kVoid;
    const Record& r = records_[size_t(recordOf_[material])];
    return r.kind == Kind::Wgmd ? r.wgmdMod[component] : kVoid;
}

MaterialCalcEvaluator::MaterialCalcEvaluator(const MaterialCalc& calc)
    : calc_(calc), eval_(calc.program_) {}

MaterialCalcEvaluator::~MaterialCalcEvaluator() = default;

void MaterialCalcEvaluator::setHit(int32_t material, const PatternPoint& at,
                                   const Vec3& shadingNormal, const Color& pattern) {
    RP_CHECK(material >= 0 && size_t(material) < calc_.recordOf_.size() &&
             calc_.recordOf_[material] >= 0);
    rec_ = &calc_.records_[calc_.recordOf_[material]];
    // The same function-space values as patterns see (func.c setfunc).
    const Transform t = functionTransform(at, rec_->toObject);
    npTransform_ = t;
    ctxDir_ = at.dir;
    ctx_ = functionSpace(at, rec_->toObject);
    object_ = at.object;
    if (at.rdot < 0 &&
        (rec_->kind == MaterialCalc::Kind::Func || rec_->kind == MaterialCalc::Kind::Data)) {
        // m_brdf.c m_brdf2 turns the surface to the ray (flipsurface) before its
        // functions run, so on the back they see N and Rdot reversed; BRTDfunc does not.
        ctx_.N = -ctx_.N;
        ctx_.Rdot = -ctx_.Rdot;
    }
    // m_brdf.c setbrdfunc: the perturbed normal through the same transform as N (unit:
    // divided by its scale); the material colour (first three reals) times the pattern
    // for *func/*data, the pattern alone for BRTDfunc. Both material routines orient the
    // normal towards the ray.
    ctx_.NP = toVec(t.direction(toArr(shadingNormal))) / t.scale;
    ctx_.RdotP = std::clamp(-dot(at.dir, shadingNormal), -1.0, 1.0);
    ctx_.CP = {pattern.r, pattern.g, pattern.b};
    if (rec_->kind != MaterialCalc::Kind::Brtd && rec_->rargs.size() >= 3)
        ctx_.CP = {rec_->rargs[0] * pattern.r, rec_->rargs[1] * pattern.g,
                   rec_->rargs[2] * pattern.b};
    ctx_.args = rec_->rargs;
    eval_.setRay(ctx_);
    errorsAtHit_ = eval_.mathErrors();
    serial_ = ++nextSerial_;
    hitMaterial_ = material;
    hitAt_ = at;
    hitNormal_ = shadingNormal;
    hitPattern_ = pattern;
}

BoundHit MaterialCalcEvaluator::bound() {
    BoundHit b;
    b.ev_ = this;
    b.serial_ = serial_;
    b.material_ = hitMaterial_;
    b.at_ = hitAt_;
    b.normal_ = hitNormal_;
    b.pattern_ = hitPattern_;
    return b;
}

void MaterialCalcEvaluator::restore(const BoundHit& hit) {
    if (serial_ == hit.serial_) return;
    setHit(hit.material_, hit.at_, hit.normal_, hit.pattern_);
    serial_ = hit.serial_;
}

Color BoundHit::operator()(const Vec3& toLight) const {
    RP_CHECK(ev_);
    ev_->restore(*this);
    return ev_->directional(toLight);
}

Vec3 MaterialCalcEvaluator::anisoU() {
    RP_CHECK(rec_ && rec_->kind == MaterialCalc::Kind::Aniso);
    std::array<double, 3> u;
    for (int k = 0; k < 3; ++k)
        u[k] = rec_->exprConstant[k] ? rec_->exprValue[k]
                                     : eval_.eval(calc_.program_->expression(rec_->expr[k]));
    if (eval_.mathErrors() != errorsAtHit_) return {};  // aniso.c: "compute error", punt
    Vec3 w = toVec(rec_->forward.direction(u));
    double len = length(w);
    return len > 0 && std::isfinite(len) ? w / len : Vec3{};
}

void MaterialCalcEvaluator::setBsdfInputs(SurfacePoint& sp) {
    RP_CHECK(rec_ && rec_->kind == MaterialCalc::Kind::Bsdf);
    double v[4];
    for (int k = 0; k < 4; ++k)
        v[k] = rec_->exprConstant[k] ? rec_->exprValue[k]
                                     : eval_.eval(calc_.program_->expression(rec_->expr[k]));
    sp.bsdf = rec_->bsdf.get();
    // m_bsdf.c: a thickness within FTINY of 0 is 0; both through the modifier's transform,
    // then the object's.
    double thick = std::abs(v[3]) <= 1e-6 ? 0.0 : v[3];
    Vec3 up = rec_->forward.mapDirection(Vec3{v[0], v[1], v[2]});
    thick *= rec_->forward.scale;
    if (object_) {
        up = object_->forward.mapDirection(up);
        thick *= object_->forward.scale;
    }
    sp.uDir = up;
    sp.bsdfThickness = thick;
}

void MaterialCalcEvaluator::brtdSpecular(Color& reflection, Color& transmission) {
    RP_CHECK(rec_ && rec_->kind == MaterialCalc::Kind::Brtd);
    double v[6];
    for (int k = 0; k < 6; ++k)
        v[k] = rec_->exprConstant[k] ? rec_->exprValue[k]
                                     : eval_.eval(calc_.program_->expression(rec_->expr[k]));
    reflection = calc_.pass_.ofRgb({v[0], v[1], v[2]});
    transmission = calc_.pass_.ofRgb({v[3], v[4], v[5]});
}

Redirection MaterialCalcEvaluator::redirect(int n, const Vec3& toSource) {
    RP_CHECK(rec_ && rec_->kind == MaterialCalc::Kind::Prism && n >= 0 &&
             4 * n + 3 < MaterialCalc::Record::kMaxExpr);
    // DxA..: the direction through the world -> function transform, as D (m_direct.c);
    // inside an instance through the object's space first.
    const Transform t = object_ ? rec_->toObject * object_->backward : rec_->toObject;
    ctx_.DA = t.mapDirection(toSource) / t.scale;
    eval_.setRay(ctx_);
    long before = eval_.mathErrors();
    double v[4];
    for (int k = 0; k < 4; ++k) {
        int i = 4 * n + k;
        v[k] = rec_->exprConstant[i] ? rec_->exprValue[i]
                                     : eval_.eval(calc_.program_->expression(rec_->expr[i]));
    }
    Redirection r;
    if (eval_.mathErrors() != before) return r;  // m_direct.c: "compute error"
    // Back to world space by the forward transforms (m_direct.c: the modifier's, then
    // the object's).
    Vec3 d = rec_->forward.mapDirection(Vec3{v[1], v[2], v[3]});
    if (object_) d = object_->forward.mapDirection(d);
    double len = length(d);
    if (!(len > 0) || !std::isfinite(len) || !std::isfinite(v[0])) return r;
    r.coef = v[0];
    r.dir = d / len;
    r.ok = true;
    return r;
}

double MaterialCalcEvaluator::expression(int k) {
    return rec_->exprConstant[k] ? rec_->exprValue[k]
                                 : eval_.eval(calc_.program_->expression(rec_->expr[k]));
}

void MaterialCalcEvaluator::setPerturbedNormal(const Vec3& n) {
    ctx_.NP = toVec(npTransform_.direction(toArr(n))) / npTransform_.scale;
    ctx_.RdotP = std::clamp(-dot(ctxDir_, n), -1.0, 1.0);
    eval_.setRay(ctx_);
}

void MaterialCalcEvaluator::wgmd(WgmdInputs& in) {
    RP_CHECK(rec_ && rec_->kind == MaterialCalc::Kind::Wgmd);
    long before = eval_.mathErrors();
    std::array<double, 3> u{expression(6), expression(7), expression(8)};
    in.u = eval_.mathErrors() == before ? toVec(rec_->forward.direction(u)) : Vec3{};
    // m_wgmdf.c set_scomp: the roughnesses only where the coefficient counts, v only
    // where u does; a math error blacks out the component.
    auto component = [&](int k, const Vec3& n, double& coef, double& ur, double& vr) {
        setPerturbedNormal(n);
        before = eval_.mathErrors();
        coef = expression(k);
        ur = vr = 0;
        if (coef > 1e-6) {
            ur = expression(k + 1);
            if (ur > 1e-6) vr = expression(k + 2);
        }
        if (eval_.mathErrors() != before || !std::isfinite(coef)) coef = 0;
    };
    component(3, in.normal[WgmdParams::kTs], in.ts, in.tsU, in.tsV);
    component(0, in.normal[WgmdParams::kRs], in.rs, in.rsU, in.rsV);
}

double MaterialCalcEvaluator::call(const MaterialCalc::Callable& c, std::span<const double> args) {
    switch (c.how) {
        case MaterialCalc::Callable::How::Constant:
            return c.value;
        case MaterialCalc::Callable::How::Function:
            return eval_.call(c.function, args);
        default:
            return eval_.eval(c.variable);
    }
}

Color MaterialCalcEvaluator::directional(const Vec3& toLight, double omega) {
    // m_brdf.c: a math error ("compute error") drops the whole specular part.
    long before = eval_.mathErrors();
    Color c = directionalValue(toLight, omega);
    return eval_.mathErrors() == before ? c : Color{};
}

Color MaterialCalcEvaluator::directionalValue(const Vec3& toLight, double omega) {
    RP_CHECK(rec_ && rec_->kind != MaterialCalc::Kind::Aniso);
    // m_brdf.c: the light direction through the world -> function transform, made unit
    // again (RADIANCE divides by the transform's scale), then the source solid angle.
    Vec3 l = toVec(rec_->toObject.direction(toArr(toLight)));
    double len = length(l);
    if (len > 0) l = l / len;
    double args[5] = {0, l.x, l.y, l.z, omega};
    std::span<const double> ldx(args + 1, 4);
    switch (rec_->kind) {
        case MaterialCalc::Kind::Func:
            return Color::grey(call(rec_->fn[0], ldx));
        case MaterialCalc::Kind::Data: {
            std::array<double, calc::DataFile::kMaxDimensions> pt{};
            size_t nd = rec_->coords.size();
            for (size_t k = 0; k < nd; ++k) pt[k] = call(rec_->coords[k], ldx);
            args[0] = rec_->data->value(std::span<const double>(pt.data(), nd));
            return Color::grey(call(rec_->fn[0], std::span<const double>(args, 5)));
        }
        default: {  // BRTDfunc; a repeated name is evaluated once (m_brdf.c)
            Color c;
            for (int k = 0; k < 3; ++k) {
                const auto& f = rec_->fn[k];
                int same = -1;
                for (int j = 0; j < k && same < 0; ++j)
                    if (rec_->fn[j].name == f.name) same = j;
                c[k] = same >= 0 ? c[same] : call(f, ldx);
            }
            return calc_.pass_.ofRgb(c);
        }
    }
}

WgmdInputs wgmdHitInputs(const MaterialCalc& calc, MaterialCalcEvaluator& ev,
                         SurfaceChainEvaluator& chains, int32_t material, const WgmdParams& m,
                         const PatternPoint& at, const SurfacePoint& sp, Rng& rng) {
    WgmdInputs in = wgmdInputs(m, sp);
    for (int c = 0; c < 3; ++c) {
        const int32_t mod = calc.wgmdModifier(material, c);
        if (mod == kVoid) continue;
        // RADIANCE raytexture on a copy of the ray: patterns and textures only; a mixture
        // in such a chain gives its first layer.
        const ChainResult r = chains.resolve(mod, at, rng);
        if (r.count <= 0) continue;
        const ShadingLayer& l = r.layers[0];
        in.pattern[size_t(c)] = l.pattern;
        if (lengthSquared(l.perturbation) > 0)
            in.normal[size_t(c)] = perturbedNormal(at.normal, l.perturbation, at.rdot >= 0, at.dir);
    }
    // Even all-constant expressions go through the evaluator: u needs the transform.
    ev.setHit(material, at, sp.normal, sp.pattern);
    ev.wgmd(in);
    return in;
}

}  // namespace rp::material

namespace rp::material {

MaterialCalcEvaluator& HitEvaluators::calc() {
    RP_CHECK(calc_);
    if (!calcEval_) calcEval_.emplace(*calc_);
    return *calcEval_;
}

SurfaceChainEvaluator& HitEvaluators::chains() {
    if (!chainEval_) chainEval_.emplace(chains_);
    return *chainEval_;
}

bool needsPreparation(const MaterialCalc* calc, int32_t material, const MaterialParams& params) {
    if (std::holds_alternative<WgmdParams>(params) || std::holds_alternative<PrismParams>(params))
        return calc != nullptr;
    return calc && calc->uses(material);
}

void prepareHit(HitEvaluators& evs, int32_t material, const MaterialParams& params,
                const PatternPoint& at, SurfacePoint& sp, HitScratch& scratch, Rng& rng) {
    const MaterialCalc* calc = evs.materialCalc();
    if (!needsPreparation(calc, material, params)) return;
    MaterialCalcEvaluator& ev = evs.calc();
    if (const auto* w = std::get_if<WgmdParams>(&params)) {
        scratch.wgmd = wgmdHitInputs(*calc, ev, evs.chains(), material, *w, at, sp, rng);
        sp.wgmd = &scratch.wgmd;
        return;
    }
    if (const auto* prism = std::get_if<PrismParams>(&params)) {
        // m_direct.c: a ray aimed at no source (DxA DyA DzA zero); the functions see the
        // plain normal and no pattern. Shadow rays toward its virtual sources are the
        // direct calculation's (MaterialCalcEvaluator::redirect).
        ev.setHit(material, at);
        for (int k = 0; k < prism->redirections; ++k)
            scratch.redirections[size_t(k)] = ev.redirect(k, Vec3{});
        sp.redirections = &scratch.redirections;
        return;
    }
    ev.setHit(material, at, sp.normal, sp.pattern);
    if (std::holds_alternative<AnisoParams>(params) ||
        std::holds_alternative<AshikParams>(params)) {
        sp.uDir = ev.anisoU();
    } else if (std::holds_alternative<BrtdParams>(params)) {
        Color refl, trans;
        ev.brtdSpecular(refl, trans);
        sp.brtdSpecularReflection = refl;
        sp.brtdSpecularTransmission = trans;
        scratch.directional = ev.bound();
        sp.directional = &scratch.directional;
    } else if (std::holds_alternative<FuncParams>(params)) {
        scratch.directional = ev.bound();
        sp.directional = &scratch.directional;
    } else if (std::holds_alternative<BsdfParams>(params)) {
        ev.setBsdfInputs(sp);
    }
}

Redirection prismRedirect(const MaterialCalc& calc, MaterialCalcEvaluator& ev, int32_t material,
                          const MaterialParams& params, const PatternPoint& at, int projection,
                          const Vec3& toSource) {
    const auto* prism = std::get_if<PrismParams>(&params);
    if (!prism || projection >= prism->redirections || !calc.uses(material)) return {};
    ev.setHit(material, at);
    return ev.redirect(projection, toSource);
}

void resetPreparedInputs(SurfacePoint& sp) {
    sp.uDir = Vec3{};
    sp.brtdSpecularReflection = sp.brtdSpecularTransmission = std::nullopt;
    sp.directional = nullptr;
    sp.redirections = nullptr;
    sp.bsdf = nullptr;
    sp.bsdfThickness = 0;
    sp.wgmd = nullptr;
}

}  // namespace rp::material

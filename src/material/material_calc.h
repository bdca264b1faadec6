// The .cal side of the function-driven materials, compiled once per scene: the u
// orientation of plastic2/metal2/trans2 (aniso.c), the specular function or data file
// of plasfunc/metfunc/transfunc/plasdata/metdata/transdata (m_brdf.c m_brdf2), and the
// ideal specular colours and directional-diffuse functions of BRTDfunc (m_brdf.c m_brdf),
// and the coefficients and directions of prism1/prism2 (m_direct.c).
// material.h stays free of calc/: the renderer evaluates these per hit and hands the
// results in through SurfacePoint (uDir, brtdSpecular..., directional).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bsdf/bsdf.h"
#include "calc/data_file.h"
#include "calc/program.h"
#include "material/material.h"
#include "material/pattern.h"
#include "material/surface_chain.h"
#include "scene/primitive.h"
#include "scene/xform.h"
#include "util/color.h"
#include "util/spectrum.h"
#include "util/vec.h"

namespace rp::material {

class MaterialCalcEvaluator;
class SurfaceChainEvaluator;

// Every function-driven material of a scene compiled into one calc Program (function
// and data files found along `searchPath`; RADIANCE's global context after rayinit.cal,
// files loaded once in order of first use). Immutable after construction and shareable
// between threads. Throws InputError at the record's file:line for a missing function
// or data file, an unknown function name, too few data coordinates or a bad transform
// (syntax errors in a function file keep their own file:line).
class MaterialCalc {
public:
    // Colour expressions (BRTDfunc) come out as the bands of `pass`.
    MaterialCalc(const Scene& scene, std::vector<std::string> searchPath,
                 const spectral::Pass& pass = {});
    ~MaterialCalc();
    MaterialCalc(const MaterialCalc&) = delete;
    MaterialCalc& operator=(const MaterialCalc&) = delete;

    // True if `material` (a prim index) has expressions to evaluate. A BRTDfunc whose
    // six specular arguments are plain numbers and whose rbrtd gbrtd bbrtd are "0" needs
    // nothing (params.cpp already holds its constants).
    bool uses(int32_t material) const;
    // WGMDfunc (a prim index): the modifier a component (WgmdParams::kRs, kTs, kTd) names
    // where it is WgmdParams::Mod::Named, found at load as RADIANCE's lastmod (an
    // unknown name is an InputError at the material's line); kVoid otherwise.
    int32_t wgmdModifier(int32_t material, int component) const;

private:
    friend class MaterialCalcEvaluator;
    enum class Kind : uint8_t { Aniso, Func, Data, Brtd, Prism, Bsdf, Wgmd };

    // A function named in a string argument, called with the light direction: a user
    // or builtin function, a variable (RADIANCE's funvalue accepts one: it ignores the
    // arguments), or a plain number (our extension; "0" is RADIANCE's "none").
    struct Callable {
        enum class How : uint8_t { Constant, Function, Variable } how = How::Constant;
        double value = 0;
        calc::Function function;
        calc::Entry variable;
        std::string name;  // as given, for resolving after build and for errors
    };

    struct Record {
        int32_t prim = -1;
        Kind kind = Kind::Func;
        PrimType type = PrimType::Plasfunc;
        Transform toObject;  // world -> function space
        Transform forward;   // function space -> world
        std::vector<double> rargs;
        // aniso: ux uy uz; BRTDfunc: 6 colours; prism1: coef dx dy dz; prism2: two sets;
        // WGMDfunc: rs rs_ur rs_vr ts ts_ur ts_vr ux uy uz
        static constexpr int kMaxExpr = 9;
        int expr[kMaxExpr] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};
        bool exprConstant[kMaxExpr] = {};
        double exprValue[kMaxExpr] = {};
        Callable fn[3];                // func/data: fn[0]; BRTDfunc: rbrtd gbrtd bbrtd
        std::vector<Callable> coords;  // data types: x1 .. xN
        std::shared_ptr<const calc::DataFile> data;
        std::shared_ptr<const bsdf::BsdfData> bsdf;  // BSDF/aBSDF: expr 0-2 up, 3 thickness
        bool needed = true;
        int32_t wgmdMod[3] = {kVoid, kVoid, kVoid};  // WGMDfunc's named component modifiers
    };

    std::vector<int32_t> recordOf_;  // prim index -> index into records_, or -1
    std::vector<Record> records_;
    std::shared_ptr<const calc::Program> program_;
    spectral::Pass pass_;
};

// A hit set on a MaterialCalcEvaluator, to be evaluated again after the evaluator served
// other hits (a shadow ray's BSDF, a prism relay): the directional part of the material
// being lit is read per light sample, after those. Valid while the evaluator lives.
class BoundHit final : public DirectionalPart {
public:
    Color operator()(const Vec3& toLight) const override;

private:
    friend class MaterialCalcEvaluator;
    MaterialCalcEvaluator* ev_ = nullptr;
    uint64_t serial_ = 0;
    int32_t material_ = kVoid;
    PatternPoint at_;
    Vec3 normal_;
    Color pattern_;
};

// Per-thread evaluation state for a MaterialCalc (not thread-safe itself).
class MaterialCalcEvaluator {
public:
    explicit MaterialCalcEvaluator(const MaterialCalc& calc);
    ~MaterialCalcEvaluator();

    // Sets the hit for `material` (must be uses()): at.dir, at.point, at.normal
    // (unperturbed surface normal, not flipped), at.distance, at.rdot. The values the
    // functions see are in the material's function space (its transform arguments).
    // `shadingNormal` (the perturbed normal on the ray's side) and `pattern` (the
    // colour of the modifier chain's patterns) give NxP NyP NzP RdotP CrP CgP CbP.
    void setHit(int32_t material, const PatternPoint& at, const Vec3& shadingNormal,
                const Color& pattern);
    // The hit set last, as a value its reader can come back to (BoundHit).
    BoundHit bound();
    // The same with the plain normal turned to the ray and no pattern (prisms, whose
    // functions see no NxP..CbP in RADIANCE).
    void setHit(int32_t material, const PatternPoint& at) {
        setHit(material, at, at.rdot < 0 ? -at.normal : at.normal, Color{1, 1, 1});
    }

    // plastic2/metal2/trans2: the u orientation, world space (aniso.c getacoords: the
    // ux uy uz values through the forward transform). Normalised; zero if degenerate or
    // on a math error (evaluate() then punts to an isotropic frame, as aniso.c does).
    Vec3 anisoU();

    // BSDF/aBSDF (m_bsdf.c): sets sp.bsdf (the data), sp.uDir (the up vector, world,
    // through the modifier's and the object's transforms) and sp.bsdfThickness (scaled
    // as the up vector is; 0 for aBSDF).
    void setBsdfInputs(SurfacePoint& sp);

    // BRTDfunc: the ideal specular reflection (rrefl grefl brefl) and transmission
    // (rtrns gtrns btrns) colours at the hit. Not modified by the pattern (m_brdf.c).
    void brtdSpecular(Color& reflection, Color& transmission);

    // plasfunc/metfunc/transfunc: refl(lx, ly, lz, omega); ..data: func(datavalue(x1..xN),
    // lx, ly, lz, omega) with each xi(lx, ly, lz, omega); BRTDfunc: rbrtd gbrtd bbrtd of
    // (lx, ly, lz, omega). (lx ly lz) is the unit direction to the light in function space.
    // The raw function values: material.cpp applies the specularity, colour and cosine.
    // `omega` is the source's solid angle (RADIANCE passes it; 0 when unknown). A math
    // error (division by zero, ...) gives zero, as m_brdf.c's "compute error".
    Color directional(const Vec3& toLight, double omega = 0);

    // prism1/prism2: redirection `n` (0, or 1 for prism2) at the hit, m_direct.c: DxA DyA
    // DzA are the unit world direction `toSource` as the functions see directions (zero:
    // the ray is not aimed at a source); the coefficient, and the direction through the
    // forward transform, made unit. Not ok after a math error or for a zero direction.
    Redirection redirect(int n, const Vec3& toSource);

    // WGMDfunc (after setHit, with the main modifier's normal): the expression values
    // into `in`, whose patterns and normals are set. As m_wgmdf.c, the u orientation sees
    // the main modifier's NxP NyP NzP RdotP, the rs and ts expressions their own
    // modifier's; a math error blacks out that component (a zero u punts to isotropic).
    void wgmd(WgmdInputs& in);

private:
    friend class BoundHit;
    // Sets `hit` again if another hit was set since (its serial is no longer current).
    void restore(const BoundHit& hit);
    double expression(int k);
    void setPerturbedNormal(const Vec3& n);
    double call(const MaterialCalc::Callable& c, std::span<const double> args);
    Color directionalValue(const Vec3& toLight, double omega);

    const MaterialCalc& calc_;
    calc::Evaluator eval_;
    calc::RayContext ctx_;
    const MaterialCalc::Record* rec_ = nullptr;
    const TransformPair* object_ = nullptr;  // the hit's object space (PatternPoint::object)
    Transform npTransform_;                  // world -> function space at the hit, for NxP NyP NzP
    Vec3 ctxDir_;                            // the ray direction at the hit (world), for RdotP
    long errorsAtHit_ = 0;
    // The hit set last: its arguments and a serial that setHit advances (BoundHit).
    uint64_t serial_ = 0, nextSerial_ = 0;
    int32_t hitMaterial_ = kVoid;
    PatternPoint hitAt_;
    Vec3 hitNormal_;
    Color hitPattern_;
};

// WGMDfunc at a hit, for either direction: wgmdInputs(m, sp), then each named component
// modifier's patterns and textures (its chain from at, through `chains`; the perturbed
// normal turned to the ray, as sp.normal), then the expressions where calc.uses(material).
// `at` as for setHit; sp.normal and sp.pattern are the main modifier's.
WgmdInputs wgmdHitInputs(const MaterialCalc& calc, MaterialCalcEvaluator& ev,
                         SurfaceChainEvaluator& chains, int32_t material, const WgmdParams& m,
                         const PatternPoint& at, const SurfacePoint& sp, Rng& rng);

// What prepareHit evaluates into, kept by the caller for as long as the SurfacePoint is
// used (the SurfacePoint points into it).
struct HitScratch {
    std::array<Redirection, 2> redirections{};
    WgmdInputs wgmd;
    BoundHit directional;
};

// The evaluators prepareHit uses, per thread; made on first use (most rays and photons
// meet materials without functions).
struct HitEvaluators {
    HitEvaluators(const MaterialCalc* calc, const SurfaceChains& chains)
        : calc_(calc), chains_(chains) {}
    MaterialCalcEvaluator& calc();
    SurfaceChainEvaluator& chains();
    const MaterialCalc* materialCalc() const { return calc_; }

private:
    const MaterialCalc* calc_;  // null: the scene has no function-driven material
    const SurfaceChains& chains_;
    std::optional<MaterialCalcEvaluator> calcEval_;
    std::optional<SurfaceChainEvaluator> chainEval_;
};

// Whether prepareHit evaluates anything for `material` (a function-driven material, a
// WGMDfunc or a prism); callers may skip it otherwise.
bool needsPreparation(const MaterialCalc* calc, int32_t material, const MaterialParams& params);

// The one preparation of a hit for all three directions (backward shading, shadow rays,
// photon scattering), so that they see the same inputs: the u orientation of
// plastic2/metal2/trans2/ashik2, BRTDfunc's specular colours, a BSDF's data, thickness
// and up vector, WGMDfunc's expressions and component modifiers, prism redirections (for
// a ray aimed at no source), and the directional part of BRTDfunc and the *func/*data
// types. `at` as for setHit; sp.normal and sp.pattern are the hit's shading normal and
// pattern. Nothing for a material needsPreparation rejects.
void prepareHit(HitEvaluators& ev, int32_t material, const MaterialParams& params,
                const PatternPoint& at, SurfacePoint& sp, HitScratch& scratch, Rng& rng);

// prism1/prism2 (m_direct.c): redirection `projection` of `material` at `at` for a
// shadow ray toward a virtual source, DxA DyA DzA along `toSource`; not ok where the
// material is no prism, has no such projection or no functions.
Redirection prismRedirect(const MaterialCalc& calc, MaterialCalcEvaluator& ev, int32_t material,
                          const MaterialParams& params, const PatternPoint& at, int projection,
                          const Vec3& toSource);

// Clears what prepareHit sets, for a SurfacePoint reused from hit to hit (the photon
// tracer's, one per path).
void resetPreparedInputs(SurfacePoint& sp);

}  // namespace rp::material

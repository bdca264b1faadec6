// What a surface's modifier chain does at a hit point (RADIANCE raytrace.c rayshade and
// raytexture): patterns multiply the colour (r->pcol), textures add to the normal
// (r->pert), mixtures choose between two modifiers, until a material is reached. Every
// pattern, texture and mixture type of ray.html is here: colorfunc brightfunc colordata
// brightdata colorpict colortext brighttext, texfunc texdata, mixfunc mixdata mixpict
// mixtext. The chain is walked in RADIANCE's order: from the surface's modifier through
// each record's own modifier to the material, whose own modifier chain then applies too.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "material/material_table.h"
#include "material/pattern.h"
#include "scene/primitive.h"
#include "util/color.h"
#include "util/rng.h"
#include "util/spectrum.h"
#include "util/vec.h"

namespace rp::material {

// One material to shade with, and what the chain did to it.
struct ShadingLayer {
    int32_t material = kVoid;  // a material record (plastic, light, ...); kVoid: invisible
    double weight = 1;         // mixture weight (layers of one resolve sum to 1)
    Color pattern{1, 1, 1};    // product of the patterns on the way (r->pcol)
    Vec3 perturbation;         // sum of texture perturbations (r->pert), world space
};

// Up to kMaxLayers layers; nested mixtures beyond that are chosen at random with the
// mixture's probability (the expectation is the same as RADIANCE's raymixture).
struct ChainResult {
    static constexpr int kMaxLayers = 4;
    // Room for kMaxLayers layers, of which only layers[0 .. count) are set: a resolve
    // runs at every shaded point and shadow test, and initialising all four (256 bytes,
    // a memcpy from a template) was a visible part of rtrace's time for plain materials.
    // ShadingLayer is trivially copyable, so the bytes are its storage (C++20 implicit
    // object creation).
    class Layers {
    public:
        ShadingLayer& operator[](size_t i) { return data()[i]; }
        const ShadingLayer& operator[](size_t i) const { return data()[i]; }
        ShadingLayer* begin() { return data(); }
        const ShadingLayer* begin() const { return data(); }

    private:
        ShadingLayer* data() { return reinterpret_cast<ShadingLayer*>(bytes_); }
        const ShadingLayer* data() const { return reinterpret_cast<const ShadingLayer*>(bytes_); }
        alignas(ShadingLayer) unsigned char bytes_[kMaxLayers * sizeof(ShadingLayer)];
    };
    static_assert(std::is_trivially_copyable_v<ShadingLayer>);
    Layers layers;
    int count = 0;
    // One plain layer: `material` (kVoid: invisible) with weight 1, no pattern or texture.
    static ChainResult plain(int32_t material) {
        ChainResult r;
        r.layers[0] = ShadingLayer{};
        r.layers[0].material = material;
        r.count = 1;
        return r;
    }
};

// Every pattern, texture and mixture of a scene, compiled once (function and data files
// loaded through the search path, pictures read). Immutable and shared by threads.
class SurfaceChains {
public:
    // Throws InputError naming the record for missing files, bad arguments and syntax
    // errors in function files; text patterns need their font file on the search path.
    // Colours come out as the bands of `pass` (RGB unless rendering a spectrum).
    SurfaceChains(const Scene& scene, std::vector<std::string> searchPath,
                  const spectral::Pass& pass = {});
    ~SurfaceChains();

    // Throws InputError / notSupportedYet if the chain from `modifier` cannot be
    // evaluated (a record type that is neither pattern, texture, mixture nor material).
    void checkChain(int32_t modifier) const;
    // True if the chain from `modifier` holds no pattern, texture or mixture (only a
    // material, possibly through aliases): resolve() would give one plain layer.
    bool isPlain(int32_t modifier) const;
    // The material reached when the chain is plain (kVoid if none).
    int32_t plainMaterial(int32_t modifier) const;
    // True if the chain from `modifier` (a light's pattern chain, walked to void) holds
    // only function, data, picture and spectral patterns whose value depends on the ray
    // direction D alone (their expressions, and every variable and function those reach
    // in function files, read no other ray variable).
    bool directionalOnly(int32_t modifier) const;

    const Scene& scene() const;
    // The material records the chains end at (backward shading, shadow rays, photon
    // scattering and emission all read them here).
    const MaterialTable& materials() const;

private:
    friend class SurfaceChainEvaluator;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Per-thread evaluator (calc state is not shareable).
class SurfaceChainEvaluator {
public:
    explicit SurfaceChainEvaluator(const SurfaceChains& chains);
    ~SurfaceChainEvaluator();

    // Resolves the chain from a surface's modifier at `at` (world space; at.normal is the
    // unperturbed surface normal as RADIANCE's ron: NOT flipped toward the ray). `u`,
    // `v` are the hit's local coordinates (unused by RADIANCE's types; kept for Lu/Lv).
    ChainResult resolve(int32_t modifier, const PatternPoint& at, Rng& rng);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp::material

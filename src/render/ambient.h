// The ambient (indirect diffuse) calculation of the backward pass: Monte Carlo
// hemisphere sampling with Ward's irradiance cache and its rotational and translational
// gradients (RADIANCE ambient.c, ambcomp.c; Ward & Heckbert 1992), with RADIANCE's
// options -ab -ad -as -aa -ar -av -aw -ae -ai -aE -aI -af. Rays are traced by the
// caller's HemisphereTracer (the renderer core). Thread-safe: one Ambient shared by all
// threads.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "render/irradiance_cache.h"
#include "render/render_options.h"
#include "scene/primitive.h"
#include "util/color.h"
#include "util/rng.h"
#include "util/vec.h"

namespace rp::render {

// Traces one hemisphere sample ray (implemented by the renderer core, per thread).
class HemisphereTracer {
public:
    virtual ~HemisphereTracer() = default;
    struct Sample {
        Color radiance;          // radiance arriving back along the ray
        double distance = 1e10;  // distance to the surface hit (1e10 if none)
        Vec3 normal;             // geometric normal there, either sign (zero: unknown)
        // False when the ray was not traced (lighter than -lw, lost at Russian roulette,
        // past -lr): RADIANCE's failed ambsample, which keeps a value from being cached.
        bool traced = true;
    };
    // `ambientLevel` is the level of the new ray (1 for rays from a primary hit);
    // `weight` its RADIANCE ray weight (for -lw and the division count at deeper levels);
    // `share` the fraction of the hemisphere's value its radiance makes (rcontrib's path
    // coefficients; exact without super-samples, which rcontrib turns off).
    virtual Sample trace(const Vec3& origin, const Vec3& dir, int ambientLevel, double weight,
                         double share) = 0;
};

// The surface point needing indirect irradiance.
struct AmbientPoint {
    Vec3 point;
    Vec3 normal;            // shading normal on the side the light is wanted from
    Vec3 offsetOrigin;      // point moved off the surface on that side (sample ray origin)
    int32_t modifier = -1;  // for -ae/-ai
    int ambientLevel = 0;   // bounces already made by the ray that hit this point
    double weight = 1;      // the hitting ray's weight
    // The largest component of the material's ambient coefficient (RADIANCE intens of
    // the ambient colour; pi for rtrace -I's white receiver): without the cache the
    // division count and the samples' weights follow it.
    double coefficient = 0.5;
    // Tests cached records that may have leaked through a surface (null: no test).
    LeakTest* leaks = nullptr;
};

class Ambient {
public:
    // `sceneSize`: the size of RADIANCE's scene cube (SceneGeometry::sceneCube().size),
    // which -ar divides into the minimum record spacing. Loads -af records if the file
    // exists (a foreign or truncated file is an InputError naming it).
    // `minWeight` is -lw: without the cache (-aa 0), RADIANCE lowers the division count so
    // that no sample ray's weight drops far below it (ambcomp.c); 2e-3 is its default.
    Ambient(const AmbientOptions& options, double sceneSize, const Scene& scene,
            double minWeight = 2e-3);
    ~Ambient();

    // Average radiance of the hemisphere above at.normal (irradiance / pi): from the
    // cache when records cover the point within -aa, else computed with -ad samples
    // (plus -as super-samples) and stored. Past -ab bounces, or for excluded modifiers,
    // returns the ambient value -av (with -aw averaging). The caller multiplies the
    // result by the material's ambient coefficient.
    Color indirect(const AmbientPoint& at, HemisphereTracer& tracer, Rng& rng) const;

    // Writes records created since loading to the -af file, if any.
    void save() const;

    // Records in the cache, loaded and computed (0 without the cache).
    long recordCount() const;

    // RADIANCE's running ambient value (-aw > 0): the -av colour scaled to the geometric
    // mean of the brightness of -av (counted -aw times) and of every record stored or
    // loaded so far; just -av when -aw is 0 or no record exists yet (always, with -aa 0).
    Color ambientValue() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp::render

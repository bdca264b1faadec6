// Function patterns (brightfunc, colorfunc) compiled once from a scene's records against
// the function files they name, and the colour a chain of them gives at a point: what
// modifies a light source's emission (e.g. gensky's skyfunc) and a material's colour.
// Data and picture patterns, textures and mixtures are not here yet: a chain that holds
// one is reported with notSupportedYet at its line.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "calc/program.h"
#include "scene/primitive.h"
#include "scene/xform.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::material {

// World-space values at the point being shaded or emitting (ray.html, "Function Files").
struct PatternPoint {
    Vec3 dir;          // D: ray direction; for photon emission it points towards the photon
                       // origin (photon-map manual 3.1.2)
    Vec3 point;        // P
    Vec3 normal;       // N
    double distance = 0;  // T (undefined for emission: 0)
    double rdot = 0;      // Rdot: cosine between the ray and the surface normal
};

class PatternEvaluator;

// Every brightfunc/colorfunc of a scene, compiled into one calc Program (function files
// share RADIANCE's global context, loaded after rayinit.cal in order of first use).
class PatternSet {
public:
    // `searchPath`: directories for .cal files (calc::defaultSearchPath). Throws
    // InputError for missing function files and syntax errors.
    PatternSet(const Scene& scene, std::vector<std::string> searchPath);

    // Throws notSupportedYet / InputError if the chain starting at `modifier` (a
    // material's modifier field) holds a pattern this set cannot evaluate.
    void checkChain(int32_t modifier) const;
    // True if `modifier` starts a non-empty chain of patterns.
    bool isModified(int32_t modifier) const { return modifier != kVoid; }
    // True if no pattern in the chain reads P, N or T: the colour depends on D only.
    bool directionalOnly(int32_t modifier) const;

private:
    friend class PatternEvaluator;
    struct Pattern {
        int32_t prim = -1;
        bool colour = false;    // colorfunc (3 expressions) vs brightfunc (1)
        int expr[3] = {-1, -1, -1};
        Transform toObject;     // world -> the pattern's object space
        bool usesPosition = true;
    };
    const Scene& scene_;
    std::vector<int32_t> patternOf_;  // prim index -> index into patterns_, or -1
    std::vector<Pattern> patterns_;
    std::shared_ptr<const calc::Program> program_;
};

// Per-thread evaluation state for a PatternSet (not thread-safe itself).
class PatternEvaluator {
public:
    explicit PatternEvaluator(const PatternSet& set);
    // Product of the chain's colours at `at` (white for kVoid). The chain must have
    // passed checkChain.
    Color chainColor(int32_t modifier, const PatternPoint& at);

private:
    const PatternSet& set_;
    calc::Evaluator eval_;
};

}  // namespace rp::material

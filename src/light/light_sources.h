// The photon emitters of a scene: which surfaces and distant `source`s emit photons by
// RADIANCE's rules (source.c marksources, photon-map manual 3.1.2), and which surfaces
// act as photon ports (-apo, manual 3.2.4). Partitioning, flux and sampling live in
// partition.h and emitter.h; the backward pass's own source list is not built here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "material/material.h"
#include "scene/primitive.h"

namespace rp::light {

// Which ShapeSet array an emitter (or port) lives in.
enum class EmitterShape : uint8_t { Polygon, Sphere, Cone, Ring, Distant };

struct LightSource {
    int32_t prim = -1;  // index into Scene::prims of the surface / source
    std::string name;   // the surface's name and place, for messages
    SourceLoc loc;
    int32_t material = -1;  // its light/glow/spotlight material record
    // First modifier of the material's chain (a pattern such as `brightfunc skyfunc`),
    // kVoid if unmodified. A modified source needs an EmissionModifier (emitter.h).
    int32_t patternModifier = kVoid;
    material::LightParams params;  // radiance, kind, spotlight cone/aim, glow radius
    EmitterShape shape = EmitterShape::Polygon;
    int32_t shapeIndex = -1;  // into the ShapeSet array of `shape`
    // Photon path length limit: a local glow's maximum radius (pmapsrc.c emitPhoton),
    // 0 = unlimited.
    double maxDistance = 0;
    bool distant() const { return shape == EmitterShape::Distant; }
    bool modified() const { return patternModifier != kVoid; }
    // A distant glow (a sky or ground): RADIANCE's direct calculation skips it (source.c
    // SSKIP) and its light reaches surfaces only through the ambient calculation, so the
    // renderer's direct light never holds it, and photon maps must carry all of it.
    bool ambientOnly() const { return params.glow() && distant(); }
    bool spotlight() const { return params.spotlight(); }
};

struct LightSearchOptions {
    // RADIANCE compat: source.c puts `illum` surfaces into its source list and pmap.c
    // emits from every entry, but the photon-map manual (3.1.2) names only light,
    // spotlight, glow and source as photon emitters, and an illum is a secondary source
    // (mkillum) whose light the photons already carry through the opening it covers:
    // emitting from it double counts. Off by default; on reproduces RADIANCE's list.
    bool illumEmits = false;
    // The bands the sources' colours are rendered in (RGB unless rendering a spectrum).
    spectral::Pass pass;
};

// Every emitter, in scene order. Rules (source.c marksources, RADIANCE 5.4):
//  - the surface's material (its modifier, walked past non-materials) is light,
//    spotlight, glow (or illum with illumEmits);
//  - zero radiance in every channel: not a source ("don't bother");
//  - a glow on local geometry emits only with a positive maximum radius, which then
//    limits the photon path; radius 0 is left to the ambient calculation and a negative
//    radius means no illumination at all. A glow on a `source` (sky, ground) always
//    emits, with no path limit;
//  - a spotlight on a `source` warns and emits as a light ("distant source is a
//    spotlight"); a flat spotlight whose cone lies wholly behind its surface warns and
//    is skipped (srcsupp.c checkspot).
// Shapes skipped by geometry (degenerate) are not found. Unlike RADIANCE, which refuses
// cones, cups, tubes and bubbles as sources ("illegal material"), every surface emits.
std::vector<LightSource> findLightSources(const Scene& scene, const SceneGeometry& geometry,
                                          const LightSearchOptions& options = {});

// -apo[+|-|0] mod. RADIANCE's port normals point INTO the interior (mkillum convention).
enum class PortDirection : uint8_t {
    Forward,        // default / '+': photons enter along the normal (into the interior)
    Backward,       // '-': photons leave against the normal
    Bidirectional,  // '0': both; each partition used twice with opposite normals
};

struct PortSpec {
    std::string modifier;  // material name as given to -apo, matched whole
    PortDirection direction = PortDirection::Forward;
};

struct PhotonPort {
    int32_t prim = -1;
    int32_t modifier = kVoid;  // the port's material record
    EmitterShape shape = EmitterShape::Polygon;
    int32_t shapeIndex = -1;
    PortDirection direction = PortDirection::Forward;
};

// Surfaces whose material (name, after alias resolution) is one of the specs and is not
// a light source material (pmapsrc.c getPhotonPorts). Throws InputError if specs are
// given but no surface matches ("no valid photon ports found").
std::vector<PhotonPort> findPhotonPorts(const Scene& scene, const SceneGeometry& geometry,
                                        const std::vector<PortSpec>& specs);

// The material record of a surface: its modifier, followed past non-material records
// (RADIANCE findmaterial). kVoid if none.
int32_t findMaterial(const Scene& scene, int32_t prim);

}  // namespace rp::light

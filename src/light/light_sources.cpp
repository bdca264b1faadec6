// Finding photon emitters and photon ports in a scene (see light_sources.h).
#include "light/light_sources.h"

#include <algorithm>
#include <cmath>

#include "light/aperture.h"
#include "material/type_traits.h"
#include "util/warnings.h"

namespace rp::light {

namespace {

bool isLightType(PrimType t, bool illumEmits) {
    using L = material::TypeTraits::Light;
    const L light = material::typeTraits(t).light;
    return light != L::None && (illumEmits || light != L::Illum);
}

bool isAnyLightType(PrimType t) { return isLightType(t, true); }

// Calls f(shape, shapeIndex, prim, modifier) for every shape of the geometry.
template <class F>
void forEachShape(const ShapeSet& s, F f) {
    for (size_t i = 0; i < s.polygons.size(); ++i)
        f(EmitterShape::Polygon, int32_t(i), s.polygons[i].prim);
    for (size_t i = 0; i < s.spheres.size(); ++i)
        f(EmitterShape::Sphere, int32_t(i), s.spheres[i].prim);
    for (size_t i = 0; i < s.cones.size(); ++i) f(EmitterShape::Cone, int32_t(i), s.cones[i].prim);
    for (size_t i = 0; i < s.rings.size(); ++i) f(EmitterShape::Ring, int32_t(i), s.rings[i].prim);
    for (size_t i = 0; i < s.sources.size(); ++i)
        f(EmitterShape::Distant, int32_t(i), s.sources[i].prim);
}

// The surface normal of a flat shape (polygon, ring), zero vector for curved ones.
Vec3 flatNormal(const ShapeSet& s, EmitterShape shape, int32_t index) {
    if (shape == EmitterShape::Polygon) return s.polygons[size_t(index)].normal;
    if (shape == EmitterShape::Ring) return s.rings[size_t(index)].normal;
    return {};
}

}  // namespace

int32_t findMaterial(const Scene& scene, int32_t prim) {
    // Lights and ports are materials: a chain ending in a mixture has none here.
    const int32_t m = chainMaterial(scene, scene.prims[size_t(prim)].modifier);
    return m != kVoid && primCategory(scene.prims[size_t(m)].type) == PrimCategory::Material
               ? m
               : kVoid;
}

std::vector<LightSource> findLightSources(const Scene& scene, const SceneGeometry& geometry,
                                          const LightSearchOptions& options) {
    struct Found {
        int32_t prim;
        LightSource src;
    };
    std::vector<Found> found;
    const ShapeSet& shapes = geometry.shapes();
    forEachShape(shapes, [&](EmitterShape shape, int32_t index, int32_t prim) {
        int32_t mat = findMaterial(scene, prim);
        if (mat == kVoid) return;
        const Primitive& m = scene.prims[size_t(mat)];
        if (!isLightType(m.type, options.illumEmits)) return;
        const Primitive& surf = scene.prims[size_t(prim)];
        LightSource src;
        src.prim = prim;
        src.name = surf.name;
        src.loc = surf.loc;
        src.material = mat;
        src.patternModifier = m.modifier;
        src.params = std::get<material::LightParams>(material::makeMaterial(m, options.pass));
        src.shape = shape;
        src.shapeIndex = index;
        const Color& L = src.params.radiance;
        if (L.r <= kFtiny && L.g <= kFtiny && L.b <= kFtiny) return;
        const bool distant = shape == EmitterShape::Distant;
        if (src.params.glow() && !distant) {
            // Radius 0: ambient calculation only; negative: no illumination.
            if (src.params.glowMaxRadius <= kFtiny) return;
            src.maxDistance = src.params.glowMaxRadius;
        }
        if (src.spotlight() && distant) {
            warn(surf.loc, "source '" + surf.name + "': distant source is a spotlight");
            src.params.kind = material::LightParams::Kind::Light;
        }
        if (src.spotlight()) {
            Vec3 n = flatNormal(shapes, shape, index);
            double cosCone = std::cos(src.params.spotAngleDeg * (kPi / 360));
            if (lengthSquared(n) > 0 && projectedSolidAngle(src.params.spotAim, cosCone, n) <= 0) {
                warn(surf.loc, std::string(primTypeName(surf.type)) + " '" + surf.name +
                                   "': invalid spotlight direction");
                return;
            }
        }
        found.push_back({prim, src});
    });
    // Scene order, as RADIANCE's source list (shape arrays are grouped by family).
    std::stable_sort(found.begin(), found.end(),
                     [](const Found& a, const Found& b) { return a.prim < b.prim; });
    std::vector<LightSource> out;
    out.reserve(found.size());
    for (Found& f : found) out.push_back(f.src);
    return out;
}

std::vector<PhotonPort> findPhotonPorts(const Scene& scene, const SceneGeometry& geometry,
                                        const std::vector<PortSpec>& specs) {
    std::vector<PhotonPort> ports;
    if (specs.empty()) return ports;
    forEachShape(geometry.shapes(), [&](EmitterShape shape, int32_t index, int32_t prim) {
        if (shape == EmitterShape::Distant) return;  // no geometry to emit from
        int32_t mat = findMaterial(scene, prim);
        if (mat == kVoid || isAnyLightType(scene.prims[size_t(mat)].type)) return;
        const std::string& name = scene.prims[size_t(mat)].name;
        for (const PortSpec& spec : specs)
            if (spec.modifier == name) {
                ports.push_back({prim, mat, shape, index, spec.direction});
                break;
            }
    });
    std::stable_sort(ports.begin(), ports.end(),
                     [](const PhotonPort& a, const PhotonPort& b) { return a.prim < b.prim; });
    if (ports.empty()) throw InputError("no valid photon ports found");
    return ports;
}

}  // namespace rp::light

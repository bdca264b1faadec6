// Building the direct calculation's source list (see source_list.h).
#include "render/source_list.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "material/material.h"
#include "material/type_traits.h"
#include "render/clip_set.h"

namespace rp::render {

namespace {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY

double area2(const std::array<double, 6>& t) {
    return (t[2] - t[0]) * (t[5] - t[1]) - (t[4] - t[0]) * (t[3] - t[1]);
}

Vec3 sourceCentre(const light::LightSource& s, const ShapeSet& shapes,
                  const std::vector<PlanarRegion>& regions, int32_t region) {
    size_t i = size_t(s.shapeIndex);
    switch (s.shape) {
        case light::EmitterShape::Polygon:
            return regions[size_t(region)].centroid;
        case light::EmitterShape::Sphere:
            return shapes.spheres[i].center;
        case light::EmitterShape::Ring:
            return shapes.rings[i].centre;
        case light::EmitterShape::Cone: {
            const ConeShape& c = shapes.cones[i];
            return c.p0 + c.axis * (0.5 * c.length);
        }
        case light::EmitterShape::Distant:
            return shapes.sources[i].dir;
    }
    return {};
}

// Side (+1/-1) of the relay on which `src` (real or virtual) lies, 0 if none: a local
// source must lie off the plane, a distant one off its direction.
int reflectingSide(const RelayPlane& m, const DirectSource& src) {
    double s = src.distant() ? dot(m.region.normal, src.apparentCentre)
                             : m.region.signedDistance(src.apparentCentre);
    double tol = src.distant() ? kFtiny : kFtiny * std::fmax(1.0, maxAbs(src.apparentCentre));
    if (std::fabs(s) <= tol) return 0;
    return s > 0 ? 1 : -1;
}

// Whether a flat real source emits toward some part of the mirror (its front faces a
// mirror corner).
bool facesMirror(const DirectSource& src, const ShapeSet& shapes,
                 const std::vector<PlanarRegion>& regions, const RelayPlane& m) {
    Vec3 n;
    if (src.light.shape == light::EmitterShape::Polygon)
        n = regions[size_t(src.region)].normal;
    else if (src.light.shape == light::EmitterShape::Ring)
        n = shapes.rings[size_t(src.light.shapeIndex)].normal;
    else
        return true;
    for (const auto& t : m.region.tris)
        for (int k = 0; k < 3; ++k)
            if (dot(n, m.region.at(t[2 * k], t[2 * k + 1]) - src.centre) > 0) return true;
    return false;
}

// Modifiers of surfaces a pretest ray may pass: anything that is not plainly opaque
// (transmitting materials, light sources, unknown kinds), since the oracle that knows
// materials is not available here. Conservative: a virtual source is only dropped when
// opaque surfaces block every pretest ray.
ModifierSet passableModifiers(const Scene& scene, const ShapeSet& shapes) {
    ModifierSet skip;
    auto consider = [&](int32_t prim, int32_t modifier) {
        int32_t mat = light::findMaterial(scene, prim);
        if (mat == kVoid) return;
        if (!material::typeTraits(scene.prims[size_t(mat)].type).opaqueToPretest)
            skip.add(modifier);
    };
    for (const auto& p : shapes.polygons) consider(p.prim, p.modifier);
    for (const auto& p : shapes.spheres) consider(p.prim, p.modifier);
    for (const auto& p : shapes.cones) consider(p.prim, p.modifier);
    for (const auto& p : shapes.rings) consider(p.prim, p.modifier);
    return skip;
}

// Whether the segment from `origin` along unit `dir` (to `tmax`) is free of opaque
// surfaces: those in `skip` are passed, and so are antimatter surfaces and what the
// antimatter the segment is inside clips (clip_set.h), as for a shadow ray. The
// segment starts outside all antimatter, as RADIANCE's pretest rays do.
bool clearPath(const SceneGeometry& geometry, const ModifierSet& skip,
               const AntimatterTable& antimatter, const Vec3& origin, const Vec3& dir,
               double tmax) {
    if (antimatter.empty()) return !geometry.occluded(origin, dir, tmax, &skip);
    ClipSet clip;
    Ray ray{origin, dir, tmax};
    double travelled = 0;
    for (int pass = 0; pass < 64; ++pass) {  // bounded like the renderer's pass loop
        std::optional<Hit> hit = geometry.closestHit(ray, &skip);
        if (!hit) return true;
        if (!clip.contains(hit->modifier)) {
            const std::vector<int32_t>* clips = antimatter.clips(hit->modifier);
            if (!clips) return false;  // opaque
            clip.cross(*clips, hit->front);
        }
        travelled += hit->t;
        ray = spawnRay(*hit, dir, tmax < HUGE_VAL ? std::fmax(0.0, tmax - travelled) : tmax);
    }
    return false;
}

// RADIANCE's -dp pretest (virtuals.c vstestvis), geometric: whether some point of the
// mirror sees the real source's centre past opaque surfaces. Sample count: `density`
// per steradian of the mirror as seen from the source (at least 4, at most 256).
bool mirrorSeesSource(const SceneGeometry& geometry, const ModifierSet& skip,
                      const AntimatterTable& antimatter, const RelayPlane& m,
                      const DirectSource& src, int side, int density) {
    const PlanarRegion& r = m.region;
    double omega = 2 * kPi;
    if (!src.distant()) {
        double d = length(src.centre - r.centroid);
        omega = d > 0 ? std::fmin(2 * kPi, r.area / (d * d)) : 2 * kPi;
    }
    int n = int(std::clamp(std::ceil(density * omega), 4.0, 256.0));
    int k = int(std::ceil(std::sqrt(double(n))));
    Vec3 lift = r.normal * (side * 1e-6 * std::fmax(1.0, maxAbs(r.centroid)));
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            double u = r.u0 + (i + 0.5) / k * (r.u1 - r.u0);
            double v = r.v0 + (j + 0.5) / k * (r.v1 - r.v0);
            if (!r.contains(u, v)) continue;
            Vec3 p = r.at(u, v) + lift;
            Vec3 dir = src.distant() ? src.centre : src.centre - p;
            double dist = src.distant() ? HUGE_VAL : length(dir);
            if (!src.distant()) dir = dir / dist;
            // Light surfaces are passed (so the source's own never blocks); stop short
            // of the source's centre.
            double tmax = src.distant() ? HUGE_VAL : dist * (1 - 1e-6);
            if (clearPath(geometry, skip, antimatter, p, dir, tmax)) return true;
        }
    return false;
}

// virtuals.c getdisk: a virtual source is relayed again only by a surface on the other
// side of the relay that made it than where the source appears (the side its light
// leaves that relay toward).
bool beyondRelay(const RelayPlane& prev, const DirectSource& base, const RelayPlane& next) {
    double rd = base.distant() ? dot(prev.region.normal, base.apparentCentre)
                               : prev.region.signedDistance(base.apparentCentre);
    double d = prev.region.signedDistance(next.region.centroid);
    return (d > 0) != (rd > 0);
}

// The image of source `s` in mirror `mi` (m_mirror.c), if the mirror can relay it.
std::optional<DirectSource> mirrorImage(const SourceList& list, size_t s, size_t mi) {
    const DirectSource& base = list.sources[s];
    const RelayPlane& m = list.relays[mi];
    // A mirror reflects on its front only (the oracle answers Opaque on its back), so
    // only sources in front of it are relayed.
    int side = reflectingSide(m, base);
    if (side <= 0) return std::nullopt;
    if (base.isVirtual()) {
        const RelayPlane& prev = list.relays[size_t(base.relays.front().relay)];
        if (prev.isPrism()) {
            if (!beyondRelay(prev, base, m)) return std::nullopt;
        } else {
            // The relaying mirror must lie on the side light reaches this one from.
            double d = m.region.signedDistance(prev.region.centroid);
            if (d * side <= 0) return std::nullopt;
        }
    }
    RelayStep step;
    step.relay = int32_t(mi);
    step.shear = m.region.normal * -2.0;
    step.target = base.apparentCentre;
    step.targetDistant = base.distant();
    DirectSource v = base;
    v.relays.insert(v.relays.begin(), step);
    v.mirrorSide = side;
    v.apparentCentre =
        base.distant() ? m.reflectDir(base.apparentCentre) : m.reflectPoint(base.apparentCentre);
    return v;
}

// The image of source `s` through redirection `k` of prism `mi` (m_direct.c dir_proj):
// the redirection is evaluated for light from the source reaching the prism's centre
// (DxA DyA DzA zero, as RADIANCE), and the shear maps the source to where it appears
// along the redirected direction.
std::optional<DirectSource> prismImage(const SourceList& list, size_t s, size_t mi, int k,
                                       const RedirectFunction& redirect) {
    const DirectSource& base = list.sources[s];
    const RelayPlane& m = list.relays[mi];
    const Vec3& n = m.region.normal;
    if (reflectingSide(m, base) == 0) return std::nullopt;
    if (base.isVirtual() && !beyondRelay(list.relays[size_t(base.relays.front().relay)], base, m))
        return std::nullopt;
    Vec3 centre = m.region.centroid;
    Vec3 old;
    double dist = 1;
    if (base.distant()) {
        old = -base.apparentCentre;
    } else {
        old = centre - base.apparentCentre;
        dist = length(old);
        if (!(dist > 0)) return std::nullopt;
        old = old / dist;
    }
    double oldDot = dot(old, n);
    if (std::fabs(oldDot) <= kFtiny) return std::nullopt;  // parallels the plane
    Hit at;
    at.t = dist;
    at.point = centre;
    at.normal = n;
    at.front = oldDot < 0;
    at.prim = m.prim;
    at.modifier = m.modifier;
    at.offset = 1e-6 * std::fmax(1.0, maxAbs(centre));
    material::Redirection r = redirect(at, old, k, Vec3{});
    if (!r.ok || r.coef <= kFtiny) return std::nullopt;  // insignificant
    double newDot = dot(r.dir, n);
    if (std::fabs(newDot) <= kFtiny) return std::nullopt;
    RelayStep step;
    step.relay = int32_t(mi);
    step.projection = k;
    step.shear = r.dir / newDot - old / oldDot;
    if ((newDot > 0) != (oldDot > 0)) step.shear -= n * 2.0;  // crossing back: mirrored
    // A redirection that changes nothing makes no virtual source (makevsrc: no-op).
    if (maxAbs(step.shear) <= kFtiny) return std::nullopt;
    step.target = base.apparentCentre;
    step.targetDistant = base.distant();
    DirectSource v = base;
    v.relays.insert(v.relays.begin(), step);
    v.mirrorSide = 0;
    v.apparentCentre = base.distant() ? normalize(step.projectDir(m.region, base.apparentCentre))
                                      : step.project(m.region, base.apparentCentre);
    return v;
}

}  // namespace

bool PlanarRegion::contains(double u, double v) const {
    if (u < u0 || u > u1 || v < v0 || v > v1) return false;
    for (const auto& t : tris) {
        double a = (t[2] - t[0]) * (v - t[1]) - (u - t[0]) * (t[3] - t[1]);
        double b = (t[4] - t[2]) * (v - t[3]) - (u - t[2]) * (t[5] - t[3]);
        double c = (t[0] - t[4]) * (v - t[5]) - (u - t[4]) * (t[1] - t[5]);
        if (a >= 0 && b >= 0 && c >= 0) return true;
    }
    return false;
}

PlanarRegion makePlanarRegion(const ShapeSet& shapes, size_t index) {
    const PolygonShape& p = shapes.polygons[index];
    PlanarRegion r;
    r.normal = p.normal;
    r.offset = p.offset;
    r.origin = p.origin;
    r.uAxis = p.uAxis;
    r.vAxis = cross(p.normal, p.uAxis);
    r.u0 = r.v0 = HUGE_VAL;
    r.u1 = r.v1 = -HUGE_VAL;
    double cu = 0, cv = 0;
    for (size_t t = 0; t < shapes.triangles.size(); ++t) {
        if (shapes.trianglePolygon[t] != index) continue;
        std::array<double, 6> uv;
        for (int k = 0; k < 3; ++k) {
            Vec3 rel = shapes.vertices[shapes.triangles[t][size_t(k)]] - r.origin;
            uv[size_t(2 * k)] = dot(rel, r.uAxis);
            uv[size_t(2 * k + 1)] = dot(rel, r.vAxis);
            r.u0 = std::fmin(r.u0, uv[size_t(2 * k)]);
            r.u1 = std::fmax(r.u1, uv[size_t(2 * k)]);
            r.v0 = std::fmin(r.v0, uv[size_t(2 * k + 1)]);
            r.v1 = std::fmax(r.v1, uv[size_t(2 * k + 1)]);
        }
        double a = 0.5 * area2(uv);
        if (a < 0) {  // keep every triangle counter-clockwise about the normal
            std::swap(uv[2], uv[4]);
            std::swap(uv[3], uv[5]);
            a = -a;
        }
        if (a <= 0) continue;
        r.tris.push_back(uv);
        r.area += a;
        cu += a * (uv[0] + uv[2] + uv[4]) / 3;
        cv += a * (uv[1] + uv[3] + uv[5]) / 3;
    }
    r.centroid = r.area > 0 ? r.at(cu / r.area, cv / r.area) : r.origin;
    Vec3 rel = p.vertexMean - r.origin;
    r.centre = r.contains(dot(rel, r.uAxis), dot(rel, r.vAxis)) ? p.vertexMean : r.centroid;
    return r;
}

SourceList buildSourceList(const Scene& scene, const SceneGeometry& geometry,
                           const DirectOptions& options, bool virtualSources,
                           const RedirectFunction& redirect) {
    SourceList list;
    const ShapeSet& shapes = geometry.shapes();
    list.sourceOfPrim.assign(scene.prims.size(), -1);
    list.distantInList.assign(shapes.sources.size(), false);

    // RADIANCE compat: illum surfaces are direct sources in the backward pass.
    light::LightSearchOptions search;
    search.illumEmits = true;
    search.pass = options.pass;
    for (const light::LightSource& ls : light::findLightSources(scene, geometry, search)) {
        if (ls.ambientOnly()) continue;  // sky or ground glow: SSKIP
        const bool glow = ls.params.glow();
        DirectSource src;
        src.light = ls;
        if (glow) src.proximity = ls.params.glowMaxRadius;
        if (ls.shape == light::EmitterShape::Polygon) {
            src.region = int32_t(list.regions.size());
            list.regions.push_back(makePlanarRegion(shapes, size_t(ls.shapeIndex)));
            if (list.regions.back().area <= 0) {
                list.regions.pop_back();
                continue;
            }
        }
        src.centre = sourceCentre(ls, shapes, list.regions, src.region);
        src.apparentCentre = src.centre;
        if (ls.distant())
            list.distantInList[size_t(ls.shapeIndex)] = true;
        else
            list.sourceOfPrim[size_t(ls.prim)] = int32_t(list.sources.size());
        list.sources.push_back(std::move(src));
    }
    list.realCount = list.sources.size();
    if (!virtualSources || options.relays <= 0 || list.sources.empty()) return list;

    // Planar mirrors and prisms. RADIANCE relays only through flat surfaces; a curved
    // mirror (sphere, cone) makes no virtual source. Prisms need the renderer's functions.
    for (size_t i = 0; i < shapes.polygons.size(); ++i) {
        int32_t mat = light::findMaterial(scene, shapes.polygons[i].prim);
        if (mat == kVoid) continue;
        const material::TypeTraits::Relay relay =
            material::typeTraits(scene.prims[size_t(mat)].type).relay;
        RelayPlane m;
        if (relay == material::TypeTraits::Relay::Mirror) {
            m.kind = RelayPlane::Kind::Mirror;
        } else if (relay != material::TypeTraits::Relay::None && redirect) {
            m.kind = RelayPlane::Kind::Prism;
            m.projections = relay == material::TypeTraits::Relay::Prism2 ? 2 : 1;
        } else {
            continue;
        }
        m.prim = shapes.polygons[i].prim;
        m.modifier = shapes.polygons[i].modifier;
        m.region = makePlanarRegion(shapes, i);
        if (m.region.area > 0) list.relays.push_back(std::move(m));
    }
    if (list.relays.empty()) return list;

    const ModifierSet passable = passableModifiers(scene, shapes);
    const AntimatterTable antimatter(scene);
    // Level by level (virtuals.c addvirtuals): each source of the previous level seen
    // through each relay other than the one it was last relayed by.
    size_t levelStart = 0, levelEnd = list.sources.size();
    for (int level = 1; level <= options.relays; ++level) {
        for (size_t s = levelStart; s < levelEnd; ++s) {
            for (size_t mi = 0; mi < list.relays.size(); ++mi) {
                const RelayPlane& m = list.relays[mi];
                if (!list.sources[s].relays.empty() &&
                    list.sources[s].relays.front().relay == int32_t(mi))
                    continue;
                for (int k = 0; k < m.projections; ++k) {
                    std::optional<DirectSource> v = m.isPrism()
                                                        ? prismImage(list, s, mi, k, redirect)
                                                        : mirrorImage(list, s, mi);
                    if (!v) continue;
                    const DirectSource& base = list.sources[s];
                    if (!base.isVirtual()) {
                        if (!facesMirror(base, shapes, list.regions, m)) continue;
                        int side = reflectingSide(m, base);
                        if (options.pretest > 0 &&
                            !mirrorSeesSource(geometry, passable, antimatter, m, base, side,
                                              options.pretest))
                            continue;
                    }
                    // A local glow relayed farther than its radius lights nothing
                    // (makevsrc: SPROX).
                    if (v->proximity > 0 && !v->distant() &&
                        length(v->apparentCentre - m.region.centroid) > v->proximity)
                        continue;
                    list.sources.push_back(std::move(*v));
                }
            }
        }
        levelStart = levelEnd;
        levelEnd = list.sources.size();
        if (levelStart == levelEnd) break;
    }
    return list;
}

}  // namespace rp::render

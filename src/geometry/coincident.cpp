// Coincident polygons (see coincident.h).
#include "geometry/coincident.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rp {

namespace {

// RADIANCE's FTINY: hits this close along the ray are coincident (rayreject).
constexpr double kFtiny = 1e-6;

// A polygon's plane, with the normal's sign fixed so that coplanar polygons facing
// either way share it: the largest component positive.
struct PlaneKey {
    int axis;
    Vec3 normal;
    double offset;
};

PlaneKey planeKey(const PolygonShape& p) {
    int a = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(p.normal[k]) > std::fabs(p.normal[a])) a = k;
    const double s = p.normal[a] < 0 ? -1 : 1;
    return {a, p.normal * s, p.offset * s};
}

struct Extent {
    Bounds3 box;
    TriangleRange triangles;
};

bool withinPlane(const ShapeSet& shapes, TriangleRange r, const PolygonShape& plane) {
    for (uint32_t t = r.first; t < r.last; ++t)
        for (uint32_t v : shapes.triangles[t])
            if (std::fabs(dot(plane.normal, shapes.vertices[v]) - plane.offset) > kFtiny)
                return false;
    return true;
}

// Overlap of positive area in the plane: the boxes overlap by more than FTINY along
// both axes other than the plane's main one (polygons that only touch at an edge are
// not partners).
bool overlapInPlane(const Bounds3& a, const Bounds3& b, int axis) {
    for (int k = 0; k < 3; ++k) {
        const double overlap = std::fmin(a.max[k], b.max[k]) - std::fmax(a.min[k], b.min[k]);
        if (overlap < (k == axis ? -kFtiny : kFtiny)) return false;
    }
    return true;
}

// Whether p (in the polygon's plane, within rounding) lies in one of its triangles; the
// triangle is returned. Edges count as inside, with a relative tolerance.
bool insideTriangles(const ShapeSet& shapes, TriangleRange r, const Vec3& n, const Vec3& p,
                     uint32_t& triangle) {
    for (uint32_t t = r.first; t < r.last; ++t) {
        const TriIndices& tri = shapes.triangles[t];
        const Vec3& a = shapes.vertices[tri[0]];
        const Vec3& b = shapes.vertices[tri[1]];
        const Vec3& c = shapes.vertices[tri[2]];
        const double area = dot(n, cross(b - a, c - a));
        if (area == 0) continue;
        const double tol = -1e-9 * std::fabs(area);
        if (dot(n, cross(b - a, p - a)) * (area > 0 ? 1 : -1) >= tol &&
            dot(n, cross(c - b, p - b)) * (area > 0 ? 1 : -1) >= tol &&
            dot(n, cross(a - c, p - c)) * (area > 0 ? 1 : -1) >= tol) {
            triangle = t;
            return true;
        }
    }
    return false;
}

uint8_t materialClass(const Scene& scene, int32_t modifier) {
    const int32_t m = chainMaterial(scene, modifier);
    if (m == kVoid) return 0;
    return isTransparentMaterial(scene.prims[size_t(m)].type) ? 1 : 2;
}

}  // namespace

CoincidentPolygons::CoincidentPolygons(const Scene& scene, const ShapeSet& shapes) {
    const size_t n = shapes.polygons.size();
    if (n < 2) return;
    std::vector<Extent> extents(n);
    for (uint32_t t = 0; t < shapes.triangles.size(); ++t) {
        Extent& e = extents[shapes.trianglePolygon[t]];
        if (e.triangles.first == e.triangles.last) e.triangles.first = t;
        e.triangles.last = t + 1;
        for (uint32_t v : shapes.triangles[t]) e.box.extend(shapes.vertices[v]);
    }
    std::vector<PlaneKey> keys(n);
    std::vector<uint32_t> order(n);
    for (uint32_t i = 0; i < n; ++i) {
        keys[i] = planeKey(shapes.polygons[i]);
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return keys[a].axis != keys[b].axis ? keys[a].axis < keys[b].axis
                                            : keys[a].offset < keys[b].offset;
    });

    // Groups of (nearly) one plane, then pairs within a group by a sweep along an
    // in-plane axis, so that a floor of many tiles costs its neighbours, not its square.
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (size_t g = 0; g < n;) {
        size_t end = g + 1;
        while (end < n && keys[order[end]].axis == keys[order[g]].axis &&
               keys[order[end]].offset - keys[order[end - 1]].offset <= kFtiny)
            ++end;
        if (end - g > 1) {
            const int axis = keys[order[g]].axis, sweep = (axis + 1) % 3;
            std::vector<uint32_t> group(order.begin() + long(g), order.begin() + long(end));
            std::sort(group.begin(), group.end(), [&](uint32_t a, uint32_t b) {
                return extents[a].box.min[sweep] < extents[b].box.min[sweep];
            });
            for (size_t i = 0; i < group.size(); ++i) {
                const uint32_t a = group[i];
                for (size_t j = i + 1; j < group.size(); ++j) {
                    const uint32_t b = group[j];
                    if (extents[b].box.min[sweep] > extents[a].box.max[sweep] - kFtiny) break;
                    if (std::fabs(dot(keys[a].normal, keys[b].normal)) < 1 - 1e-9) continue;
                    if (!overlapInPlane(extents[a].box, extents[b].box, axis)) continue;
                    if (!withinPlane(shapes, extents[b].triangles, shapes.polygons[a]) ||
                        !withinPlane(shapes, extents[a].triangles, shapes.polygons[b]))
                        continue;
                    pairs.emplace_back(a, b);
                    pairs.emplace_back(b, a);
                }
            }
        }
        g = end;
    }
    if (pairs.empty()) return;
    std::sort(pairs.begin(), pairs.end());
    begin_.assign(n, 0);
    end_.assign(n, 0);
    partners_.reserve(pairs.size());
    for (size_t i = 0; i < pairs.size(); ++i) {
        const uint32_t p = pairs[i].first;
        if (i == 0 || pairs[i - 1].first != p) begin_[p] = uint32_t(partners_.size());
        partners_.push_back(pairs[i].second);
        end_[p] = uint32_t(partners_.size());
    }
    triangles_.resize(n);
    materialClass_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
        triangles_[i] = extents[i].triangles;
        materialClass_[i] = materialClass(scene, shapes.polygons[i].modifier);
    }
}

void CoincidentPolygons::resolve(const ShapeSet& shapes, const Vec3& o, const Vec3& d,
                                 const ModifierSet* skip, uint32_t& polygon, uint32_t& triangle,
                                 double& t) const {
    if (partners_.empty() || begin_[polygon] == end_[polygon]) return;
    const uint32_t hit = polygon;
    const double hitT = t;
    // RADIANCE's order (raytrace.c rayreject, checked with rtrace -oms): material class,
    // then the later modifier, then the later surface.
    auto beats = [&](uint32_t a, uint32_t b) {
        if (materialClass_[a] != materialClass_[b]) return materialClass_[a] > materialClass_[b];
        const PolygonShape& pa = shapes.polygons[a];
        const PolygonShape& pb = shapes.polygons[b];
        if (pa.modifier != pb.modifier) return pa.modifier > pb.modifier;
        return pa.prim > pb.prim;
    };
    for (uint32_t i = begin_[hit]; i < end_[hit]; ++i) {
        const uint32_t q = partners_[i];
        const PolygonShape& p = shapes.polygons[q];
        if (skip && skip->contains(p.modifier)) continue;
        const double dn = dot(p.normal, d);
        if (dn == 0) continue;
        const double tq = (p.offset - dot(p.normal, o)) / dn;
        if (!(tq > 0) || std::fabs(tq - hitT) > kFtiny || !beats(q, polygon)) continue;
        uint32_t tri;
        if (!insideTriangles(shapes, triangles_[q], p.normal, o + d * tq, tri)) continue;
        polygon = q;
        triangle = tri;
        t = tq;
    }
}

}  // namespace rp

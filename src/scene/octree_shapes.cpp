// See octree_shapes.h. Every tolerance, constant and order of evaluation follows RADIANCE's
// oconv, because which cube an object is found to meet decides the octree's bytes.
#include "scene/octree_shapes.h"

#include <cmath>

#include "util/warnings.h"

namespace rp::octree {

using namespace radgeom;

namespace {
constexpr double kRoot3 = 1.732050808;  // RADIANCE's ROOT3, not sqrt(3)
constexpr double kVertexEps = 1e-5;     // face.c VERTEPS: allowed distance off the plane

Vec kidOrigin(const Cube& cu, double half, int i) {
    Vec o = cu.org;
    for (int j = 0; j < 3; ++j)
        if ((1 << j) & i) o[j] += half;
    return o;
}

void addPoint(const Vec& p, Vec& lo, Vec& hi) {
    for (int i = 0; i < 3; ++i) {
        if (p[i] < lo[i]) lo[i] = p[i];
        if (p[i] > hi[i]) hi[i] = p[i];
    }
}

// bbox.c circle2bbox(): the box of a disc of radius rad around cent, facing norm.
void addCircle(const Vec& cent, const Vec& norm, double rad, Vec& lo, Vec& hi) {
    for (int i = 0; i < 3; ++i) {
        const double r = std::sqrt(1. - norm[i] * norm[i]);
        double d = cent[i] + r * rad;
        if (d > hi[i]) hi[i] = d;
        d = cent[i] - r * rad;
        if (d < lo[i]) lo[i] = d;
    }
}

std::string who(const Primitive& p) {
    return std::string(primTypeName(p.type)) + " '" + p.name + "': ";
}
}  // namespace

Shapes::Shapes(const Scene& scene, size_t count, const PlacedCube& placedCube)
    : scene_(scene), shapes_(count) {
    for (size_t i = 0; i < count; ++i) {
        const Primitive& p = scene.prims[i];
        Shape& s = shapes_[i];
        s.a = p.rargs.data();
        switch (p.type) {
            case PrimType::Polygon:
                prepareFace(int32_t(i), s);
                break;
            case PrimType::Sphere:
            case PrimType::Bubble:
                // The reader has made negative radii positive (flipping the type) and
                // refused zero ones, as o_sphere() would on first sight.
                s.kind = Shape::Kind::Sphere;
                s.d0 = p.rargs[3];
                break;
            case PrimType::Cone:
            case PrimType::Cup:
            case PrimType::Cylinder:
            case PrimType::Tube:
            case PrimType::Ring:
                prepareCone(int32_t(i), s);
                break;
            case PrimType::Instance:
            case PrimType::Mesh:
                s.kind = Shape::Kind::Placed;
                s.nv = int32_t(placements_.size());
                placements_.push_back({placedCube(p), fullTransform(p.sargs, 1)});
                break;
            default:
                break;
        }
    }
}

// face.c getface(): a closing vertex equal to the first is dropped; the normal sums the
// fan's cross products; the offset averages the vertices' distances.
void Shapes::prepareFace(int32_t obj, Shape& s) {
    const Primitive& p = scene_.prims[size_t(obj)];
    const double* v = s.a;
    int nv = int(p.rargs.size() / 3);
    if (nv > 3 && dist2(vec(v), vec(v + 3 * (nv - 1))) <= kTiny * kTiny) --nv;
    Vec n{0, 0, 0};
    Vec v1 = sub(vec(v + 3), vec(v));
    for (int i = 2; i < nv; ++i) {
        const Vec v2 = sub(vec(v + 3 * i), vec(v));
        const Vec c = cross(v1, v2);
        for (int k = 0; k < 3; ++k) n[k] += c[k];
        v1 = v2;
    }
    s.nv = nv;
    s.d1 = normalize(n);
    s.dir = n;
    if (s.d1 == 0.0) return;  // no area: misses every cube (the reader warned)
    s.kind = Shape::Kind::Face;
    s.d1 *= 0.5;
    double offset = dot(v, n);
    const bool smallOffset = std::fabs(offset) <= kVertexEps;
    int bad = 0;
    for (int i = 1; i < nv; ++i) {
        const double d = dot(v + 3 * i, n);
        bad += smallOffset ? std::fabs(d - offset / i) > kVertexEps
                           : std::fabs(1.0 - d * i / offset) > kVertexEps;
        offset += d;
    }
    s.d0 = offset / double(nv);
    if (nv > 3 && bad) warn(p.loc, who(p) + "non-planar vertex");
    s.ax = std::fabs(n[1]) > std::fabs(n[0]);
    if (std::fabs(n[2]) > std::fabs(n[s.ax])) s.ax = 2;
}

// cone.c getcone(), after the reader's checks: the radii are non-negative, a cone whose
// radii are equal has been made a cylinder, and the axis is not degenerate. The smaller
// radius comes first.
void Shapes::prepareCone(int32_t obj, Shape& s) {
    const Primitive& p = scene_.prims[size_t(obj)];
    const double* ca = s.a;
    const bool ring = p.type == PrimType::Ring;
    s.p0 = 0;
    s.p1 = ring ? 0 : 3;
    s.d0 = s.d1 = ca[6];
    if (p.type == PrimType::Cone || p.type == PrimType::Cup || ring) {
        if (ca[7] - ca[6] > kTiny) {
            s.d1 = ca[7];
        } else if (ca[6] - ca[7] > kTiny) {
            if (!ring) std::swap(s.p0, s.p1);
            s.d0 = ca[7];
        } else {
            return;  // equal radii: a ring is refused by the reader, a cone converted
        }
    }
    s.dir = ring ? vec(ca + 3) : sub(vec(ca + s.p1), vec(ca + s.p0));
    if (normalize(s.dir) == 0.0) return;  // refused by the reader
    s.kind = ring ? Shape::Kind::Ring : Shape::Kind::Cone;
}

void Shapes::addBounds(int32_t obj, Vec& lo, Vec& hi) const {
    const Shape& s = shapes_[size_t(obj)];
    const Primitive& p = scene_.prims[size_t(obj)];
    switch (s.kind) {
        case Shape::Kind::Sphere:
            for (int i = 0; i < 3; ++i) {
                Vec v = vec(s.a);
                v[i] -= s.a[3];
                addPoint(v, lo, hi);
                v[i] += 2.0 * s.a[3];
                addPoint(v, lo, hi);
            }
            break;
        case Shape::Kind::Face:
            for (int j = s.nv; j-- > 0;) addPoint(vec(s.a + 3 * j), lo, hi);
            break;
        case Shape::Kind::Cone:
            addCircle(vec(s.a + s.p0), s.dir, s.d0, lo, hi);
            [[fallthrough]];
        case Shape::Kind::Ring:
            addCircle(vec(s.a + s.p1), s.dir, s.d1, lo, hi);
            break;
        case Shape::Kind::Placed: {
            const Placement& pl = placements_[size_t(s.nv)];
            for (int j = 0; j < 8; ++j) {
                Vec v;
                for (int i = 0; i < 3; ++i)
                    v[i] = pl.cube.org[i] + ((j & 1 << i) ? pl.cube.size : 0.0);
                addPoint(pl.xf.forward.point(v), lo, hi);
            }
            break;
        }
        case Shape::Kind::None:
            // A polygon without area still counts in RADIANCE's bounds.
            if (p.type == PrimType::Polygon)
                for (int j = s.nv; j-- > 0;) addPoint(vec(s.a + 3 * j), lo, hi);
            break;
    }
}

bool Shapes::isVolume(int32_t obj) const {
    return shapes_[size_t(obj)].kind == Shape::Kind::Placed;
}

int Shapes::overlap(int32_t obj, const Cube& cu) const {
    const Shape& s = shapes_[size_t(obj)];
    switch (s.kind) {
        case Shape::Kind::Face:
            return faceOverlap(s, cu);
        case Shape::Kind::Sphere:
            return sphereOverlap(s, cu);
        case Shape::Kind::Cone:
        case Shape::Kind::Ring:
            return coneOverlap(s, cu);
        case Shape::Kind::Placed:
            return placedOverlap(placements_[size_t(s.nv)], cu);
        case Shape::Kind::None:
            return kMiss;
    }
    return kMiss;
}

// o_face.c.
int Shapes::faceOverlap(const Shape& f, const Cube& cu) const {
    return faceMeetsCube(f.a, f.nv, f.dir, f.d0, f.ax, cu.org, cu.size) ? kHit : kMiss;
}

// sphere.c o_sphere(): the cube's bounding sphere against the sphere, then the distance
// from the centre to the nearest point of the cube.
int Shapes::sphereOverlap(const Shape& s, const Cube& cu) const {
    const double* cent = s.a;
    const double rad = s.d0;
    const double d1 = kRoot3 / 2.0 * cu.size;
    double d2 = cu.size * 0.5;
    Vec v1;
    for (int i = 0; i < 3; ++i) v1[i] = cu.org[i] + d2 - cent[i];
    d2 = dot(v1, v1);
    if (d2 > (rad + d1 + kTiny) * (rad + d1 + kTiny)) return kMiss;
    if (d1 < rad) {
        if (d2 < (rad - d1 - kTiny) * (rad - d1 - kTiny)) return kMiss;  // cube inside
        if (d2 < (rad + kTiny) * (rad + kTiny)) return kHit;
    }
    for (int i = 0; i < 3; ++i) {
        if (cent[i] < cu.org[i])
            v1[i] = cu.org[i] - cent[i];
        else if (cent[i] > cu.org[i] + cu.size)
            v1[i] = cent[i] - (cu.org[i] + cu.size);
        else
            v1[i] = 0;
    }
    return dot(v1, v1) <= (rad + kTiny) * (rad + kTiny) ? kHit : kMiss;
}

// o_cone.c (STRICT): the cone's side line nearest the cube's centre against the cube's
// bounding sphere and then the cube; failing both, the eight half-size cubes, down to
// the smallest cube size.
int Shapes::coneOverlap(const Shape& c, const Cube& cu) const {
    double r = cu.size * 0.5;
    Vec p;
    for (int i = 0; i < 3; ++i) p[i] = cu.org[i] + r;
    r *= kRoot3;
    const double* p0 = c.a + c.p0;
    const double* p1 = c.a + c.p1;
    Vec v = sub(p, vec(p0));
    const double d = dot(v, c.dir);
    for (int i = 0; i < 3; ++i) v[i] -= d * c.dir[i];
    if (normalize(v) != 0.0) {
        Vec e0, e1;
        for (int i = 0; i < 3; ++i) {
            e0[i] = c.d0 * v[i] + p0[i];
            e1[i] = c.d1 * v[i] + p1[i];
        }
        if (dist2Segment(p, e0, e1) > (r + kTiny) * (r + kTiny)) return kMiss;
        Vec hi;
        for (int i = 0; i < 3; ++i) hi[i] = cu.org[i] + cu.size;
        if (clipSegment(e0, e1, cu.org, hi)) return kHit;
    }
    Cube kid;
    kid.size = cu.size * 0.5;
    if (kid.size < minCube_) return kHit;
    for (int j = 0; j < 8; ++j) {
        kid.org = kidOrigin(cu, kid.size, j);
        if (coneOverlap(c, kid)) return kHit;
    }
    return kMiss;
}

// o_instance.c o_cube(): the cube's corners taken into the placed file's space, then the
// placed cube's corners and edges taken into ours.
int Shapes::placedOverlap(const Placement& pl, const Cube& cu) const {
    Vec lo = pl.cube.org, hi;
    for (int j = 0; j < 3; ++j) hi[j] = lo[j] + pl.cube.size;
    int vloc = kAbove | kBelow, vout = 0;
    for (int i = 0; i < 8; ++i) {
        const int j = locate(pl.xf.backward.point(kidOrigin(cu, cu.size, i)), lo, hi);
        if (j) vout++;
        vloc &= j;
    }
    if (vout == 0) return kInside;
    if (vout < 8) return kHit;
    if (vloc) return kMiss;
    lo = cu.org;
    for (int j = 0; j < 3; ++j) hi[j] = lo[j] + cu.size;
    std::array<Vec, 8> vert;
    vloc = kAbove | kBelow;
    for (int i = 0; i < 8; ++i) {
        vert[size_t(i)] = pl.xf.forward.point(kidOrigin(pl.cube, pl.cube.size, i));
        const int j = locate(vert[size_t(i)], lo, hi);
        if (!j) return kHit;
        vloc &= j;
    }
    if (vloc) return kMiss;
    static constexpr int kStart[4] = {0, 3, 5, 6};
    for (int s : kStart)
        for (int j = 0; j < 3; ++j)
            if (clipSegment(vert[size_t(s)], vert[size_t(s ^ 1 << j)], lo, hi)) return kHit;
    return kMiss;
}

}  // namespace rp::octree

// Cone, cup, cylinder, tube (see cone.h).
#include "geometry/cone.h"

#include <cmath>
#include <string>

#include "util/warnings.h"

namespace rp {

namespace {
constexpr double kFtiny = 1e-6;  // RADIANCE's FTINY, used for its radius sign tests
}

bool makeCone(const Primitive& prim, int32_t primIndex, ConeShape& shape) {
    const std::string what = std::string(primTypeName(prim.type)) + " '" + prim.name + "'";
    bool cylinder = prim.type == PrimType::Cylinder || prim.type == PrimType::Tube;
    size_t want = cylinder ? 7 : 8;
    const std::vector<double>& a = prim.rargs;
    if (a.size() != want)
        throw InputError(prim.loc, what + ": expected " + std::to_string(want) +
                                       " real arguments, got " + std::to_string(a.size()));
    shape.inward = prim.type == PrimType::Cup || prim.type == PrimType::Tube;
    double r0 = a[6], r1 = cylinder ? a[6] : a[7];
    if (cylinder) {
        if (r0 < -kFtiny) {
            warn(prim.loc, what + ": negative radius");
            shape.inward = !shape.inward;
            r0 = r1 = -r0;
        } else if (r0 <= kFtiny) {
            warn(prim.loc, what + ": illegal radii, ignored");
            return false;
        }
    } else {
        int s0 = r0 < -kFtiny ? -1 : (r0 > kFtiny ? 1 : 0);
        int s1 = r1 < -kFtiny ? -1 : (r1 > kFtiny ? 1 : 0);
        if (s0 + s1 == 0) {
            warn(prim.loc, what + ": illegal radii, ignored");
            return false;
        }
        if (s0 < 0 || s1 < 0) {
            warn(prim.loc, what + ": negative radii");
            shape.inward = !shape.inward;
        }
        r0 = std::fabs(r0) * (s0 != 0);
        r1 = std::fabs(r1) * (s1 != 0);
    }
    shape.p0 = {a[0], a[1], a[2]};
    Vec3 p1{a[3], a[4], a[5]};
    Vec3 axis = p1 - shape.p0;
    shape.length = length(axis);
    if (!(shape.length > 0)) {
        warn(prim.loc, what + ": unknown orientation (zero-length axis), ignored");
        return false;
    }
    shape.axis = axis / shape.length;
    shape.r0 = r0;
    shape.r1 = r1;
    shape.slope = (r1 - r0) / shape.length;
    orthonormalFrame(shape.axis, shape.e1, shape.e2);
    shape.prim = primIndex;
    shape.modifier = prim.modifier;
    return true;
}

bool intersectCone(const ConeShape& c, const Vec3& o, const Vec3& d, double tmin, double tmax,
                   double& t) {
    // With w = o + t d - p0, h = w.a the height and q = w - h a the radial part, the
    // surface is |q|^2 = (r0 + k h)^2, 0 <= h <= L. Splitting into axial and radial
    // parts first avoids cancellation for rays nearly parallel to the axis.
    Vec3 w0 = o - c.p0;
    double h0 = dot(w0, c.axis);
    double dd = dot(d, c.axis);
    Vec3 q0 = w0 - c.axis * h0;
    Vec3 dq = d - c.axis * dd;
    double k = c.slope;
    double rad0 = c.r0 + k * h0;  // cone radius at the origin's height
    double qa = dot(dq, dq) - k * k * dd * dd;
    double qb = dot(q0, dq) - k * rad0 * dd;
    double qc = dot(q0, q0) - rad0 * rad0;
    auto onSegment = [&](double tt) {
        double h = h0 + tt * dd;
        return h >= 0 && h <= c.length;
    };
    return smallestRoot(qa, qb, qc, tmin, tmax, onSegment, t);
}

Vec3 coneNormal(const ConeShape& c, const Vec3& p) {
    Vec3 w = p - c.p0;
    Vec3 radial = w - c.axis * dot(w, c.axis);
    double rl = length(radial);
    Vec3 rho = rl > 0 ? radial / rl : c.e1;  // at a cone's apex any radial direction
    // Gradient of |q| - k h: outward normal tilts back along the axis as radius grows.
    Vec3 n = normalize(rho - c.axis * c.slope);
    return c.inward ? -n : n;
}

Bounds3 diskBounds(const Vec3& centre, const Vec3& n, double r) {
    Vec3 ext{r * std::sqrt(std::fmax(0.0, 1 - n.x * n.x)),
             r * std::sqrt(std::fmax(0.0, 1 - n.y * n.y)),
             r * std::sqrt(std::fmax(0.0, 1 - n.z * n.z))};
    return Bounds3{centre - ext, centre + ext};
}

Bounds3 coneBounds(const ConeShape& c) {
    Bounds3 b = diskBounds(c.p0, c.axis, c.r0);
    b.extend(diskBounds(c.p0 + c.axis * c.length, c.axis, c.r1));
    return b;
}

}  // namespace rp

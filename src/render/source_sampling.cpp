// Source subdivision and sample directions (see source_sampling.h).
#include "render/source_sampling.h"

#include <algorithm>
#include <cmath>

#include "geometry/surface.h"
#include "render/source_polygon.h"

namespace rp::render {

namespace {

constexpr double kFtiny = 1e-6;  // RADIANCE FTINY
constexpr int kMaxPerAxis = 8;   // sqrt(MAXSPART): cells per axis of a 2-D grid

// Cells per axis so that a source of size `size` at distance `dist` gets cells of at
// most ds/weight times their distance (RADIANCE's -ds rule), 1 with ds = 0.
int cellsPerAxis(double size, double dist, double ds, double weight) {
    if (ds <= 0 || !(dist > 0)) return 1;
    double n = std::ceil(std::fmax(weight, 1e-6) * size / (dist * ds) - 1e-9);
    return int(std::clamp(n, 1.0, double(kMaxPerAxis)));
}

// Position within cell i of n along one axis, moved by the jitter (RADIANCE: dj times a
// uniform offset over the cell).
double cellCoord(int i, int n, double jitter, Rng& rng) {
    double off = jitter > 0 ? jitter * (rng.uniform() - 0.5) : 0;
    return (i + 0.5 + off) / n;
}

// Shirley & Chiu (1997) concentric map of the unit square onto the unit disk: equal
// areas stay equal, so cells of the square become equal-area cells of the disk. rho >= 0:
// the left and lower wedges (x or y negative) turn by pi, so that they cover their own
// half of the disk and not the right and upper one a second time.
void concentric(double a, double b, double& rho, double& phi) {
    double x = 2 * a - 1, y = 2 * b - 1;
    if (x == 0 && y == 0) {
        rho = phi = 0;
        return;
    }
    if (std::fabs(x) > std::fabs(y)) {
        rho = x;
        phi = (kPi / 4) * (y / x);
    } else {
        rho = y;
        phi = kPi / 2 - (kPi / 4) * (x / y);
    }
    if (rho < 0) {
        rho = -rho;
        phi += kPi;
    }
}

// Directions in the cone about `axis` with cos half angle `cosMax`, n x n cells of equal
// solid angle: the disk point at radius rho maps to 1 - cos(theta) = rho^2 (1 - cosMax),
// which preserves area ratios.
template <class F>
void coneCells(const Vec3& axis, double cosMax, int n, double jitter, Rng& rng, F emit) {
    if (n == 1 && !(jitter > 0)) {
        // One unjittered cell: its centre maps to the disk's centre (rho = 0), so the
        // direction is the axis itself, as the general loop computes it bit for bit.
        // Why apart: small sources far away (many lamps, rcontrib -dt 0) are nearly all
        // one cell, and the frame, sin and cos were a tenth of their direct calculation.
        emit(normalize(axis), 2 * kPi * (1 - cosMax));
        return;
    }
    Vec3 e1, e2;
    orthonormalFrame(axis, e1, e2);
    double omega = 2 * kPi * (1 - cosMax) / (n * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double a = cellCoord(i, n, jitter, rng), b = cellCoord(j, n, jitter, rng);
            double rho, phi;
            concentric(a, b, rho, phi);
            double cosT = 1 - rho * rho * (1 - cosMax);
            double sinT = std::sqrt(std::fmax(0.0, 1 - cosT * cosT));
            Vec3 d = axis * cosT + (e1 * std::cos(phi) + e2 * std::sin(phi)) * sinT;
            emit(normalize(d), omega);
        }
}

void sampleSphere(const SphereShape& s, const Vec3& from, const DirectOptions& opt, double weight,
                  Rng& rng, std::vector<SourceSample>& out) {
    Vec3 toC = s.center - from;
    double d = length(toC);
    if (d <= s.radius * (1 + kFtiny)) return;  // inside: an outward sphere is not seen
    double sinMax = s.radius / d;
    double cosMax = std::sqrt(std::fmax(0.0, 1 - sinMax * sinMax));
    int n = cellsPerAxis(2 * s.radius, d, opt.sampling, weight);
    coneCells(toC / d, cosMax, n, opt.jitter, rng, [&](const Vec3& dir, double omega) {
        // Nearest intersection with the sphere; at the rim (rounding) the closest point.
        double b = dot(toC, dir);
        double disc = b * b - (d * d - s.radius * s.radius);
        double t = disc > 0 ? b - std::sqrt(disc) : b;
        SourceSample smp;
        smp.dir = dir;
        smp.dist = t;
        smp.target = from + dir * t;
        smp.omega = omega;
        out.push_back(smp);
    });
}

void sampleDistant(const DistantSource& s, const Vec3& from, const DirectOptions& opt,
                   double weight, Rng& rng, std::vector<SourceSample>& out) {
    double angle = 2 * std::acos(std::clamp(s.cosHalfAngle, -1.0, 1.0));
    int n = cellsPerAxis(angle, 1, opt.sampling, weight);
    coneCells(s.dir, s.cosHalfAngle, n, opt.jitter, rng, [&](const Vec3& dir, double omega) {
        SourceSample smp;
        smp.dir = dir;
        smp.dist = HUGE_VAL;
        smp.target = from + dir;
        // RADIANCE compat: one sample gets the source's whole solid angle (ss2).
        smp.omega = n == 1 ? s.solidAngle : omega;
        out.push_back(smp);
    });
}

// A sample at surface point p with emitting-side normal nrm and cell area `area`:
// omega = area cos / d^2, nothing if the cell faces away (RADIANCE: "behind source").
// `diskCorrection` uses area cos / (d^2 + area/pi) instead, which makes the irradiance
// of a whole disk seen on its axis exact (pi r^2 / (r^2 + h^2)) rather than RADIANCE's
// overestimate by (r/h)^2; it fades away as cells get small.
void addAreaSample(const Vec3& from, const Vec3& p, const Vec3& nrm, double area, double cosFactor,
                   std::vector<SourceSample>& out, bool diskCorrection = false) {
    Vec3 d = p - from;
    double dist = length(d);
    if (!(dist > 0)) return;
    Vec3 dir = d / dist;
    double cosSrc = -dot(dir, nrm);
    if (cosSrc <= kFtiny) return;
    SourceSample s;
    s.dir = dir;
    s.dist = dist;
    s.target = p;
    double d2 = dist * dist + (diskCorrection ? area / kPi : 0);
    s.omega = area * cosSrc * cosFactor / d2;
    out.push_back(s);
}

void sampleRing(const RingShape& r, const Vec3& from, const DirectOptions& opt, double weight,
                Rng& rng, std::vector<SourceSample>& out) {
    Vec3 rel = from - r.centre;
    if (dot(rel, r.normal) <= kFtiny) return;  // behind the ring
    double area = kPi * (r.r1 * r.r1 - r.r0 * r.r0);
    int n = cellsPerAxis(2 * r.r1, length(rel), opt.sampling, weight);
    if (n == 1 && opt.jitter <= 0) {
        // RADIANCE aims at the centre; an annulus has none, so aim at its mid radius on
        // the side facing the point.
        Vec3 p = r.centre;
        if (r.r0 > 0) {
            Vec3 inPlane = rel - r.normal * dot(rel, r.normal);
            Vec3 u = lengthSquared(inPlane) > 0 ? normalize(inPlane) : r.e1;
            p = r.centre + u * (0.5 * (r.r0 + r.r1));
        }
        // With -ds 0 RADIANCE's point rule exactly (srcsamp.c: A cos / d^2); a single
        // cell of a subdivided ring keeps the on-axis disk correction.
        addAreaSample(from, p, r.normal, area, 1, out, opt.sampling > 0);
        return;
    }
    // Equal-area polar cells: uniform in angle and in radius squared.
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double phi = 2 * kPi * cellCoord(i, n, opt.jitter, rng);
            double f = cellCoord(j, n, opt.jitter, rng);
            double rad = std::sqrt(r.r0 * r.r0 + f * (r.r1 * r.r1 - r.r0 * r.r0));
            Vec3 p = r.centre + (r.e1 * std::cos(phi) + r.e2 * std::sin(phi)) * rad;
            addAreaSample(from, p, r.normal, area / (n * n), 1, out, true);
        }
}

void sampleCone(const ConeShape& c, const Vec3& from, const DirectOptions& opt, double weight,
                Rng& rng, std::vector<SourceSample>& out) {
    Vec3 rel = from - c.p0;
    double along = dot(rel, c.axis);
    Vec3 radial = rel - c.axis * along;
    double dperp = length(radial);
    double rmax = std::fmax(c.r0, c.r1), rmid = 0.5 * (c.r0 + c.r1);
    // Angles about the axis measured from the side facing the point.
    Vec3 e1 = dperp > 0 ? radial / dperp : c.e1;
    Vec3 e2 = cross(c.axis, e1);
    double phiMax = kPi;  // inward surfaces: seen all round from inside
    if (!c.inward) {
        if (dperp <= rmid) return;  // inside an outward surface
        phiMax = std::acos(std::clamp(rmax / dperp, 0.0, 1.0));
        if (rmax >= dperp) phiMax = kPi / 2;
    } else if (dperp >= rmax) {
        return;  // outside a cup or tube: its emitting side faces away
    }
    Vec3 centre = c.p0 + c.axis * (0.5 * c.length);
    int n =
        cellsPerAxis(std::fmax(2 * rmax, c.length), length(from - centre), opt.sampling, weight);
    double slant = std::sqrt(c.length * c.length + (c.r1 - c.r0) * (c.r1 - c.r0));
    double dphi = 2 * phiMax / n;
    // Average of cos over a cell's angle relative to its centre's (exact for a distant
    // point square to the axis): keeps one wide cell from overstating the projected area.
    double cosFactor = c.inward ? 1.0 : std::sin(dphi / 2) / (dphi / 2);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double phi = -phiMax + 2 * phiMax * cellCoord(i, n, opt.jitter, rng);
            double v = cellCoord(j, n, opt.jitter, rng);
            double va = double(j) / n, vb = double(j + 1) / n;
            double ra = c.r0 + (c.r1 - c.r0) * va, rb = c.r0 + (c.r1 - c.r0) * vb;
            double area = dphi * 0.5 * (ra + rb) * slant * (vb - va);
            double rad = c.r0 + (c.r1 - c.r0) * v;
            Vec3 radialDir = e1 * std::cos(phi) + e2 * std::sin(phi);
            Vec3 p = c.p0 + c.axis * (v * c.length) + radialDir * rad;
            addAreaSample(from, p, coneNormal(c, p), area, cosFactor, out);
        }
}

// A bubble (inward sphere) emits toward its centre: seen only from inside.
void sampleBubble(const SphereShape& s, const Vec3& from, const DirectOptions& opt, double weight,
                  Rng& rng, std::vector<SourceSample>& out) {
    if (length(from - s.center) >= s.radius) return;
    int n = cellsPerAxis(2 * s.radius, s.radius, opt.sampling, weight);
    Vec3 e1, e2;
    orthonormalFrame({0, 0, 1}, e1, e2);
    double area = 4 * kPi * s.radius * s.radius / (n * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double phi = 2 * kPi * cellCoord(i, n, opt.jitter, rng);
            double z = 1 - 2 * cellCoord(j, n, opt.jitter, rng);
            double sz = std::sqrt(std::fmax(0.0, 1 - z * z));
            Vec3 w{sz * std::cos(phi), sz * std::sin(phi), z};
            addAreaSample(from, s.center + w * s.radius, -w, area, 1, out);
        }
}

}  // namespace

double triangleSolidAngle(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 ra = a - o, rb = b - o, rc = c - o;
    double la = length(ra), lb = length(rb), lc = length(rc);
    double num = std::fabs(dot(ra, cross(rb, rc)));
    double den = la * lb * lc + dot(ra, rb) * lc + dot(ra, rc) * lb + dot(rb, rc) * la;
    return 2 * std::atan2(num, den);
}

void sampleSource(const SourceList& list, const DirectSource& src, const ShapeSet& shapes,
                  const Vec3& from, const DirectOptions& options, double weight, Rng& rng,
                  PolygonScratch& scratch, std::vector<SourceSample>& out) {
    const light::LightSource& ls = src.light;
    if (src.proximity > 0 && !ls.distant() && length(from - src.centre) > src.proximity)
        return;  // RADIANCE SPROX: a local glow lights only its neighbourhood
    size_t first = out.size();
    size_t i = size_t(ls.shapeIndex);
    switch (ls.shape) {
        case light::EmitterShape::Polygon: {
            const PlanarRegion& r = list.regions[size_t(src.region)];
            if (r.signedDistance(from) <= kFtiny) return;  // behind the source
            samplePolygon(r, from, options.sampling, weight, options.jitter, rng, scratch, out);
            break;
        }
        case light::EmitterShape::Sphere:
            if (shapes.spheres[i].inward)
                sampleBubble(shapes.spheres[i], from, options, weight, rng, out);
            else
                sampleSphere(shapes.spheres[i], from, options, weight, rng, out);
            break;
        case light::EmitterShape::Ring:
            sampleRing(shapes.rings[i], from, options, weight, rng, out);
            break;
        case light::EmitterShape::Cone:
            sampleCone(shapes.cones[i], from, options, weight, rng, out);
            break;
        case light::EmitterShape::Distant:
            sampleDistant(shapes.sources[i], from, options, weight, rng, out);
            break;
    }
    if (ls.spotlight()) {
        // RADIANCE compat (srcray): outside the spot's cone no light leaves the source.
        const double coneOmega = ls.params.spotSolidAngle;
        const Vec3& aim = ls.params.spotAim;
        out.erase(std::remove_if(out.begin() + std::ptrdiff_t(first), out.end(),
                                 [&](const SourceSample& s) {
                                     return coneOmega < 2 * kPi * (1 + dot(aim, s.dir));
                                 }),
                  out.end());
        // RADIANCE compat (ray.html spotlight; see the caustic validation README): the
        // length of the orientation vector puts the effective focus that far behind the
        // source, so the direct contribution falls off as (d / (d + flen))^2.
        const double flen = ls.params.spotFocalLength;
        if (flen > 0)
            for (size_t k = first; k < out.size(); ++k) {
                double d = out[k].dist;
                if (std::isfinite(d) && d > 0) out[k].omega *= (d / (d + flen)) * (d / (d + flen));
            }
    }
}

Hit sourceSurfaceHit(const DirectSource& src, const ShapeSet& shapes,
                     const std::vector<PlanarRegion>& regions, const Vec3& p, const Vec3& dir,
                     double t) {
    Hit h;
    h.t = t;
    h.point = p;
    h.prim = src.light.prim;
    double scale = maxAbs(p);
    size_t i = size_t(src.light.shapeIndex);
    // Hit::u, v stay 0: RADIANCE's uv, which only meshes have.
    switch (src.light.shape) {
        case light::EmitterShape::Polygon: {
            const PolygonShape& poly = shapes.polygons[i];
            h.normal = poly.normal;
            h.modifier = poly.modifier;
            h.offset = kFloatOffsetRel * std::fmax(scale, poly.scale);
            (void)regions;
            break;
        }
        case light::EmitterShape::Sphere:
            h.normal = sphereNormal(shapes.spheres[i], p);
            h.modifier = shapes.spheres[i].modifier;
            h.offset = kDoubleOffsetRel * std::fmax(scale, shapes.spheres[i].radius);
            break;
        case light::EmitterShape::Cone: {
            const ConeShape& c = shapes.cones[i];
            h.normal = coneNormal(c, p);
            h.modifier = c.modifier;
            h.offset = kDoubleOffsetRel * std::fmax(scale, c.length + std::fmax(c.r0, c.r1));
            break;
        }
        case light::EmitterShape::Ring:
            h.normal = shapes.rings[i].normal;
            h.modifier = shapes.rings[i].modifier;
            h.offset = kDoubleOffsetRel * std::fmax(scale, shapes.rings[i].r1);
            break;
        case light::EmitterShape::Distant:
            h.modifier = shapes.sources[i].modifier;
            break;
    }
    h.front = dot(dir, h.normal) < 0;
    return h;
}

Hit relaySurfaceHit(const RelayPlane& m, const Vec3& p, const Vec3& dir, double t) {
    Hit h;
    h.t = t;
    h.point = p;
    h.prim = m.prim;
    h.modifier = m.modifier;
    h.normal = m.region.normal;
    h.front = dot(dir, h.normal) < 0;
    h.offset = kFloatOffsetRel * maxAbs(p);
    return h;
}

}  // namespace rp::render

// Partitioning emitters at -ds and sampling points in partitions (see partition.h).
#include "light/partition.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "util/fast_minmax.h"
#include "util/warnings.h"

namespace rp::light {

namespace {

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    return 0.5 * length(cross(b - a, c - a));
}

// Longest-edge bisection until area <= maxArea (iterative: a stack, not recursion).
void bisectTriangle(const Vec3& a0, const Vec3& b0, const Vec3& c0, double maxArea, int32_t index,
                    std::vector<Partition>& out) {
    struct Tri {
        Vec3 a, b, c;
    };
    std::vector<Tri> stack{{a0, b0, c0}};
    while (!stack.empty()) {
        Tri t = stack.back();
        stack.pop_back();
        double area = triangleArea(t.a, t.b, t.c);
        if (area <= maxArea) {
            Partition p;
            p.shape = PartitionShape::Triangle;
            p.shapeIndex = index;
            p.a = t.a;
            p.b = t.b;
            p.c = t.c;
            p.area = area;
            out.push_back(p);
            continue;
        }
        // Rotate so that edge a-b is the longest, then split it at its midpoint.
        double lab = lengthSquared(t.b - t.a), lbc = lengthSquared(t.c - t.b),
               lca = lengthSquared(t.a - t.c);
        if (lbc >= lab && lbc >= lca)
            t = {t.b, t.c, t.a};
        else if (lca >= lab && lca >= lbc)
            t = {t.c, t.a, t.b};
        Vec3 m = (t.a + t.b) * 0.5;
        stack.push_back({m, t.b, t.c});
        stack.push_back({t.a, m, t.c});
    }
}

// Predicted partition count of a shape at edge length p (before building them).
double predictedCount(const ShapeSet& s, EmitterShape shape, int32_t i, double p) {
    double p2 = p * p;
    switch (shape) {
        case EmitterShape::Polygon: {
            double area = 0;
            for (size_t t = 0; t < s.triangles.size(); ++t)
                if (s.trianglePolygon[t] == uint32_t(i)) {
                    const TriIndices& tri = s.triangles[t];
                    area +=
                        triangleArea(s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]);
                }
            return 2 * area / p2 + 1;  // bisection overshoots by up to a factor 2
        }
        case EmitterShape::Sphere: {
            double r = s.spheres[size_t(i)].radius;
            return 4 * kPi * r * r / p2 + 1;
        }
        case EmitterShape::Ring: {
            const RingShape& r = s.rings[size_t(i)];
            return std::ceil((r.r1 - r.r0) / p) * std::ceil(2 * kPi * r.r1 / p);
        }
        case EmitterShape::Cone: {
            const ConeShape& c = s.cones[size_t(i)];
            double slant = c.length * std::sqrt(1 + c.slope * c.slope);
            return std::ceil(slant / p) * std::ceil(2 * kPi * std::fmax(c.r0, c.r1) / p);
        }
        case EmitterShape::Distant:
            break;
    }
    return 1;
}

uint32_t cellsFor(double extent, double p) {
    return uint32_t(std::clamp(std::ceil(extent / p - 1e-9), 1.0, 1e9));
}

}  // namespace

std::vector<Partition> partitionShape(const ShapeSet& s, EmitterShape shape, int32_t i,
                                      double edge) {
    RP_CHECK(edge > 0);
    double p = edge;
    double predicted = predictedCount(s, shape, i, p);
    if (predicted > double(kMaxPartitions)) {
        p *= std::sqrt(predicted / double(kMaxPartitions));
        warn("light source partition size enlarged to " + std::to_string(p) + " to keep at most " +
             std::to_string(kMaxPartitions) + " partitions per shape");
    }
    std::vector<Partition> out;
    switch (shape) {
        case EmitterShape::Polygon:
            for (size_t t = 0; t < s.triangles.size(); ++t)
                if (s.trianglePolygon[t] == uint32_t(i)) {
                    const TriIndices& tri = s.triangles[t];
                    bisectTriangle(s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]],
                                   p * p, i, out);
                }
            break;
        case EmitterShape::Sphere: {
            double r = s.spheres[size_t(i)].radius;
            double n = std::ceil(4 * kPi * r * r / (p * p) - 1e-9);
            uint32_t nTheta = uint32_t(std::fmax(std::round(std::sqrt(2 * n / kPi)), 1.0));
            uint32_t nPhi = uint32_t(std::fmax(std::ceil(n / nTheta), 1.0));
            for (uint32_t t = 0; t < nTheta; ++t)
                for (uint32_t f = 0; f < nPhi; ++f) {
                    Partition q;
                    q.shape = PartitionShape::SphereCell;
                    q.shapeIndex = i;
                    q.u0 = 1 - 2.0 * t / nTheta;
                    q.u1 = 1 - 2.0 * (t + 1) / nTheta;
                    q.v0 = 2 * kPi * f / nPhi;
                    q.v1 = 2 * kPi * (f + 1) / nPhi;
                    q.area = r * r * std::fabs(q.u1 - q.u0) * (q.v1 - q.v0);
                    out.push_back(q);
                }
            break;
        }
        case EmitterShape::Ring: {
            const RingShape& r = s.rings[size_t(i)];
            uint32_t nr = cellsFor(r.r1 - r.r0, p), nPhi = cellsFor(2 * kPi * r.r1, p);
            for (uint32_t k = 0; k < nr; ++k)
                for (uint32_t f = 0; f < nPhi; ++f) {
                    Partition q;
                    q.shape = PartitionShape::RingCell;
                    q.shapeIndex = i;
                    q.u0 = r.r0 + (r.r1 - r.r0) * k / nr;
                    q.u1 = r.r0 + (r.r1 - r.r0) * (k + 1) / nr;
                    q.v0 = 2 * kPi * f / nPhi;
                    q.v1 = 2 * kPi * (f + 1) / nPhi;
                    q.area = 0.5 * (q.u1 * q.u1 - q.u0 * q.u0) * (q.v1 - q.v0);
                    out.push_back(q);
                }
            break;
        }
        case EmitterShape::Cone: {
            const ConeShape& c = s.cones[size_t(i)];
            double stretch = std::sqrt(1 + c.slope * c.slope);  // slant length per axial length
            uint32_t nAxial = cellsFor(c.length * stretch, p);
            uint32_t nPhi = cellsFor(2 * kPi * std::fmax(c.r0, c.r1), p);
            for (uint32_t k = 0; k < nAxial; ++k)
                for (uint32_t f = 0; f < nPhi; ++f) {
                    Partition q;
                    q.shape = PartitionShape::ConeCell;
                    q.shapeIndex = i;
                    q.u0 = c.length * k / nAxial;
                    q.u1 = c.length * (k + 1) / nAxial;
                    q.v0 = 2 * kPi * f / nPhi;
                    q.v1 = 2 * kPi * (f + 1) / nPhi;
                    double ra = c.r0 + c.slope * q.u0, rb = c.r0 + c.slope * q.u1;
                    q.area = stretch * 0.5 * (ra + rb) * (q.u1 - q.u0) * (q.v1 - q.v0);
                    out.push_back(q);
                }
            break;
        }
        case EmitterShape::Distant:
            RP_CHECK(false);  // distant sources use partitionCube or a port's shape
    }
    return out;
}

uint32_t cubeCellsPerSide(double ds) {
    return uint32_t(std::clamp(std::round(1 / ds), 1.0, 65536.0));
}

std::vector<Partition> partitionCube(double ds) {
    uint32_t n = cubeCellsPerSide(ds);
    std::vector<Partition> out(6);
    for (int f = 0; f < 6; ++f) {
        out[size_t(f)].shape = PartitionShape::CubeFace;
        out[size_t(f)].shapeIndex = f;
        out[size_t(f)].cells = n * n;
    }
    return out;
}

namespace {

// Point at parameters (su, sv) in [0,1]^2, mapped so that uniform (su, sv) is uniform
// in area.
EmissionPoint pointAt(const ShapeSet& s, const SceneCube& cube, const Partition& q, double su,
                      double sv) {
    EmissionPoint e;
    switch (q.shape) {
        case PartitionShape::Triangle: {
            // Square-root warp (Turk 1990): uniform over the triangle.
            double r = std::sqrt(su);
            e.point = q.a * (1 - r) + q.b * (r * (1 - sv)) + q.c * (r * sv);
            const PolygonShape& poly = s.polygons[size_t(q.shapeIndex)];
            e.normal = poly.normal;
            e.offset = kFloatOffsetRel * fastMax(maxAbs(e.point), poly.scale);
            break;
        }
        case PartitionShape::SphereCell: {
            const SphereShape& sp = s.spheres[size_t(q.shapeIndex)];
            double cosT = q.u0 + su * (q.u1 - q.u0), phi = q.v0 + sv * (q.v1 - q.v0);
            double sinT = std::sqrt(fastMax(0.0, 1 - cosT * cosT));
            Vec3 d{std::cos(phi) * sinT, std::sin(phi) * sinT, cosT};
            e.point = sp.center + d * sp.radius;
            e.normal = sp.inward ? -d : d;
            e.offset = kDoubleOffsetRel * fastMax(maxAbs(e.point), sp.radius);
            break;
        }
        case PartitionShape::RingCell: {
            const RingShape& rg = s.rings[size_t(q.shapeIndex)];
            double r = std::sqrt(q.u0 * q.u0 + su * (q.u1 * q.u1 - q.u0 * q.u0));
            double phi = q.v0 + sv * (q.v1 - q.v0);
            e.point = rg.centre + (rg.e1 * std::cos(phi) + rg.e2 * std::sin(phi)) * r;
            e.normal = rg.normal;
            e.offset = kDoubleOffsetRel * std::fmax(maxAbs(e.point), rg.r1);
            break;
        }
        case PartitionShape::ConeCell: {
            const ConeShape& c = s.cones[size_t(q.shapeIndex)];
            double ra = c.r0 + c.slope * q.u0, rb = c.r0 + c.slope * q.u1;
            double h;
            if (std::fabs(rb - ra) <= 1e-12 * std::fmax(ra, rb)) {
                h = q.u0 + su * (q.u1 - q.u0);
            } else {  // area element grows with the radius: r^2 uniform
                double r = std::sqrt(ra * ra + su * (rb * rb - ra * ra));
                h = std::clamp((r - c.r0) / c.slope, q.u0, q.u1);
            }
            double phi = q.v0 + sv * (q.v1 - q.v0);
            Vec3 rho = c.e1 * std::cos(phi) + c.e2 * std::sin(phi);
            e.point = c.p0 + c.axis * h + rho * (c.r0 + c.slope * h);
            Vec3 n = normalize(rho - c.axis * c.slope);
            e.normal = c.inward ? -n : n;
            e.offset =
                kDoubleOffsetRel * std::fmax(maxAbs(e.point), c.length + std::fmax(c.r0, c.r1));
            break;
        }
        case PartitionShape::CubeFace: {
            int axis = q.shapeIndex / 2;
            bool positive = q.shapeIndex % 2 == 1;
            Vec3 p = cube.origin;
            p[axis] += positive ? cube.size : 0;
            p[(axis + 1) % 3] += su * cube.size;
            p[(axis + 2) % 3] += sv * cube.size;
            e.point = p;
            e.normal = {};
            e.normal[axis] = positive ? 1 : -1;
            e.offset = 0;  // outside every surface by the oconv margin
            break;
        }
    }
    return e;
}

}  // namespace

EmissionPoint samplePartition(const ShapeSet& shapes, const SceneCube& cube, const Partition& part,
                              Rng& rng) {
    double su = rng.uniform(), sv = rng.uniform();
    return pointAt(shapes, cube, part, su, sv);
}

EmissionPoint partitionCentre(const ShapeSet& shapes, const SceneCube& cube,
                              const Partition& part) {
    if (part.shape == PartitionShape::Triangle) {
        EmissionPoint e = pointAt(shapes, cube, part, 0, 0);
        e.point = (part.a + part.b + part.c) / 3.0;
        return e;
    }
    return pointAt(shapes, cube, part, 0.5, 0.5);
}

}  // namespace rp::light

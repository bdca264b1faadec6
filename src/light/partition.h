// Spatial partitioning of emitting geometry at resolution -ds (photon-map manual 4.5,
// pmapsrc.c *PhotonPartition), and uniform sampling of a point within a partition.
// Partitions cover their shape exactly (no rejection), so the emitted flux does not
// depend on -ds. Flux, directions and the partition CDF live in emitter.h.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/light_sources.h"
#include "util/rng.h"

namespace rp::light {

enum class PartitionShape : uint8_t { Triangle, SphereCell, RingCell, ConeCell, CubeFace };

// One partition. Parameter ranges [u0,u1] x [v0,v1] per shape:
//   Triangle:   vertices a, b, c (a piece of the polygon's triangulation);
//   SphereCell: u = cos(polar angle from +z), v = azimuth (radians); equal areas;
//   RingCell:   u = radius, v = angle about the ring normal (ring frame e1, e2);
//   ConeCell:   u = distance along the axis from p0, v = angle about the axis;
//   CubeFace:   shapeIndex = face 0..5 (axis = face/2, positive side if face is odd);
//               stands for `cells` jittered (1/ds)^2 cells of that face, which sample
//               exactly like one uniform face.
struct Partition {
    PartitionShape shape = PartitionShape::Triangle;
    int32_t shapeIndex = -1;  // into the ShapeSet array of the emitter / port
    Vec3 a, b, c;
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    double area = 0;
    uint32_t cells = 1;  // partitions this record stands for (RADIANCE's count)
};

// A point on an emitter with its RADIANCE-oriented unit normal (bubbles, cups, tubes
// inward; polygons right-handed) and spawn offset (ray.h rules for that shape).
struct EmissionPoint {
    Vec3 point;
    Vec3 normal;
    double offset = 0;
};

// Edge length limit p = ds * cube size: partitions have area <= p^2.
//  - polygon: each triangle of its triangulation is bisected at its longest edge until
//    its area is <= p^2 (RADIANCE bisects the source's bounding rectangle along the
//    longer axis and rejects points outside the polygon; triangles need no rejection
//    and handle concave outlines exactly);
//  - sphere: N = ceil(A/p^2) cells, nTheta = round(sqrt(2N/pi)) bands equal in cos(theta),
//    nPhi = ceil(N/nTheta) sectors (pmapsrc.c spherePhotonPartition's proportions);
//  - ring: ceil((r1-r0)/p) radial bands x ceil(2 pi r1/p) sectors;
//  - cone family: ceil(slant length/p) axial bands x ceil(2 pi max(r0,r1)/p) sectors.
// At most kMaxPartitions per shape: p is enlarged (with a warning) beyond that.
constexpr size_t kMaxPartitions = size_t(1) << 20;
std::vector<Partition> partitionShape(const ShapeSet& shapes, EmitterShape shape,
                                      int32_t shapeIndex, double edge);

// RADIANCE's scene-cube emission for a distant source without ports: every face of the
// cube in (1/ds)^2 cells (pmapsrc.c sourcePhotonPartition). One record per face.
std::vector<Partition> partitionCube(double ds);
// Cells per cube side: max(1, round(1/ds)).
uint32_t cubeCellsPerSide(double ds);

// Uniform point in the partition (density 1/area).
EmissionPoint samplePartition(const ShapeSet& shapes, const SceneCube& cube, const Partition& part,
                              Rng& rng);
// The point at the parametric centre (for tables built once per partition).
EmissionPoint partitionCentre(const ShapeSet& shapes, const SceneCube& cube, const Partition& part);

}  // namespace rp::light

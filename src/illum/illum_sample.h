// How mkillum samples a surface's outgoing light (RADIANCE mkillum2.c my_face, my_ring,
// my_sphere): rays start just in front of random points of the surface and look back
// through it, d= directions per projected steradian in altitude/azimuth bins, s= rays
// in each; with l+ a flat surface also gets the light sources behind it directly
// (srcsamps). The shapes are read here from the primitives' words; writing the result
// is illum_output.h.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "illum/illum_input.h"
#include "illum/illum_settings.h"
#include "util/color.h"
#include "util/vec.h"

namespace rp::illum {

// RADIANCE R_EPS: ray origins are moved this fraction of the surface's size off it.
constexpr double kOriginEpsilon = 0.005;

// What sampling asks of a renderer (render/illum_rays.h gives the real one). Both calls
// may come from several threads at once; `rayIndex` keys each ray's random streams.
class IllumTracer {
public:
    virtual ~IllumTracer() = default;
    // Radiance arriving at `origin` from the way unit `dir` travels; light sources the
    // ray meets count nothing (they are the direct component).
    virtual Color radiance(const Vec3& origin, const Vec3& dir, uint64_t rayIndex) const = 0;
    // For each light source: the unit direction toward it from `point` and the radiance
    // arriving from it times its solid angle, for those that are not blocked, with the
    // shadow ray starting `offset` before `point` on its way (so that it crosses the
    // surface at the point).
    using SourceVisit = std::function<void(const Vec3& toSource, const Color& radianceOmega)>;
    virtual void sourceSamples(const Vec3& point, double offset, uint64_t rayIndex,
                               const SourceVisit& visit) const = 0;
    // Base of the sampling streams (surface points and directions).
    virtual uint64_t seed() const { return 0; }
};

// Summed ray values per direction bin, altitude major: bin = alt * azimuths + azi.
struct Distribution {
    int altitudes = 1, azimuths = 1;
    int samples = 0;          // rays per bin (s=)
    std::vector<Color> sums;  // altitudes * azimuths

    // RADIANCE average(): the mean radiance over all bins and rays.
    Color average() const;
};

// RADIANCE mkillum's direction grids for d=density (0: one bin): a hemisphere of about
// pi*d bins, pi times as many azimuths as altitudes; a sphere of about 4*pi*d bins,
// pi/2 times as many azimuths as altitudes.
void flatGrid(int density, int& altitudes, int& azimuths);
void roundGrid(int density, int& altitudes, int& azimuths);

// Local direction for altitude coordinate `alt` (sin^2 of the angle from the normal, so
// bins of equal width have equal projected solid angle) and azimuth `azi` (turns).
Vec3 flatDirection(double alt, double azi);
// The bin of local unit direction `d` (z along the normal, z >= 0). Azimuth bins are
// centred on j / azimuths, bin 0 straddling azimuth 0.
int flatIndex(const Vec3& d, int altitudes, int azimuths);
// Direction for `alt` in [0, 1] (z = 1 - 2 alt: equal solid angles) and `azi` (turns).
Vec3 roundDirection(double alt, double azi);

// A flat surface's frame: u and v in its plane, w its normal (the side light leaves).
struct FlatFrame {
    Vec3 u, v, w;
};

// A polygon as RADIANCE's face.c sees it: a repeated closing vertex dropped, the normal
// by the right-hand rule, the offset of its plane averaged over the vertices.
struct Face {
    std::vector<Vec3> vertices;
    Vec3 normal;
    double offset = 0;
    double area = 0;  // 0: degenerate
    int axis = 0;     // the normal's largest component: the inside test projects it away
    bool contains(const Vec3& p) const;
};
// Throws InputError (at the primitive) unless there are at least three vertices.
Face makeFace(const InputObject& o);

struct Ring {
    Vec3 centre, normal;  // unit normal
    double inner = 0, outer = 0;
};
// Throws InputError for a bad argument count, radii that are not 0 <= r0 < r1 (either
// order) or a zero direction (RADIANCE: "cannot create illum").
Ring makeRing(const InputObject& o);

struct Sphere {
    Vec3 centre;
    double radius = 0;
};
// Throws InputError unless there are four real arguments.
Sphere makeSphere(const InputObject& o);

// RADIANCE mkaxes without randomness: u perpendicular to unit `w` (from the first axis,
// counting from z, whose component of w is small), v = w x u.
FlatFrame frameAbout(const Vec3& w);

// Samples ray indices from `nextRay` on, advancing it past those used. Face: the frame
// follows the first edge at least sqrt(area) long; nullopt when points inside the polygon
// are too rare in its bounding rectangle (RADIANCE "bad aspect").
std::optional<Distribution> sampleFace(const Face& face, const IllumSettings& s,
                                       const IllumTracer& tracer, uint64_t& nextRay,
                                       FlatFrame& frame);
Distribution sampleRing(const Ring& ring, const IllumSettings& s, const IllumTracer& tracer,
                        uint64_t& nextRay, FlatFrame& frame);
// RADIANCE compat (my_sphere): a sphere gets no direct component, even with l+.
Distribution sampleSphere(const Sphere& sphere, const IllumSettings& s, const IllumTracer& tracer,
                          uint64_t& nextRay);

}  // namespace rp::illum

// The small vector routines RADIANCE's octree builders (oconv, obj2mesh) decide with:
// normalisation, point location against a box, segment clipping, distance to a segment
// and the transform arguments as a row-vector matrix pair. They repeat RADIANCE's order
// of operations (common/fvect.c, plocate.c, clip.c, xf.c, mat4.c) because the octree a
// builder makes, and so the file, depends on every last bit of these results.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace rp::radgeom {

using Vec = std::array<double, 3>;

constexpr double kTiny = 1e-6;  // FTINY of RADIANCE's double-precision build
constexpr double kHuge = 1e10;  // FHUGE

inline Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double dot(const double* a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec vec(const double* p) { return {p[0], p[1], p[2]}; }
// Squared distance, as fvect.c dist2() sums it.
inline double dist2(const Vec& a, const Vec& b) {
    const Vec d = sub(b, a);
    return dot(d, d);
}

// fvect.c normalize(): near-unit vectors get a first-order correction instead of a
// square root. Returns the old length; a zero vector is left alone and gives 0.
double normalize(Vec& v);

// plocate.h position codes: two bits per axis, one "below" and one "above".
constexpr int kBelow = 025, kAbove = 052;
constexpr int axisBits(int i) { return 3 << (i << 1); }

// plocate(): where p lies against the box [lo, hi] grown by FTINY; 0 inside.
int locate(const Vec& p, const Vec& lo, const Vec& hi);

// clip(): Cohen-Sutherland, true if any part of segment a-b lies in the box.
bool clipSegment(Vec a, Vec b, const Vec& lo, const Vec& hi);

// dist2lseg(): squared distance from p to the segment a-b.
double dist2Segment(const Vec& p, const Vec& a, const Vec& b);

// face.c inface(): is p, a point in the plane of the polygon of nv vertices at va (x, y,
// z each), inside it? Counts crossings in the plane of the two axes other than ax, the
// normal's dominant axis.
bool insideFace(const Vec& p, const double* va, int nv, int ax);

// o_face.c o_face(): does the polygon (vertices va, unit normal norm, plane offset,
// dominant axis ax) meet the cube at org of side size, grown by FTINY?
bool faceMeetsCube(const double* va, int nv, const Vec& norm, double offset, int ax, const Vec& org,
                   double size);

// A RADIANCE transform (XF): a 4x4 matrix applied to row vectors, and its scale.
struct Xf {
    std::array<std::array<double, 4>, 4> m{
        {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    double scale = 1.0;
    // multp3(): the point transformed.
    Vec point(const Vec& p) const;
};

// fullxf(): the transform that args[first..] describe and its inverse, each built as
// xf() and invxf() build them. The arguments must already be known to be a complete,
// valid transform (parseTransform checks that); a negative scale is made positive, as
// instance.c and mesh.c do.
struct FullXf {
    Xf forward, backward;
};
FullXf fullTransform(const std::vector<std::string>& args, size_t first);

}  // namespace rp::radgeom

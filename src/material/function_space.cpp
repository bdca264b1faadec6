#include "material/function_space.h"

#include <algorithm>

namespace rp::material {

namespace {

Vec3 toVec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
std::array<double, 3> toArr(const Vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

Transform functionTransform(const PatternPoint& at, const Transform& toObject) {
    return at.object ? toObject * at.object->backward : toObject;
}

Vec3 functionToWorld(const PatternPoint& at, const Transform* forward, Vec3 v) {
    if (forward) v = toVec(forward->direction(toArr(v))) / forward->scale;
    if (at.object) v = toVec(at.object->forward.direction(toArr(v))) / at.object->forward.scale;
    return v;
}

calc::RayContext functionSpace(const PatternPoint& at, const Transform& toObject) {
    const Transform composed = at.object ? functionTransform(at, toObject) : Transform{};
    const Transform& t = at.object ? composed : toObject;
    // RADIANCE transforms are similarities: dividing by the scale leaves a rotation (and
    // perhaps a mirror), which keeps unit vectors unit.
    const double unit = 1.0 / t.scale;
    calc::RayContext ctx;
    ctx.P = toVec(t.point(toArr(at.point)));
    ctx.D = toVec(t.direction(toArr(at.dir))) * unit;
    ctx.N = toVec(t.direction(toArr(at.normal))) * unit;
    ctx.T = at.distance * t.scale;
    // PatternPoint carries one segment's length. RADIANCE's T adds the rays before it
    // back to the eye (raydist), Ts only the shadow rays before it: for the segment alone
    // (a shadow ray from the shaded point to a light) both are this length.
    ctx.Ts = ctx.T;
    ctx.Rdot = std::clamp(at.rdot, -1.0, 1.0);
    ctx.S = t.scale;
    ctx.Tvec = toVec(t.point({0, 0, 0}));
    ctx.I = toVec(t.direction({1, 0, 0})) * unit;
    ctx.J = toVec(t.direction({0, 1, 0})) * unit;
    ctx.K = toVec(t.direction({0, 0, 1})) * unit;
    ctx.Lu = at.lu;
    ctx.Lv = at.lv;
    return ctx;
}

}  // namespace rp::material

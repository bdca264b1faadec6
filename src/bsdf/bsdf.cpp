// BsdfData's queries over its four scattering sets (RADIANCE bsdf.c SDevalBSDF,
// SDsizeBSDF, SDdirectHemi).
#include "bsdf/bsdf.h"

namespace rp::bsdf {

bool BsdfData::coloured() const {
    for (const Color& c : {rLambFront, rLambBack, tLambFront, tLambBack})
        if (c.r != c.g || c.g != c.b) return true;
    for (const ScatteringSet* s : {ptr(rf), ptr(rb), ptr(tf), ptr(tb)})
        if (s)
            for (const auto& d : s->components)
                if (d->coloured()) return true;
    return false;
}

Color BsdfData::evaluate(const Vec3& in, const Vec3& out) const {
    const bool inFront = in.z > 0, outFront = out.z > 0;
    Color lamb;
    const ScatteringSet* set;
    if (inFront == outFront) {
        lamb = inFront ? rLambFront : rLambBack;
        set = reflection(inFront);
    } else {
        lamb = inFront ? tLambFront : tLambBack;
        set = transmission(inFront);
    }
    Color v = lamb * (1 / kPi);
    if (set)
        for (const auto& c : set->components) v += c->value(in, out);
    return v;
}

void BsdfData::size(const Vec3& v1, const Vec3* v2, SizeQuery q, double psa[2]) const {
    if (q == SizeQuery::Max) {
        psa[0] = 0;
    } else {
        psa[0] = 10;
        if (q == SizeQuery::MinMax) psa[1] = 0;
    }
    const bool front = v1.z > 0;
    const ScatteringSet* r = reflection(front);
    const ScatteringSet* t = transmission(front);
    if (v2) ((v1.z > 0) != (v2->z > 0) ? r : t) = nullptr;
    bool any = false;
    for (const ScatteringSet* s : {r, t}) {
        if (!s) continue;
        for (const auto& c : s->components) {
            c->projectedSolidAngle(v1, v2, q, psa);
            any = true;
        }
    }
    if (!any) {  // all diffuse
        psa[0] = kPi;
        if (q == SizeQuery::MinMax) psa[1] = kPi;
    } else if (q == SizeQuery::MinMax && psa[0] > psa[1]) {
        psa[0] = psa[1];
    }
}

double BsdfData::nonDiffuseHemispherical(const Vec3& in, bool transmission_) const {
    const bool front = in.z > 0;
    const ScatteringSet* s = transmission_ ? transmission(front) : reflection(front);
    double h = 0;
    if (s)
        for (const auto& c : s->components) h += c->hemispherical(in);
    return h;
}

}  // namespace rp::bsdf

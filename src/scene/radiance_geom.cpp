// See radiance_geom.h. Expressions keep RADIANCE's grouping; do not "simplify" them.
#include "scene/radiance_geom.h"

#include <cmath>
#include <cstdlib>
#include <utility>

namespace rp::radgeom {

double normalize(Vec& v) {
    double d = dot(v, v);
    if (d == 0.0) return 0.0;
    double len;
    if (d <= 1.0 + kTiny && d >= 1.0 - kTiny) {
        len = 0.5 + 0.5 * d;
        d = 2.0 - len;
    } else {
        len = std::sqrt(d);
        d = 1.0 / len;
    }
    v[0] *= d;
    v[1] *= d;
    v[2] *= d;
    return len;
}

int locate(const Vec& p, const Vec& lo, const Vec& hi) {
    int loc = 0;
    for (int i = 0; i < 3; ++i) {
        if (p[i] < lo[i] - kTiny)
            loc |= axisBits(i) & kBelow;
        else if (p[i] > hi[i] + kTiny)
            loc |= axisBits(i) & kAbove;
    }
    return loc;
}

bool clipSegment(Vec a, Vec b, const Vec& lo, const Vec& hi) {
    Vec* e1 = &a;
    Vec* e2 = &b;
    int loc1 = locate(a, lo, hi), loc2 = locate(b, lo, hi);
    int limit = 6;  // the most chops a segment can need
    bool inside;
    while (!((inside = !(loc1 | loc2)) || (loc1 & loc2))) {
        if (limit-- <= 0) return false;
        if (!loc1) {
            std::swap(e1, e2);
            std::swap(loc1, loc2);
        }
        for (int i = 0; i < 3; ++i) {
            double d;
            if (loc1 & axisBits(i) & kBelow) {
                d = (lo[i] - (*e1)[i]) / ((*e2)[i] - (*e1)[i]);
                (*e1)[i] = lo[i];
            } else if (loc1 & axisBits(i) & kAbove) {
                d = (hi[i] - (*e1)[i]) / ((*e2)[i] - (*e1)[i]);
                (*e1)[i] = hi[i];
            } else {
                continue;
            }
            for (int j = 0; j < 3; ++j)
                if (j != i) (*e1)[j] += ((*e2)[j] - (*e1)[j]) * d;
            break;
        }
        loc1 = locate(*e1, lo, hi);
    }
    return inside;
}

double dist2Segment(const Vec& p, const Vec& a, const Vec& b) {
    const double d = dist2(a, b);
    const double d1 = dist2(a, p);
    double d2 = dist2(b, p);
    // Past either end the nearest point is that end.
    if (d2 > d1) {
        if (d2 - d1 > d) return d1;
    } else if (d1 - d2 > d) {
        return d2;
    }
    d2 = d + d1 - d2;
    return d1 - 0.25 * d2 * d2 / d;
}

namespace {
bool relEq(double a, double b) {
    return std::fabs(a - b) <= kTiny * 0.5 * (std::fabs(a) + std::fabs(b));
}
}  // namespace

bool insideFace(const Vec& p, const double* va, int nv, int ax) {
    int xi = ax + 1;
    if (xi >= 3) xi -= 3;
    int yi = xi + 1;
    if (yi >= 3) yi -= 3;
    const double x = p[xi], y = p[yi];
    int ncross = 0;
    const double* p0 = va + 3 * (nv - 1);
    const double* p1 = va;
    for (int n = nv; n-- > 0; p0 = p1, p1 += 3) {
        if ((p0[yi] > y) ^ (p1[yi] > y)) {
            const int tst = (p0[xi] > x) + (p1[xi] > x);
            if (tst == 2) {
                ncross++;
            } else if (tst) {
                const double prodA = (p0[yi] - y) * (p1[xi] - x);
                const double prodB = (p0[xi] - x) * (p1[yi] - y);
                if (relEq(prodA, prodB)) return true;
                ncross += (p1[yi] > p0[yi]) ^ (prodA > prodB);
            } else if (relEq(p0[xi], x) && relEq(p1[xi], x)) {
                return true;
            }
        } else if (relEq(p0[yi], y) && relEq(p1[yi], y) && ((p0[xi] > x) ^ (p1[xi] > x))) {
            return true;
        }
    }
    return ncross & 1;
}

// A vertex in the cube, all on one side, an edge through the cube, or the cube's
// diagonal crossing the plane inside the polygon.
bool faceMeetsCube(const double* va, int nv, const Vec& norm, double offset, int ax, const Vec& org,
                   double size) {
    Vec lo, hi;
    for (int j = 0; j < 3; ++j) {
        lo[j] = org[j] - kTiny;
        hi[j] = lo[j] + size + 2.0 * kTiny;
    }
    int vloc = kAbove | kBelow;
    for (int i = 0; i < nv; ++i) {
        const int j = locate(vec(va + 3 * i), lo, hi);
        if (!j) return true;
        vloc &= j;
    }
    if (vloc) return false;
    for (int i = 0; i < nv; ++i) {
        const int j = i + 1 < nv ? i + 1 : 0;
        if (clipSegment(vec(va + 3 * i), vec(va + 3 * j), lo, hi)) return true;
    }
    Vec v1, v2;
    for (int j = 0; j < 3; ++j) {
        v1[j] = norm[j] > 0.0 ? lo[j] : hi[j];
        v2[j] = norm[j] > 0.0 ? hi[j] : lo[j];
    }
    const double d1 = dot(v1, norm) - offset;
    if (d1 > kTiny) return false;
    const double d2 = dot(v2, norm) - offset;
    if (d2 < -kTiny) return false;
    for (int j = 0; j < 3; ++j) v1[j] = (v1[j] * d2 - v2[j] * d1) / (d2 - d1);
    return insideFace(v1, va, nv, ax);
}

Vec Xf::point(const Vec& p) const {
    return {p[0] * m[0][0] + p[1] * m[1][0] + p[2] * m[2][0] + m[3][0],
            p[0] * m[0][1] + p[1] * m[1][1] + p[2] * m[2][1] + m[3][1],
            p[0] * m[0][2] + p[1] * m[1][2] + p[2] * m[2][2] + m[3][2]};
}

namespace {
using Mat = std::array<std::array<double, 4>, 4>;

Mat identity() { return Xf{}.m; }

// mat4.c multmat4(): a * b, each element summed in column order.
Mat multiply(const Mat& a, const Mat& b) {
    Mat r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j];
    return r;
}

double radians(double degrees) { return (3.14159265358979323846 / 180.) * degrees; }

// One option's matrix and scale factor (sign < 0: the inverse's). Returns the number of
// values it consumed.
int optionMatrix(const std::vector<std::string>& a, size_t i, double sign, Mat& m4, double& sca) {
    m4 = identity();
    const std::string& o = a[i];
    auto val = [&](size_t k) { return std::atof(a[i + k].c_str()); };
    if (o == "-t") {
        for (int k = 0; k < 3; ++k) m4[3][k] = sign * val(k + 1);
        return 3;
    }
    if (o == "-s") {
        const double s = sign < 0 ? 1.0 / val(1) : val(1);
        sca *= m4[0][0] = m4[1][1] = m4[2][2] = s;
        return 1;
    }
    if (o[1] == 'm') {
        const int k = o[2] - 'x';
        sca *= m4[k][k] = -1.0;
        return 0;
    }
    // -rx, -ry, -rz: the rotation in the plane of the other two axes.
    const double t = sign < 0 ? -radians(val(1)) : radians(val(1));
    const int ax = o[2] - 'x';
    const int p = ax == 0 ? 1 : 0, q = ax == 2 ? 1 : 2;
    m4[p][p] = m4[q][q] = std::cos(t);
    if (ax == 1)
        m4[p][q] = -(m4[q][p] = std::sin(t));
    else
        m4[q][p] = -(m4[p][q] = std::sin(t));
    return 1;
}

// xf() (sign > 0) or invxf() (sign < 0) over args[first..]: options compose in order,
// the inverse's in reverse; "-i n" repeats the group before the next -i n times.
Xf build(const std::vector<std::string>& args, size_t first, double sign) {
    Xf ret;
    Mat group = identity();
    double groupScale = 1.0;
    long count = 1;
    auto flush = [&] {
        while (count-- > 0) {
            ret.m = sign > 0 ? multiply(ret.m, group) : multiply(group, ret.m);
            ret.scale *= groupScale;
        }
    };
    for (size_t i = first; i < args.size(); ++i) {
        if (args[i] == "-i") {
            flush();
            count = std::atol(args[++i].c_str());
            group = identity();
            groupScale = 1.0;
            continue;
        }
        Mat m4;
        i += optionMatrix(args, i, sign, m4, groupScale);
        group = sign > 0 ? multiply(group, m4) : multiply(m4, group);
    }
    flush();
    return ret;
}
}  // namespace

FullXf fullTransform(const std::vector<std::string>& args, size_t first) {
    FullXf x{build(args, first, 1.0), build(args, first, -1.0)};
    if (x.forward.scale < 0.0) {
        x.forward.scale = -x.forward.scale;
        x.backward.scale = -x.backward.scale;
    }
    return x;
}

}  // namespace rp::radgeom

// Hemisphere bases for rfluxmtx (see basis.h).
#include "flux/basis.h"

#include <array>
#include <cmath>
#include <cstdio>

#include "bsdf/klems_basis.h"

namespace rp::flux {

namespace {

// The Klems basis of `kind` (bsdf/klems_basis.h, shared with the BSDF reader): latitude
// bands from the normal out, each of equal azimuth patches.
const bsdf::KlemsBasis& klemsBasis(BasisKind kind) {
    const auto& bases = bsdf::standardKlemsBases();
    if (kind == BasisKind::KlemsHalf) return bases[1];
    if (kind == BasisKind::KlemsQuarter) return bases[2];
    return bases[0];
}

// Reinhart's subdivision of the Tregenza sky (MF per Tregenza band): 7 MF rows of 30,
// 30, 24, 24, 18, 12 and 6 patches times MF, and one zenith cap.
constexpr std::array<int, 7> kTregenzaPatches{30, 30, 24, 24, 18, 12, 6};

int reinhartRowPatches(int row, int mf) {
    const int rows = 7 * mf + 1;
    return row >= rows - 1 ? 1 : mf * kTregenzaPatches[size_t(row / mf)];
}

int reinhartBins(int mf) {
    int n = 0;
    for (int row = 0; row < 7 * mf + 1; ++row) n += reinhartRowPatches(row, mf);
    return n;
}

// Altitude rows of equal height (the cap half a row), azimuth from the up direction
// (local -y) towards local +x, patch 0 of a row centred on it (rfluxmtx.c sample_reinhart,
// matching reinhartb.cal's rbin).
Vec3 reinhartVector(int mf, int bin, double s1, double s2) {
    const int rows = 7 * mf + 1;
    int row = 0;
    while (bin >= reinhartRowPatches(row, mf)) bin -= reinhartRowPatches(row++, mf);
    // RADIANCE compat (rfluxmtx.c sample_reinhart): the cap's samples are squeezed
    // towards its rim to avoid crowding at the zenith.
    if (row >= rows - 1) s1 *= s1;
    const double rowHeight = 0.5 * kPi / (rows - 0.5);
    const double alt = (row + s1) * rowHeight;
    const double azi = 2 * kPi * (bin + s2 - .5) / reinhartRowPatches(row, mf);
    const double cosAlt = std::cos(alt);
    return {std::sin(azi) * cosAlt, -std::cos(azi) * cosAlt, std::sqrt(1 - cosAlt * cosAlt)};
}

std::string fmtG(const char* format, double a, double b, double c) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

}  // namespace

int basisBins(BasisKind kind, int size) {
    switch (kind) {
        case BasisKind::Uniform:
            return 1;
        case BasisKind::ShirleyChiu:
            return size * size;
        case BasisKind::Reinhart:
            return reinhartBins(size);
        default:
            return klemsBasis(kind).nangles;
    }
}

void squareToDisc(double sx, double sy, double& dx, double& dy) {
    const double a = 2 * sx - 1, b = 2 * sy - 1;
    double r, phi;  // concentric squares to concentric circles, by octant pairs
    if (a > -b) {
        if (a > b) {
            r = a;
            phi = kPi / 4 * (b / a);
        } else {
            r = b;
            phi = kPi / 4 * (2 - a / b);
        }
    } else if (a < b) {
        r = -a;
        phi = kPi / 4 * (4 + b / a);
    } else {
        r = -b;
        phi = b != 0 ? kPi / 4 * (6 - a / b) : 0;
    }
    // RADIANCE compat (disk2square.c square2disk): the radius is shrunk a hair so that
    // a point on the rim still gives a direction above the horizon.
    r *= 0.9999999999999;
    dx = r * std::cos(phi);
    dy = r * std::sin(phi);
}

void multiSample3(double x, const double jitter[3], double t[3]) {
    // A Morton (Z-order) curve rather than RADIANCE's Hilbert curve: any curve whose
    // aligned runs of 8^k cells fill cubes stratifies equally well, and this one is three
    // bit shuffles. 21 bits per axis fill the 63 bits a double's fraction can index.
    constexpr int kBits = 21;
    if (!(x >= 0)) x = 0;
    if (x >= 1) x = 0.999999999999999;
    const auto d = static_cast<uint64_t>(x * double(uint64_t(1) << (3 * kBits)));
    uint64_t c[3] = {0, 0, 0};
    for (int bit = 0; bit < kBits; ++bit)
        for (int axis = 0; axis < 3; ++axis) c[axis] |= ((d >> (3 * bit + axis)) & 1) << bit;
    const double scale = 1.0 / double(uint64_t(1) << kBits);
    for (int axis = 0; axis < 3; ++axis) t[axis] = (double(c[axis]) + jitter[axis]) * scale;
}

Vec3 senderDirection(BasisKind kind, int size, int bin, double s1, double s2) {
    switch (kind) {
        case BasisKind::Uniform: {
            // RADIANCE compat (rfluxmtx.c sample_uniform): the disc point is not mirrored
            // as the other bases' are; the same cosine distribution either way.
            double dx, dy;
            squareToDisc(s1, s2, dx, dy);
            return {dx, dy, -std::sqrt(1 - dx * dx - dy * dy)};
        }
        case BasisKind::ShirleyChiu: {
            double dx, dy;
            squareToDisc((bin / size + s1) / size, (bin % size + s2) / size, dx, dy);
            return -Vec3{dx, dy, std::sqrt(1 - dx * dx - dy * dy)};
        }
        case BasisKind::Reinhart:
            return -reinhartVector(size, bin, s1, s2);
        default:
            return -bsdf::klemsPatchVector(klemsBasis(kind), bin, s1, s2);
    }
}

ReceiverBins receiverBins(BasisKind kind, int size, char sign, const Vec3& n, const Vec3& up) {
    ReceiverBins r;
    const std::string frame = fmtG("rNx=%g,rNy=%g,rNz=%g", n.x, n.y, n.z) + "," +
                              fmtG("Ux=%g,Uy=%g,Uz=%g", up.x, up.y, up.z) + ",RHS=" + sign + "1";
    r.bins = basisBins(kind, size);
    switch (kind) {
        case BasisKind::Uniform:
            r.countExpr = "1";
            r.binExpr = fmtG("if(-Dx*%g-Dy*%g-Dz*%g,0,-1)", n.x, n.y, n.z);
            return r;
        case BasisKind::ShirleyChiu:
            r.calFile = "disk2square.cal";
            r.params = "SCdim=" + std::to_string(size) + "," + frame;
            r.countExpr = "SCdim*SCdim";
            r.binExpr = "scbin";
            return r;
        case BasisKind::Reinhart:
            r.calFile = "reinhartb.cal";
            r.params = "MF=" + std::to_string(size) + "," + frame;
            r.countExpr = "Nrbins";
            r.binExpr = "rbin";
            return r;
        default:
            break;
    }
    const char* fn = kind == BasisKind::KlemsFull   ? "kbin"
                     : kind == BasisKind::KlemsHalf ? "khbin"
                                                    : "kqbin";
    r.calFile = kind == BasisKind::KlemsFull   ? "klems_full.cal"
                : kind == BasisKind::KlemsHalf ? "klems_half.cal"
                                               : "klems_quarter.cal";
    r.countExpr = kind == BasisKind::KlemsFull   ? "Nkbins"
                  : kind == BasisKind::KlemsHalf ? "Nkhbins"
                                                 : "Nkqbins";
    r.params = std::string("RHS=") + sign + "1";
    r.binExpr = std::string(fn) + "(" + fmtG("%g,%g,%g", n.x, n.y, n.z) + "," +
                fmtG("%g,%g,%g", up.x, up.y, up.z) + ")";
    return r;
}

}  // namespace rp::flux

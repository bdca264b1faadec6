// rfluxmtx's hemisphere bases (rfluxmtx.1 h=): how many bins each has, how a sender
// picks directions inside a bin, and the rcontrib arguments that bin what a receiver
// receives (the .cal files in lib/ and their parameters). Directions are in a surface's
// frame: x along its u axis, y along v, z along its normal.
#pragma once

#include <string>
#include <vector>

#include "flux/flux_params.h"
#include "util/vec.h"

namespace rp::flux {

// Bins of a basis: 1 (uniform), N*N (Shirley-Chiu), 144 MF^2 + 1 (Reinhart), 145, 73
// or 41 (Klems full, half, quarter).
int basisBins(BasisKind kind, int size);

// The direction in which a sender's ray leaves through its back side for bin `bin` at
// (s1, s2) in [0,1)^2 inside the bin (rfluxmtx.c sample_*: uniform in projected solid
// angle over the patch). The frame's u axis is already reversed for a left-handed basis.
Vec3 senderDirection(BasisKind kind, int size, int bin, double s1, double s2);

// The Shirley-Chiu map of the unit square onto the unit disc (Shirley and Chiu 1997,
// "A low distortion map between disk and square", J. Graphics Tools 2(3)), as
// RADIANCE's square2disk.
void squareToDisc(double sx, double sy, double& dx, double& dy);

// RADIANCE's SDmultiSamp for three dimensions: one number in [0,1) to a point of the unit
// cube along a space-filling curve, so that stratifying the number stratifies the point.
// `jitter` (three numbers in [0,1)) places it inside its cell.
void multiSample3(double x, const double jitter[3], double t[3]);

// What rfluxmtx hands rcontrib for one receiver (rfluxmtx.c finish_receiver): the .cal
// file to load (empty: none, or already loaded for an earlier receiver), -p parameters,
// the -bn count expression and -b bin expression.
struct ReceiverBins {
    std::string calFile;
    std::string params;
    std::string countExpr;
    std::string binExpr;
    int bins = 1;  // what countExpr evaluates to with the parameters
};

// `normal` and `up` are the receiver's (unit; up as set or defaulted). `sign` '+' or '-'.
ReceiverBins receiverBins(BasisKind kind, int size, char sign, const Vec3& normal, const Vec3& up);

}  // namespace rp::flux

// The `#@rfluxmtx variable=value ..` settings of rfluxmtx's sender and receiver files
// (RADIANCE rfluxmtx.1, VARIABLES): h= hemisphere basis, u= up direction, o= output.
// Parsing one line and naming the basis it picks; when a setting takes effect (which
// surface it belongs to) is decided by flux_scan.h.
#pragma once

#include <optional>
#include <string>

#include "util/error.h"
#include "util/vec.h"

namespace rp::flux {

enum class BasisKind { Uniform, ShirleyChiu, Reinhart, KlemsFull, KlemsHalf, KlemsQuarter };

// The settings in force for a sender or receiver. RADIANCE keeps h= from one receiver to
// the next, but u= and o= only for the receiver they precede (rfluxmtx.c clear_params).
struct FluxParams {
    char sign = 0;       // '+', or '-' for left-handed coordinates; 0: no h= yet
    std::string hemis;   // what h= names, sign dropped ("kf", "r4", "sc6", "u")
    int size = 1;        // the digits in it (Reinhart MF, Shirley-Chiu N), 1 if none
    SourceLoc hemisLoc;  // the line that set h=
    Vec3 up;             // u=, normalised; zero when unset
    std::optional<std::string> outSpec;  // o=
};

// Applies one line's settings (the text after `#@rfluxmtx`) to `p`. Throws InputError at
// `loc`: "bad parameter string: ..." for an unknown variable, a missing '=', an empty
// value, an unterminated quote or a u= that is not an axis or a vector, and
// "unrecognized hemisphere sampling: h=..." for an h= that names no basis.
void applyParamLine(const std::string& text, const SourceLoc& loc, FluxParams& p);

// A u= value (rfluxmtx.c get_direction): [+|-]X|Y|Z, or "ux,uy,uz"; nullopt if bad.
std::optional<Vec3> parseUpDirection(const std::string& text);

// The basis an h= value names, or nullopt (rfluxmtx.c finish_receiver/prepare_sampler):
// u or 1; sc; r or t; k, kf or k1; kh or k2; kq or k4. Letters in either case.
std::optional<BasisKind> basisOf(const std::string& hemis);

}  // namespace rp::flux

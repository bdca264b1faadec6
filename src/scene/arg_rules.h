// Argument rules for every RADIANCE primitive type (ray.html): how many string, integer
// and real arguments each takes, where the transform starts in its string arguments,
// and the value checks RADIANCE itself makes when it loads the object (radii, zero area).
// Material-specific meaning of the arguments belongs to material/, not here.
#pragma once

#include <string>

#include "scene/primitive.h"

namespace rp {

// An allowed argument count: min..max (max < 0: no upper bound), a multiple of
// `multiple`, or, when oneOf[0] >= 0, exactly one of the listed values.
struct ArgCount {
    int min = 0;
    int max = 0;
    int multiple = 1;
    int oneOf[4] = {-1, -1, -1, -1};

    bool allows(size_t n) const;
    // "5 real arguments", "3 or 4 real arguments", "at least 4 string arguments", ...
    std::string describe(const char* kind) const;
};

// Where a type's transform begins in its string arguments.
enum class XformAt : uint8_t {
    None,    // no transform (surfaces, colortext, ...)
    Fixed,   // at index `xformIndex`; everything from there on is the transform
    Search,  // data types: after a variable number of coordinate functions; the first
             // transform option at or after `xformIndex` starts it
};

struct ArgRule {
    ArgCount strings, integers, reals;
    XformAt xformAt = XformAt::None;
    int xformIndex = 0;
};

const ArgRule& argRule(PrimType t);

// Index of the first transform argument of p (p.sargs.size() if it has none).
size_t transformStart(const Primitive& p);

// Checks p's argument counts and values as RADIANCE does when loading it. Throws
// InputError at p.loc ("plastic 'wall': expected 5 real arguments, got 4"). Where RADIANCE
// only warns and corrects (negative sphere radius -> bubble), p is corrected and a warning
// is issued. Returns false if p is degenerate and is to be skipped (warned).
// instance and mesh are notSupportedYet.
bool checkArgs(Primitive& p);

}  // namespace rp

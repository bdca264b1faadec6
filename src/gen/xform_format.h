// Writing Primitive records back as RADIANCE scene text, in the layout RADIANCE's xform
// writes (one primitive per call, no leading blank line). Reading scene text and
// transforming records live in xform_scene.h; other generators may reuse these writers.
#pragma once

#include <string>
#include <string_view>

#include "scene/primitive.h"

namespace rp {

// A word as RADIANCE's fputword() writes it: as is, or quoted when it holds white space
// or a quote character (quoted with the quote it does not contain).
std::string formatWord(std::string_view word);

// A real as RADIANCE's xform writes it: printf "%18.12g" (right-aligned, 12 digits).
std::string formatReal(double v);
// The shorter "%12.6g" that xform uses for mist, dielectric and interface arguments.
std::string formatShortReal(double v);

// "mod type name\n" followed by the argument lines, laid out per type exactly as xform
// prints the type: polygon vertices one per line, sphere/source/glow reals after their
// count, cone/cylinder/ring end points on separate lines, spotlight direction on a tab
// line, text anchor and vectors on lines of three, everything else on one line per
// argument kind. An alias record keeps the aliased name in sargs[0] ("mod alias new old").
std::string formatPrimitive(const Primitive& p);

}  // namespace rp

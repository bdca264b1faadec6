// Small pieces shared by the generators (genbox, gensky, gendaylit, genprism): the
// surface record the geometric generators produce (GenSurface), printf-style formatting
// (output must match RADIANCE's printf digit for digit), the "# prog args" header line,
// and strict number parsing of command words. The generators live in genbox.h, gensky.h,
// gendaylit.h and genprism.h.
#pragma once

#include <string>
#include <vector>

#include "util/vec.h"

namespace rp::gen {

// One surface a geometric generator emits, before it becomes text. Polygons list their
// vertices in output order (counter-clockwise seen from the front, RADIANCE's rule);
// cylinders hold two end points, spheres one centre.
struct GenSurface {
    enum class Kind { Polygon, Cylinder, Sphere };
    Kind kind = Kind::Polygon;
    std::string name;
    std::vector<Vec3> points;
    double radius = 0;
};

// printf into a std::string (C locale formatting, as RADIANCE's printf).
std::string cformat(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

// One command word as RADIANCE's fputword() writes it: as is, or in quotes when it holds
// white space or an inner quote character ("-e \"x = 2\"").
std::string headerWord(const std::string& word);

// RADIANCE's "# " + printargs(): "#" then " word" for every argument (argv[0] included,
// each through headerWord), newline. RADIANCE compat: gendaylit prints its own header
// with the words unquoted (quoteWords = false).
std::string commandHeader(const std::vector<std::string>& args, bool quoteWords = true);

// One vertex line as genbox and genprism print it: "\t%18.12g\t%18.12g\t%18.12g\n".
std::string vertexLine(const Vec3& p);

// Whole-word numbers; anything else (empty, trailing junk, inf/nan) is an InputError
// naming `what` (e.g. "x size"). RADIANCE uses atof() and would read junk as 0.
double parseReal(const std::string& word, const std::string& what);
int parseInt(const std::string& word, const std::string& what);

// The word after option args[i], advancing i; an InputError when the line ends first.
const std::string& optionValue(const std::vector<std::string>& args, size_t& i);

}  // namespace rp::gen

// Small pieces shared by the generators (genbox, gensky, gendaylit, genprism): the
// surface record the geometric generators produce (GenSurface), printf-style formatting
// (output must match RADIANCE's printf digit for digit), the "# prog args" header line,
// strict number parsing of positional words, and the generators' option tables
// (util/options.h). The generators live in genbox.h, gensky.h, gendaylit.h, genprism.h, ...
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "util/options.h"
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

// A generator's option table: its options follow the positional arguments (parse them
// with OptionTable::parseAll), "option -r needs a value" and "unknown option '-q'" as
// the generators have always said; -version is the tool's main's (info_options.h).
OptionTable genOptionTable();
// An option with one number, checked as parseReal/parseInt check (their message names
// `what`), then handed to `set` (which may check its range).
OptionSpec realOption(const std::string& name, const std::string& what,
                      std::function<void(double)> set);
OptionSpec intOption(const std::string& name, const std::string& what,
                     std::function<void(int)> set);
// An option without a value.
OptionSpec wordOption(const std::string& name, std::function<void()> set);

}  // namespace rp::gen

// RADIANCE's xform(1): command-line parsing (arrays -a, argument files -f, -n/-m/-c/-e/-I
// and the transform options of scene/xform.h), transforming one Primitive record, and
// transforming whole scene streams into RADIANCE scene text. The tool main is tools/xform.cpp;
// the writer of records as text is gen/xform_format.h.
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/primitive.h"
#include "scene/reader.h"  // CommandHook
#include "scene/xform.h"

namespace rp {

// One invocation of RADIANCE xform's main(): one copy of the input. Arrays (-a) and
// argument files (-f) expand into several runs, each with its rewritten command line
// (what its "# xform ..." header line shows) exactly as RADIANCE rewrites argv.
struct XformRun {
    std::vector<std::string> argv;  // argv[0] = "xform"
    size_t xfBegin = 1;             // argv[xfBegin, xfEnd) are the transform options
    size_t xfEnd = 1;               // argv[xfEnd..] are the scene files
    bool expand = true;             // run in-line commands (-c turns this off, -e back on)
    bool invert = false;            // -I: reverse every surface's orientation
    std::string newModifier;        // -m: modifier for every surface ("" = keep)
    std::string idPrefix;           // -n (joined with '.' when given twice)
    Transform xf;                   // parseTransform(argv[xfBegin, xfEnd))

    std::vector<std::string> transformArgs() const {
        return {argv.begin() + static_cast<long>(xfBegin), argv.begin() + static_cast<long>(xfEnd)};
    }
    std::vector<std::string> files() const {
        return {argv.begin() + static_cast<long>(xfEnd), argv.end()};
    }
    // True when polygon vertex order must be reversed: mirrored, or -I (not both).
    bool reverse() const { return xf.mirrors() != invert; }
};

struct XformOptions {
    std::vector<XformRun> runs;  // in output order
    CommandHook commandHook;     // may supply a command's output instead of /bin/sh
    int maxCommandDepth = 32;    // commands whose output runs commands, and so on
};

// Parses xform's command line (argv[0] is the program name). Bad or missing option
// values, an unknown option before the files, a bad -a count and an unreadable -f file
// are InputErrors. "-f -" reads the argument lines from `argLines` (standard input).
XformOptions parseXformArgs(int argc, const char* const* argv, std::istream* argLines = nullptr);
XformOptions parseXformArgs(const std::vector<std::string>& args, std::istream* argLines = nullptr);

// Runs every run: its header line, then each of its files (searched along RAYPATH), or
// the text of `in` when it names none (read once, reused by every copy). Returns the
// scene text RADIANCE's xform would print. Errors are InputErrors with file and line.
std::string xformScene(const XformOptions& opts, std::istream& in);
// The same with `text` standing in for standard input.
std::string xformText(const XformOptions& opts, std::string_view text);

// Transforms one record in place as xform does: points and directions through xf.m,
// radii and lengths by xf.scale, polygon vertex order reversed when xf mirrors (or when
// `invert`, the -I option), and `xfArgs` appended to the string arguments of types that
// carry their own transform (instance, mesh, patterns, textures, mixtures, plasfunc, ...).
// With `invert`, surfaces also turn inside out (sphere <-> bubble, cone <-> cup,
// cylinder <-> tube, ring normal negated). Does not apply -n or -m.
void transformPrimitive(Primitive& p, const Transform& xf, const std::vector<std::string>& xfArgs,
                        bool invert = false);
// The same with the transform options derived from the matrix (transformArgs(xf)).
void transformPrimitive(Primitive& p, const Transform& xf);

// Transform options equivalent to xf (a similarity: mirror, scale, rotation, translation):
// "-mx -s f -rx a -ry b -rz c -t x y z", each part left out when it is the identity.
std::vector<std::string> transformArgs(const Transform& xf);

// RADIANCE's argument checks for the types xform treats specially (sphere: no strings and
// 4 reals, polygon: a multiple of 3 reals, ...). Throws InputError at p.loc
// ("bad sphere 'ball': expected 4 real arguments, got 3").
void checkXformArgs(const Primitive& p);


}  // namespace rp

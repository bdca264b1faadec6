// RADIANCE's xform(1): command-line parsing (arrays -a, argument files -f, -n/-m/-c/-e/-I
// and the transform options of scene/xform.h), transforming one Primitive record, and
// transforming whole scene streams into RADIANCE scene text. The tool main is tools/xform.cpp;
// the writer of records as text is gen/xform_format.h.
#pragma once

#include <functional>
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

// Where a command in a scene file runs: the directory xform has changed to (RADIANCE
// xform.c runs a file's commands in that file's directory; "" = the current one), and
// the scene files whose commands led to it, outermost first (canonical paths), so that a
// file that includes itself stops with an error instead of recursing.
struct CommandContext {
    std::string dir;
    std::vector<std::string> includeChain;
    SourceLoc includer;  // the command running this xform: where errors about its files point
};

// May supply a command's output instead of /bin/sh (builtin_commands.h); nullopt: the
// shell runs it, in context.dir.
using ContextCommandHook = std::function<std::optional<std::string>(
    const std::string& command, const SourceLoc& loc, const CommandContext& context)>;

struct XformOptions {
    std::vector<XformRun> runs;  // in output order
    ContextCommandHook commandHook;
    CommandContext context;    // where this xform runs and what included it
    int maxCommandDepth = 32;  // commands whose output runs commands, and so on
};

// The canonical name of scene file `path` for CommandContext::includeChain.
std::string includeKey(const std::string& path);

// Parses xform's command line (argv[0] is the program name). Bad or missing option
// values, an unknown option before the files, a bad -a count and an unreadable -f file
// are InputErrors. "-f -" reads the argument lines from `argLines` (standard input).
XformOptions parseXformArgs(int argc, const char* const* argv, std::istream* argLines = nullptr);
XformOptions parseXformArgs(const std::vector<std::string>& args, std::istream* argLines = nullptr);

// Runs every run: its header line, then each of its files (searched along RAYPATH from
// opts.context.dir), or the text of `in` when it names none (read once, reused by every
// copy). Returns the scene text RADIANCE's xform would print. Errors are InputErrors with
// file and line; a file already on opts.context.includeChain is "scene file includes
// itself", at the command that included it.
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

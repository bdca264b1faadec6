// rfluxmtx (RADIANCE rfluxmtx.1): flux-transfer matrices between a sender and the
// receivers of a scene, computed by our rcontrib in-process. This file holds the command
// line (which rcontrib options pass, which rfluxmtx keeps) and the rcontrib run it sets
// up: the options RADIANCE's rfluxmtx would put on rcontrib's command line, the scene
// its `oconv -f` would compile, and the rays it would pipe in.
#pragma once

#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "flux/flux_surfaces.h"
#include "render/rcontrib_options.h"
#include "render/rcontrib_tool.h"
#include "util/cluster.h"

namespace rp::flux {

struct RfluxmtxCommand {
    // rcontrib's command line so far: "rcontrib -fo+", the options passed on, then (in
    // pass-through mode) -I/-i -x -y -ld, then the format option and -c.
    std::vector<std::string> rcontribArgs;
    bool verbose = false;    // -v
    bool warnings = true;    // false after -w (RADIANCE's verbose < 0)
    int samples = 0;         // -c, or 10000 with a sender, 1 passing rays through
    std::string senderFile;  // empty: rays from standard input ("-")
    std::string receiverFile;
    std::vector<std::string> systemArgs;  // after the receiver: [-i system.oct] files
};

// Screens argv (argv[0] first) as RADIANCE's rfluxmtx.c main: @file and $EVAR expand,
// rcontrib's options pass on with their arguments, -f, -fo, -e, -p, -b, -bn, -m, -M and
// anything unknown are refused ("unsupported option '-x'" plus the usage line, as one
// InputError), -x -y -ld -i -I only pass in pass-through mode ("-i, -I supported for
// pass-through only").
RfluxmtxCommand parseRfluxmtxArgs(std::vector<std::string> args);

// The usage line RADIANCE prints.
std::string rfluxmtxUsage(const std::string& program);

// What a run hands rcontrib: parsed options (modifiers, bins, definitions as RADIANCE's
// generated command line has them, which the header shows), the scene, and the sender
// (empty with rays from standard input).
struct RfluxmtxSetup {
    render::RcontribOptions options;
    render::RcontribScene scene;
    std::vector<FluxGroup> receivers;
    std::optional<FluxGroup> sender;
    std::vector<std::string> commandLine;  // rcontrib's words, the octree's last (-v)
};

// Reads sender and receivers and builds the rcontrib run. Throws InputError.
RfluxmtxSetup setupRfluxmtx(const RfluxmtxCommand& cmd, const LoadOptions& load);

// Runs it: rays from the sender's bins, or from `in` in pass-through mode; matrices to
// `out` or the receivers' o= outputs. With `verbose`, says what runs on `diag`.
void runRfluxmtx(const RfluxmtxCommand& cmd, const LoadOptions& load, std::istream& in,
                 std::ostream& out, std::ostream& diag, Cluster& cluster);

}  // namespace rp::flux

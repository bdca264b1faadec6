// One whole rcontrib run as a library call (RADIANCE rcontrib.c main after option
// parsing): load the scene, set up the tally and outputs, read rays from a stream, trace
// them and write the records. tools/rcontrib.cpp and rfluxmtx (src/flux) both call it;
// option parsing, warning sinks and exit codes stay with the tools.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "render/rcontrib_options.h"
#include "scene/reader.h"
#include "util/cluster.h"

namespace rp::render {

// What rcontrib traces: the inputs loadScene reads in order (RADIANCE's octree, or the
// files oconv would have compiled into one), how to read them (the tools pass
// gen::builtinLoadOptions(), which render does not link), and the header lines RADIANCE
// copies from that octree into every output header (FORMAT excluded).
struct RcontribScene {
    std::vector<std::string> files;
    LoadOptions load;
    std::vector<std::string> headerLines;
};

// rcontrib's scene: the octree or scene file on its command line, with its header.
RcontribScene rcontribSceneOf(const std::string& sceneFile, const LoadOptions& load);

// Runs rcontrib with parsed options on `scene`: rays from `rays` (the root's; other ranks
// read nothing), records to `out` (standard output's stream; -o files are opened by
// name). Throws InputError for bad input, as the parts it calls do.
void runRcontribTool(const RcontribOptions& options, const RcontribScene& scene, std::istream& rays,
                     std::ostream& out, Cluster& cluster);

}  // namespace rp::render

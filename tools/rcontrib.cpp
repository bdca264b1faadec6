// rcontrib: contributions of tracked modifiers (light sources, sky patches) to rays from
// standard input (RADIANCE rcontrib.1), classic or from a contribution photon map (-ap).
// Options in src/render/rcontrib_options.h, the run in rcontrib_tool.h (the tally in
// rcontrib.h, outputs in rcontrib_output.h, the loop in rcontrib_run.h). Under mpirun
// (the build in tools/mpi/) the first rank reads the rays and writes the outputs, every
// rank traces.
#include "render/rcontrib.h"

#include <iostream>
#include <memory>
#include <string>

#include "cluster_main.h"
#include "gen/builtin_commands.h"
#include "main_errors.h"
#include "render/rcontrib_options.h"
#include "render/rcontrib_tool.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/version.h"
#include "util/warnings.h"

namespace {

using namespace rp::render;

int run(const RcontribOptions& o, rp::Cluster& cluster) {
    const bool warnings = o.render.warnings;
    rp::setWarningSink([warnings](const std::string& m) {
        if (warnings) std::cerr << "rcontrib: warning: " << m << '\n';
    });
    rp::tools::quietUnlessRoot(cluster);
    const RcontribScene scene = rcontribSceneOf(o.sceneFile, rp::gen::builtinLoadOptions());
    runRcontribTool(o, scene, std::cin, std::cout, cluster);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    std::unique_ptr<rp::Cluster> cluster;
    auto fail = [&](const std::string& what, int code) {
        std::cout.flush();
        return rp::tools::failRun(cluster.get(), "rcontrib", what, std::cerr, code);
    };
    try {
        cluster = rp::tools::startCluster(argc, argv);
        RcontribOptions o = parseRcontribArgs(rp::argVector(argc, argv), &evalBinCount);
        if (o.printVersion) {
            if (cluster->isRoot()) std::cout << rp::versionLine() << '\n';
            return 0;
        }
        if (o.printDefaults) {
            if (cluster->isRoot()) std::cout << formatRcontribDefaults(o);
            return 0;
        }
        return run(o, *cluster);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        return fail(e.line, e.exitCode);
    }
}

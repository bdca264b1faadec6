// rcontrib: contributions of tracked modifiers (light sources, sky patches) to rays from
// standard input (RADIANCE rcontrib.1), classic or from a contribution photon map (-ap).
// Options in src/render/rcontrib_options.h, the tally in rcontrib.h, outputs in
// rcontrib_output.h, the loop in rcontrib_run.h. Under mpirun (the build in tools/mpi/)
// the first rank reads the rays and writes the outputs, every rank traces.
#include "render/rcontrib.h"

#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "calc/search_path.h"
#include "cluster_main.h"
#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "main_errors.h"
#include "material/mist_probe.h"
#include "render/photon_lighting.h"
#include "render/rcontrib_options.h"
#include "render/rcontrib_output.h"
#include "render/rcontrib_run.h"
#include "render/renderer.h"
#include "render/rtrace_tracer.h"
#include "scene/scene_load.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/header.h"
#include "util/paths.h"
#include "util/version.h"
#include "util/warnings.h"

namespace {

using namespace rp::render;

// The scene file's header lines but FORMAT (RADIANCE checkheader copies them into every
// output header); none for a file without a header.
std::vector<std::string> sceneHeaderLines(const std::string& file) {
    std::vector<std::string> lines;
    std::ifstream in(file, std::ios::binary);
    rp::Header h;
    if (!in || !rp::tryReadHeader(in, h)) return lines;
    for (const std::string& l : h.lines)
        if (l.rfind("FORMAT=", 0) != 0) lines.push_back(l);
    return lines;
}

int run(RcontribOptions o, rp::Cluster& cluster) {
    const bool warnings = o.render.warnings;
    rp::setWarningSink([warnings](const std::string& m) {
        if (warnings) std::cerr << "rcontrib: warning: " << m << '\n';
    });
    rp::tools::quietUnlessRoot(cluster);
    const auto threads = threadLimit(o.render);
    for (const ContribModifier& m : o.modifiers) o.render.contribModifiers.push_back(m.name);
    rp::Scene scene = rp::loadScene({o.sceneFile}, rp::gen::builtinLoadOptions());
    rp::SceneGeometry geometry(scene);
    Renderer renderer(scene, geometry, o.render, rp::calc::defaultSearchPath(rp::projectLibDir()));
    // RADIANCE compat (raytrace.c raycontrib): coefficients leave participating media out.
    if (o.render.mist.any() || rp::material::sceneHasMist(scene))
        rp::warn("ray contribution calculation does not support participating media");

    std::vector<PhotonSource> sources;
    if (renderer.photons().hasContrib()) {
        sources = contributionSources(scene, geometry);
        int bandwidth = o.render.photonMaps.front().bandwidth;
        if (bandwidth <= 0) bandwidth = kDefaultBandwidth;
        // RADIANCE compat (pmcontrib2.c initPmapContrib).
        if (size_t(bandwidth) < o.modifiers.size())
            rp::warn(
                "photon density estimate bandwidth too low, contributions may be underestimated");
    }
    ContribTargets targets(scene, o.modifiers, o.definitions, o.contributions, sources);
    // Only the root writes (and with -r reads) the outputs.
    std::optional<ContribOutput> output;
    if (cluster.isRoot()) output.emplace(o, sceneHeaderLines(o.sceneFile), std::cout);
    RendererTracer tracer(renderer, o.immediateIrradiance);

    RcontribRunSettings s;
    s.inputFormat = o.inputFormat;
    s.xres = o.xres;
    s.yres = o.yres;
    s.accumulate = o.accumulate;
    s.threads = o.render.threads;
    s.limitDistance = o.limitDistance;
    s.reportSeconds = o.reportSeconds;
    s.progress = &std::cerr;
    s.values = targets.size();
    s.cluster = &cluster;
    // RADIANCE compat (rcontrib.c rcinit): -r continues binary records, or with -c 0
    // adds to the totals the outputs hold.
    if (output && o.recover && o.accumulate <= 0)
        s.totals = output->reload();
    else if (output && o.recover)
        s.skipRecords = output->recover();
    runRcontrib(s, std::cin, output ? &*output : nullptr, tracer.contributions(targets));
    if (cluster.isRoot()) targets.badBins().report();
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

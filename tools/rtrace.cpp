// rtrace: trace rays from standard input through a scene (RADIANCE rtrace.1). Options in
// src/render/rtrace_options.h, input/output in rtrace_io.h, the loop in rtrace_run.h.
// Under mpirun (the build in tools/mpi/) the first rank reads and writes, every rank traces.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

#include "calc/search_path.h"
#include "cluster_main.h"
#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "main_errors.h"
#include "render/renderer.h"
#include "render/rtrace_io.h"
#include "render/rtrace_options.h"
#include "render/rtrace_run.h"
#include "render/rtrace_tracer.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/header.h"
#include "util/paths.h"
#include "util/version.h"
#include "util/warnings.h"

namespace {

std::string headerCommandLine(const rp::render::RtraceOptions& o) {
    std::vector<const char*> argv;
    for (size_t k = 0; k < o.optionCount && k < o.args.size(); ++k)
        argv.push_back(o.args[k].c_str());
    return rp::commandLine(int(argv.size()), argv.data());
}

int run(const rp::render::RtraceOptions& o, std::ostream*& diag, std::ofstream& diagFile,
        rp::Cluster& cluster) {
    using namespace rp::render;
    if (!o.render.errorFile.empty() && cluster.isRoot()) {
        // RADIANCE compat (rtmain.c -e): diagnostics appended to the file.
        diagFile.open(o.render.errorFile, std::ios::app);
        if (!diagFile) {
            std::cerr << "rtrace: cannot open error file " << o.render.errorFile << '\n';
            return rp::tools::endRun(cluster, 2);
        }
        diag = &diagFile;
        *diag << "**************\n*** " << headerCommandLine(o) << ' ' << o.sceneFile << '\n';
    }
    std::ostream* warnTo = diag;
    const bool warnings = o.render.warnings;
    rp::setWarningSink([warnTo, warnings](const std::string& m) {
        if (warnings) *warnTo << "rtrace: warning: " << m << '\n';
    });
    rp::tools::quietUnlessRoot(cluster);
    OutputSpec spec = parseOutputSpec(o.outputSpec, o.outputFormat);

    const auto threads = threadLimit(o.render);  // for the whole run, loading included
    rp::Scene scene = rp::loadScene({o.sceneFile}, rp::gen::builtinLoadOptions());
    rp::SceneGeometry geometry(scene);
    Renderer renderer(scene, geometry, o.render, rp::calc::defaultSearchPath(rp::projectLibDir()));

    std::ostream& out = std::cout;
    if (o.header && cluster.isRoot()) out << rtraceHeader(headerCommandLine(o), o.outputFormat);

    // rtrace -I: the input origin is a surface point and the direction its normal.
    RendererTracer tracer(renderer, o.immediateIrradiance);
    RtraceRunSettings settings;
    settings.inputFormat = o.inputFormat;
    settings.xres = o.xres;
    settings.yres = o.yres;
    settings.threads = o.render.threads;
    settings.limitDistance = o.limitDistance;
    settings.cluster = &cluster;
    RayWriter writer(spec, o.outputFormat, &scene);
    writer.setTraceFilter(o.trace);
    // The -af file is written by one process only: with other ranks, the root's records.
    auto keepAmbient = [&] {
        if (cluster.isRoot()) renderer.flushAmbientFile();
    };
    try {
        runRtrace(settings, std::cin, out, writer, tracer.trace());
    } catch (...) {
        keepAmbient();  // keep the records computed so far, as RADIANCE
        throw;
    }
    keepAmbient();
    if (std::getenv("RADPHOTON_STATS") &&
        cluster.isRoot())  // run statistics for tuning and benchmarks
        std::cerr << "rtrace: " << renderer.raysTraced() << " rays, " << renderer.ambientRecords()
                  << " ambient records\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);  // rays are read and written through iostreams only
    std::ostream* diag = &std::cerr;
    std::ofstream diagFile;
    std::unique_ptr<rp::Cluster> cluster;
    try {
        cluster = rp::tools::startCluster(argc, argv);
        rp::render::RtraceOptions o = rp::render::parseRtraceArgs(argc, argv);
        if (o.printVersion) {
            if (cluster->isRoot()) std::cout << rp::versionLine() << '\n';
            return 0;
        }
        if (o.printDefaults) {
            if (cluster->isRoot()) std::cout << rp::render::formatRtraceDefaults(o);
            return 0;
        }
        return run(o, diag, diagFile, *cluster);
    } catch (...) {
        std::cout.flush();
        const rp::tools::MainError e = rp::tools::currentMainError();
        return rp::tools::failRun(cluster.get(), "rtrace", e.line, *diag, e.exitCode);
    }
}

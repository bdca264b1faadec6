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
#include "render/spectral_passes.h"
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
    // RADIANCE 6's -cs/-cw: more than three samples are rendered in passes of three.
    const rp::spectral::Sampling sampling = spectralSampling(o.render);
    ColourOutput colours = o.colours;
    colours.resolve(sampling);
    // RADIANCE compat (rtrace.c setrtoutput): RGBE, or spectral samples with a common
    // exponent (a hyperspectral picture), never one channel.
    if (o.outputFormat == 'c' && colours.components() < 3)
        throw rp::InputError("color format incompatible with -pY, -pS, -pM");
    rp::Scene scene = rp::loadScene({o.sceneFile}, rp::gen::builtinLoadOptions());
    rp::SceneGeometry geometry(scene);
    const PassRenderers renderers = passRenderers(scene, geometry, o.render, sampling,
                                                  rp::calc::defaultSearchPath(rp::projectLibDir()));
    std::vector<std::unique_ptr<RendererTracer>> tracers;
    std::vector<RayTraceFn> traceFns;
    for (const auto& r : renderers) {
        // rtrace -I: the input origin is a surface point and the direction its normal.
        tracers.push_back(std::make_unique<RendererTracer>(*r, o.immediateIrradiance));
        traceFns.push_back(tracers.back()->trace());
    }

    std::ostream& out = std::cout;
    if (o.header && cluster.isRoot())
        out << rtraceHeader(headerCommandLine(o), o.outputFormat, spec, colours);

    RtraceRunSettings settings;
    settings.inputFormat = o.inputFormat;
    settings.xres = o.xres;
    settings.yres = o.yres;
    settings.threads = o.render.threads;
    settings.limitDistance = o.limitDistance;
    settings.paddedResolution = o.outputFormat == 'c' && colours.components() > 3;
    settings.cluster = &cluster;
    RayWriter writer(spec, o.outputFormat, &scene, colours);
    writer.setTraceFilter(o.trace);
    // The -af file is written by one process only: with other ranks, the root's records.
    auto keepAmbient = [&] {
        if (!cluster.isRoot()) return;
        for (const auto& r : renderers) r->flushAmbientFile();  // each pass its own file
    };
    try {
        runRtrace(settings, std::cin, out, writer, traceFns, rp::spectral::passesOf(sampling));
    } catch (...) {
        keepAmbient();  // keep the records computed so far, as RADIANCE
        throw;
    }
    keepAmbient();
    if (std::getenv("RADPHOTON_STATS") && cluster.isRoot()) {  // for tuning and benchmarks
        long rays = 0, records = 0;
        for (const auto& r : renderers) {
            rays += r->raysTraced();
            records += r->ambientRecords();
        }
        std::cerr << "rtrace: " << rays << " rays, " << records << " ambient records\n";
    }
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

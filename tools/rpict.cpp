// rpict: render a RADIANCE picture of a scene (RADIANCE rpict.1). Options in
// src/render/rpict_options.h, the picture loop in rpict.h, the renderer in renderer.h.
//   rpict [options] [@file] [$EVAR] scene.oct|scene.rad ...
// Under mpirun (the build in tools/mpi/) every rank traces its share of the scanlines and
// the first writes the picture.
#include "render/rpict.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

#include "calc/search_path.h"
#include "cluster_main.h"
#include "gen/builtin_commands.h"
#include "geometry/scene_geometry.h"
#include "image/view.h"
#include "main_errors.h"
#include "render/photon_lighting.h"
#include "render/renderer.h"
#include "render/rpict_options.h"
#include "render/rpict_run.h"
#include "render/rpict_tracer.h"
#include "render/source_draw.h"
#include "render/spectral_passes.h"
#include "scene/scene_load.h"
#include "util/command_args.h"
#include "util/error.h"
#include "util/header.h"
#include "util/paths.h"
#include "util/version.h"
#include "util/warnings.h"

namespace {

using namespace rp::render;

int run(int argc, char** argv, std::ostream*& diag, std::ofstream& diagFile, rp::Cluster& cluster) {
    std::vector<std::string> args = rp::argVector(argc, argv);
    args.erase(args.begin());
    RpictCommand cmd = parseRpictCommand(args);
    const RpictOptions& o = cmd.options;
    if (cmd.printVersion) {
        if (cluster.isRoot()) std::cout << rp::versionLine() << '\n';
        return 0;
    }
    if (cmd.printDefaults) {
        if (cluster.isRoot()) std::cout << formatRpictDefaults(o);
        return 0;
    }
    // RADIANCE compat (rpmain.c fixargv0 + printargs): the header's command line starts
    // with the program's base name and stops before the scene.
    const int headerCount = std::max(1, argc - int(cmd.sceneFiles.size()));
    std::vector<const char*> headerArgs(argv, argv + headerCount);
    headerArgs[0] = "rpict";
    const std::string commandLine = rp::commandLine(int(headerArgs.size()), headerArgs.data());
    if (!o.render.errorFile.empty() && cluster.isRoot()) {
        // RADIANCE compat (rpmain.c -e): diagnostics appended to the file.
        diagFile.open(o.render.errorFile, std::ios::app);
        if (!diagFile) throw rp::InputError("cannot open error file " + o.render.errorFile);
        diag = &diagFile;
        *diag << "**************\n*** " << rp::commandLine(argc, argv) << '\n';
    }
    std::ostream* warnTo = diag;
    const bool warnings = o.render.warnings;
    rp::setWarningSink([warnTo, warnings](const std::string& m) {
        if (warnings) *warnTo << "rpict: warning: " << m << '\n';
    });
    rp::tools::quietUnlessRoot(cluster);
    // RADIANCE reads the octree from standard input without a scene argument; we need
    // the scene to be named (use "-" for standard input).
    if (cmd.sceneFiles.empty()) throw rp::InputError("missing scene file");
    // RADIANCE compat (rpict.1, -S): the views come on standard input, the scene cannot.
    if (o.sequenceStart > 0 &&
        std::find(cmd.sceneFiles.begin(), cmd.sceneFiles.end(), "-") != cmd.sceneFiles.end())
        throw rp::InputError("-S reads views from standard input: the scene must be a file");
    // Check the view before the (slow) scene load, as RADIANCE's setview does.
    rp::ViewRays checkView(o.view);

    const auto threads = threadLimit(o.render);  // for the whole run, loading included
    rp::Scene scene = rp::loadScene(cmd.sceneFiles, rp::gen::builtinLoadOptions());
    rp::SceneGeometry geometry(scene);
    // RADIANCE 6's -cs/-cw: more than three samples are rendered in passes of three, each
    // pixel sample turned into RGB from all of them.
    const rp::spectral::Sampling sampling = spectralSampling(o.render);
    const PassRenderers renderers = passRenderers(scene, geometry, o.render, sampling,
                                                  rp::calc::defaultSearchPath(rp::projectLibDir()));
    const Renderer& renderer = *renderers[0];
    const PixelTracerFactory tracers = passPixelTracers(renderers, sampling);
    auto raysTraced = [&] {
        long n = 0;
        for (const auto& r : renderers) n += r->raysTraced();
        return n;
    };

    // Bias compensation statistics (manual 5.3) after each report; threads merge theirs
    // when they finish, so the figures are complete in the last report.
    auto biasReport = [&] {
        std::string b = renderer.photons().biasReport();
        if (!b.empty()) *diag << "rpict: " << b << std::endl;
    };
    auto progress = [&](const RenderProgress& p) {
        // The renderer's count includes shadow and ambient rays, as RADIANCE's nrays.
        *diag << "rpict: " << formatProgress(raysTraced(), p.percentDone, p.seconds) << std::endl;
        biasReport();
    };
    RpictIo io;
    io.cluster = &cluster;
    io.views = &std::cin;
    io.out = &std::cout;
    io.commandLine = commandLine;
    // RADIANCE compat (rpict.c render, -dv): sources too small for the pixel rays.
    std::vector<const Renderer*> passes;
    for (const auto& r : renderers) passes.push_back(r.get());
    io.finishRows = [&](const RpictOptions& frame) {
        return bittySourcePass(passes, sampling, frame);
    };
    io.frameStarted = [&](int frame, const rp::View& view) {
        // RADIANCE compat (rpict.c): with -t, each frame is announced with its view.
        if (o.reportInterval > 0)
            *diag << "FRAME " << frame << ":" << rp::formatView(view) << std::endl;
    };
    // The -af file is written by one process only: with other ranks, the root's records.
    auto keepAmbient = [&] {
        if (!cluster.isRoot()) return;
        for (const auto& r : renderers) r->flushAmbientFile();  // each pass its own file
    };
    try {
        runRpict(o, tracers, cluster.isRoot() ? progress : ProgressCallback{}, io);
    } catch (...) {
        keepAmbient();  // keep the records computed so far, as RADIANCE
        throw;
    }
    keepAmbient();
    if (o.reportInterval > 0 && cluster.isRoot()) biasReport();
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::ostream* diag = &std::cerr;
    std::ofstream diagFile;
    std::unique_ptr<rp::Cluster> cluster;
    try {
        cluster = rp::tools::startCluster(argc, argv);
        return run(argc, argv, diag, diagFile, *cluster);
    } catch (...) {
        const rp::tools::MainError e = rp::tools::currentMainError();
        return rp::tools::failRun(cluster.get(), "rpict", e.line, *diag, e.exitCode);
    }
}

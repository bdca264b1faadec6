// The body of rcontrib (see rcontrib_tool.h), moved out of tools/rcontrib.cpp so that
// rfluxmtx runs it in-process.
#include "render/rcontrib_tool.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "calc/search_path.h"
#include "geometry/scene_geometry.h"
#include "material/mist_probe.h"
#include "render/photon_lighting.h"
#include "render/rcontrib.h"
#include "render/rcontrib_output.h"
#include "render/rcontrib_run.h"
#include "render/renderer.h"
#include "render/rtrace_tracer.h"
#include "render/spectral_passes.h"
#include "scene/scene_load.h"
#include "util/header.h"
#include "util/paths.h"
#include "util/warnings.h"

namespace rp::render {

RcontribScene rcontribSceneOf(const std::string& sceneFile, const LoadOptions& load) {
    RcontribScene s;
    s.files = {sceneFile};
    s.load = load;
    // RADIANCE checkheader copies the octree's header lines but FORMAT into every output
    // header; a file without a header gives none.
    std::ifstream in(sceneFile, std::ios::binary);
    Header h;
    if (!in || !tryReadHeader(in, h)) return s;
    for (const std::string& l : h.lines)
        if (l.rfind("FORMAT=", 0) != 0) s.headerLines.push_back(l);
    return s;
}

namespace {

RcontribRunSettings runSettings(const RcontribOptions& o, size_t values, Cluster& cluster) {
    RcontribRunSettings s;
    s.inputFormat = o.inputFormat;
    s.xres = o.xres;
    s.yres = o.yres;
    s.accumulate = o.accumulate;
    s.threads = o.render.threads;
    s.limitDistance = o.limitDistance;
    s.reportSeconds = o.reportSeconds;
    s.progress = &std::cerr;
    s.values = values;
    s.cluster = &cluster;
    return s;
}

}  // namespace

void runRcontribTool(const RcontribOptions& options, const RcontribScene& sceneInputs,
                     std::istream& rays, std::ostream& out, Cluster& cluster) {
    RcontribOptions o = options;
    const auto threads = threadLimit(o.render);
    for (const ContribModifier& m : o.modifiers) o.render.contribModifiers.push_back(m.name);
    Scene scene = loadScene(sceneInputs.files, sceneInputs.load);
    SceneGeometry geometry(scene);
    // RADIANCE 6's -cs/-cw: more than three samples are traced in passes of three bands,
    // every pass's bins side by side in one record (ContribOutput::writeRecord).
    const spectral::Sampling sampling = spectralSampling(o.render);
    const PassRenderers renderers = passRenderers(scene, geometry, o.render, sampling,
                                                  calc::defaultSearchPath(projectLibDir()));
    const Renderer& renderer = *renderers[0];
    // RADIANCE compat (raytrace.c raycontrib): coefficients leave participating media out.
    if (o.render.mist.any() || material::sceneHasMist(scene))
        warn("ray contribution calculation does not support participating media");

    PhotonOrigins photons;
    const std::vector<pmap::CoeffInfo> precomputed = renderer.photons().precomputedModifiers();
    checkPrecomputedBins(o.modifiers, o.contributions, precomputed);
    if (renderer.photons().hasContrib() && precomputed.empty()) {
        const pmap::PhotonMap& map = *renderer.photons().contribMap();
        photons = {contributionSources(scene, geometry), map.primaries(), map.primaryRays(),
                   std::max(1, o.render.threads)};
        int bandwidth = o.render.photonMaps.front().bandwidth;
        if (bandwidth <= 0) bandwidth = kDefaultBandwidth;
        // RADIANCE compat (pmcontrib2.c initPmapContrib).
        if (size_t(bandwidth) < o.modifiers.size())
            warn("photon density estimate bandwidth too low, contributions may be underestimated");
    }
    ContribTargets targets(scene, o.modifiers, o.definitions, o.contributions, photons);
    // Only the root writes (and with -r reads) the outputs.
    std::optional<ContribOutput> output;
    if (cluster.isRoot()) output.emplace(o, sceneInputs.headerLines, out);
    std::vector<std::unique_ptr<RendererTracer>> tracers;
    std::vector<ContribTraceFn> passTrace;
    for (const auto& r : renderers) {
        tracers.push_back(std::make_unique<RendererTracer>(*r, o.immediateIrradiance));
        passTrace.push_back(tracers.back()->contributions(targets));
    }
    const size_t bins = targets.size();
    const ContribTraceFn trace =
        passTrace.size() == 1
            ? passTrace[0]
            : ContribTraceFn([&passTrace, bins](const Vec3& org, const Vec3& dir, uint64_t index,
                                                double maxDistance, std::vector<Color>& values) {
                  std::vector<Color> pass(bins);
                  for (size_t p = 0; p < passTrace.size(); ++p) {
                      std::fill(pass.begin(), pass.end(), Color{});
                      passTrace[p](org, dir, index, maxDistance, pass);
                      std::copy(pass.begin(), pass.end(),
                                values.begin() + std::ptrdiff_t(p * bins));
                  }
              });

    RcontribRunSettings s = runSettings(o, bins * passTrace.size(), cluster);
    // RADIANCE compat (rcontrib.c rcinit): -r continues binary records, or with -c 0
    // adds to the totals the outputs hold.
    if (output && o.recover && o.accumulate <= 0)
        s.totals = output->reload();
    else if (output && o.recover)
        s.skipRecords = output->recover();
    runRcontrib(s, rays, output ? &*output : nullptr, trace);
    if (cluster.isRoot()) targets.badBins().report();
}

}  // namespace rp::render

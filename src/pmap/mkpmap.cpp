// runMkpmap: mkpmap's steps in RADIANCE's order (mkpmap.c main, pmap.c distribPhotons,
// savePmaps), see mkpmap.h.
#include "pmap/mkpmap.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <set>

#include <tbb/task_arena.h>

#include "geometry/scene_geometry.h"
#include "light/emitter.h"
#include "light/light_sources.h"
#include "light/pattern_emission.h"
#include "calc/search_path.h"
#include "material/pattern.h"
#include "pmap/distribute.h"
#include "pmap/photon_map.h"
#include "pmap/trace.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/paths.h"
#include "util/warnings.h"

namespace rp::pmap {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

void checkRequest(const MkpmapOptions& o) {
    if (o.wants(PhotonMapType::Volume))
        throw notSupportedYet({}, "volume photon maps (mist)");
    if (o.wants(PhotonMapType::PreComp))
        throw notSupportedYet({}, "precomputed global photon maps (-app)");
    if (o.wants(PhotonMapType::Contrib))
        throw notSupportedYet({}, "contribution photon maps (-apC)");
    // RADIANCE mkpmap.c: refuse existing outputs before any work is done.
    std::set<std::string> files;
    for (const auto& m : o.maps) {
        if (!m) continue;
        if (!files.insert(m->file).second)
            throw InputError("photon map file " + m->file + " specified more than once");
        std::error_code ec;
        if (!o.overwrite && std::filesystem::exists(m->file, ec))
            throw InputError("photon map file " + m->file + " exists, not overwritten");
    }
}

}  // namespace

MkpmapReport runMkpmap(const MkpmapOptions& o, const std::string& commandLine,
                       std::ostream& diag, const LoadOptions& load) {
    checkRequest(o);
    MkpmapReport report;

    Scene scene = loadScene(o.sceneFiles, load);
    SceneGeometry geometry(scene);
    std::vector<light::LightSource> sources = light::findLightSources(scene, geometry);
    if (sources.empty()) throw InputError("no light sources found");

    light::EmissionOptions eo;
    eo.partitionSize = o.partitionSize;
    eo.samplesPerSr = o.pdfSamples;
    if (!o.portSpecs.empty()) {
        std::vector<light::PortSpec> specs;
        for (const std::string& s : o.portSpecs) specs.push_back(light::parsePortSpec(s));
        eo.ports = light::findPhotonPorts(scene, geometry, specs);
    }
    // Pattern-modified sources (e.g. gensky's skyfunc) emit through their pattern chain.
    material::PatternSet patterns(scene, calc::defaultSearchPath(projectLibDir()));
    eo.modifierFor = light::patternModifiers(patterns);
    light::EmissionPlan plan(geometry, std::move(sources), eo);

    TraceSettings ts;
    for (size_t t = 0; t < o.maps.size(); ++t) ts.maps[t] = o.maps[t].has_value();
    ts.backVisible = o.backVisible;
    ts.maxBounce = o.maxBounce;
    ts.maxDistance = o.maxDistance;
    ts.rois = o.rois;
    ts.sensors = o.sensors;
    ts.include = o.include;
    ts.exclude = o.exclude;
    PhotonTracer tracer(scene, geometry, plan, ts);

    DistributionSettings ds;
    for (size_t t = 0; t < o.maps.size(); ++t)
        if (o.maps[t]) ds.targets[t] = o.maps[t]->target;
    ds.preDistrib = o.preDistrib;
    ds.maxPrepass = o.maxPrepass;
    ds.seed = uint64_t(o.seed);
    ds.threads = o.nproc;
    ds.reportSeconds = o.reportSeconds;
    ds.progress = &diag;

    auto t0 = Clock::now();
    DistributionResult dist = distributePhotons(tracer, ds);
    report.traceSeconds = secondsSince(t0);
    report.emitted = dist.emitted;
    report.prepassEmitted = dist.prepassEmitted;
    report.prepasses = dist.prepasses;
    report.runaways = dist.runaways;
    if (dist.runaways > 0)
        warn(std::to_string(dist.runaways) + " runaway photons terminated after " +
             std::to_string(o.maxBounce) + " bounces (manual 4.3)");

    tbb::task_arena arena(std::max(1, o.nproc));
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t]) continue;
        auto tb = Clock::now();
        PhotonMap map;
        arena.execute([&] {
            map = PhotonMap(PhotonMapType(t), std::move(dist.photons[t]), {}, o.nproc > 1);
        });
        report.buildSeconds += secondsSince(tb);
        auto tsave = Clock::now();
        map.save(o.maps[t]->file, commandLine, o.overwrite);
        report.saveSeconds += secondsSince(tsave);
        report.stored[t] = map.size();
    }

    char line[160];
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t]) continue;
        std::snprintf(line, sizeof line, "%llu %s photons stored in %s (target %llu)\n",
                      (unsigned long long)report.stored[t],
                      photonMapTypeName(PhotonMapType(t)), o.maps[t]->file.c_str(),
                      (unsigned long long)o.maps[t]->target);
        diag << line;
    }
    std::snprintf(line, sizeof line,
                  "%llu photons emitted (%llu in %d prepass%s), %.2f s distribution, "
                  "%.2f s kd-tree\n",
                  (unsigned long long)report.emitted, (unsigned long long)report.prepassEmitted,
                  report.prepasses, report.prepasses == 1 ? "" : "es", report.traceSeconds,
                  report.buildSeconds);
    diag << line << std::flush;
    return report;
}

}  // namespace rp::pmap

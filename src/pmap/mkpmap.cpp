// runMkpmap: mkpmap's steps in RADIANCE's order (mkpmap.c main, pmap.c distribPhotons,
// savePmaps), see mkpmap.h.
#include "pmap/mkpmap.h"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>
#include <set>

#include "calc/search_path.h"
#include "geometry/scene_geometry.h"
#include "light/emitter.h"
#include "light/light_sources.h"
#include "light/pattern_emission.h"
#include "material/material_calc.h"
#include "material/surface_chain.h"
#include "pmap/contrib.h"
#include "pmap/distribute.h"
#include "pmap/map_output.h"
#include "pmap/photon_map.h"
#include "pmap/precomp.h"
#include "pmap/record_store.h"
#include "pmap/trace.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/paths.h"
#include "util/temp_file.h"
#include "util/warnings.h"

namespace rp::pmap {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

void checkRequest(const MkpmapOptions& o) {
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

// Manual 4.2: a volume map needs a medium that scatters: a mist (with its own albedo or
// the global -ma), or the global medium (-me with -ma). Said at once rather than after
// the prepasses find no volume photons.
void checkVolumeMedium(const MkpmapOptions& o, const Scene& scene) {
    if (!o.wants(PhotonMapType::Volume)) return;
    if (o.trace.medium.scatters()) return;
    for (const Primitive& p : scene.prims) {
        if (p.type != PrimType::Mist) continue;
        const bool ownAlbedo = p.rargs.size() >= 6;
        if (!ownAlbedo && o.trace.medium.albedo.max() > 1e-6) return;
        if (ownAlbedo && std::max({p.rargs[3], p.rargs[4], p.rargs[5]}) > 1e-6) return;
    }
    throw InputError("volume photon map " + o.maps[size_t(PhotonMapType::Volume)]->file +
                     ": no scattering medium in the scene (a mist with an albedo, or -me "
                     "with -ma)");
}

// Manual 4.5: a contribution map needs its own distribution, so -apC ignores the
// other maps on the command line (with a warning, as RADIANCE).
MkpmapOptions withoutIgnoredMaps(const MkpmapOptions& in) {
    MkpmapOptions o = in;
    if (!o.wants(PhotonMapType::Contrib)) return o;
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t] || PhotonMapType(t) == PhotonMapType::Contrib) continue;
        warn(std::string("ignoring ") + photonMapTypeName(PhotonMapType(t)) + " photon map " +
             o.maps[t]->file + " with contribution photon map (-apC)");
        o.maps[t].reset();
    }
    return o;
}

// One map's photons for its last step: in memory, or spilled to a temporary file.
struct MapPhotons {
    std::vector<Photon> inMemory;
    std::optional<TempFile> spilled;
    uint64_t spilledCount = 0;
};

// -app: the precomputed photons from the global photons of map t (in memory: the density
// estimates search all of them).
std::vector<Photon> precompute(const MkpmapOptions& o, size_t t, MapPhotons& m,
                               std::ostream& diag) {
    PrecompSettings ps;
    ps.fraction = o.precompFraction;
    ps.bandwidth = o.maps[t]->bandwidth;
    ps.seed = uint64_t(o.seed);
    ps.threads = o.nproc;
    ps.reportSeconds = o.reportSeconds;
    ps.progress = &diag;
    const size_t globalCount = m.inMemory.size();
    std::vector<Photon> pre = precomputeGlobal(std::move(m.inMemory), ps);
    if (pre.empty())
        throw InputError("no precomputed global photons (-apP " +
                         std::to_string(o.precompFraction) + " of " + std::to_string(globalCount) +
                         " global photons)");
    return pre;
}

// Trees and files: the maps in memory first, then the spilled ones one at a time, each
// with the whole budget (inCorePhotons) for the parts it builds in memory. With -n 2 or
// more the maps in memory are built at once: the top splits of a tree are serial, so the
// global and caustic trees keep each other's threads busy. Each file is the same either way.
void saveMaps(const MkpmapOptions& o, std::array<MapPhotons, kNumPhotonMapTypes>& photons,
              const std::string& commandLine, const std::vector<PhotonPrimary>& primaries,
              const std::vector<PrimaryRay>& primaryRays, uint64_t inCorePhotons,
              MkpmapReport& report) {
    auto outputOf = [&](size_t t) {
        MapOutput out;
        out.type = PhotonMapType(t);
        out.file = o.maps[t]->file;
        out.commandLine = commandLine;
        out.overwrite = o.overwrite;
        if (out.type == PhotonMapType::Contrib) {
            out.primaries = primaries;
            out.primaryRays = primaryRays;
        }
        out.parallel = o.nproc > 1;
        return out;
    };
    auto saveInMemory = [&](size_t t) {
        report.stored[t] = saveMapInMemory(photons[t].inMemory, outputOf(t));
        std::vector<Photon>().swap(photons[t].inMemory);  // freed once written
    };
    tbb::task_arena arena(std::max(1, o.nproc));
    auto tb = Clock::now();
    arena.execute([&] {
        tbb::task_group group;
        for (size_t t = 0; t < o.maps.size(); ++t) {
            if (!o.maps[t] || photons[t].spilled) continue;
            if (o.nproc > 1)
                group.run([&saveInMemory, t] { saveInMemory(t); });
            else
                saveInMemory(t);
        }
        group.wait();
        for (size_t t = 0; t < o.maps.size(); ++t) {
            if (!o.maps[t] || !photons[t].spilled) continue;
            report.stored[t] = saveSpilledMap(std::move(*photons[t].spilled),
                                              photons[t].spilledCount, inCorePhotons, outputOf(t));
            photons[t].spilled.reset();
        }
    });
    report.buildSeconds = secondsSince(tb);
}

}  // namespace

MkpmapReport runMkpmap(const MkpmapOptions& options, const std::string& commandLine,
                       std::ostream& diag, const LoadOptions& load, Cluster* cluster) {
    MkpmapOptions o = withoutIgnoredMaps(options);
    checkRequest(o);
    MkpmapReport report;

    Scene scene = loadScene(o.sceneFiles, load);
    checkVolumeMedium(o, scene);
    SceneGeometry geometry(scene);
    std::vector<light::LightSource> sources = light::findLightSources(scene, geometry);
    if (sources.empty()) throw InputError("no light sources found");

    light::EmissionOptions eo;
    eo.partitionSize = o.partitionSize;
    eo.samplesPerSr = o.pdfSamples;
    if (!o.portSpecs.empty()) eo.ports = light::findPhotonPorts(scene, geometry, o.portSpecs);
    // Pattern-modified sources (gensky's skyfunc, luminaire data) emit through their
    // pattern chain.
    material::SurfaceChains chains(scene, calc::defaultSearchPath(projectLibDir()));
    eo.modifierFor = light::patternModifiers(chains);
    // The plan's tables are built in parallel; -n bounds that as every other phase.
    tbb::task_arena planArena(std::max(1, o.nproc));
    std::optional<light::EmissionPlan> planHolder;
    planArena.execute([&] { planHolder.emplace(geometry, std::move(sources), eo); });
    const light::EmissionPlan& plan = *planHolder;

    TraceSettings& ts = o.trace;  // as parsed; which maps follows from the requests
    for (size_t t = 0; t < o.maps.size(); ++t) ts.maps[t] = o.maps[t].has_value();
    // BRTDfunc's specular expressions at photon hits (pmapmat.c brdfPhotonScatter).
    material::MaterialCalc functions(scene, calc::defaultSearchPath(projectLibDir()));
    auto t0 = Clock::now();
    DistributionResult dist;
    std::vector<PhotonPrimary> primaries;  // contribution map only
    std::vector<PrimaryRay> primaryRays;   // with -apCPD
    std::vector<Photon> contribPhotons;    // contribution maps stay in memory
    // Photons in memory, all maps together (mkpmap -aC); the rest goes to temporary files.
    MemoryBudget budget(o.memoryPhotons * sizeof(Photon));
    if (o.wants(PhotonMapType::Contrib)) {
        ContribSettings cs;
        cs.target = o.maps[size_t(PhotonMapType::Contrib)]->target;
        cs.preDistrib = o.preDistrib;
        cs.maxPrepass = o.maxPrepass;
        cs.seed = uint64_t(o.seed);
        cs.threads = o.nproc;
        cs.reportSeconds = o.reportSeconds;
        cs.progress = &diag;
        cs.primaryRays = o.maps[size_t(PhotonMapType::Contrib)]->primaryRays;
        cs.cluster = cluster;
        ContribResult cr = distributeContrib(scene, geometry, plan, eo, ts, cs, chains, &functions);
        contribPhotons = std::move(cr.photons);
        primaries = std::move(cr.primaries);
        primaryRays = std::move(cr.primaryRays);
        dist.emitted = cr.totalEmitted;
        dist.runaways = cr.runaways;
    } else {
        PhotonTracer tracer(scene, geometry, plan, ts, chains, &functions);
        DistributionSettings ds;
        for (size_t t = 0; t < o.maps.size(); ++t)
            if (o.maps[t]) ds.targets[t] = o.maps[t]->target;
        ds.preDistrib = o.preDistrib;
        ds.maxPrepass = o.maxPrepass;
        ds.seed = uint64_t(o.seed);
        ds.threads = o.nproc;
        ds.reportSeconds = o.reportSeconds;
        ds.progress = &diag;
        ds.budget = &budget;
        ds.cluster = cluster;
        for (size_t t = 0; t < o.maps.size(); ++t)
            if (o.maps[t]) ds.files[t] = o.maps[t]->file;
        dist = distributePhotons(tracer, ds);
    }
    report.traceSeconds = secondsSince(t0);
    // The other ranks have traced their share; the root builds and writes the maps.
    if (cluster && !cluster->isRoot()) return report;
    report.emitted = dist.emitted;
    report.storingSeconds = dist.storingSeconds;
    report.prepassEmitted = dist.prepassEmitted;
    report.prepasses = dist.prepasses;
    report.runaways = dist.runaways;
    if (dist.runaways > 0)
        warn(std::to_string(dist.runaways) + " runaway photons terminated after " +
             std::to_string(o.trace.maxBounce) + " bounces (manual 4.3)");

    std::array<MapPhotons, kNumPhotonMapTypes> photons;
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t]) continue;
        MapPhotons& m = photons[t];
        RecordStore<Photon>& store = dist.photons[t];
        if (PhotonMapType(t) == PhotonMapType::Contrib) {
            m.inMemory = std::move(contribPhotons);
        } else if (store.spilled() && PhotonMapType(t) != PhotonMapType::PreComp) {
            m.spilledCount = store.size();
            m.spilled = store.takeFile();
        } else {
            m.inMemory = store.takeAll<std::vector<Photon>>();
        }
        if (PhotonMapType(t) == PhotonMapType::PreComp) m.inMemory = precompute(o, t, m, diag);
    }
    saveMaps(o, photons, commandLine, primaries, primaryRays, budget.limit() / sizeof(Photon),
             report);
    char line[160];
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t]) continue;
        char frac[48] = "";
        if (PhotonMapType(t) == PhotonMapType::PreComp)
            std::snprintf(frac, sizeof frac, " x -apP %g", o.precompFraction);
        std::snprintf(line, sizeof line, "%llu %s photons stored in %s (target %llu%s)\n",
                      (unsigned long long)report.stored[t], photonMapTypeName(PhotonMapType(t)),
                      o.maps[t]->file.c_str(), (unsigned long long)o.maps[t]->target, frac);
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

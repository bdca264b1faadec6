// runMkpmap: mkpmap's steps in RADIANCE's order (mkpmap.c main, pmap.c distribPhotons,
// savePmaps), see mkpmap.h.
#include "pmap/mkpmap.h"

#include <fmt/format.h>
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
#include "material/type_traits.h"
#include "pmap/contrib.h"
#include "pmap/contrib_coeffs.h"
#include "pmap/distribute.h"
#include "pmap/map_output.h"
#include "pmap/photon_map.h"
#include "pmap/precomp.h"
#include "pmap/precomp_contrib.h"
#include "pmap/record_store.h"
#include "pmap/trace.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/file_write.h"
#include "util/paths.h"
#include "util/temp_file.h"
#include "util/warnings.h"

namespace rp::pmap {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

void checkRequest(const MkpmapOptions& o, const PortExteriorFactory& exterior,
                  const std::vector<spectral::Pass>& passes) {
    if (o.portExterior) {
        if (o.portSpecs.empty()) throw InputError("-apE: no photon ports (-apo, -apO)");
        if (!exterior) throw InputError("-apE: not available in this program");
        // Contribution photons are binned by the source that emitted them; the light of
        // the surfaces outside has no one source.
        if (o.wants(PhotonMapType::Contrib))
            throw InputError("-apE: not with a contribution photon map (-apC)");
    }
    // RADIANCE mkpmap.c: refuse existing outputs before any work is done.
    std::set<std::string> files;
    for (const auto& m : o.maps) {
        if (!m) continue;
        if (!files.insert(m->file).second)
            throw InputError("photon map file " + m->file + " specified more than once");
        for (const spectral::Pass& pass : passes) {
            const std::string file = spectral::passFile(m->file, pass);
            std::error_code ec;
            if (!o.overwrite && std::filesystem::exists(file, ec))
                throw InputError("photon map file " + file + " exists, not overwritten");
        }
    }
    if (!o.precomputedContrib()) return;
    const std::string& file = o.maps[size_t(PhotonMapType::Contrib)]->file;
    std::vector<std::string> outputs = {optionFile(file)};
    for (const spectral::Pass& pass : passes)
        outputs.push_back(coeffFolder(spectral::passFile(file, pass)));
    for (const std::string& f : outputs) {
        std::error_code ec;
        if (!o.overwrite && std::filesystem::exists(f, ec))
            throw InputError("precomputed contributions " + f + " exist, not overwritten");
    }
}

// Manual 4.2: a volume map needs a medium that scatters: a mist (with its own albedo or
// the global -ma), or the global medium (-me with -ma). Said at once rather than after
// the prepasses find no volume photons.
void checkVolumeMedium(const MkpmapOptions& o, const Scene& scene) {
    if (!o.wants(PhotonMapType::Volume)) return;
    if (o.trace.medium.scatters()) return;
    for (const Primitive& p : scene.prims) {
        if (!material::typeTraits(p.type).mist) continue;
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
    ps.pass = o.pass;
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
              const spectral::Pass& pass, MkpmapReport& report) {
    auto outputOf = [&](size_t t) {
        MapOutput out;
        out.type = PhotonMapType(t);
        out.file = spectral::passFile(o.maps[t]->file, pass);
        out.bands = mapBandsOf(pass);
        out.commandLine = commandLine;
        out.overwrite = o.overwrite;
        if (out.type == PhotonMapType::Contrib && o.precomputedContrib()) {
            out.type = PhotonMapType::PreCompContrib;
        } else if (out.type == PhotonMapType::Contrib) {
            out.primaries = primaries;
            out.primaryRays = primaryRays;
        }
        out.parallel = o.pass.threads > 1;
        return out;
    };
    auto saveInMemory = [&](size_t t) {
        report.stored[t] = saveMapInMemory(photons[t].inMemory, outputOf(t));
        std::vector<Photon>().swap(photons[t].inMemory);  // freed once written
    };
    tbb::task_arena arena(std::max(1, o.pass.threads));
    auto tb = Clock::now();
    arena.execute([&] {
        tbb::task_group group;
        for (size_t t = 0; t < o.maps.size(); ++t) {
            if (!o.maps[t] || photons[t].spilled) continue;
            if (o.pass.threads > 1)
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

// The scene and what emits into it: sources and ports, pattern chains (gensky's skyfunc,
// luminaire data), BRTDfunc's expressions, and the emission plan, made in RADIANCE's
// order (so a scene with several faults names the same one first), for one rendering
// pass (its colours) of a scene loaded once. Built in place: the chains and the plan refer
// to the scene and its geometry.
struct EmittingScene {
    const Scene& scene;
    const SceneGeometry& geometry;
    spectral::Pass pass;  // the bands it emits
    std::optional<material::SurfaceChains> chains;
    // BRTDfunc's specular expressions at photon hits (pmapmat.c brdfPhotonScatter).
    std::optional<material::MaterialCalc> functions;
    light::EmissionOptions emission;
    std::optional<light::EmissionPlan> plan;

    EmittingScene(const MkpmapOptions& o, const Scene& s, const SceneGeometry& g,
                  const PortExteriorFactory& exterior, const spectral::Pass& pass)
        : scene(s), geometry(g), pass(pass) {
        light::LightSearchOptions search;
        search.pass = pass;
        std::vector<light::LightSource> sources = light::findLightSources(scene, geometry, search);
        if (sources.empty()) throw InputError("no light sources found");
        emission.partitionSize = o.partitionSize;
        emission.samplesPerSr = o.pdfSamples;
        if (!o.portSpecs.empty())
            emission.ports = light::findPhotonPorts(scene, geometry, o.portSpecs);
        if (o.portExterior) {
            // One direction table per flat port side (light/emitter.cpp planExteriorSide).
            for (const light::PhotonPort& port : emission.ports)
                if (port.shape != light::EmitterShape::Polygon &&
                    port.shape != light::EmitterShape::Ring)
                    throw notSupportedYet(scene.prims[size_t(port.prim)].loc,
                                          "-apE with a curved photon port");
            emission.exterior = exterior(scene, geometry, pass);
        }
        // Pattern-modified sources emit through their pattern chain.
        chains.emplace(scene, calc::defaultSearchPath(projectLibDir()), pass);
        emission.modifierFor = light::patternModifiers(*chains);
        // The plan's tables are built in parallel; -n bounds that as every other phase.
        tbb::task_arena arena(std::max(1, o.pass.threads));
        arena.execute([&] { plan.emplace(geometry, std::move(sources), emission); });
        functions.emplace(scene, calc::defaultSearchPath(projectLibDir()), pass);
    }
};

Scene loadCheckedScene(const MkpmapOptions& o, const LoadOptions& load) {
    Scene s = loadScene(o.sceneFiles, load);
    checkVolumeMedium(o, s);
    return s;
}

// What the distribution leaves: the photons of every map but a contribution map, which
// has its own (in memory, with its primaries).
struct Distributed {
    DistributionResult dist;
    std::vector<Photon> contribPhotons;
    std::vector<PhotonPrimary> primaries;
    std::vector<PrimaryRay> primaryRays;  // with -apCPD
};

// Manual 4.5: a contribution map's own distribution, per source.
Distributed distributeContribution(const MkpmapOptions& o, EmittingScene& es, std::ostream& diag,
                                   Cluster* cluster) {
    const MapRequest& request = *o.maps[size_t(PhotonMapType::Contrib)];
    ContribSettings cs;
    cs.target = request.target;
    cs.pass = o.pass;
    cs.progress = &diag;
    // Precomputation bins photons by where they came from, as rcontrib does with -apCPD.
    cs.primaryRays = request.primaryRays || o.precomputedContrib();
    cs.cluster = cluster;
    ContribResult cr = distributeContrib(es.scene, es.geometry, *es.plan, es.emission, o.trace, cs,
                                         *es.chains, &*es.functions);
    Distributed d;
    d.contribPhotons = std::move(cr.photons);
    d.primaries = std::move(cr.primaries);
    d.primaryRays = std::move(cr.primaryRays);
    d.dist.emitted = cr.totalEmitted;
    d.dist.runaways = cr.runaways;
    return d;
}

// Every other map: one distribution for all of them (pmap.c distribPhotons), photons
// beyond the memory budget (-aC) spilled beside their map files.
Distributed distributeMaps(const MkpmapOptions& o, EmittingScene& es, MemoryBudget& budget,
                           std::ostream& diag, Cluster* cluster) {
    PhotonTracer tracer(es.scene, es.geometry, *es.plan, o.trace, *es.chains, &*es.functions);
    DistributionSettings ds;
    for (size_t t = 0; t < o.maps.size(); ++t)
        if (o.maps[t]) {
            ds.targets[t] = o.maps[t]->target;
            ds.files[t] = o.maps[t]->file;
        }
    ds.pass = o.pass;
    ds.progress = &diag;
    ds.budget = &budget;
    ds.cluster = cluster;
    Distributed d;
    d.dist = distributePhotons(tracer, ds);
    return d;
}

// The development branch's precomputed contributions (precomp_contrib.h): coefficient
// files and file.opt written, the precomputed photons returned for the map file.
std::vector<Photon> precomputeContribution(const MkpmapOptions& o, const EmittingScene& es,
                                           Distributed& d, const std::string& commandLine,
                                           std::ostream& diag) {
    const MapRequest& request = *o.maps[size_t(PhotonMapType::Contrib)];
    std::vector<ContribSource> sources;
    for (const light::LightSource& s : es.plan->sources()) {
        const Color& r = s.params.radiance;
        sources.push_back({es.scene.prims[size_t(s.material)].name, {r.r, r.g, r.b}, s.distant()});
    }
    const ContribBins bins(o.contribModifiers, o.contribDefinitions);
    PrecompContribSettings ps;
    ps.fraction = o.precompFraction;
    ps.bandwidth = request.bandwidth;
    ps.compression = request.compression;
    ps.contributions = o.contributions;
    ps.pass = o.pass;
    ps.progress = &diag;
    // A spectral map set's passes each keep their coefficients beside their own file
    // (rcontrib's pass opens that file); the one option file serves them all.
    ps.mapFile = spectral::passFile(request.file, es.pass);
    ps.commandLine = commandLine;
    ps.overwrite = o.overwrite;
    // manual rev 1.51: fewer photons per estimate than bins leaves bins empty.
    for (size_t m = 0; m < bins.modifiers().size(); ++m)
        if (request.bandwidth < bins.bins(m))
            warn("bandwidth " + std::to_string(request.bandwidth) + " below the " +
                 std::to_string(bins.bins(m)) + " bins of modifier " + bins.modifiers()[m].name +
                 ": some bins will be zero");
    PrecompContribResult r = precomputeContrib(std::move(d.contribPhotons), d.primaries,
                                               d.primaryRays, sources, bins, ps);
    for (size_t m = 0; m < r.emptyBins.size(); ++m)
        if (r.emptyBins[m] > 0.5)
            warn(
                fmt::format("{:.0f}% of the bins of modifier {} are empty: contributions may be "
                            "biased (more photons or a larger bandwidth)",
                            100 * r.emptyBins[m], bins.modifiers()[m].name));
    bins.badBins().report();
    // checkRequest refused an existing one without -fo.
    writeFileAtomically(
        optionFile(request.file),
        rcontribOptionText(o.contribModifiers, o.contribDefinitions, o.contributions));
    return std::move(r.photons);
}

// Each map's photons for its last step: the contribution photons, a spilled file, or
// the photons in memory (precomputed for -app).
std::array<MapPhotons, kNumPhotonMapTypes> collectPhotons(const MkpmapOptions& o,
                                                          const EmittingScene& es, Distributed& d,
                                                          const std::string& commandLine,
                                                          std::ostream& diag) {
    std::array<MapPhotons, kNumPhotonMapTypes> photons;
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t]) continue;
        MapPhotons& m = photons[t];
        RecordStore<Photon>& store = d.dist.photons[t];
        // -apE: what a final gather sees through a port outside holds no port photon;
        // the plan's exterior photons are global photons there.
        if (PhotonMapType(t) == PhotonMapType::Global || PhotonMapType(t) == PhotonMapType::PreComp)
            for (const light::ExteriorPhoton& x : es.plan->exteriorPhotons())
                store.append(makePhoton(x.point, x.normal, {x.flux.r, x.flux.g, x.flux.b}));
        if (PhotonMapType(t) == PhotonMapType::Contrib && o.precomputedContrib()) {
            m.inMemory = precomputeContribution(o, es, d, commandLine, diag);
        } else if (PhotonMapType(t) == PhotonMapType::Contrib) {
            m.inMemory = std::move(d.contribPhotons);
        } else if (store.spilled() && PhotonMapType(t) != PhotonMapType::PreComp) {
            m.spilledCount = store.size();
            m.spilled = store.takeFile();
        } else {
            m.inMemory = store.takeAll<std::vector<Photon>>();
        }
        if (PhotonMapType(t) == PhotonMapType::PreComp) m.inMemory = precompute(o, t, m, diag);
    }
    return photons;
}

// The distribution's numbers in the report, and its runaway warning.
void reportDistribution(const MkpmapOptions& o, const DistributionResult& dist,
                        MkpmapReport& report) {
    report.emitted = dist.emitted;
    report.storingSeconds = dist.storingSeconds;
    report.prepassEmitted = dist.prepassEmitted;
    report.prepasses = dist.prepasses;
    report.runaways = dist.runaways;
    if (dist.runaways > 0)
        warn(std::to_string(dist.runaways) + " runaway photons terminated after " +
             std::to_string(o.trace.maxBounce) + " bounces (manual 4.3)");
}

// The closing lines on the diagnostics stream: each map, then the totals.
void printSummary(const MkpmapOptions& o, const MkpmapReport& report, size_t passes,
                  std::ostream& diag) {
    char line[200];
    for (size_t t = 0; t < o.maps.size(); ++t) {
        if (!o.maps[t]) continue;
        char frac[48] = "";
        if (PhotonMapType(t) == PhotonMapType::PreComp)
            std::snprintf(frac, sizeof frac, " x -apP %g", o.precompFraction);
        PhotonMapType saved = PhotonMapType(t);
        if (saved == PhotonMapType::Contrib && o.precomputedContrib())
            saved = PhotonMapType::PreCompContrib;
        if (saved == PhotonMapType::PreCompContrib)
            std::snprintf(frac, sizeof frac, " x -apP %g", o.precompFraction);
        // A spectral map set: the photons of all its files, each of the target.
        const std::string where =
            passes > 1 ? o.maps[t]->file + " and its " + std::to_string(passes - 1) + " band files"
                       : o.maps[t]->file;
        std::snprintf(line, sizeof line, "%llu %s photons stored in %s (target %llu%s%s)\n",
                      (unsigned long long)report.stored[t], photonMapTypeName(saved), where.c_str(),
                      (unsigned long long)o.maps[t]->target, frac, passes > 1 ? " each" : "");
        diag << line;
    }
    std::snprintf(line, sizeof line,
                  "%llu photons emitted (%llu in %d prepass%s), %.2f s distribution, "
                  "%.2f s kd-tree\n",
                  (unsigned long long)report.emitted, (unsigned long long)report.prepassEmitted,
                  report.prepasses, report.prepasses == 1 ? "" : "es", report.traceSeconds,
                  report.buildSeconds);
    diag << line << std::flush;
}

// The maps of one rendering pass (all of them for RGB).
void runPass(const MkpmapOptions& o, const std::string& commandLine, std::ostream& diag,
             const Scene& scene, const SceneGeometry& geometry, Cluster* cluster,
             const PortExteriorFactory& exterior, const spectral::Pass& pass,
             MkpmapReport& report) {
    MkpmapOptions po = o;
    po.trace.medium.extinction = pass.ofRgb(o.trace.medium.extinction);
    po.trace.medium.albedo = pass.ofRgb(o.trace.medium.albedo);
    EmittingScene es(po, scene, geometry, exterior, pass);
    // Photons in memory, all maps together (mkpmap -aC); the rest goes to temporary files.
    MemoryBudget budget(po.memoryPhotons * sizeof(Photon));
    const auto t0 = Clock::now();
    Distributed d = po.wants(PhotonMapType::Contrib)
                        ? distributeContribution(po, es, diag, cluster)
                        : distributeMaps(po, es, budget, diag, cluster);
    report.traceSeconds += secondsSince(t0);
    // The other ranks have traced their share; the root builds and writes the maps.
    if (cluster && !cluster->isRoot()) return;
    MkpmapReport passReport;
    reportDistribution(po, d.dist, passReport);
    std::array<MapPhotons, kNumPhotonMapTypes> photons =
        collectPhotons(po, es, d, commandLine, diag);
    saveMaps(po, photons, commandLine, d.primaries, d.primaryRays, budget.limit() / sizeof(Photon),
             pass, passReport);
    for (size_t t = 0; t < kNumPhotonMapTypes; ++t) report.stored[t] += passReport.stored[t];
    report.emitted += passReport.emitted;
    report.prepassEmitted += passReport.prepassEmitted;
    report.prepasses = std::max(report.prepasses, passReport.prepasses);
    report.runaways += passReport.runaways;
    report.buildSeconds += passReport.buildSeconds;
    report.storingSeconds += passReport.storingSeconds;
}

}  // namespace

MkpmapReport runMkpmap(const MkpmapOptions& options, const std::string& commandLine,
                       std::ostream& diag, const LoadOptions& load, Cluster* cluster,
                       const PortExteriorFactory& exterior) {
    MkpmapOptions o = withoutIgnoredMaps(options);
    const auto sampling = spectral::makeSampling(o.spectralSamples, o.wavelengthA, o.wavelengthB);
    if (!sampling) throw InputError("unsupported spectral sampling");
    const std::vector<spectral::Pass> passes = spectral::passesOf(sampling->sampling);
    checkRequest(o, exterior, passes);
    // The tracer's settings as parsed; which maps it fills follows from the requests.
    for (size_t t = 0; t < o.maps.size(); ++t) o.trace.maps[t] = o.maps[t].has_value();
    MkpmapReport report;
    const Scene scene = loadCheckedScene(o, load);
    const SceneGeometry geometry(scene);
    // A spectral map set: the passes one after another over the one scene, each its own
    // files (photon_map.h).
    for (const spectral::Pass& pass : passes)
        runPass(o, commandLine, diag, scene, geometry, cluster, exterior, pass, report);
    if (cluster && !cluster->isRoot()) return report;
    printSummary(o, report, passes.size(), diag);
    return report;
}

}  // namespace rp::pmap

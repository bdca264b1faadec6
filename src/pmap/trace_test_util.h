// Test-only helpers for the mkpmap tests: build scene + geometry + emission plan +
// tracer from scene text or files and run the distribution. Not part of rp_pmap.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "light/emitter.h"
#include "light/light_sources.h"
#include "material/material_calc.h"
#include "material/surface_chain.h"
#include "pmap/distribute.h"
#include "pmap/trace.h"
#include "scene/reader.h"
#include "scene/scene_load.h"

namespace rp::pmap::testing {

struct Run {
    Scene scene;
    std::unique_ptr<SceneGeometry> geometry;
    std::unique_ptr<light::EmissionPlan> plan;
    std::unique_ptr<material::MaterialCalc> functions;
    std::unique_ptr<material::SurfaceChains> chains;
    std::unique_ptr<PhotonTracer> tracer;
};

// Modifier chains are evaluated (files along the project's lib/); `functions`: also
// the function-driven materials' expressions.
inline std::unique_ptr<Run> makeRun(Scene scene, TraceSettings ts,
                                    const std::vector<std::string>& ports = {},
                                    bool functions = false) {
    auto r = std::make_unique<Run>();
    r->scene = std::move(scene);
    r->geometry = std::make_unique<SceneGeometry>(r->scene);
    light::EmissionOptions eo;
    if (!ports.empty()) {
        std::vector<light::PortSpec> specs;
        for (const auto& p : ports) specs.push_back({p});
        eo.ports = light::findPhotonPorts(r->scene, *r->geometry, specs);
    }
    r->plan = std::make_unique<light::EmissionPlan>(
        *r->geometry, light::findLightSources(r->scene, *r->geometry), eo);
    std::vector<std::string> path{std::string(RP_SOURCE_DIR) + "/lib"};
    r->chains = std::make_unique<material::SurfaceChains>(r->scene, path);
    if (functions) r->functions = std::make_unique<material::MaterialCalc>(r->scene, path);
    r->tracer = std::make_unique<PhotonTracer>(r->scene, *r->geometry, *r->plan, std::move(ts),
                                               *r->chains, r->functions.get());
    return r;
}

inline Scene sceneFromText(const std::string& text) {
    SceneReader reader;
    reader.readText(text, "test.rad");
    return reader.take();
}

inline Scene sceneFromFile(const std::string& path) { return loadScene({path}); }

// Distributes with the given targets (0 = map not requested) for the tracer's maps.
inline DistributionResult distribute(const Run& r, uint64_t global, uint64_t caustic,
                                     uint64_t direct, int threads = 1, uint64_t seed = 1) {
    DistributionSettings ds;
    ds.targets[size_t(PhotonMapType::Global)] = global;
    ds.targets[size_t(PhotonMapType::Caustic)] = caustic;
    ds.targets[size_t(PhotonMapType::Direct)] = direct;
    ds.pass.seed = seed;
    ds.pass.threads = threads;
    return distributePhotons(*r.tracer, ds);
}

inline TraceSettings mapsFor(bool global, bool caustic, bool direct) {
    TraceSettings ts;
    ts.maps[size_t(PhotonMapType::Global)] = global;
    ts.maps[size_t(PhotonMapType::Caustic)] = caustic;
    ts.maps[size_t(PhotonMapType::Direct)] = direct;
    return ts;
}

// The surfaces of a closed 4 m cube room: walls and ceiling of modifier `wallmat`, the
// floor of `floormat`, a light panel (`lamp`) under the ceiling facing down; all room
// surfaces face inward. The modifiers are the caller's.
inline std::string boxRoomSurfaces() {
    return R"(
floormat polygon floor 0 0 12  0 0 0  4 0 0  4 4 0  0 4 0
wallmat polygon ceiling 0 0 12  0 0 4  0 4 4  4 4 4  4 0 4
wallmat polygon wall_s 0 0 12  0 0 0  0 0 4  4 0 4  4 0 0
wallmat polygon wall_n 0 0 12  0 4 0  4 4 0  4 4 4  0 4 4
wallmat polygon wall_w 0 0 12  0 0 0  0 4 0  0 4 4  0 0 4
wallmat polygon wall_e 0 0 12  4 0 0  4 0 4  4 4 4  4 4 0
lamp polygon panel 0 0 12  1.5 1.5 3.99  1.5 2.5 3.99  2.5 2.5 3.99  2.5 1.5 3.99
)";
}

// That room with plastic 0.5 walls, ceiling and floor and a lamp of radiance 10.
inline std::string boxRoom(const std::string& extra = "") {
    return R"(
void plastic wallmat 0 0 5 0.5 0.5 0.5 0 0
void plastic floormat 0 0 5 0.5 0.5 0.5 0 0
void light lamp 0 0 3 10 10 10
)" + boxRoomSurfaces() +
           extra;
}

}  // namespace rp::pmap::testing

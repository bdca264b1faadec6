// Photon emission: the EmissionPlan (every source's partitions, their exact flux and an
// alias table over them, built once) and emitPhoton, which turns a random stream into one
// photon ray with equal flux. Finding sources is light_sources.h, partitioning
// partition.h; tracing the photon through the scene belongs to pmap/.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "geometry/ray.h"
#include "geometry/scene_geometry.h"
#include "light/aperture.h"
#include "light/light_sources.h"
#include "light/partition.h"

namespace rp::light {

// The ray variables of a light source's modifier during emission (photon-map manual
// 3.1.2): D points towards the photon origin (= minus the photon direction; for a
// distant source, towards the source), N is the surface normal at the origin (the face
// or port normal for distant sources), P the origin, Rdot = N . photon direction.
struct EmissionQuery {
    Vec3 rayDir;  // D
    Vec3 point;   // P
    Vec3 normal;  // N
    double rdot;  // Rdot
    int32_t source;
};

// RGB multiplier of a modified source's radiance (its pattern chain, e.g. skyfunc).
struct EmissionModifier {
    std::function<Color(const EmissionQuery&)> eval;
    // True if eval ignores P (and N): flat sources then share one direction table.
    bool directionalOnly = false;
};

// mkpmap -apE: what photon ports see outside besides the sources, i.e. surfaces lit by
// them (ground, facades, overhangs), whose light the port then emits as well. RADIANCE's
// ports emit the sources alone (manual 3.2.4). `view(from, w, index)` traces one ray from
// `from` outside a port in unit direction w; `index` keys its random streams. It is
// called from one thread, in a fixed order, so that the plan is the same for any -n.
struct ExteriorView {
    bool surface = false;  // w met a surface (not the sky, not a light source or glow,
                           // whose photons their own groups emit)
    Color radiance;        // arriving at `from` along -w from that surface
    Color ambient;         // irradiance there from all but the direct calculation's sources
    Vec3 point, normal;    // the surface point, its normal turned toward `from`
    double distance = 0;
};
struct PortExterior {
    std::function<ExteriorView(const Vec3& from, const Vec3& w, uint64_t index)> view;
    // Each port side's table: directions over the hemisphere outside (cells per sr), each
    // the mean of `positions` rays from points spread over the port.
    double samplesPerSr = 64;
    int positions = 16;
    explicit operator bool() const { return bool(view); }
};

// A global photon that -apE leaves where a port's ray met a surface outside: what a final
// gather looking out through the port finds there (no photon from a port reaches it). Its
// flux is the ambient irradiance there times the area the ray stands for, in W.
struct ExteriorPhoton {
    Vec3 point, normal;
    Color flux;
};

struct EmissionOptions {
    double partitionSize = 0.01;    // -ds: partition edge / scene cube size
    double samplesPerSr = 1000;     // -dp: direction table samples per steradian
    std::vector<PhotonPort> ports;  // -apo (findPhotonPorts); distant sources emit here
    // Called once per modified source (LightSource::modified()). A modified source with
    // no modifier (null function or empty eval) throws notSupportedYet.
    std::function<EmissionModifier(const LightSource&)> modifierFor;
    PortExterior exterior;  // -apE (with ports only)
};

// One emitted photon. `weight` is the RGB flux it carries if it were the only photon:
// its mean over RGB equals EmissionPlan::totalFluxW() for every photon (facts §7: equal
// flux, RGB normalised to mean 1), so divide by the number emitted.
struct EmittedPhoton {
    Ray ray;  // unit dir; origin off the surface (spawnRay); tmax = glow radius
    Color weight;
    int32_t source = -1;    // index into EmissionPlan::sources(); -1 for exterior light
    bool exterior = false;  // -apE: light of the surfaces outside a port (PortExterior)
    int32_t port = -1;      // index into EmissionOptions::ports, -1 if not from a port
    // From a port: the origin lies just behind the port surface so that the photon's
    // first hit is the port itself (scattered by it, e.g. glass); a photon whose first
    // hit is not `portPrim` must be terminated (pmap.c's port rejection).
    int32_t portPrim = -1;
};

class EmissionPlan {
public:
    // Throws InputError if the total flux is zero ("zero flux from light sources"),
    // notSupportedYet for a modified source without a modifier.
    EmissionPlan(const SceneGeometry& geometry, std::vector<LightSource> sources,
                 const EmissionOptions& options = {});
    ~EmissionPlan();
    EmissionPlan(EmissionPlan&&) noexcept;
    EmissionPlan& operator=(EmissionPlan&&) noexcept;

    // Thread-safe: photon i is a function of its Rng stream only.
    EmittedPhoton emitPhoton(Rng& rng) const;
    EmittedPhoton emitPhoton(uint64_t seed, uint64_t photonIndex) const {
        Rng rng(seed, RngDomain::Emission, photonIndex);
        return emitPhoton(rng);
    }

    const std::vector<LightSource>& sources() const;
    Color totalFlux() const;    // W per channel
    double totalFluxW() const;  // mean over RGB (RADIANCE's colorAvg)
    Color sourceFlux(size_t source) const;
    Color exteriorFlux() const;  // -apE: what the ports' exterior tables emit
    const std::vector<ExteriorPhoton>& exteriorPhotons() const;
    // RADIANCE's partition count (cube faces count (1/ds)^2 cells each).
    size_t partitionCount() const;
    size_t partitionCount(size_t source) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace rp::light

// Every material record of a scene, checked once and shared read-only by backward
// shading, shadow rays, photon scattering and emission (through SurfaceChains, which
// owns it: the chains end at these records). What each record is for the light
// transport - light, antimatter, opaque back, alternate - is decided here, once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "material/material.h"
#include "scene/primitive.h"

namespace rp::material {

struct MaterialRecord {
    std::optional<MaterialParams> params;  // empty: `error` says why
    std::string error;
    int32_t alternate = kVoid;  // mirror/illum alternate material record (kVoid: void)
    bool hasAlternate = false;
    bool isLight = false;      // light, illum, glow, spotlight
    bool diffuseLike = false;  // material::evaluate can be non-zero (direct light applies)
    bool antimatter = false;
    bool backAbsorbs = false;  // opaque: photons meeting the back are absorbed unless -bv
    // Shading turns the surface to face a ray that hits its back (RADIANCE flipsurface in
    // normal.c, aniso.c, ashikhmin.c, glass.c, m_brdf.c m_brdf2), so rtrace -on reports
    // the normal facing the ray; the others (lights, mirror, dielectric, BRTDfunc, BSDF,
    // mist, prisms) keep it as given.
    bool reorientsBackHits = false;
    // With -i, rays pass it to compute the irradiance on the first opaque surface behind
    // (RADIANCE irr_ignore: glass, dielectric, interface, antimatter).
    bool passesIrradiance = false;
    // A shadow ray stopped by transparent surfaces in photon-map mode still passes it
    // (pmapmat.h shadowRayInPmap: antimatter and mist boundaries are no surfaces to it).
    bool passesPhotonShadows = false;
    // An ambient record behind it is hidden (RADIANCE ambient.c plugaleak: neither
    // transparent, initotypes.c T_TRANSP, nor a thick BSDF's proxy). Set from the type
    // even where the arguments are bad, as RADIANCE's test looks at the type only.
    bool plugsLeaks = true;
    // Photons can meet it (RADIANCE's photon tracer has no prism1/prism2).
    bool scattersPhotons = true;
    std::vector<int32_t> clips;  // antimatter: the modifiers it clips (RADIANCE lastmod)
};

// The last modifier named `name` defined before record `before` (RADIANCE lastmod);
// kVoid for "void" or an unknown name.
int32_t lastModifier(const Scene& scene, int32_t before, const std::string& name);

// The modifiers the antimatter record `index` clips: each of its names resolved with
// lastModifier, "void" and repeats skipped; unknown names are warned about with
// `warnUnknown` (RADIANCE warns and goes on without them).
std::vector<int32_t> antimatterClips(const Scene& scene, int32_t index, bool warnUnknown);

// The mist's parameters if the record is a mist boundary, else null.
inline const MistParams* mistOf(const MaterialRecord& r) {
    return r.params ? std::get_if<MistParams>(&*r.params) : nullptr;
}

class MaterialTable {
public:
    // Argument errors are kept and thrown when the record is used (`at`), so that a
    // scene may hold unused broken materials, as RADIANCE allows. With `warnUnknown`,
    // antimatter names that match no modifier are reported once here. Colours are the
    // bands of `pass` (RGB unless rendering a spectrum).
    explicit MaterialTable(const Scene& scene, bool warnUnknown = false,
                           const spectral::Pass& pass = {});

    // The record of material `index`; throws its argument error, or that it is no
    // material.
    const MaterialRecord& at(int32_t index) const;
    // The record of `index`, unchecked: for callers that checked it with at() before.
    const MaterialRecord& operator[](int32_t index) const { return records_[size_t(index)]; }
    const Scene& scene() const { return scene_; }
    const spectral::Pass& pass() const { return pass_; }
    // Whether `index` is a material whose arguments are fine.
    bool usable(int32_t index) const {
        return index >= 0 && size_t(index) < records_.size() && records_[size_t(index)].params;
    }

private:
    const Scene& scene_;
    spectral::Pass pass_;
    std::vector<MaterialRecord> records_;  // indexed by prim; only material records set
};

}  // namespace rp::material

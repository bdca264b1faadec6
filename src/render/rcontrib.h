// rcontrib's tally (RADIANCE rcontrib.c trace_contrib, pmcontrib2.c photonContrib): the
// tracked modifiers with their bins, the bin expressions compiled once, and a per-thread
// ContributionSink that adds each reported contribution to its modifier's bin.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "pmap/contrib_bins.h"
#include "pmap/contrib_coeffs.h"
#include "render/rcontrib_options.h"
#include "render/renderer.h"
#include "scene/primitive.h"
#include "util/color.h"
#include "util/warnings.h"

namespace rp::render {

using pmap::evalBinCount;

// A source a contribution map's primaries name (light::findLightSources order).
using PhotonSource = pmap::ContribSource;

// A contribution map's photons' origins (rcontrib -ap): the sources and primaries that
// place each photon in its modifier's bin.
struct PhotonOrigins {
    std::vector<PhotonSource> sources;
    std::span<const pmap::PhotonPrimary> primaries;
    std::span<const pmap::PrimaryRay> rays;  // empty: the map keeps none
    int threads = 1;                         // to bin the primaries with
};

// The sources a contribution map's primaries index, in mkpmap's order
// (light::findLightSources).
std::vector<PhotonSource> contributionSources(const Scene& scene, const SceneGeometry& geometry);

// A precomputed contribution map's coefficient files (one per modifier, in modifier
// order) against rcontrib's -bn and -V: InputError where mkpmap binned otherwise (the map's
// .opt file gives rcontrib mkpmap's options).
void checkPrecomputedBins(const std::vector<ContribModifier>& modifiers, bool contributions,
                          const std::vector<pmap::CoeffInfo>& precomputed);

class ContribTargets {
public:
    // `modifiers` as parsed; `defs` the -e/-f definitions (loaded after rayinit.cal, each
    // modifier's -p values after them). `photons`: no sources without -ap. Throws
    // InputError for a bin expression that does not evaluate, and (with photon sources)
    // "modifiers not in photon map" when none of the modifiers is one.
    ContribTargets(const Scene& scene, const std::vector<ContribModifier>& modifiers,
                   const std::vector<CalcDefinition>& defs, bool contributions,
                   const PhotonOrigins& photons = {});
    ~ContribTargets();

    const std::vector<ContribModifier>& modifiers() const { return bins_.modifiers(); }
    // Values per input ray: every modifier's bins, in modifier order (offset(m) + bin).
    size_t size() const { return bins_.size(); }
    size_t offset(size_t m) const { return bins_.offset(m); }
    const pmap::ContribBins& bins() const { return bins_; }

    // Bin numbers of the input that were too large for -bn (reported at the end).
    WarningCounter& badBins() const { return bins_.badBins(); }

    struct Target;
    const Target* targetOfModifier(int32_t prim) const {
        return prim >= 0 && size_t(prim) < byModifier_.size() ? byModifier_[size_t(prim)] : nullptr;
    }
    // Where the photons of each primary go (rcontrib -ap).
    const pmap::PrimaryBins& photonBins() const { return photonBins_; }
    bool contributions() const { return contributions_; }

private:
    pmap::ContribBins bins_;
    std::vector<std::unique_ptr<Target>> targets_;
    std::vector<const Target*> byModifier_;  // per scene record
    pmap::PrimaryBins photonBins_;
    bool contributions_ = false;
};

// One thread's tally of one input ray's contributions (reset between rays).
class ContribTally : public ContributionSink {
public:
    explicit ContribTally(const ContribTargets& targets);
    ~ContribTally() override;

    void reset();
    const std::vector<Color>& values() const { return values_; }

    bool tracks(int32_t modifier) const override {
        return targets_.targetOfModifier(modifier) != nullptr;
    }
    void add(int32_t modifier, const Vec3& point, const Vec3& dir, const Color& coef,
             const Color& value) override;
    void addPhotons(std::span<const pmap::FoundPhoton> photons, double scale,
                    const Color& coef) override;
    // One photon of primary `primary` bringing `value` (addPhotons' step).
    void addPhoton(uint32_t primary, const Color& value);
    void addBins(int32_t modifier, std::span<const Color> values) override;

private:
    const ContribTargets& targets_;
    pmap::ContribBins::Binner binner_;
    std::vector<Color> values_;
};

}  // namespace rp::render

// rcontrib's tally (see rcontrib.h).
#include "render/rcontrib.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <unordered_map>

#include "light/light_sources.h"
#include "pmap/photon_store.h"
#include "util/error.h"

namespace rp::render {

struct ContribTargets::Target {
    size_t index = 0;  // into bins().modifiers()
    size_t offset = 0;
    bool constant = true;
};

namespace {

std::atomic<bool> warnedPhotonBins{false};

}  // namespace

std::vector<PhotonSource> contributionSources(const Scene& scene, const SceneGeometry& geometry) {
    std::vector<PhotonSource> out;
    for (const light::LightSource& s : light::findLightSources(scene, geometry)) {
        const Color& r = s.params.radiance;
        out.push_back({scene.prims[size_t(s.material)].name, {r.r, r.g, r.b}, s.distant()});
    }
    return out;
}

void checkPrecomputedBins(const std::vector<ContribModifier>& modifiers, bool contributions,
                          const std::vector<pmap::CoeffInfo>& precomputed) {
    for (size_t i = 0; i < precomputed.size() && i < modifiers.size(); ++i) {
        const pmap::CoeffInfo& c = precomputed[i];
        const ContribModifier& m = modifiers[i];
        if (c.bins != m.bins)
            throw InputError("modifier '" + m.name + "' was precomputed in " +
                             std::to_string(c.bins) + " bins, -bn gives " + std::to_string(m.bins) +
                             " (use the map's .opt file)");
        if (c.contributions != contributions)
            throw InputError(std::string("modifier '") + m.name + "' was precomputed as " +
                             (c.contributions ? "contributions (-V+)" : "coefficients (-V-)") +
                             " (use the map's .opt file)");
    }
}

ContribTargets::ContribTargets(const Scene& scene, const std::vector<ContribModifier>& modifiers,
                               const std::vector<CalcDefinition>& defs, bool contributions,
                               const PhotonOrigins& photons)
    : bins_(modifiers, defs), contributions_(contributions) {
    std::unordered_map<std::string, const Target*> byName;
    for (size_t i = 0; i < modifiers.size(); ++i) {
        auto t = std::make_unique<Target>();
        t->index = i;
        t->offset = bins_.offset(i);
        t->constant = isConstantBin(modifiers[i].binExpr);
        byName[modifiers[i].name] = t.get();
        targets_.push_back(std::move(t));
    }
    // RADIANCE compat (rcontrib.c trace_contrib): a surface is tracked by the name of its
    // own modifier.
    byModifier_.assign(scene.prims.size(), nullptr);
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        auto it = byName.find(scene.prims[i].name);
        if (it != byName.end()) byModifier_[i] = it->second;
    }
    // pmcontrib2.c: photons by the name of their source's light material.
    bool any = photons.sources.empty();
    for (const PhotonSource& s : photons.sources) any = any || byName.count(s.material);
    if (!any) throw InputError("modifiers not in photon map");
    if (!photons.sources.empty())
        photonBins_ = pmap::PrimaryBins(bins_, photons.sources, contributions, photons.primaries,
                                        photons.rays, photons.threads);
}

ContribTargets::~ContribTargets() = default;

ContribTally::ContribTally(const ContribTargets& targets)
    : targets_(targets), binner_(targets.bins()), values_(targets.size()) {}

ContribTally::~ContribTally() = default;

void ContribTally::reset() { std::fill(values_.begin(), values_.end(), Color{}); }

void ContribTally::add(int32_t modifier, const Vec3& point, const Vec3& dir, const Color& coef,
                       const Color& value) {
    const ContribTargets::Target* t = targets_.targetOfModifier(modifier);
    if (!t) return;
    const int b = binner_.bin(t->index, point, dir);
    if (b < 0) return;
    values_[t->offset + size_t(b)] += targets_.contributions() ? coef * value : coef;
}

void ContribTally::addBins(int32_t modifier, std::span<const Color> values) {
    const ContribTargets::Target* t = targets_.targetOfModifier(modifier);
    if (!t) return;
    const size_t n = std::min(values.size(), size_t(targets_.modifiers()[t->index].bins));
    for (size_t b = 0; b < n; ++b) values_[t->offset + b] += values[b];
}

void ContribTally::addPhotons(std::span<const pmap::FoundPhoton> photons, double scale,
                              const Color& coef) {
    // Where each photon goes is looked up by its primary, all over a large table: ask for
    // every photon's entry before the first is needed.
    for (const pmap::FoundPhoton& p : photons) targets_.photonBins().prefetch(p.primary);
    for (const pmap::FoundPhoton& p : photons) {
        const auto f = p.fluxRgb();
        addPhoton(p.primary, coef * Color{f[0] * scale, f[1] * scale, f[2] * scale});
    }
}

void ContribTally::addPhoton(uint32_t primary, const Color& value) {
    const pmap::PrimaryBins::Share& sh = targets_.photonBins().share(primary);
    if (sh.slot < 0) {
        if (sh.slot == pmap::PrimaryBins::kPastEnd) targets_.badBins().add();
        // RADIANCE compat (pmcontrib2.c, default build): a map without primary rays
        // cannot place a photon in a bin. RADIANCE warns (its advice is to rebuild
        // RADIANCE; ours is mkpmap -apCPD) and drops the photon: its dummy ray meets no
        // source, except a full-sky one, whose photons all land in the bin of D = 0. We
        // drop those too.
        if (sh.slot == pmap::PrimaryBins::kNoRay && !warnedPhotonBins.exchange(true)) {
            warn(
                "no photon primary hitpoints for bin evaluation; using dummy (0,0,0)!"
                " (make the map with mkpmap -apCPD)");
            warn("no photon primary directions for bin evaluation; using dummy (0,0,0)!");
        }
        return;
    }
    // Coefficients (-V-): per unit radiance of the source (0 where it emits nothing).
    const std::array<double, 3> v = sh.of({value.r, value.g, value.b});
    values_[size_t(sh.slot)] += Color{v[0], v[1], v[2]};
}

}  // namespace rp::render

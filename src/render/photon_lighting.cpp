#include "render/photon_lighting.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <string>

#include "util/error.h"
#include "util/henyey_greenstein.h"
#include "util/warnings.h"

namespace rp::render {

pmap::LookupParams PhotonLighting::lookupParams(const Map& m) const {
    pmap::LookupParams p;
    // With bias compensation the search radius is sized for the upper bandwidth.
    p.bandwidth = m.use.bandwidth2 > 0 ? m.use.bandwidth2 : m.use.bandwidth;
    p.maxSearchRadius = maxSearchRadius_;
    p.edgeAware = m.use.edgeAware;  // -ape
    // RADIANCE compat (pmcontrib2.c): contribution lookups count as short unless the
    // queue fills, so every requested photon's contribution is there.
    if (!m.map.primaries().empty()) p.gatherTolerance = 1;
    return p;
}

PhotonLighting::Lookups::Lookups(const PhotonLighting& owner) : owner_(owner) {
    for (const Map& m : owner.maps_) lookups.emplace_back(m.map, owner.lookupParams(m));
    if (owner.contribCaustic_) {
        const Map& m = owner.maps_[size_t(owner.contrib_)];
        pmap::LookupParams p = owner.lookupParams(m);
        p.causticOnly = true;
        contribCaustic.emplace(m.map, p);
    }
    biasStats.resize(owner.maps_.size());
}

PhotonLighting::Lookups::~Lookups() {
    for (const pmap::PhotonLookup& l : lookups) {
        owner_.shortLookups_ += l.shortLookups();
        owner_.lookups_ += l.lookups();
    }
    if (contribCaustic) {
        owner_.shortLookups_ += contribCaustic->shortLookups();
        owner_.lookups_ += contribCaustic->lookups();
    }
    std::lock_guard<std::mutex> lock(owner_.statsMutex_);
    for (size_t i = 0; i < biasStats.size(); ++i) owner_.biasStats_[i].merge(biasStats[i]);
}

namespace {

std::string lowerCase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

int64_t fileMtime(const std::string& path) {
    std::error_code ec;
    auto t = std::filesystem::last_write_time(path, ec);
    if (ec) return 0;
    auto sys = std::chrono::file_clock::to_sys(t);
    return std::chrono::duration_cast<std::chrono::seconds>(sys.time_since_epoch()).count();
}

}  // namespace

PhotonLighting::PhotonLighting(const std::vector<PhotonMapUse>& uses, double maxSearchRadius,
                               const Scene& scene, const std::vector<bool>* trackedSources,
                               const pmap::StoreOptions& store,
                               const std::vector<std::string>& trackedModifiers)
    : maxSearchRadius_(maxSearchRadius) {
    const bool contributions = trackedSources != nullptr;
    int64_t newestInput = 0;
    std::string newestName;
    for (const SceneInput& in : scene.inputs)
        if (in.mtime > newestInput) {
            newestInput = in.mtime;
            newestName = in.path;
        }
    // The maps are opened concurrently (with two threads, the global map's store is built
    // while the larger caustic map still loads); errors are reported in command-line
    // order whatever the threads did.
    using T = pmap::PhotonMapType;
    std::vector<Map> loaded(uses.size());
    std::vector<std::exception_ptr> failed(uses.size());
    tbb::parallel_for(size_t(0), uses.size(), [&](size_t i) {
        try {
            pmap::StoreOptions o = store;
            o.bandwidth = std::max({uses[i].bandwidth, uses[i].bandwidth2, kDefaultBandwidth});
            const std::string file = spectral::passFile(uses[i].file, uses[i].pass);
            loaded[i].map = pmap::PhotonMap::open(file, o, trackedSources);
            pmap::checkMapBands(loaded[i].map.bands(), uses[i].pass, file);
        } catch (...) {
            failed[i] = std::current_exception();
        }
    });
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);
    for (size_t i = 0; i < uses.size(); ++i) {
        const PhotonMapUse& use = uses[i];
        Map m = std::move(loaded[i]);
        m.use = use;
        m.file = spectral::passFile(use.file, use.pass);
        T type = m.map.type();
        const char* name = pmap::photonMapTypeName(type);
        const bool contribType = type == T::Contrib || type == T::PreCompContrib;
        if (contribType && !contributions)
            throw InputError(use.file +
                             ": contribution photon maps are used by rcontrib, "
                             "not by the renderer");
        // RADIANCE compat (pmcontrib2.c initPmapContrib).
        if (!contribType && contributions)
            throw InputError(use.file + ": " + lowerCase(name) +
                             " photon map does not support contributions");
        if (type == T::Volume && use.bandwidth2 > 0)
            throw InputError(use.file +
                             ": bias compensation is not available with volume photon maps");
        int* slot = type == T::Caustic  ? &caustic_
                    : type == T::Direct ? &direct_
                    : type == T::Volume ? &volume_
                    : contribType       ? &contrib_
                                        : &global_;
        if (*slot >= 0)
            throw InputError(use.file + ": more than one " + std::string(name) +
                             " photon map given with -ap");
        // Precomputed maps are read at their single nearest photon.
        const bool precomputed = type == T::PreComp || type == T::PreCompContrib;
        if (m.use.bandwidth <= 0) {
            m.use.bandwidth = precomputed ? 1 : kDefaultBandwidth;
            if (!precomputed)
                warn("no bandwidth given for " + std::string(name) + " photon map " + use.file +
                     ", using " + std::to_string(kDefaultBandwidth));
        }
        if (m.use.bandwidth2 > 0 && m.use.bandwidth2 <= m.use.bandwidth)
            throw InputError(use.file + ": bias compensation needs bwidth2 > bwidth1 (" +
                             std::to_string(m.use.bandwidth) + " " +
                             std::to_string(m.use.bandwidth2) + ")");
        if (precomputed) m.use.bandwidth2 = 0;  // RADIANCE: precomputed maps use 1
        int64_t mt = fileMtime(use.file);
        if (mt > 0 && newestInput > mt)
            throw InputError(use.file + ": photon map is older than scene file " + newestName +
                             " (stale: rerun mkpmap)");
        *slot = int(maps_.size());
        maps_.push_back(std::move(m));
        // RADIANCE compat (pmapamb.c ambPmapCaustic, pmapmat.h srcRayInPmap): with a
        // contribution map its caustic photons stand for light through specular surfaces.
        if (contribType) contribCaustic_ = true;
    }
    biasStats_.resize(maps_.size());
    if (contrib_ >= 0 && maps_[size_t(contrib_)].map.type() == T::PreCompContrib)
        openCoefficients(scene, trackedModifiers);
}

// Each tracked modifier's coefficient file; its name resolved to a scene record once.
void PhotonLighting::openCoefficients(const Scene& scene,
                                      const std::vector<std::string>& modifiers) {
    const std::string& file = maps_[size_t(contrib_)].file;
    for (const std::string& name : modifiers) {
        const std::string path = pmap::coeffFile(file, name);
        std::error_code ec;
        if (!std::filesystem::exists(path, ec))
            throw InputError(file + ": modifier '" + name + "' was not precomputed (no " + path +
                             "; see " + pmap::optionFile(file) + ")");
        Coefficients c{pmap::CoeffFile(path), -1};
        if (c.file.info().modifier != name)
            throw InputError(path + ": holds modifier '" + c.file.info().modifier + "', not '" +
                             name + "'");
        for (size_t i = 0; i < scene.prims.size() && c.modifier < 0; ++i)
            if (scene.prims[i].name == name) c.modifier = int32_t(i);
        coefficients_.push_back(std::move(c));
    }
}

std::vector<pmap::CoeffInfo> PhotonLighting::precomputedModifiers() const {
    std::vector<pmap::CoeffInfo> out;
    for (const Coefficients& c : coefficients_) out.push_back(c.file.info());
    return out;
}

std::string PhotonLighting::biasReport() const {
    std::lock_guard<std::mutex> lock(statsMutex_);
    std::string out;
    for (size_t i = 0; i < maps_.size(); ++i) {
        const std::string type = lowerCase(pmap::photonMapTypeName(maps_[i].map.type()));
        std::string r = biasStats_[i].report(type.c_str());
        if (r.empty()) continue;
        if (!out.empty()) out += ", ";
        out += r;
    }
    return out;
}

PhotonLighting::~PhotonLighting() = default;

std::unique_ptr<PhotonLighting::Lookups> PhotonLighting::makeLookups() const {
    return std::make_unique<Lookups>(*this);
}

Color PhotonLighting::density(Lookups& l, int index, const Vec3& pos, const Vec3& normal,
                              const pmap::DiscCoverage* coverage) const {
    if (index < 0) return {};
    pmap::PhotonLookup& lookup = l.lookups[size_t(index)];
    const Map& m = maps_[size_t(index)];
    std::array<double, 3> d;
    if (m.map.type() == pmap::PhotonMapType::PreComp)
        d = lookup.precompDensity(pos, normal);
    else if (m.use.bandwidth2 > 0)
        d = lookup.biasCompensatedDensity(pos, normal, m.use.bandwidth, m.use.bandwidth2,
                                          &l.biasStats[size_t(index)]);
    else
        d = lookup.surfaceDensity(pos, normal, coverage);
    return Color{d[0], d[1], d[2]};
}

Color PhotonLighting::globalDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                                    const pmap::DiscCoverage* coverage) const {
    return density(l, global_, pos, normal, coverage);
}
Color PhotonLighting::causticDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                                     const pmap::DiscCoverage* coverage) const {
    return density(l, caustic_, pos, normal, coverage);
}
Color PhotonLighting::directDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                                    const pmap::DiscCoverage* coverage) const {
    return density(l, direct_, pos, normal, coverage);
}

Color PhotonLighting::contribDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                                     const Color& coef, ContributionSink* sink, bool caustic,
                                     const pmap::DiscCoverage* coverage) const {
    if (contrib_ < 0) return {};
    const pmap::PhotonMap& map = maps_[size_t(contrib_)].map;
    if (map.type() == pmap::PhotonMapType::PreCompContrib)
        return precomputedContrib(l, pos, normal, coef, sink, caustic);
    auto share = [&](std::span<const pmap::FoundPhoton> photons, double scale) {
        if (sink) sink->addPhotons(photons, scale, coef);
    };
    pmap::PhotonLookup& lookup = caustic ? *l.contribCaustic : l.lookups[size_t(contrib_)];
    auto d = lookup.contribDensity(pos, normal, share, coverage);
    return Color{d[0], d[1], d[2]};
}

// The development branch's lookup: the bins of the single nearest precomputed photon.
Color PhotonLighting::precomputedContrib(Lookups& l, const Vec3& pos, const Vec3& normal,
                                         const Color& coef, ContributionSink* sink,
                                         bool caustic) const {
    // Its caustic-flagged photons hold estimates of caustic photons alone.
    const pmap::FoundPhoton* p = l.lookups[size_t(contrib_)].nearestPhoton(pos, normal, caustic);
    if (!p) return {};
    Color total;
    for (const Coefficients& c : coefficients_) {
        const size_t n = size_t(c.file.info().bins);
        l.bins.resize(n);
        l.binValues.resize(n);
        if (!c.file.decode(p->primary, l.bins, l.scratch))
            throw InputError(c.file.path() + ": no record for precomputed photon " +
                             std::to_string(p->primary) + " (files of different runs?)");
        for (size_t b = 0; b < n; ++b) {
            l.binValues[b] = coef * Color{l.bins[b][0], l.bins[b][1], l.bins[b][2]};
            total += l.binValues[b];
        }
        if (sink) sink->addBins(c.modifier, l.binValues);
    }
    return total;
}

Color PhotonLighting::volumeDensity(Lookups& l, const Vec3& pos, const Vec3& out, double g) const {
    if (volume_ < 0) return {};
    auto d = l.lookups[size_t(volume_)].volumeDensity(pos, out, g, &henyeyGreenstein4Pi);
    return Color{d[0], d[1], d[2]};
}

}  // namespace rp::render

#include "render/photon_lighting.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <iterator>
#include <string>

#include "util/dir_code.h"
#include "util/error.h"
#include "util/henyey_greenstein.h"
#include "util/warnings.h"

namespace rp::render {

PhotonLighting::Lookups::Lookups(const PhotonLighting& owner) : owner_(owner) {
    for (const Map& m : owner.maps_) {
        pmap::LookupParams p;
        // With bias compensation the search radius is sized for the upper bandwidth.
        p.bandwidth = m.use.bandwidth2 > 0 ? m.use.bandwidth2 : m.use.bandwidth;
        p.maxSearchRadius = owner.maxSearchRadius_;
        // RADIANCE compat (pmcontrib2.c): contribution lookups count as short unless the
        // queue fills, so every requested photon's contribution is there.
        if (!m.map.primaries().empty()) p.gatherTolerance = 1;
        // Eager indexes exist already (get() returns at once); lazy ones are chosen per
        // lookup (PhotonLighting::density).
        lookups.emplace_back(m.map, p,
                             m.indexedOnDemand() ? nullptr : &m.index.get(m.map.photons()));
    }
    biasStats.resize(owner.maps_.size());
}

PhotonLighting::Lookups::~Lookups() {
    for (const pmap::PhotonLookup& l : lookups) {
        owner_.shortLookups_ += l.shortLookups();
        owner_.lookups_ += l.lookups();
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
                               const Scene& scene, const std::vector<bool>* trackedSources)
    : maxSearchRadius_(maxSearchRadius) {
    const bool contributions = trackedSources != nullptr;
    int64_t newestInput = 0;
    std::string newestName;
    for (const SceneInput& in : scene.inputs)
        if (in.mtime > newestInput) {
            newestInput = in.mtime;
            newestName = in.path;
        }
    // The maps load and get their search indexes concurrently, each index as soon as its
    // map is loaded (with two threads, the global map's index is built while the larger
    // caustic map still loads); errors are reported in command-line order whatever the
    // threads did.
    using T = pmap::PhotonMapType;
    std::vector<Map> loaded(uses.size());
    std::vector<std::exception_ptr> failed(uses.size());
    tbb::parallel_for(size_t(0), uses.size(), [&](size_t i) {
        try {
            // Searched through a PhotonIndex (pmap/lookup_index.h: same photons as the
            // kd-tree walk, about 1.7x faster), so the file's kd-tree order is not
            // checked here. Caustic maps, whose first rays walk it (Lookups::kKdTreeRays),
            // are read on demand: the walks read and check the photons they visit, and
            // the rest is read when the index is built.
            Map& m = loaded[i];
            m.map = pmap::PhotonMap::load(uses[i].file, pmap::PhotonMap::TreeOrder::Unchecked,
                                          /*causticOnDemand=*/true);
            const T type = m.map.type();
            if (!m.indexedOnDemand() && (type != T::Contrib) != contributions)
                m.index.get(m.map.photons());  // maps refused below are not indexed
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
        m.file = use.file;
        T type = m.map.type();
        const char* name = pmap::photonMapTypeName(type);
        if (type == T::Contrib && !contributions)
            throw InputError(use.file +
                             ": contribution photon maps are used by rcontrib, "
                             "not by the renderer");
        // RADIANCE compat (pmcontrib2.c initPmapContrib).
        if (type != T::Contrib && contributions)
            throw InputError(use.file + ": " + lowerCase(name) +
                             " photon map does not support contributions");
        if (type == T::Volume && use.bandwidth2 > 0)
            throw InputError(use.file +
                             ": bias compensation is not available with volume photon maps");
        int* slot = type == T::Caustic   ? &caustic_
                    : type == T::Direct  ? &direct_
                    : type == T::Volume  ? &volume_
                    : type == T::Contrib ? &contrib_
                                         : &global_;
        if (*slot >= 0)
            throw InputError(use.file + ": more than one " + std::string(name) +
                             " photon map given with -ap");
        if (m.use.bandwidth <= 0) {
            m.use.bandwidth = type == T::PreComp ? 1 : kDefaultBandwidth;
            if (type != T::PreComp)
                warn("no bandwidth given for " + std::string(name) + " photon map " + use.file +
                     ", using " + std::to_string(kDefaultBandwidth));
        }
        if (m.use.bandwidth2 > 0 && m.use.bandwidth2 <= m.use.bandwidth)
            throw InputError(use.file + ": bias compensation needs bwidth2 > bwidth1 (" +
                             std::to_string(m.use.bandwidth) + " " +
                             std::to_string(m.use.bandwidth2) + ")");
        if (type == T::PreComp) m.use.bandwidth2 = 0;  // RADIANCE: precomputed maps use 1
        int64_t mt = fileMtime(use.file);
        if (mt > 0 && newestInput > mt)
            throw InputError(use.file + ": photon map is older than scene file " + newestName +
                             " (stale: rerun mkpmap)");
        *slot = int(maps_.size());
        maps_.push_back(std::move(m));
        if (type == T::Contrib) prepareContrib(*trackedSources);
    }
    biasStats_.resize(maps_.size());
}

void PhotonLighting::prepareContrib(const std::vector<bool>& trackedSources) {
    Map& full = maps_[size_t(contrib_)];
    const auto& primaries = full.map.primaries();
    auto tracked = [&](const pmap::Photon& p) {
        const int s = p.primary < primaries.size() ? primaries[p.primary].srcIdx : -1;
        return s >= 0 && size_t(s) < trackedSources.size() && trackedSources[size_t(s)];
    };
    const auto photons = full.map.photons();
    if (!std::all_of(photons.begin(), photons.end(), tracked)) {
        std::vector<pmap::Photon> kept;
        std::copy_if(photons.begin(), photons.end(), std::back_inserter(kept), tracked);
        std::vector<pmap::PrimaryRay> rays = full.map.primaryRays();
        full.map = pmap::PhotonMap(pmap::PhotonMapType::Contrib, std::move(kept), primaries);
        full.map.setPrimaryRays(std::move(rays));
        full.index = pmap::LazyPhotonIndex{};
    }
    std::vector<pmap::Photon> caustic;
    for (const pmap::Photon& p : full.map.photons())
        if (p.caustic()) caustic.push_back(p);
    if (caustic.empty()) return;
    Map m;
    m.map = pmap::PhotonMap(pmap::PhotonMapType::Contrib, std::move(caustic), full.map.primaries());
    m.map.setPrimaryRays(full.map.primaryRays());
    m.use = full.use;
    m.file = full.file;
    contribCaustic_ = int(maps_.size());
    maps_.push_back(std::move(m));
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

Color PhotonLighting::density(Lookups& l, int index, const Vec3& pos, const Vec3& normal) const {
    if (index < 0) return {};
    pmap::PhotonLookup& lookup = l.lookups[size_t(index)];
    const Map& m = maps_[size_t(index)];
    if (m.indexedOnDemand()) lookup.useIndex(l.earlyRay ? nullptr : &m.index.get(m.map.photons()));
    std::array<double, 3> d;
    if (m.map.type() == pmap::PhotonMapType::PreComp)
        d = lookup.precompDensity(pos, normal);
    else if (m.use.bandwidth2 > 0)
        d = lookup.biasCompensatedDensity(pos, normal, m.use.bandwidth, m.use.bandwidth2,
                                          &l.biasStats[size_t(index)]);
    else
        d = lookup.surfaceDensity(pos, normal);
    return Color{d[0], d[1], d[2]};
}

Color PhotonLighting::globalDensity(Lookups& l, const Vec3& pos, const Vec3& normal) const {
    return density(l, global_, pos, normal);
}
Color PhotonLighting::causticDensity(Lookups& l, const Vec3& pos, const Vec3& normal) const {
    return density(l, caustic_, pos, normal);
}
Color PhotonLighting::directDensity(Lookups& l, const Vec3& pos, const Vec3& normal) const {
    return density(l, direct_, pos, normal);
}

Color PhotonLighting::contribDensity(Lookups& l, const Vec3& pos, const Vec3& normal,
                                     const Color& coef, ContributionSink* sink,
                                     bool caustic) const {
    const int index = caustic ? contribCaustic_ : contrib_;
    if (index < 0) return {};
    const Map& m = maps_[size_t(index)];
    const pmap::PhotonMap& map = m.map;
    const auto& primaries = map.primaries();
    const auto& rays = map.primaryRays();
    auto share = [&](const pmap::Photon& p, const std::array<double, 3>& v) {
        if (!sink || p.primary >= primaries.size()) return;
        const Color value = coef * Color{v[0], v[1], v[2]};
        if (rays.empty()) {
            sink->addPhotons(primaries[p.primary].srcIdx, nullptr, value);
            return;
        }
        const pmap::PrimaryRay& r = rays[p.primary];
        const std::array<double, 3> d = decodeDirection(r.dir);
        const ContributionSink::PhotonOrigin o{Vec3{r.pos[0], r.pos[1], r.pos[2]},
                                               Vec3{d[0], d[1], d[2]}};
        sink->addPhotons(primaries[p.primary].srcIdx, &o, value);
    };
    pmap::PhotonLookup& lookup = l.lookups[size_t(index)];
    if (m.indexedOnDemand()) lookup.useIndex(l.earlyRay ? nullptr : &m.index.get(map.photons()));
    auto d = lookup.contribDensity(pos, normal, share);
    return Color{d[0], d[1], d[2]};
}

Color PhotonLighting::volumeDensity(Lookups& l, const Vec3& pos, const Vec3& out,
                                   double g) const {
    if (volume_ < 0) return {};
    auto d = l.lookups[size_t(volume_)].volumeDensity(pos, out, g, &henyeyGreenstein4Pi);
    return Color{d[0], d[1], d[2]};
}

}  // namespace rp::render

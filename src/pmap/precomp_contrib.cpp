// Precomputed contribution photons (precomp_contrib.h).
#include "pmap/precomp_contrib.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <unordered_set>
#include <utility>

#include "pmap/contrib_coeffs.h"
#include "pmap/density.h"
#include "pmap/photon_map.h"
#include "pmap/precomp.h"
#include "util/error.h"

namespace rp::pmap {

namespace {

// Every modifier must be some source's light material (mkpmap's check; rcontrib only
// needs one of them to be).
void checkModifiersNamed(const std::vector<ContribSource>& sources, const ContribBins& bins) {
    std::unordered_set<std::string> materials;
    for (const ContribSource& s : sources) materials.insert(s.material);
    for (const ContribModifier& m : bins.modifiers())
        if (!materials.count(m.name))
            throw InputError("modifier '" + m.name + "' is not the material of a light source");
}

// One thread's state for a chunk of precomputed photons: estimates over all photons, and
// over the caustic photons only.
struct ChunkState {
    PhotonLookup all, caustic;
    std::vector<Rgb> acc;
    std::vector<uint8_t> record;
    CoeffCodec::Scratch scratch;
    ChunkState(const PhotonMap& map, LookupParams lp, const ContribBins& bins, size_t recordBytes)
        : all(map, lp), caustic(map, causticParams(lp)), acc(bins.size()), record(recordBytes) {}
    static LookupParams causticParams(LookupParams lp) {
        lp.causticOnly = true;
        return lp;
    }
};

// The photons' primary indices replaced by their keys into the bins' few distinct shares,
// which an estimate's photons then find in the cache (through the primary, each photon
// cost a cache miss).
void keyPhotons(const PrimaryBins& pb, std::vector<Photon>& photons) {
    for (Photon& p : photons) p.primary = pb.key(p.primary);
}

// The binned contributions at photon p into st.acc (zeroed first), from every photon or,
// for a caustic estimate, from the caustic ones; the map's photons carry keyPhotons' keys.
void gather(const std::vector<PrimaryBins::Share>& shares, const Photon& p, bool causticEstimate,
            ChunkState& st) {
    std::fill(st.acc.begin(), st.acc.end(), Rgb{0, 0, 0});
    auto share = [&](std::span<const FoundPhoton> photons, double scale) {
        for (const FoundPhoton& f : photons) {
            const PrimaryBins::Share& sh = shares[f.primary];
            if (sh.slot < 0) continue;
            const auto flux = f.fluxRgb();
            const Rgb add = sh.of({flux[0] * scale, flux[1] * scale, flux[2] * scale});
            Rgb& a = st.acc[size_t(sh.slot)];
            for (int c = 0; c < 3; ++c) a[size_t(c)] += add[size_t(c)];
        }
    };
    (causticEstimate ? st.caustic : st.all).contribDensity(p.position(), p.normal(), share);
}

// The photons to precompute: a selection of all of them (estimates over every photon),
// then a selection of the caustic ones (estimates over caustic photons only): what
// rcontrib reads at hits of other rays than final-gather ones (its sensor points), as a
// contribution map's caustic photons (render/photon_mode.h). Returns the indices and the
// size of the first population.
std::pair<std::vector<uint64_t>, size_t> selectPhotons(const std::vector<Photon>& photons,
                                                       const PrecompContribSettings& s) {
    std::vector<uint64_t> sel = precompSelection(photons.size(), s.fraction, s.pass.seed);
    if (sel.empty())
        throw InputError("no precomputed contribution photons (-apP " + std::to_string(s.fraction) +
                         " of " + std::to_string(photons.size()) + " photons)");
    std::vector<uint64_t> caustic;
    for (uint64_t i = 0; i < photons.size(); ++i)
        if (photons[i].caustic()) caustic.push_back(i);
    const size_t all = sel.size();
    for (uint64_t k : precompSelection(caustic.size(), s.fraction, s.pass.seed + 1))
        sel.push_back(caustic[k]);
    sortAlongCurve(photons, sel.begin(), sel.begin() + std::ptrdiff_t(all));
    sortAlongCurve(photons, sel.begin() + std::ptrdiff_t(all), sel.end());
    return {std::move(sel), all};
}

std::vector<std::unique_ptr<CoeffWriter>> openWriters(const ContribBins& bins, uint64_t records,
                                                      const PrecompContribSettings& s) {
    std::vector<std::unique_ptr<CoeffWriter>> writers;
    for (size_t m = 0; m < bins.modifiers().size(); ++m) {
        CoeffInfo info{bins.modifiers()[m].name, bins.bins(m), s.compression, s.contributions,
                       records};
        writers.push_back(std::make_unique<CoeffWriter>(coeffFile(s.mapFile, info.modifier), info,
                                                        s.commandLine));
    }
    return writers;
}

// Record i of every modifier from st.acc; counts the empty bins into `zeros` and returns
// the sum of all bins.
Rgb writeRecords(uint64_t i, ChunkState& st, const ContribBins& bins,
                 const std::vector<std::unique_ptr<CoeffWriter>>& writers,
                 std::vector<std::atomic<uint64_t>>& zeros) {
    Rgb total{0, 0, 0};
    for (size_t m = 0; m < writers.size(); ++m) {
        const std::span<const Rgb> values(st.acc.data() + bins.offset(m), size_t(bins.bins(m)));
        uint64_t z = 0;
        for (const Rgb& v : values) {
            z += v[0] == 0 && v[1] == 0 && v[2] == 0;
            for (int c = 0; c < 3; ++c) total[size_t(c)] += v[size_t(c)];
        }
        zeros[m] += z;
        writers[m]->codec().encode(values, st.record.data(), st.scratch);
        writers[m]->write(i, st.record.data());
    }
    return total;
}

}  // namespace

PrecompContribResult precomputeContrib(std::vector<Photon> photons,
                                       const std::vector<PhotonPrimary>& primaries,
                                       const std::vector<PrimaryRay>& rays,
                                       const std::vector<ContribSource>& sources,
                                       const ContribBins& bins, const PrecompContribSettings& s) {
    RP_CHECK(rays.size() == primaries.size());
    checkModifiersNamed(sources, bins);
    const auto [sel, selectedAll] = selectPhotons(photons, s);
    // A plain copy for the lambda below: clang 14 cannot capture a structured binding.
    const auto nall = selectedAll;
    PrecompContribResult res;
    res.photons.resize(sel.size());
    for (size_t i = 0; i < sel.size(); ++i) res.photons[i] = photons[sel[i]];
    const auto writers = openWriters(bins, sel.size(), s);
    size_t recordBytes = 0;
    for (const auto& w : writers) recordBytes = std::max(recordBytes, w->codec().recordBytes());

    const PrimaryBins pb(bins, sources, s.contributions, primaries, rays, s.pass.threads);
    keyPhotons(pb, photons);
    PhotonMap map;
    tbb::task_arena arena(std::max(1, s.pass.threads));
    arena.execute([&] {
        map = PhotonMap::searchableFrom(PhotonMapType::Contrib, std::move(photons),
                                        s.pass.threads > 1);
    });
    LookupParams lp;
    lp.bandwidth = std::max(1, s.bandwidth);
    lp.gatherTolerance = 1;  // as rcontrib's contribution lookups
    std::vector<std::atomic<uint64_t>> zeros(writers.size());
    forEachPrecompChunk(sel.size(), s.pass, s.progress, [&](uint64_t i0, uint64_t i1) {
        // A fresh lookup per chunk: its adaptive radius depends on the chunk only.
        ChunkState st(map, lp, bins, recordBytes);
        for (uint64_t i = i0; i < i1; ++i) {
            Photon& p = res.photons[i];
            gather(pb.shares(), p, i >= nall, st);
            const Rgb total = writeRecords(i, st, bins, writers, zeros);
            p.setFlux(total[0], total[1], total[2]);
            p.setCaustic(i >= nall);
            p.setDiscr(0);
            p.primary = uint32_t(i);
        }
    });
    for (size_t m = 0; m < writers.size(); ++m) {
        writers[m]->commit(s.overwrite);
        res.emptyBins.push_back(double(zeros[m].load()) /
                                (double(sel.size()) * double(bins.bins(m))));
    }
    return res;
}

}  // namespace rp::pmap

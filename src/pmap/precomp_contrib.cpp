// Precomputed contribution photons (precomp_contrib.h).
#include "pmap/precomp_contrib.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <unordered_map>
#include <utility>

#include "pmap/contrib_coeffs.h"
#include "pmap/density.h"
#include "pmap/photon_map.h"
#include "pmap/precomp.h"
#include "util/dir_code.h"
#include "util/error.h"

namespace rp::pmap {

namespace {

// Per source, the tracked modifier its material names (-1: untracked).
std::vector<int> modifierOfSource(const std::vector<ContribSource>& sources,
                                  const ContribBins& bins) {
    std::unordered_map<std::string, int> byName;
    for (size_t m = 0; m < bins.modifiers().size(); ++m) byName[bins.modifiers()[m].name] = int(m);
    std::vector<bool> named(bins.modifiers().size(), false);
    std::vector<int> out;
    for (const ContribSource& s : sources) {
        auto it = byName.find(s.material);
        out.push_back(it != byName.end() ? it->second : -1);
        if (out.back() >= 0) named[size_t(out.back())] = true;
    }
    for (size_t m = 0; m < named.size(); ++m)
        if (!named[m])
            throw InputError("modifier '" + bins.modifiers()[m].name +
                             "' is not the material of a light source");
    return out;
}

// Where each primary's photons go: the index of their value (offset(m) + bin over all
// modifiers; -1: untracked or dropped), and the factor -V- divides by. A primary's bin
// depends on its ray alone, so it is evaluated once, not at every estimate that finds
// one of its photons.
struct PrimaryBins {
    std::vector<int32_t> slot;
    std::vector<Rgb> scale;
};

PrimaryBins binPrimaries(const std::vector<PhotonPrimary>& primaries,
                         const std::vector<PrimaryRay>& rays,
                         const std::vector<ContribSource>& sources, const std::vector<int>& modOf,
                         const ContribBins& bins, const PrecompContribSettings& s) {
    PrimaryBins pb;
    pb.slot.assign(primaries.size(), -1);
    pb.scale.assign(sources.size(), Rgb{1, 1, 1});
    for (size_t i = 0; i < sources.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double r = sources[i].radiance[size_t(c)];
            pb.scale[i][size_t(c)] = s.contributions ? 1 : r != 0 ? 1 / r : 0;
        }
    PassSettings quiet = s.pass;
    quiet.reportSeconds = 0;
    forEachPrecompChunk(primaries.size(), quiet, nullptr, [&](uint64_t i0, uint64_t i1) {
        ContribBins::Binner binner(bins);
        for (uint64_t i = i0; i < i1; ++i) {
            const int src = primaries[i].srcIdx;
            if (src < 0 || size_t(src) >= sources.size()) continue;
            const int m = modOf[size_t(src)];
            if (m < 0) continue;
            const PrimaryRay& r = rays[i];
            const std::array<double, 3> d = decodeDirection(r.dir);
            // rcontrib's binning of photons (render/rcontrib.cpp ContribTally::addPhotons).
            const Vec3 at =
                sources[size_t(src)].distant ? Vec3{} : Vec3{r.pos[0], r.pos[1], r.pos[2]};
            const int b = binner.bin(size_t(m), at, Vec3{d[0], d[1], d[2]});
            if (b >= 0) pb.slot[i] = int32_t(bins.offset(size_t(m)) + size_t(b));
        }
    });
    return pb;
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

// The binned contributions at photon p into st.acc (zeroed first), from every photon or,
// for a caustic estimate, from the caustic ones.
void gather(const PrimaryBins& pb, const std::vector<PhotonPrimary>& primaries, const Photon& p,
            bool causticEstimate, ChunkState& st) {
    std::fill(st.acc.begin(), st.acc.end(), Rgb{0, 0, 0});
    auto share = [&](const FoundPhoton& f, const std::array<double, 3>& v) {
        if (f.primary >= pb.slot.size() || pb.slot[f.primary] < 0) return;
        const Rgb& k = pb.scale[size_t(primaries[f.primary].srcIdx)];
        Rgb& a = st.acc[size_t(pb.slot[f.primary])];
        for (int c = 0; c < 3; ++c) a[size_t(c)] += v[size_t(c)] * k[size_t(c)];
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
    const std::vector<int> modOf = modifierOfSource(sources, bins);
    const auto [sel, selectedAll] = selectPhotons(photons, s);
    // A plain copy for the lambda below: clang 14 cannot capture a structured binding.
    const auto nall = selectedAll;
    PrecompContribResult res;
    res.photons.resize(sel.size());
    for (size_t i = 0; i < sel.size(); ++i) res.photons[i] = photons[sel[i]];
    const auto writers = openWriters(bins, sel.size(), s);
    size_t recordBytes = 0;
    for (const auto& w : writers) recordBytes = std::max(recordBytes, w->codec().recordBytes());

    PhotonMap map;
    tbb::task_arena arena(std::max(1, s.pass.threads));
    arena.execute([&] {
        map = PhotonMap::searchableFrom(PhotonMapType::Contrib, std::move(photons),
                                        s.pass.threads > 1);
    });
    LookupParams lp;
    lp.bandwidth = std::max(1, s.bandwidth);
    lp.gatherTolerance = 1;  // as rcontrib's contribution lookups
    const PrimaryBins pb = binPrimaries(primaries, rays, sources, modOf, bins, s);
    std::vector<std::atomic<uint64_t>> zeros(writers.size());
    forEachPrecompChunk(sel.size(), s.pass, s.progress, [&](uint64_t i0, uint64_t i1) {
        // A fresh lookup per chunk: its adaptive radius depends on the chunk only.
        ChunkState st(map, lp, bins, recordBytes);
        for (uint64_t i = i0; i < i1; ++i) {
            Photon& p = res.photons[i];
            gather(pb, primaries, p, i >= nall, st);
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

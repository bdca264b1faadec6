// Statistics, kd-tree and file of one map (see map_output.h).
#include "pmap/map_output.h"

#include <vector>

#include "pmap/kdtree.h"
#include "pmap/kdtree_external.h"
#include "pmap/map_file_writer.h"

namespace rp::pmap {

namespace {

// Photons per read of a spilled file for the statistics (1.5 MB).
constexpr size_t kStatsBlock = size_t{1} << 16;

PhotonMapFileInfo infoOf(const MapOutput& out, const PhotonMapStats& stats) {
    PhotonMapFileInfo info;
    info.type = out.type;
    info.stats = stats;
    info.primaries = out.primaries;
    info.primaryRays = out.primaryRays;
    info.bands = out.bands;
    return info;
}

// The cell of the whole tree: the photons' bounding box.
void cellOf(const PhotonMapStats& s, float lo[3], float hi[3]) {
    for (int a = 0; a < 3; ++a) {
        lo[a] = s.bboxMin[size_t(a)];
        hi[a] = s.bboxMax[size_t(a)];
    }
}

// computeStats over a spilled file: two passes, in collection order as in memory.
PhotonMapStats spilledStats(const TempFile& f, uint64_t n) {
    StatsAccumulator acc;
    std::vector<Photon> block(kStatsBlock);
    for (int pass = 0; pass < 2; ++pass)
        for (uint64_t i = 0; i < n; i += kStatsBlock) {
            const size_t m = size_t(std::min<uint64_t>(kStatsBlock, n - i));
            f.readAt(i * sizeof(Photon), block.data(), m * sizeof(Photon));
            const std::span<const Photon> b(block.data(), m);
            pass == 0 ? acc.addFirst(b) : acc.addSecond(b);
        }
    return acc.stats();
}

}  // namespace

uint64_t saveMapInMemory(std::span<Photon> photons, const MapOutput& out) {
    const PhotonMapStats stats = computeStats(photons);
    PhotonMapFileWriter writer(out.file, infoOf(out, stats), out.commandLine, out.overwrite);
    float lo[3], hi[3];
    cellOf(stats, lo, hi);
    buildKdTreeInOrder(photons, lo, hi, out.parallel);
    writeSubtreeHeap(photons, 1, writer, out.parallel);
    writer.commit();
    return photons.size();
}

uint64_t saveSpilledMap(TempFile spilled, uint64_t n, uint64_t inCorePhotons,
                        const MapOutput& out) {
    const PhotonMapStats stats = spilledStats(spilled, n);
    PhotonMapFileWriter writer(out.file, infoOf(out, stats), out.commandLine, out.overwrite);
    float lo[3], hi[3];
    cellOf(stats, lo, hi);
    const ExternalBuildSettings settings{inCorePhotons, folderOf(out.file), out.file, out.parallel};
    buildKdTreeExternal(std::move(spilled), n, lo, hi, writer, settings);
    writer.commit();
    return n;
}

}  // namespace rp::pmap

// Map files written by heap node: from the in-core layout and from the external build,
// byte for byte the file PhotonMap::save writes for the same photons; statistics summed in
// blocks equal computeStats; an existing file is kept without overwrite.
#include "pmap/map_file_writer.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "pmap/kdtree.h"
#include "pmap/pmap_test_util.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

std::vector<Photon> photonsOnPlanes(size_t n) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i) {
        Vec3 p(u(rng) * 5, u(rng) * 3, i % 3 == 0 ? 0.0 : u(rng) * 2.5);
        v.push_back(makePhoton(p, Vec3(0, 0, 1), {u(rng), u(rng), u(rng)}, i % 4 == 0));
    }
    return v;
}

TEST(StatsAccumulator, BlocksGiveComputeStats) {
    const auto photons = photonsOnPlanes(10007);
    StatsAccumulator acc;
    for (size_t i = 0; i < photons.size(); i += 1000)
        acc.addFirst(std::span(photons).subspan(i, std::min<size_t>(1000, photons.size() - i)));
    for (size_t i = 0; i < photons.size(); i += 333)
        acc.addSecond(std::span(photons).subspan(i, std::min<size_t>(333, photons.size() - i)));
    EXPECT_EQ(acc.stats(), computeStats(photons));
    EXPECT_EQ(StatsAccumulator().stats(), computeStats({}));
}

TEST(PhotonMapFileWriter, SameBytesAsSave) {
    TempDir dir;
    const auto photons = photonsOnPlanes(30001);
    PhotonMap(PhotonMapType::Caustic, photons).save(dir.file("ref.pm"), "mkpmap x", false);
    const std::string ref = test::slurp(dir.file("ref.pm"));
    PhotonMapFileInfo info{PhotonMapType::Caustic, computeStats(photons), {}, {}};
    {
        PhotonMapFileWriter w(dir.file("in.pm"), info, "mkpmap x", false);
        std::vector<Photon> tree = photons;
        buildKdTreeInOrder(tree, true);
        writeSubtreeHeap(tree, 1, w, true);
        w.commit();
    }
    EXPECT_TRUE(test::slurp(dir.file("in.pm")) == ref);
    {
        PhotonMapFileWriter w(dir.file("ext.pm"), info, "mkpmap x", false);
        TempFile f(dir.path().string(), "ext.pm");
        f.append(photons.data(), photons.size() * sizeof(Photon));
        const auto& s = info.stats;
        const float lo[3] = {s.bboxMin[0], s.bboxMin[1], s.bboxMin[2]};
        const float hi[3] = {s.bboxMax[0], s.bboxMax[1], s.bboxMax[2]};
        buildKdTreeExternal(std::move(f), photons.size(), lo, hi, w,
                            {1000, dir.path().string(), "ext.pm", true});
        w.commit();
    }
    EXPECT_TRUE(test::slurp(dir.file("ext.pm")) == ref);
    EXPECT_EQ(dir.count(), 3u);  // ref, in, ext: no temporary file left
}

TEST(PhotonMapFileWriter, KeepsAnExistingFileWithoutOverwrite) {
    TempDir dir;
    const auto photons = photonsOnPlanes(10);
    PhotonMap(PhotonMapType::Global, photons).save(dir.file("g.pm"), "", false);
    const std::string before = test::slurp(dir.file("g.pm"));
    PhotonMapFileInfo info{PhotonMapType::Global, computeStats(photons), {}, {}};
    EXPECT_NE(test::errorOf([&] {
                  PhotonMapFileWriter(dir.file("g.pm"), info, "", false);
              }).find("use -fo to overwrite"),
              std::string::npos);
    info.stats.numPhotons = 0;
    EXPECT_NE(test::errorOf([&] {
                  PhotonMapFileWriter(dir.file("e.pm"), info, "", true);
              }).find("empty photon map"),
              std::string::npos);
    EXPECT_EQ(test::slurp(dir.file("g.pm")), before);
    EXPECT_EQ(dir.count(), 1u);
}

}  // namespace
}  // namespace rp::pmap

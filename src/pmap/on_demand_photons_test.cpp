// Caustic maps read on demand: the same searches as the map read whole, every photon the
// walk reaches checked, and the rest checked when all of it is needed.
#include "pmap/on_demand_photons.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "pmap/photon_map.h"
#include "util/error.h"
#include "pmap/pmap_test_util.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

namespace fs = std::filesystem;
using test::errorOf;
using test::slurp;

PhotonMap randomMap(PhotonMapType type, size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i)
        v.push_back(makePhoton(Vec3(u(rng), u(rng), 0.1 * u(rng)), normalize(Vec3(u(rng), u(rng), 4)),
                               {std::abs(u(rng)) * 1e-3, 1e-3, 1e-4}, true));
    return PhotonMap(type, std::move(v));
}



PhotonMap loadOnDemand(const std::string& f) {
    return PhotonMap::load(f, PhotonMap::TreeOrder::Unchecked, /*causticOnDemand=*/true);
}

TEST(OnDemandPhotons, SameSearchesAsTheMapReadWhole) {
    TempDir dir;
    const std::string f = dir.file("c.pm");
    randomMap(PhotonMapType::Caustic, 20000, 1).save(f, "", false);
    const PhotonMap whole = PhotonMap::load(f);
    const PhotonMap lazy = loadOnDemand(f);
    EXPECT_EQ(lazy.size(), whole.size());
    EXPECT_EQ(lazy.stats(), whole.stats());

    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-3.5, 3.5);
    std::vector<PhotonHit> a(51), b(51);
    for (int i = 0; i < 300; ++i) {
        const Vec3 q(u(rng), u(rng), 0.1 * u(rng));
        const Vec3 n = normalize(Vec3(u(rng), u(rng), i % 3 == 0 ? -4 : 4));
        const size_t k = std::array<size_t, 3>{1, 11, 51}[i % 3];
        const float r2 = i % 2 ? 0.05f : 1e30f;
        const Vec3* normal = i % 5 == 0 ? nullptr : &n;
        const size_t na = whole.findNearest(q, normal, r2, {a.data(), k});
        const size_t nb = lazy.findNearest(q, normal, r2, {b.data(), k});
        ASSERT_EQ(na, nb) << "query " << i;
        for (size_t j = 0; j < na; ++j) {
            ASSERT_EQ(a[j].index, b[j].index) << "query " << i;
            ASSERT_EQ(a[j].dist2, b[j].dist2);
            EXPECT_EQ(lazy.searchedPhoton(b[j].index), whole.photons()[a[j].index]);
        }
    }
    // Reading the rest gives the whole map, and saving it the same file.
    ASSERT_EQ(lazy.photons().size(), whole.photons().size());
    for (size_t i = 0; i < whole.size(); ++i) ASSERT_EQ(lazy.photons()[i], whole.photons()[i]);
    const std::string again = dir.file("again.pm");
    loadOnDemand(f).save(again, "", false);
    EXPECT_EQ(slurp(again), slurp(f));
}

TEST(OnDemandPhotons, OnlyCausticMapsAreReadOnDemand) {
    TempDir dir;
    const std::string f = dir.file("g.pm");
    randomMap(PhotonMapType::Global, 500, 3).save(f, "", false);
    // A global map is read whole: a bad record is found at load, before any search.
    std::string d = slurp(f);
    d[d.size() - 27 * 100 + 26] = 3;  // split axis 3 in photon 400's flag byte
    std::ofstream(f, std::ios::binary) << d;
    EXPECT_NE(errorOf([&] { loadOnDemand(f); }).find("photon 400 has split axis 3"),
              std::string::npos);
}

class OnDemandBadFile : public ::testing::Test {
protected:
    void SetUp() override {
        f_ = dir_.file("c.pm");
        randomMap(PhotonMapType::Caustic, 1000, 4).save(f_, "", false);
        data_ = slurp(f_);
        records_ = data_.size() - 1000 * 27;
    }
    void write() { std::ofstream(f_, std::ios::binary) << data_; }
    // The walk for a query at the root photon visits the root and its subtree's first path.
    std::string searchError(const PhotonMap& m) {
        std::vector<PhotonHit> hits(10);
        const Vec3 up(0, 0, 1);
        return errorOf([&] { m.findNearest(Vec3(0, 0, 0), &up, 1e30f, hits); });
    }
    TempDir dir_;
    std::string f_, data_;
    size_t records_ = 0;
};

TEST_F(OnDemandBadFile, SwappedRecordsFailTheSearchThatReachesThem) {
    // Exchange the root with its left child: the child now lies beyond the root's split.
    std::string a = data_.substr(records_, 27), b = data_.substr(records_ + 27, 27);
    data_.replace(records_, 27, b);
    data_.replace(records_ + 27, 27, a);
    write();
    const PhotonMap m = loadOnDemand(f_);  // header and size are fine
    const std::string msg = searchError(m);
    EXPECT_NE(msg.find(f_), std::string::npos) << msg;
    EXPECT_NE(msg.find("not a valid kd-tree"), std::string::npos) << msg;
    EXPECT_NE(errorOf([&] { m.photons(); }).find("wrong side of an ancestor's split"),
              std::string::npos);
}

TEST_F(OnDemandBadFile, BadRecordsFailTheSearchOrTheFullRead) {
    data_[records_ + 26] = 3;  // the root's split axis
    write();
    EXPECT_NE(searchError(loadOnDemand(f_)).find("photon 0 has split axis 3"), std::string::npos);
    // A bad last photon may escape a search but not the full read.
    data_ = slurp(f_);
    data_[records_ + 26] = 0;
    data_[records_ + 999 * 27 + 26] = 3;
    write();
    const PhotonMap m = loadOnDemand(f_);
    EXPECT_NE(errorOf([&] { m.photons(); }).find("photon 999 has split axis 3"), std::string::npos);
    // ... and the failure is not remembered as done: asking again fails again.
    EXPECT_NE(errorOf([&] { m.photons(); }).find("photon 999"), std::string::npos);
}

TEST_F(OnDemandBadFile, FileTruncatedAfterOpening) {
    const PhotonMap m = loadOnDemand(f_);
    fs::resize_file(f_, records_ + 10 * 27);  // as a writer truncating it in place would
    const std::string msg = searchError(m);
    EXPECT_NE(msg.find("truncated photon map"), std::string::npos) << msg;
    EXPECT_NE(msg.find(f_), std::string::npos) << msg;
}

}  // namespace
}  // namespace rp::pmap

// Damaged map files: out of core, a record out of place, a bad record and a file
// truncated after opening are each reported, naming the file, by the search that reads
// them; in core, the same damage is refused at opening. The fixture's maps are as
// RADIANCE writes them (no checksums); radphoton's own maps also carry record checksums,
// which catch what the order and record checks cannot (a changed flux). (Answers against
// brute force are in photon_store_test.cpp.)
#include "pmap/ooc_store.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "pmap/photon_map.h"
#include "pmap/pmap_test_util.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

namespace fs = std::filesystem;
using test::errorOf;
using test::slurp;

PhotonMap randomMap(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i)
        v.push_back(makePhoton(Vec3(u(rng), u(rng), 0.1 * u(rng)),
                               normalize(Vec3(u(rng), u(rng), 4)),
                               {std::abs(u(rng)) * 1e-3, 1e-3, 1e-4}, true));
    return PhotonMap(PhotonMapType::Caustic, std::move(v));
}

// Out of core with 7 photons resident (3 tree levels) and pages of 8.
PhotonMap openOutOfCore(const std::string& f) {
    StoreOptions o;
    o.cachePhotons = 7;
    o.pageSize = 4;
    o.bandwidth = 2;
    PhotonMap m = PhotonMap::open(f, o);
    EXPECT_NE(m.store().describe().find("out of core"), std::string::npos);
    return m;
}

class OutOfCoreBadFile : public ::testing::Test {
protected:
    void SetUp() override {
        f_ = dir_.file("c.pm");
        randomMap(1000, 4).save(f_, "", false);
        withChecksums_ = slurp(f_);
        data_ = test::withoutChecksums(withChecksums_, 1000);
        write();
        records_ = data_.size() - 1000 * 27;
    }
    void write() { std::ofstream(f_, std::ios::binary) << data_; }
    void swapRecords(size_t i, size_t j) {
        const std::string a = data_.substr(records_ + 27 * i, 27);
        const std::string b = data_.substr(records_ + 27 * j, 27);
        data_.replace(records_ + 27 * i, 27, b);
        data_.replace(records_ + 27 * j, 27, a);
    }
    // Searches all over the map until one fails; errorOf's "(no InputError)" if none does.
    std::string searchError(const PhotonMap& m) {
        auto cursor = m.store().makeCursor();
        std::vector<FoundPhoton> out;
        const Vec3 up(0, 0, 1);
        for (int i = 0; i < 400; ++i) {
            const Vec3 q(-3 + 0.3 * (i % 20), -3 + 0.3 * (i / 20), 0);
            const std::string e = errorOf([&] {
                m.store().findNearest(*cursor, PhotonQuery{q, &up, false, 1e30f, 10}, out);
            });
            if (e != "(no InputError)") return e;
        }
        return "(no InputError)";
    }
    TempDir dir_;
    std::string f_, data_, withChecksums_;
    size_t records_ = 0;
};

TEST_F(OutOfCoreBadFile, IntactFileSearchesWithoutError) {
    EXPECT_EQ(searchError(openOutOfCore(f_)), "(no InputError)");
}

TEST_F(OutOfCoreBadFile, SwappedRecordsFailTheSearchThatReachesThem) {
    swapRecords(1, 2);  // resident: the root's children change sides
    write();
    std::string msg = searchError(openOutOfCore(f_));
    EXPECT_NE(msg.find(f_), std::string::npos) << msg;
    EXPECT_NE(msg.find("not a valid kd-tree"), std::string::npos) << msg;
    data_ = slurp(f_);
    swapRecords(1, 2);
    swapRecords(300, 600);  // in pages
    write();
    msg = searchError(openOutOfCore(f_));
    EXPECT_NE(msg.find("not a valid kd-tree"), std::string::npos) << msg;
}

// In core the whole map is read at opening, its records and its order checked then.
TEST_F(OutOfCoreBadFile, InCoreOpeningRefusesWhatOutOfCoreSearchesRefuse) {
    swapRecords(300, 600);
    write();
    const std::string msg = errorOf([&] { PhotonMap::open(f_, StoreOptions{}); });
    EXPECT_NE(msg.find(f_), std::string::npos) << msg;
    EXPECT_NE(msg.find("not a valid kd-tree"), std::string::npos) << msg;
    data_ = slurp(f_);
    swapRecords(300, 600);
    data_[records_ + 500 * 27 + 26] = 3;
    write();
    EXPECT_NE(
        errorOf([&] { PhotonMap::open(f_, StoreOptions{}); }).find("photon 500 has split axis 3"),
        std::string::npos);
}

TEST_F(OutOfCoreBadFile, BadRecordsFailAtOpeningOrInTheSearch) {
    data_[records_ + 26] = 3;  // the root's split axis: resident, read at opening
    write();
    EXPECT_NE(errorOf([&] { openOutOfCore(f_); }).find("photon 0 has split axis 3"),
              std::string::npos);
    data_[records_ + 26] = 0;
    data_[records_ + 500 * 27 + 26] = 3;  // paged
    write();
    const std::string msg = searchError(openOutOfCore(f_));
    EXPECT_NE(msg.find("photon 500 has split axis 3"), std::string::npos) << msg;
    EXPECT_NE(msg.find(f_), std::string::npos) << msg;
}

TEST_F(OutOfCoreBadFile, FileTruncatedAfterOpening) {
    const PhotonMap m = openOutOfCore(f_);
    fs::resize_file(f_, records_ + 10 * 27);  // as a writer truncating it in place would
    const std::string msg = searchError(m);
    EXPECT_NE(msg.find("truncated photon map"), std::string::npos) << msg;
    EXPECT_NE(msg.find(f_), std::string::npos) << msg;
}

// Our own maps: a flipped bit in a photon's flux keeps the tree valid; the checksum of its
// block finds it, in core at opening and out of core in the search that reads the block.
TEST_F(OutOfCoreBadFile, ChecksumsFindAChangedFlux) {
    data_ = withChecksums_;
    write();
    EXPECT_EQ(searchError(openOutOfCore(f_)), "(no InputError)");
    EXPECT_EQ(errorOf([&] { PhotonMap::open(f_, StoreOptions{}); }), "(no InputError)");
    const size_t records = data_.size() - 4 - 1000 * 27;
    data_[records + 700 * 27 + 13] ^= 1;  // photon 700's flux mantissa
    write();
    const std::string core = errorOf([&] { PhotonMap::open(f_, StoreOptions{}); });
    EXPECT_NE(core.find("damaged photon map: photons 0 to 999 do not match their checksum"),
              std::string::npos)
        << core;
    EXPECT_NE(core.find(f_), std::string::npos) << core;
    // Out of core: the block holding the resident top is checked at opening (this map is
    // one block); the others when a search first reads them.
    const std::string ooc = errorOf([&] {
        const std::string e = searchError(openOutOfCore(f_));
        if (e != "(no InputError)") throw InputError(e);
    });
    EXPECT_NE(ooc.find("do not match their checksum"), std::string::npos) << ooc;
    // Without the checksums (as RADIANCE would write it) the same map opens.
    data_ = test::withoutChecksums(data_, 1000);
    write();
    EXPECT_EQ(errorOf([&] { PhotonMap::open(f_, StoreOptions{}); }), "(no InputError)");
}

// A map of several blocks: opening reads and checks the block of the resident top only;
// the search that first reads the damaged block reports it.
TEST_F(OutOfCoreBadFile, ChecksumsCheckedAsBlocksAreRead) {
    randomMap(10000, 5).save(f_, "", true);
    data_ = slurp(f_);
    const size_t records = data_.size() - 4 * 3 - 10000 * 27;
    data_[records + 9000 * 27 + 13] ^= 1;  // block 2
    write();
    const PhotonMap m = openOutOfCore(f_);
    const std::string msg = searchError(m);
    EXPECT_NE(msg.find("damaged photon map: photons 8192 to 9999 do not match their checksum"),
              std::string::npos)
        << msg;
}

// A damaged checksum, or a file cut within the checksums, is an error too.
TEST_F(OutOfCoreBadFile, DamagedOrMissingChecksums) {
    data_ = withChecksums_;
    data_.back() ^= 0x40;
    write();
    EXPECT_NE(errorOf([&] { PhotonMap::open(f_, StoreOptions{}); }).find("checksum"),
              std::string::npos);
    data_.pop_back();
    write();
    EXPECT_NE(errorOf([&] { PhotonMap::open(f_, StoreOptions{}); }).find("size mismatch"),
              std::string::npos);
}

}  // namespace
}  // namespace rp::pmap

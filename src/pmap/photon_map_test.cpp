// Photon map statistics, header text, exact file bytes, round trips and bad files.
#include "pmap/photon_map.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <regex>
#include <sstream>

#include "pmap/pmap_test_util.h"
#include "pmap/record_checksums.h"
#include "util/dir_code.h"
#include "util/error.h"
#include "util/portable_io.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {

using portable::putFlt;
using portable::putInt;
namespace {

namespace fs = std::filesystem;
using test::errorOf;
using test::slurp;

void spit(const std::string& path, const std::string& data) {
    std::ofstream(path, std::ios::binary) << data;
}

PhotonMap randomMap(PhotonMapType type, size_t n, uint32_t seed, size_t numPrimaries = 0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-3, 3);
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i) {
        Photon p = makePhoton(Vec3(u(rng), u(rng), u(rng)), normalize(Vec3(u(rng), u(rng), 1)),
                              {std::abs(u(rng)) * 1e-3, std::abs(u(rng)) * 1e-3, 1e-4}, rng() & 1,
                              numPrimaries ? static_cast<uint32_t>(rng() % numPrimaries) : 0);
        p.flags |= static_cast<uint8_t>((rng() % 32) << Photon::kProcShift);  // keep proc bits
        v.push_back(p);
    }
    std::vector<PhotonPrimary> prims(numPrimaries);
    for (size_t i = 0; i < numPrimaries; ++i) prims[i].srcIdx = static_cast<int16_t>(i % 7 - 1);
    return PhotonMap(type, std::move(v), std::move(prims));
}

TEST(PhotonMap, TypeNamesAndFormats) {
    EXPECT_STREQ(photonMapTypeName(PhotonMapType::PreComp), "PreComp");
    EXPECT_EQ(photonMapTypeFromName("Contrib"), PhotonMapType::Contrib);
    EXPECT_FALSE(photonMapTypeFromName("global").has_value());
    EXPECT_EQ(photonMapFormat(PhotonMapType::Caustic), "Radiance_Caustic_kdT_Photon_Map");
}

// Two photons, values worked out by hand: flux (0.5, 0.25, 0.125) packs to RGBE
// (128, 64, 32, 128), which decodes to (128.5, 64.5, 32.5) / 256.
PhotonMap twoPhotonMap() {
    std::vector<Photon> v = {makePhoton(Vec3(-1e-5, 0, 0), Vec3(0, 0, 1), {0.5, 0.25, 0.125}),
                             makePhoton(Vec3(1, 2, 3), Vec3(0, 0, 1), {0.5, 0.25, 0.125})};
    return PhotonMap(PhotonMapType::Global, v);
}

TEST(PhotonMap, StatsAndHeaderLines) {
    PhotonMap m = twoPhotonMap();
    EXPECT_EQ(m.photons()[0].flux, (Colr{128, 64, 32, 128}));
    const Header h = m.fileHeader("mkpmap -apg x.pm 2 scene.oct");
    const std::vector<std::string> want = {
        "mkpmap -apg x.pm 2 scene.oct",
        "NumPhotons\t= 2",
        "AvgFlux\t\t= [5.02e-01, 2.52e-01, 1.27e-01]",
        "Bbox\t\t= [-0.000, 0.000, 0.000] [1.000, 2.000, 3.000]",
        "CoG\t\t= [0.500, 1.000, 1.500]",
        "MaxDist^2\t= 3.500",  // mean squared distance: (0.25 + 1 + 2.25) each
        "FORMAT=Radiance_Global_kdT_Photon_Map",
        "VERSION=3.1k"};
    EXPECT_EQ(h.lines, want);
}

// A spectral map set's files (mkpmap -cs): each names its sampling and bands, and is read
// only by a rendering of the same pass.
TEST(PhotonMap, SpectralPassFilesNameTheirBands) {
    const spectral::Sampling s = spectral::makeSampling(7, 400, 700)->sampling;
    const std::vector<spectral::Pass> passes = spectral::passesOf(s);
    ASSERT_EQ(passes.size(), 3u);
    EXPECT_EQ(spectral::passFile("g.pm", passes[0]), "g.pm");
    EXPECT_EQ(spectral::passFile("g.pm", passes[1]), "g.pm.3-5");
    EXPECT_EQ(spectral::passFile("g.pm", passes[2]), "g.pm.6-6");
    EXPECT_EQ(spectral::passFile("g.pm", spectral::passesOf(spectral::Sampling{})[0]), "g.pm");

    const std::string file = "g.pm.3-5";
    PhotonMapFileInfo info = twoPhotonMap().fileInfo();
    info.bands = mapBandsOf(passes[1]);
    const Header h = photonMapFileHeader(info, "mkpmap -cs 7");
    const std::vector<std::string> spectralLines(h.lines.end() - 5, h.lines.end() - 2);
    EXPECT_EQ(spectralLines, (std::vector<std::string>{
                                 "NCOMP=7", "WAVELENGTH_SPLITS= 700 588 480 400", "BANDS= 3 5"}));
    EXPECT_NO_THROW(checkMapBands(mapBandsOf(passes[1]), passes[1], file));
    EXPECT_NO_THROW(checkMapBands(std::nullopt, spectral::passesOf(spectral::Sampling{})[0], file));
    EXPECT_THROW(checkMapBands(mapBandsOf(passes[1]), passes[2], file), InputError);
    EXPECT_THROW(checkMapBands(std::nullopt, passes[0], file), InputError);
    EXPECT_THROW(
        checkMapBands(mapBandsOf(passes[0]), spectral::passesOf(spectral::Sampling{})[0], file),
        InputError);
}

// The getinfo output of RADIANCE 5.4's own maps: our header has the same lines, in the same
// order and the same printf formats.
TEST(PhotonMap, HeaderMatchesRadianceSamples) {
    const std::vector<std::regex> patterns = {
        std::regex("mkpmap .*"),
        std::regex("NumPhotons\t= [0-9]+"),
        std::regex("AvgFlux\t\t= \\[-?[0-9]\\.[0-9]{2}e[-+][0-9]{2}(, "
                   "-?[0-9]\\.[0-9]{2}e[-+][0-9]{2}){2}\\]"),
        std::regex("Bbox\t\t= \\[-?[0-9]+\\.[0-9]{3}(, -?[0-9]+\\.[0-9]{3}){2}\\] "
                   "\\[-?[0-9]+\\.[0-9]{3}(, -?[0-9]+\\.[0-9]{3}){2}\\]"),
        std::regex("CoG\t\t= \\[-?[0-9]+\\.[0-9]{3}(, -?[0-9]+\\.[0-9]{3}){2}\\]"),
        std::regex("MaxDist\\^2\t= [0-9]+\\.[0-9]{3}"),
        std::regex("FORMAT=Radiance_(Global|Caustic)_kdT_Photon_Map"),
        std::regex("VERSION=3\\.1k")};
    RP_REQUIRE_SHARED("validation/radiance-maps");
    const std::string dir = std::string(RP_SHARED_DIR) + "/validation/radiance-maps/";
    for (const char* name : {"cornell_caustic_50k", "cornell_global_50k", "furnace_global_50k"}) {
        std::ifstream in(dir + name + ".header.txt");
        ASSERT_TRUE(in) << dir << name << ".header.txt";
        std::string line;
        std::getline(in, line);  // "<file>:"
        std::vector<std::string> lines;
        while (std::getline(in, line)) lines.push_back(line.substr(1));  // getinfo's tab
        ASSERT_EQ(lines.front(), "#?RADIANCE");
        ASSERT_EQ(lines.back(), "");
        lines = std::vector<std::string>(lines.begin() + 1, lines.end() - 1);
        PhotonMapType type = std::string(name).find("caustic") != std::string::npos
                                 ? PhotonMapType::Caustic
                                 : PhotonMapType::Global;
        const auto ours = randomMap(type, 100, 1).fileHeader(lines[0]).lines;
        ASSERT_EQ(lines.size(), patterns.size()) << name;
        ASSERT_EQ(ours.size(), patterns.size()) << name;
        for (size_t i = 0; i < patterns.size(); ++i) {
            EXPECT_TRUE(std::regex_match(lines[i], patterns[i])) << name << ": " << lines[i];
            EXPECT_TRUE(std::regex_match(ours[i], patterns[i])) << name << ": " << ours[i];
        }
        EXPECT_EQ(ours[0], lines[0]);
        EXPECT_EQ(ours[6], lines[6]);  // FORMAT
        EXPECT_EQ(ours[7], lines[7]);  // VERSION
    }
}

// The binary part of a one-photon map, byte by byte.
TEST(PhotonMap, ExactFileBytes) {
    std::vector<Photon> v = {
        makePhoton(Vec3(1, -1, 0.5), Vec3(0, 0, 1), {0.5, 0.25, 0.125}, /*caustic=*/true)};
    PhotonMap m(PhotonMapType::Caustic, v);
    std::ostringstream out;
    m.write(out, "");
    const std::string file = out.str();
    const std::string head = "#?RADIANCE\n";
    ASSERT_EQ(file.compare(0, head.size(), head), 0);
    // Our maps end their header with the record checksums' line (record_checksums.h).
    const size_t bin = file.find("VERSION=3.1k\nRP_CRC32=4096\n\n");
    ASSERT_NE(bin, std::string::npos);
    const std::string withCrc = file.substr(bin + std::strlen("VERSION=3.1k\nRP_CRC32=4096\n\n"));
    ASSERT_GE(withCrc.size(), 4u);
    const std::string b = withCrc.substr(0, withCrc.size() - 4);

    auto flt = [](double x) {
        std::string s;
        putFlt(s, x);
        return s;
    };
    std::string want("3.1k\0", 5);
    want += std::string("\0\0\0\0\0\0\0\x01", 8);                           // numPhotons, 8 bytes
    for (double f : {128.5 / 256, 64.5 / 256, 32.5 / 256}) want += flt(f);  // avg flux
    for (double x : {1.0, 1.0, -1.0, -1.0, 0.5, 0.5}) want += flt(x);       // min0,max0,min1,...
    for (double x : {1.0, -1.0, 0.5}) want += flt(x);                       // CoG
    want += std::string(5, '\0');                                           // CoGdist = 0
    want += std::string(4, '\0');                                           // no primaries
    // Photon record: pos 1, -1, 0.5 (see portable_io_test), norm (0,0,127), RGBE,
    // primary 0, flags = discr 2 (all extents 0: RADIANCE's tie rule picks z) | caustic 4.
    want += std::string("\x3f\xff\xff\xff\x01\xc0\x00\x00\x01\x01\x3f\xff\xff\xff\x00", 15);
    want += std::string("\x00\x00\x7f", 3);
    want += std::string("\x80\x40\x20\x80", 4);
    want += std::string("\x00\x00\x00\x00", 4);
    want += std::string("\x06", 1);
    EXPECT_EQ(b.size(), 5u + 8 + 15 + 30 + 15 + 5 + 4 + 27);
    EXPECT_EQ(b, want);
    // Then the one block's CRC-32, most significant byte first.
    const uint32_t crc =
        recordsChecksum(reinterpret_cast<const unsigned char*>(want.data() + want.size() - 27), 27);
    const std::string tail = withCrc.substr(withCrc.size() - 4);
    EXPECT_EQ(uint32_t(uint8_t(tail[0])) << 24 | uint32_t(uint8_t(tail[1])) << 16 |
                  uint32_t(uint8_t(tail[2])) << 8 | uint8_t(tail[3]),
              crc);
}

void expectSameMap(const PhotonMap& a, const PhotonMap& b) {
    EXPECT_EQ(a.type(), b.type());
    EXPECT_EQ(a.stats(), b.stats());
    EXPECT_EQ(a.primaries(), b.primaries());
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.photons().data(), b.photons().data(), a.size() * sizeof(Photon)), 0);
}

TEST(PhotonMap, RoundTripIsBitExact) {
    TempDir dir;
    for (auto type : {PhotonMapType::Global, PhotonMapType::Caustic, PhotonMapType::Volume,
                      PhotonMapType::Contrib}) {
        const size_t prims = type == PhotonMapType::Contrib ? 300 : 0;
        PhotonMap m = randomMap(type, 20000, 3, prims);
        const std::string f = dir.file(std::string(photonMapTypeName(type)) + ".pm");
        m.save(f, "mkpmap test", false);
        PhotonMap r = PhotonMap::load(f);
        expectSameMap(m, r);
        EXPECT_EQ(r.stats().numPhotons, 20000u);
        // Writing what we read reproduces the file byte for byte.
        const std::string again = dir.file("again.pm");
        r.save(again, "mkpmap test", false);
        EXPECT_EQ(slurp(again), slurp(f));
        fs::remove(again);
        if (prims) {
            EXPECT_NE(slurp(f).find("\n300 primary rays\n"), std::string::npos);
        }
    }
    EXPECT_EQ(dir.count(), 4u);  // no temporary files left behind
}

TEST(PhotonMap, PrimaryRaysRoundTripAsVersion31kPD) {
    // RADIANCE's PMAP_CBDM build (pmapio.c): VERSION=3.1kPD, each primary 21 bytes:
    // srcIdx (2), direction code (4), position (3 portable floats).
    TempDir dir;
    PhotonMap m = randomMap(PhotonMapType::Contrib, 5000, 5, 200);
    std::vector<PrimaryRay> rays(200);
    for (size_t i = 0; i < rays.size(); ++i) {
        rays[i].pos = {float(i) * 0.25f, -1.5f, 2.75f};
        rays[i].dir = encodeDirection({0.6, 0, -0.8});
    }
    m.setPrimaryRays(rays);
    const std::string f = dir.file("pd.pm");
    m.save(f, "mkpmap test", false);
    const std::string bytes = slurp(f);
    EXPECT_NE(bytes.find("\nVERSION=3.1kPD\n"), std::string::npos);
    EXPECT_NE(bytes.find(std::string("3.1kPD\0", 7)), std::string::npos);
    PhotonMap r = PhotonMap::load(f);
    expectSameMap(m, r);
    EXPECT_EQ(r.primaryRays(), rays);
    // 21 bytes per primary instead of 2, and 2 more in each version string.
    PhotonMap plain = randomMap(PhotonMapType::Contrib, 5000, 5, 200);
    plain.save(dir.file("plain.pm"), "mkpmap test", false);
    EXPECT_EQ(bytes.size(), slurp(dir.file("plain.pm")).size() + 200 * 19 + 4);
}

TEST(PhotonMap, RefusesToOverwrite) {
    TempDir dir;
    const std::string f = dir.file("g.pm");
    PhotonMap m = randomMap(PhotonMapType::Global, 100, 4);
    m.save(f, "", false);
    const std::string msg = errorOf([&] { m.save(f, "", false); });
    EXPECT_NE(msg.find(f), std::string::npos) << msg;
    EXPECT_NE(msg.find("-fo"), std::string::npos) << msg;
    PhotonMap other = randomMap(PhotonMapType::Global, 50, 5);
    other.save(f, "", true);
    EXPECT_EQ(PhotonMap::load(f).size(), 50u);
    EXPECT_EQ(dir.count(), 1u);
    EXPECT_NE(errorOf([&] { PhotonMap().save(dir.file("e.pm"), "", false); }).find("empty"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { m.save(dir.file("no/such/dir/x.pm"), "", false); }), "(no InputError)");
}

// What `store` finds at fixed queries: every photon's distance and flux, in order.
std::vector<std::pair<float, uint32_t>> searchResults(const PhotonStore& store) {
    std::vector<std::pair<float, uint32_t>> r;
    auto cursor = store.makeCursor();
    std::vector<FoundPhoton> out;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 100; ++i) {
        const PhotonQuery q{Vec3(u(rng), u(rng), u(rng)), nullptr, false, 1.f, 20};
        const size_t n = store.findNearest(*cursor, q, out);
        for (size_t j = 0; j < n; ++j) {
            uint32_t flux;
            std::memcpy(&flux, out[j].flux.data(), 4);
            r.emplace_back(out[j].dist2, flux);
        }
    }
    return r;
}

ino_t inodeOf(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

// The in-core store is kept beside the map ("<map>.rpindex") by the first open and read
// back by the next; a map saved again under the same name, a damaged index and a map
// without record checksums (as RADIANCE writes them) are searched as their own photons.
TEST(PhotonMap, OpenKeepsItsStoreBesideTheMap) {
    TempDir dir;
    const std::string f = dir.file("g.pm"), index = f + ".rpindex";
    auto expected = [&] {
        PhotonMap m = PhotonMap::load(f);
        m.makeSearchable(false);
        return searchResults(m.store());
    };
    randomMap(PhotonMapType::Global, 5000, 7).save(f, "", false);
    EXPECT_EQ(searchResults(PhotonMap::open(f, StoreOptions{}).store()), expected());
    const ino_t written = inodeOf(index);
    ASSERT_NE(written, 0u) << "no index beside the map";
    EXPECT_EQ(searchResults(PhotonMap::open(f, StoreOptions{}).store()), expected());
    EXPECT_EQ(inodeOf(index), written) << "the index was built again, not read";

    randomMap(PhotonMapType::Global, 5000, 8).save(f, "", true);  // same size, new photons
    EXPECT_EQ(searchResults(PhotonMap::open(f, StoreOptions{}).store()), expected());
    EXPECT_NE(inodeOf(index), written) << "a stale index was not replaced";

    std::string bytes = slurp(index);
    bytes[bytes.size() / 2] ^= 1;
    spit(index, bytes);
    EXPECT_EQ(searchResults(PhotonMap::open(f, StoreOptions{}).store()), expected());
    EXPECT_NE(slurp(index), bytes) << "a damaged index was not replaced";

    const std::string plain = dir.file("radiance.pm");
    spit(plain, test::withoutChecksums(slurp(f), 5000));
    EXPECT_EQ(searchResults(PhotonMap::open(plain, StoreOptions{}).store()), expected());
    EXPECT_FALSE(fs::exists(plain + ".rpindex"));
}

class BadFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::make_unique<TempDir>();
        good_ = dir_->file("good.pm");
        randomMap(PhotonMapType::Global, 1000, 6).save(good_, "mkpmap x", false);
        // As RADIANCE writes it: damage beyond what checksums catch is checked as well.
        data_ = test::withoutChecksums(slurp(good_), 1000);
        binaryStart_ = data_.find("VERSION=3.1k\n\n") + std::strlen("VERSION=3.1k\n\n");
    }
    // Loads `data` written to a file; returns the InputError message.
    std::string load(const std::string& data) {
        const std::string f = dir_->file("bad.pm");
        spit(f, data);
        std::string msg = errorOf([&] { PhotonMap::load(f); });
        EXPECT_NE(msg.find(f), std::string::npos) << "message should name the file: " << msg;
        return msg;
    }
    std::string replaced(const std::string& from, const std::string& to) {
        std::string d = data_;
        d.replace(d.find(from), from.size(), to);
        return d;
    }
    std::unique_ptr<TempDir> dir_;
    std::string good_, data_;
    size_t binaryStart_ = 0;
};

TEST_F(BadFile, Truncated) {
    for (size_t cut : {size_t{1}, size_t{26}, size_t{27}, size_t{27 * 999}})
        EXPECT_NE(load(data_.substr(0, data_.size() - cut)).find("size mismatch"),
                  std::string::npos);
    EXPECT_NE(load(data_.substr(0, binaryStart_ + 20)).find("truncated"), std::string::npos);
    EXPECT_NE(load(data_.substr(0, binaryStart_ + 2)).find("truncated"), std::string::npos);
    EXPECT_NE(load(data_.substr(0, binaryStart_)).find("truncated"), std::string::npos);
    EXPECT_NE(load(data_.substr(0, 30)).find("header"), std::string::npos);
}

TEST_F(BadFile, CountDoesNotMatchSize) {
    EXPECT_NE(load(data_ + "x").find("size mismatch"), std::string::npos);
    for (int64_t n : {int64_t{1001}, int64_t{999}, int64_t{1} << 62, int64_t{-1}}) {
        std::string d = data_;
        std::string count;
        putInt(count, n, 8);
        d.replace(binaryStart_ + 5, 8, count);
        std::string msg = load(d);
        EXPECT_TRUE(msg.find("size mismatch") != std::string::npos ||
                    msg.find("corrupt") != std::string::npos)
            << msg;
    }
}

TEST_F(BadFile, WrongFormatAndVersion) {
    EXPECT_NE(load(replaced("_Global_", "_Foo_")).find("unknown photon map type 'Foo'"),
              std::string::npos);
    EXPECT_NE(load(replaced("_kdT_", "_OOC_")).find("out-of-core photon maps not supported yet"),
              std::string::npos);
    EXPECT_NE(load(replaced("FORMAT=Radiance_Global_kdT_Photon_Map", "FORMAT=ascii"))
                  .find("not a photon map (FORMAT=ascii)"),
              std::string::npos);
    EXPECT_NE(load(replaced("VERSION=3.1k", "VERSION=3.1kf")).find("not supported yet"),
              std::string::npos);
    EXPECT_NE(load(replaced("VERSION=3.1k", "VERSION=3.1o")).find("out-of-core"),
              std::string::npos);
    EXPECT_NE(load(replaced("VERSION=3.1k", "VERSION=2.0")).find("incompatible"),
              std::string::npos);
    // The binary version string is checked too (RADIANCE checks only that one).
    std::string d = data_;
    d[binaryStart_ + 3] = 'x';
    EXPECT_NE(load(d).find("incompatible photon map file version '3.1x'"), std::string::npos);
}

TEST_F(BadFile, ForeignFiles) {
    std::string picture = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n";
    picture += std::string("\x80\x80\x80\x81", 4);
    EXPECT_NE(load(picture).find("not a photon map (FORMAT=32-bit_rle_rgbe)"), std::string::npos);
    EXPECT_NE(load(std::string("\x7f"
                               "ELF\x02\x01\x01\0\0\0",
                               10))
                  .find("not a RADIANCE file"),
              std::string::npos);
    EXPECT_NE(load("").find("not a RADIANCE file"), std::string::npos);
    EXPECT_NE(load("#?RADIANCE\noconv x.rad\n\n").find("no FORMAT"), std::string::npos);
    const std::string missing = dir_->file("missing.pm");
    EXPECT_NE(errorOf([&] { PhotonMap::load(missing); }).find(missing), std::string::npos);
}

TEST_F(BadFile, CorruptTreeOrder) {
    // Exchange the first two photon records: the root no longer splits its subtrees.
    std::string d = data_;
    const size_t rec = d.size() - 1000 * 27;
    std::string a = d.substr(rec, 27), b = d.substr(rec + 27, 27);
    d.replace(rec, 27, b);
    d.replace(rec + 27, 27, a);
    EXPECT_NE(load(d).find("not a valid kd-tree"), std::string::npos);
    // TreeOrder::Unchecked skips the order check only.
    std::istringstream in(d);
    const PhotonMap unchecked = PhotonMap::read(in, "swapped.pm", PhotonMap::TreeOrder::Unchecked);
    EXPECT_EQ(unchecked.size(), 1000u);
    // ... which checkTreeOrder makes later.
    try {
        unchecked.checkTreeOrder("swapped.pm");
        FAIL() << "bad order accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("swapped.pm"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not a valid kd-tree"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rp::pmap

// getinfo's output formats (RADIANCE getinfo.c byte for byte) and error handling.
#include "image/getinfo.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "util/error.h"

namespace rp {
namespace {

struct Result {
    int status;
    std::string out, err;
};

Result run(std::vector<std::string> args, const std::string& stdinData = "") {
    std::vector<const char*> argv{"getinfo"};
    for (const auto& a : args) argv.push_back(a.c_str());
    std::istringstream in(stdinData);
    std::ostringstream out, err;
    int st = runGetinfo(parseGetinfoArgs(static_cast<int>(argv.size()), argv.data()), in, out, err);
    return {st, out.str(), err.str()};
}

class GetinfoTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("rp_getinfo_test_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
        pic_ = file("a.hdr", "#?RADIANCE\nrpict -x 4\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\nDATA");
        // Octree: header, 2-byte magic starting with 1, bounding cube as C strings.
        oct_ = file("b.oct", std::string("#?RADIANCE\noconv x.rad\nFORMAT=Radiance_octree\n\n") +
                                 std::string("\x01\x2d", 2) +
                                 std::string("-1\0-2\0-3\0"
                                             "10\0rest",
                                             16));
        txt_ = file("c.txt", "hello\nworld\n");
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string file(const char* name, const std::string& data) {
        std::string p = (dir_ / name).string();
        std::ofstream(p, std::ios::binary) << data;
        return p;
    }
    std::filesystem::path dir_;
    std::string pic_, oct_, txt_;
};

TEST_F(GetinfoTest, HeaderFormat) {
    Result r = run({pic_});
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, pic_ + ":\n\t#?RADIANCE\n\trpict -x 4\n\tFORMAT=32-bit_rle_rgbe\n\t\n");
    EXPECT_EQ(r.err, "");
}

TEST_F(GetinfoTest, Dimensions) {
    EXPECT_EQ(run({"-d", pic_}).out, pic_ + ": -Y 2 +X 4\n");
    EXPECT_EQ(run({"-d", oct_}).out, oct_ + ": -1 -2 -3 10\n");
    EXPECT_EQ(run({"+d", pic_}).out,
              pic_ + ":\n\t#?RADIANCE\n\trpict -x 4\n\tFORMAT=32-bit_rle_rgbe\n\t\n\t-Y 2 +X 4\n");
}

TEST_F(GetinfoTest, StandardInput) {
    std::string data = "#?RADIANCE\nmkpmap x\n\n-Y 1 +X 1\nBODY";
    EXPECT_EQ(run({}, data).out, "#?RADIANCE\nmkpmap x\n\n");
    EXPECT_EQ(run({"-d"}, data).out, "-Y 1 +X 1\n");
    EXPECT_EQ(run({"-"}, data).out, "-Y 1 +X 1\nBODY");
    EXPECT_EQ(run({"-d", "-"}, data).out, "BODY");
    EXPECT_EQ(run({"-a", "VIEW= -vh 10", "", "EXPOSURE=2\n"}, data).out,
              "#?RADIANCE\nmkpmap x\nVIEW= -vh 10\nEXPOSURE=2\n\n-Y 1 +X 1\nBODY");
    Result bad = run({}, "no header\n");
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.err, "getinfo: standard input: not a RADIANCE file\n");
}

TEST_F(GetinfoTest, ErrorsContinueWithOtherFiles) {
    std::string missing = (dir_ / "missing.hdr").string();
    Result r = run({txt_, missing, pic_});
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err,
              "getinfo: " + txt_ + ": not a RADIANCE file\ngetinfo: cannot open " + missing + "\n");
    EXPECT_EQ(r.out, pic_ + ":\n\t#?RADIANCE\n\trpict -x 4\n\tFORMAT=32-bit_rle_rgbe\n\t\n");
    EXPECT_EQ(run({"-d", txt_}).status, 1);
}

TEST(GetinfoArgs, Modes) {
    const char* a1[] = {"getinfo", "-d", "x"};
    EXPECT_EQ(parseGetinfoArgs(3, a1).mode, GetinfoOptions::Mode::kDimensions);
    const char* a2[] = {"getinfo", "-c", "cmd"};
    EXPECT_THROW(parseGetinfoArgs(3, a2), InputError);
    const char* a3[] = {"getinfo", "x", "-d"};
    EXPECT_THROW(parseGetinfoArgs(3, a3), InputError);
}

std::string spectralData(const std::string& name) {
    return std::string(RP_SOURCE_DIR) + "/tests/data/spectral/" + name;
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// RADIANCE 6 spectral pictures (spectral_picture_test.cpp's), against RADIANCE 6.1a's
// getinfo, run in tests/data/spectral:
//   getinfo room.hsr room12.hsr > room_getinfo.txt
//   getinfo -d room.hsr room12.hsr > room_getinfo_d.txt
//   getinfo -a "VIEW= -vtv -vh 40 -vv 30" < room12.hsr > room12_a.hsr
TEST(Getinfo, SpectralPicturesAsRadiance6) {
    const std::string a = spectralData("room.hsr"), b = spectralData("room12.hsr");
    auto named = [&](std::string s) {  // our output names the files by their paths
        for (const std::string& p : {a, b}) {
            const std::string base = p.substr(p.rfind('/') + 1);
            for (size_t i; (i = s.find(p)) != std::string::npos;) s.replace(i, p.size(), base);
        }
        return s;
    };
    Result r = run({a, b});
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(named(r.out), fileBytes(spectralData("room_getinfo.txt")));
    EXPECT_EQ(named(run({"-d", a, b}).out), fileBytes(spectralData("room_getinfo_d.txt")));
    // -a: the line goes after the header's, FORMAT= last.
    EXPECT_EQ(run({"-a", "VIEW= -vtv -vh 40 -vv 30"}, fileBytes(b)).out,
              fileBytes(spectralData("room12_a.hsr")));
}

}  // namespace
}  // namespace rp

// mkpmap's command line and run: option parsing, one test per kind of bad input, files
// written with RADIANCE's header, and bit-identical files for -n 1 and -n 2.
#include "pmap/mkpmap.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "pmap/mkpmap_options.h"
#include "pmap/photon_map.h"
#include "pmap/pmap_test_util.h"
#include "util/error.h"
#include "util/options.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

MkpmapOptions parse(std::vector<std::string> args) {
    args.insert(args.begin(), "mkpmap");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    return parseMkpmapArgs(int(argv.size()), argv.data());
}

std::string parseError(std::vector<std::string> args) {
    try {
        parse(std::move(args));
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(MkpmapOptions, ParsesRadianceCommandLine) {
    MkpmapOptions o = parse(
        {"-apg", "g.pm", "500k", "-apc", "c.pm",  "1m",  "-apd", "d.pm", "2.5K", "-apD",  "0.5",
         "-apM", "6",    "-apr", "3",    "-api",  "0",   "0",    "0",    "1",    "2",     "3",
         "-lr",  "100",  "-ld",  "7.5",  "-apo+", "win", "-aps", "sens", "-ae",  "x",     "-bv-",
         "-dp",  "500",  "-ds",  ".02",  "-fo+",  "-n",  "2",    "-t",   "10",   "a.rad", "b.rad"});
    EXPECT_EQ(o.maps[size_t(PhotonMapType::Global)]->target, 500000u);
    EXPECT_EQ(o.maps[size_t(PhotonMapType::Global)]->file, "g.pm");
    EXPECT_EQ(o.maps[size_t(PhotonMapType::Caustic)]->target, 1000000u);
    EXPECT_EQ(o.maps[size_t(PhotonMapType::Direct)]->target, 2500u);
    EXPECT_FALSE(o.wants(PhotonMapType::Volume));
    EXPECT_DOUBLE_EQ(o.pass.preDistrib, 0.5);
    EXPECT_EQ(o.pass.maxPrepass, 6);
    EXPECT_EQ(o.pass.seed, 3u);
    ASSERT_EQ(o.trace.rois.size(), 1u);
    EXPECT_EQ(o.trace.rois[0].max.z, 3);
    EXPECT_EQ(o.trace.maxBounce, 100);
    EXPECT_DOUBLE_EQ(o.trace.maxDistance, 7.5);
    ASSERT_EQ(o.portSpecs.size(), 1u);
    EXPECT_EQ(o.portSpecs[0].modifier, "win");
    EXPECT_EQ(o.portSpecs[0].direction, light::PortDirection::Forward);
    EXPECT_EQ(o.trace.sensors, std::vector<std::string>{"sens"});
    EXPECT_EQ(o.trace.exclude, std::vector<std::string>{"x"});
    EXPECT_FALSE(o.trace.backVisible);
    EXPECT_TRUE(o.overwrite);
    EXPECT_DOUBLE_EQ(o.partitionSize, 0.02);
    EXPECT_EQ(o.pass.threads, 2);
    EXPECT_EQ(o.pass.reportSeconds, 10);
    EXPECT_EQ(o.sceneFiles, (std::vector<std::string>{"a.rad", "b.rad"}));
}

// RADIANCE 5.4a's syntax (mkpmap.c): the orientation is the option's suffix, and a
// modifier name is taken whole, whatever its last character (issue 43).
TEST(MkpmapOptions, PortOrientationIsTheOptionsSuffix) {
    const std::string file = ::testing::TempDir() + "/mkpmap_ports.txt";
    {
        std::ofstream f(file);
        f << "skylight_45_59c8c160 win-\n  sky2\n";
    }
    MkpmapOptions o = parse({"-apo", "win0", "-apo-", "glass+", "-apo0", "a", "-apo+", "b", "-apO-",
                             file, "-apg", "g.pm", "1k", "x.oct"});
    using light::PortDirection;
    const std::vector<std::pair<std::string, PortDirection>> want{
        {"win0", PortDirection::Forward},
        {"glass+", PortDirection::Backward},
        {"a", PortDirection::Bidirectional},
        {"b", PortDirection::Forward},
        {"skylight_45_59c8c160", PortDirection::Backward},
        {"win-", PortDirection::Backward},
        {"sky2", PortDirection::Backward}};
    ASSERT_EQ(o.portSpecs.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(o.portSpecs[i].modifier, want[i].first) << i;
        EXPECT_EQ(o.portSpecs[i].direction, want[i].second) << i;
    }
    EXPECT_EQ(parseError({"-apox", "w", "-apg", "g", "1", "x"}), "unknown option '-apox'");
    EXPECT_EQ(parseError({"-apo-+", "w", "-apg", "g", "1", "x"}), "unknown option '-apo-+'");
}

TEST(MkpmapOptions, Defaults) {
    MkpmapOptions o = parse({"-apg", "g.pm", "1000", "x.oct"});
    EXPECT_DOUBLE_EQ(o.pass.preDistrib, 0.25);
    EXPECT_EQ(o.pass.maxPrepass, 4);
    EXPECT_DOUBLE_EQ(o.partitionSize, 0.01);
    EXPECT_TRUE(o.trace.backVisible);  // RADIANCE mkpmap.c: backvis = 1
    EXPECT_FALSE(o.overwrite);
    EXPECT_EQ(o.pass.threads, 1);
    EXPECT_EQ(parse({"-bv", "-apg", "g", "1", "x"}).trace.backVisible, false);  // bare flag toggles
    EXPECT_EQ(parse({"-apm", "9", "-apg", "g", "1", "x"}).trace.maxBounce, 9);
    // -apE: ports see the outside (issue 48); off by default, as RADIANCE's ports.
    EXPECT_FALSE(o.portExterior);
    EXPECT_TRUE(parse({"-apE", "-apg", "g", "1", "x"}).portExterior);
    EXPECT_TRUE(parse({"-apE+", "-apg", "g", "1", "x"}).portExterior);
    EXPECT_FALSE(parse({"-apE", "-apE-", "-apg", "g", "1", "x"}).portExterior);
    EXPECT_NE(formatMkpmapDefaults(o).find("-apE-"), std::string::npos);
}

TEST(MkpmapOptions, MemoryBudget) {
    EXPECT_EQ(parse({"-aC", "1k", "-apg", "g", "1", "x"}).memoryPhotons, 1000u);
    EXPECT_EQ(parse({"-aC", "2.5G", "-apg", "g", "1", "x"}).memoryPhotons, 2500000000u);
    EXPECT_EQ(parse({"-apg", "g", "1", "x"}).memoryPhotons, defaultMemoryPhotons());
    EXPECT_GT(defaultMemoryPhotons(), 1000000u);
    EXPECT_EQ(parseError({"-aC", "lots", "-apg", "g", "1", "x"}),
              "bad photon count 'lots' for option '-aC'");
}

TEST(MkpmapOptions, PhotonCounts) {
    EXPECT_EQ(parseCount("500k"), 500000u);
    EXPECT_EQ(parseCount("1M"), 1000000u);
    EXPECT_EQ(parseCount("20000"), 20000u);
    EXPECT_FALSE(parseCount("0"));
    EXPECT_FALSE(parseCount("12x"));
    EXPECT_FALSE(parseCount("-5"));
}

TEST(MkpmapOptions, Errors) {
    EXPECT_EQ(parseError({"-apx", "g", "1", "x"}), "unknown option '-apx'");
    EXPECT_EQ(parseError({"-apg", "g"}), "missing value for option '-apg'");
    EXPECT_EQ(parseError({"-apg", "g", "lots", "x"}), "bad photon count 'lots' for option '-apg'");
    EXPECT_EQ(parseError({"-n", "2", "x.oct"}), "no photon maps specified");
    EXPECT_EQ(parseError({"-apg", "g", "1k"}), "missing octree argument");
    EXPECT_NE(
        parseError({"-ai", "a", "-ae", "b", "-apg", "g", "1", "x"}).find("mutually exclusive"),
        std::string::npos);
    EXPECT_NE(parseError({"-api", "1", "0", "0", "0", "1", "1", "-apg", "g", "1", "x"})
                  .find("invalid region of interest"),
              std::string::npos);
    EXPECT_EQ(parseError({"-ds", "abc", "-apg", "g", "1", "x"}),
              "bad value 'abc' for option '-ds'");
    EXPECT_NE(parseError({"-apO", "/nonexistent/ports", "-apg", "g", "1", "x"}).find("cannot open"),
              std::string::npos);
}

class MkpmapRun : public ::testing::Test {
protected:
    std::string path(const std::string& name) const { return dir_.file(name); }
    std::string runError(std::vector<std::string> args) {
        std::ostringstream diag;
        try {
            runMkpmap(parse(std::move(args)), "mkpmap test", diag);
        } catch (const InputError& e) {
            return e.what();
        }
        return "(no error)";
    }
    TempDir dir_{"mkpmap_test"};
};

std::string cornell() { return std::string(RP_SOURCE_DIR) + "/examples/cornell/scene.rad"; }

using test::slurp;

TEST_F(MkpmapRun, SameFilesForOneAndTwoThreads) {
    std::ostringstream diag;
    for (const char* n : {"1", "2"})
        runMkpmap(
            parse({"-apg", path(std::string("g") + n + ".pm"), "20k", "-apc",
                   path(std::string("c") + n + ".pm"), "20k", "-apr", "5", "-n", n, cornell()}),
            "mkpmap -apg g.pm 20k -apc c.pm 20k", diag);
    EXPECT_EQ(slurp(path("g1.pm")), slurp(path("g2.pm")));
    EXPECT_EQ(slurp(path("c1.pm")), slurp(path("c2.pm")));
    PhotonMap g = PhotonMap::load(path("g1.pm"));
    EXPECT_EQ(g.type(), PhotonMapType::Global);
    EXPECT_NEAR(double(g.size()), 20000, 1000);
    Header h = g.fileHeader("x");
    EXPECT_EQ(h.format(), "Radiance_Global_kdT_Photon_Map");
    EXPECT_EQ(PhotonMap::load(path("c2.pm")).type(), PhotonMapType::Caustic);
}

TEST_F(MkpmapRun, RefusesExistingFileBeforeTracing) {
    std::ofstream(path("g.pm")) << "keep me";
    EXPECT_EQ(runError({"-apg", path("g.pm"), "1k", cornell()}),
              "photon map file " + path("g.pm") + " exists, not overwritten");
    EXPECT_EQ(slurp(path("g.pm")), "keep me");
    // Checked before the scene is read: even a missing scene reports the file first.
    EXPECT_EQ(runError({"-apg", path("g.pm"), "1k", "/nonexistent.rad"}),
              "photon map file " + path("g.pm") + " exists, not overwritten");
    EXPECT_EQ(runError({"-fo", "-apg", path("g.pm"), "1k", cornell()}), "(no error)");
    EXPECT_NE(slurp(path("g.pm")), "keep me");
}

TEST_F(MkpmapRun, ErrorsOnePerKind) {
    EXPECT_EQ(runError({"-apv", path("v.pm"), "1k", cornell()}),
              "volume photon map " + path("v.pm") +
                  ": no scattering medium in the scene (a mist with an albedo, or -me with "
                  "-ma)");
    EXPECT_NE(runError({"-apg", path("a.pm"), "1k", "-apc", path("a.pm"), "1k", cornell()})
                  .find("more than once"),
              std::string::npos);
    EXPECT_NE(
        runError({"-apg", path("g.pm"), "1k", "-aps", "white", cornell()}).find("not antimatter"),
        std::string::npos);
    std::ofstream(path("dark.rad")) << "void plastic p 0 0 5 .5 .5 .5 0 0\n"
                                       "p sphere s 0 0 4 0 0 0 1\n";
    EXPECT_EQ(runError({"-apg", path("g.pm"), "1k", path("dark.rad")}), "no light sources found");
    EXPECT_NE(runError({"-apg", path("g.pm"), "1k", "-apo", "nosuchport", cornell()}),
              "(no error)");
    EXPECT_FALSE(std::filesystem::exists(path("g.pm")));
    // -apE needs ports, a program that can see outside (the tool passes the classic
    // calculation), and no contribution map (its photons have no one source).
    EXPECT_EQ(runError({"-apE", "-apg", path("g.pm"), "1k", cornell()}),
              "-apE: no photon ports (-apo, -apO)");
    EXPECT_EQ(runError({"-apE", "-apo", "white", "-apg", path("g.pm"), "1k", cornell()}),
              "-apE: not available in this program");
}

// The binary part of a map file: what follows the header (which holds the command line).
std::string binaryPart(const std::string& file) {
    const std::string all = slurp(file);
    const size_t end = all.find("\n\n");
    return end == std::string::npos ? std::string() : all.substr(end + 2);
}

// -aC 1k: every map is spilled and built externally, with 1000 photons in memory; the
// files are the ones built in memory (so are photons, count and statistics), and no
// temporary file is left in the maps' folder.
TEST_F(MkpmapRun, SmallMemoryBudgetGivesTheSameMaps) {
    std::ostringstream diag;
    runMkpmap(parse({"-apg", path("g.pm"), "20k", "-apc", path("c.pm"), "5k", "-apd", path("d.pm"),
                     "3k", "-apr", "2", "-n", "2", cornell()}),
              "mkpmap", diag);
    runMkpmap(parse({"-aC", "1k", "-apg", path("gs.pm"), "20k", "-apc", path("cs.pm"), "5k", "-apd",
                     path("ds.pm"), "3k", "-apr", "2", "-n", "2", cornell()}),
              "mkpmap", diag);
    for (const char* m : {"g", "c", "d"}) {
        const std::string a = path(std::string(m) + ".pm"), b = path(std::string(m) + "s.pm");
        EXPECT_TRUE(binaryPart(a) == binaryPart(b)) << m;
        const PhotonMap x = PhotonMap::load(a), y = PhotonMap::load(b);
        EXPECT_GT(y.size(), 2000u);
        EXPECT_EQ(x.size(), y.size());
        EXPECT_EQ(x.stats(), y.stats());
    }
    EXPECT_EQ(dir_.count(), 6u);
}

// An error after the photons were spilled (here: the global map's name is a folder, so
// its file cannot be named when complete) leaves no temporary file behind.
TEST_F(MkpmapRun, NoSpillFileLeftAfterAnError) {
    std::filesystem::create_directory(path("g.pm"));
    EXPECT_NE(runError({"-fo", "-aC", "1k", "-apg", path("g.pm"), "5k", "-apc", path("c.pm"), "5k",
                        cornell()}),
              "(no error)");
    EXPECT_EQ(dir_.count(), 1u);  // the folder g.pm, nothing else
    EXPECT_FALSE(std::filesystem::exists(path("c.pm")));
}

}  // namespace
}  // namespace rp::pmap

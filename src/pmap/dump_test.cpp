// pmapdump library: option groups and their reset, count suffixes, option errors, default
// colours, sphere radius, subsampling and flux conservation, scene/ASCII structure, golden
// outputs (tests/golden/pmapdump_*.expected), a PLY read back by a small parser, bad files.
#include "pmap/dump.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pmap/pmap_test_util.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::pmap {
namespace {

namespace fs = std::filesystem;

using test::slurp;

// n photons on a fixed lattice filling [0,2]x[0,3]x[0,4] (z = 0 for flat maps), flux
// (0.001, 0.002, 0.003) W times a factor in [0.5, 1.5] that varies from photon to photon.
PhotonMap latticeMap(PhotonMapType type, size_t n, bool flat = false, bool equalFlux = false) {
    std::vector<Photon> v;
    for (size_t i = 0; i < n; ++i) {
        const double u = double(i % 10) / 9, w = double((i / 10) % 10) / 9,
                     t = double(i / 100) / std::max<double>(1, double((n - 1) / 100));
        const double f = equalFlux ? 1.0 : 0.5 + double((i * 37) % 101) / 100;
        v.push_back(makePhoton(Vec3(2 * u, 3 * w, flat ? 0.0 : 4 * t), Vec3(0, 0, 1),
                               {0.001 * f, 0.002 * f, 0.003 * f}));
    }
    return PhotonMap(type, std::move(v), {}, false);
}

std::string saveMap(const TempDir& dir, const std::string& name, const PhotonMap& map) {
    const std::string path = dir.file(name);
    map.save(path, "test", true);
    return path;
}

std::vector<DumpRequest> parse(std::vector<const char*> args) {
    args.insert(args.begin(), "pmapdump");
    return parseDumpArgs(int(args.size()), args.data());
}

std::string parseError(std::vector<const char*> args) {
    try {
        parse(std::move(args));
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

std::string dumpText(const std::vector<DumpRequest>& requests) {
    std::ostringstream out;
    runPmapdump(requests, "pmapdump test", out);
    return out.str();
}

std::vector<std::vector<double>> asciiRows(const std::string& text) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream ls(line);
        std::vector<double> row;
        for (std::string f; std::getline(ls, f, '\t');) row.push_back(std::stod(f));
        rows.push_back(row);
    }
    return rows;
}

size_t countLines(const std::string& text, const std::string& prefix) {
    size_t n = 0;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0 ? 1 : 0;
    return n;
}

TEST(DumpArgs, OptionsApplyToNextMapAndReset) {
    const auto r =
        parse({"-a", "-n", "2k", "-r", "0.5", "-c", "1", "0", "0.5", "a.pm", "-f", "b.pm", "c.pm"});
    ASSERT_EQ(r.size(), 3u);
    EXPECT_EQ(r[0].path, "a.pm");
    EXPECT_TRUE(r[0].options.ascii);
    EXPECT_EQ(r[0].options.num, 2000u);
    EXPECT_EQ(r[0].options.radScale, 0.5);
    ASSERT_TRUE(r[0].options.colour);
    EXPECT_EQ(*r[0].options.colour, (std::array<float, 3>{1, 0, 0.5}));
    EXPECT_FALSE(r[0].options.fluxColour);
    EXPECT_TRUE(r[1].options.fluxColour);
    EXPECT_FALSE(r[1].options.ascii);
    EXPECT_EQ(r[1].options.num, kDumpDefaultCount);
    EXPECT_EQ(r[1].options.radScale, 1.0);
    EXPECT_FALSE(r[1].options.colour);
    EXPECT_FALSE(r[2].options.fluxColour);
    EXPECT_EQ(r[2].options.format(), DumpFormat::Scene);
}

TEST(DumpArgs, CountSuffixes) {
    EXPECT_EQ(parse({"-n", "2k", "m"})[0].options.num, 2000u);
    EXPECT_EQ(parse({"-n", "2K", "m"})[0].options.num, 2000u);
    EXPECT_EQ(parse({"-n", "1M", "m"})[0].options.num, 1000000u);
    EXPECT_EQ(parse({"-n", "1m", "m"})[0].options.num, 1000000u);
    EXPECT_EQ(parse({"-n", "2.5k", "m"})[0].options.num, 2500u);
    EXPECT_EQ(parse({"-n", "750", "m"})[0].options.num, 750u);
    for (const char* bad : {"0", "-3", "abc", "2x", "k", ""})
        EXPECT_NE(parseError({"-n", bad, "m"}).find("invalid number of points/spheres"),
                  std::string::npos)
            << bad;
}

TEST(DumpArgs, BooleanSwitches) {
    EXPECT_TRUE(parse({"-a", "m"})[0].options.ascii);
    EXPECT_TRUE(parse({"-a+", "m"})[0].options.ascii);
    EXPECT_FALSE(parse({"-a", "-a", "m"})[0].options.ascii);  // bare switch toggles
    EXPECT_FALSE(parse({"-a+", "-a-", "m"})[0].options.ascii);
    EXPECT_TRUE(parse({"-fy", "m"})[0].options.fluxColour);
    EXPECT_TRUE(parse({"-P1", "m"})[0].options.ply);
    EXPECT_EQ(parse({"-a", "-P", "m"})[0].options.format(), DumpFormat::Ply);
    EXPECT_EQ(parseError({"-aq", "m"}), "invalid option syntax at -aq");
    EXPECT_EQ(parseError({"-f++", "m"}), "invalid option syntax at -f++");
}

TEST(DumpArgs, Errors) {
    EXPECT_EQ(parseError({"-c", "1", "0", "0", "-f", "m.pm"}),
              "m.pm: -c and -f are mutually exclusive");
    EXPECT_EQ(parseError({"-f", "-c", "1", "0", "0", "m.pm"}),
              "m.pm: -c and -f are mutually exclusive");
    EXPECT_EQ(parse({"-f", "-f", "-c", "1", "0", "0", "m.pm"}).size(), 1u);    // -f toggled off
    EXPECT_EQ(parse({"-c", "1", "0", "0", "a.pm", "-f", "b.pm"}).size(), 2u);  // separate groups
    EXPECT_EQ(parseError({"-x", "m"}), "unknown option -x");
    EXPECT_EQ(parseError({"-nx", "3", "m"}), "unknown option -nx");
    EXPECT_EQ(parseError({"-n"}), "option -n needs a count");
    EXPECT_EQ(parseError({"-c", "1", "1"}), "option -c needs 3 colour components (r g b)");
    EXPECT_NE(parseError({"-r", "0", "m"}).find("invalid radius scale '0'"), std::string::npos);
    EXPECT_NE(parseError({"-r", "x", "m"}).find("invalid radius scale"), std::string::npos);
    EXPECT_NE(parseError({"-c", "1", "-1", "0", "m"}).find("invalid RGB colour component '-1'"),
              std::string::npos);
    EXPECT_NE(parseError({"-c", "0", "0", "0", "m"}).find("all components 0"), std::string::npos);
    EXPECT_EQ(parseError({"a.pm", "-n", "5"}),
              "options after the last photon map apply to no map: -n");
    EXPECT_EQ(parseError({}), "no photon map file given");
    EXPECT_NE(parseError({"-P", "a.pm", "b.pm"}).find("b.pm: -P given for other photon maps"),
              std::string::npos);
    EXPECT_EQ(parse({"-P", "a.pm", "-P", "-f", "b.pm"}).size(), 2u);
}

TEST(Dump, SphereRadiusFromMeanSpacing) {
    PhotonMapStats s;
    s.bboxMax = {2, 3, 4};  // 3D: V = 24
    EXPECT_NEAR(dumpSphereRadius(s, 3000, 1), 0.05 * std::cbrt(24.0 / 3000), 1e-12);
    EXPECT_NEAR(dumpSphereRadius(s, 3000, 2.5), 2.5 * 0.05 * std::cbrt(24.0 / 3000), 1e-12);
    s.bboxMax = {2, 3, 0};  // plane: V = 6, d = 2
    EXPECT_NEAR(dumpSphereRadius(s, 600, 1), 0.05 * std::sqrt(6.0 / 600), 1e-12);
    s.bboxMax = {0, 0, 5};  // line
    EXPECT_NEAR(dumpSphereRadius(s, 100, 1), 0.05 * 5.0 / 100, 1e-12);
    s.bboxMax = {0, 0, 0};  // a point: unit extent instead of RADIANCE's radius 0
    EXPECT_EQ(dumpSphereRadius(s, 100, 2), 0.1);
    EXPECT_EQ(dumpProbability(10, 1000), 0.01);
    EXPECT_EQ(dumpProbability(1000, 1000), 1.0);
    EXPECT_EQ(dumpProbability(5000, 1000), 1.0);
}

TEST(Dump, DefaultColoursPerType) {
    TempDir dir;
    const std::array<std::pair<PhotonMapType, const char*>, 6> types = {{
        {PhotonMapType::Global, "void glow mat.global\n0\n0\n4 0.25 0.25 2 0\n"},
        {PhotonMapType::PreComp, "void glow mat.pglobal\n0\n0\n4 0.1 1 1 0\n"},
        {PhotonMapType::Caustic, "void glow mat.caustic\n0\n0\n4 1 0.1 0.1 0\n"},
        {PhotonMapType::Volume, "void glow mat.volume\n0\n0\n4 0.1 1 0.1 0\n"},
        {PhotonMapType::Direct, "void glow mat.direct\n0\n0\n4 1 0.1 1 0\n"},
        {PhotonMapType::Contrib, "void glow mat.contrib\n0\n0\n4 1 1 0.1 0\n"},
    }};
    for (const auto& [type, material] : types) {
        const std::string path = saveMap(dir, "m.pm", latticeMap(type, 20));
        const std::string scene = dumpText({{path, {}}});
        EXPECT_NE(scene.find(material), std::string::npos) << photonMapTypeName(type);
        const std::string name = dumpObjectName(type);
        EXPECT_EQ(countLines(scene, "mat." + name + " sphere obj." + name), 20u);
        DumpOptions a;
        a.ascii = true;
        for (const auto& row : asciiRows(dumpText({{path, a}}))) {
            const auto c = defaultDumpColour(type);
            for (size_t k = 0; k < 3; ++k) EXPECT_EQ(float(row[3 + k]), c[k]);  // %g of a float
        }
    }
}

TEST(Dump, SceneStructure) {
    TempDir dir;
    const std::string g = saveMap(dir, "g.pm", latticeMap(PhotonMapType::Global, 300));
    const std::string c = saveMap(dir, "c.pm", latticeMap(PhotonMapType::Caustic, 50));
    DumpOptions flux;
    flux.fluxColour = true;
    const std::string scene = dumpText({{g, {}}, {c, flux}});
    EXPECT_EQ(countLines(scene, "# pmapdump test"), 2u);  // RADIANCE writes it per map
    EXPECT_EQ(countLines(scene, "void glow mat.global"), 1u);
    EXPECT_EQ(countLines(scene, "mat.global sphere obj.global"), 300u);
    EXPECT_EQ(countLines(scene, "void glow mat.caustic"), 50u);  // one material per photon
    EXPECT_EQ(countLines(scene, "mat.caustic sphere obj.caustic"), 50u);
    // Every primitive is "modifier type name / 0 / 0 / 4 a b c d" and a blank line.
    std::istringstream in(scene);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    for (size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].empty() || lines[i][0] == '#') continue;
        ASSERT_LE(i + 4, lines.size());
        EXPECT_EQ(lines[i + 1], "0");
        EXPECT_EQ(lines[i + 2], "0");
        std::istringstream args(lines[i + 3]);
        int n = 0;
        double x[4];
        args >> n >> x[0] >> x[1] >> x[2] >> x[3];
        EXPECT_TRUE(args && n == 4) << lines[i + 3];
        EXPECT_EQ(lines[i + 4], "");
        i += 4;
    }
}

// Total flux of the map, summed from the decoded photon records.
std::array<double, 3> totalFlux(const PhotonMap& map) {
    std::array<double, 3> t{};
    for (const Photon& p : map.photons())
        for (size_t c = 0; c < 3; ++c) t[c] += p.fluxRgb()[c];
    return t;
}

TEST(Dump, FluxColoursKeepTotalFlux) {
    TempDir dir;
    const PhotonMap map = latticeMap(PhotonMapType::Global, 1000);
    const std::string path = saveMap(dir, "g.pm", map);
    const auto total = totalFlux(map);
    for (size_t c = 0; c < 3; ++c)  // the header's average agrees
        EXPECT_NEAR(total[c], map.stats().avgFlux[c] * 1000.0, 1e-4 * total[c]);

    DumpOptions all;
    all.ascii = all.fluxColour = true;
    all.num = 1000;
    auto rows = asciiRows(dumpText({{path, all}}));
    ASSERT_EQ(rows.size(), 1000u);
    std::array<double, 3> sum{};
    for (const auto& r : rows)
        for (size_t c = 0; c < 3; ++c) sum[c] += r[3 + c];
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], total[c], 0.01 * total[c]);

    // Subsampled to ~20 %: the count is Binomial(1000, 0.2) (sd 12.6) and the scaled sum a
    // ratio estimate whose relative sd is cv / sqrt(n) * sqrt(1 - n/N), cv = 0.29 for the
    // lattice's flux factors: about 1.8 %. Both checked at 4 sigma.
    DumpOptions sub = all;
    sub.num = 200;
    rows = asciiRows(dumpText({{path, sub}}));
    EXPECT_NEAR(double(rows.size()), 200, 4 * 12.6);
    sum = {};
    for (const auto& r : rows)
        for (size_t c = 0; c < 3; ++c) sum[c] += r[3 + c];
    const double sd = 0.29 / std::sqrt(200.0) * std::sqrt(0.8);
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], total[c], 4 * sd * total[c]);

    // Equal-flux photons: the numPhotons / numDumped scaling keeps the total exactly.
    const PhotonMap equal = latticeMap(PhotonMapType::Caustic, 1000, false, true);
    const auto equalTotal = totalFlux(equal);
    rows = asciiRows(dumpText({{saveMap(dir, "e.pm", equal), sub}}));
    sum = {};
    for (const auto& r : rows)
        for (size_t c = 0; c < 3; ++c) sum[c] += r[3 + c];
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], equalTotal[c], 1e-4 * equalTotal[c]);
}

TEST(Dump, SubsamplingIsReproducibleAndPerMap) {
    const PhotonMap map = latticeMap(PhotonMapType::Global, 1000);
    DumpOptions o;
    o.num = 100;
    const DumpedMap a = sampleMap(map, "g.pm", o, 0), b = sampleMap(map, "g.pm", o, 0),
                    c = sampleMap(map, "g.pm", o, 1);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i].pos, b.points[i].pos);
    bool differs = a.points.size() != c.points.size();
    for (size_t i = 0; !differs && i < a.points.size(); ++i)
        differs = a.points[i].pos != c.points[i].pos;
    EXPECT_TRUE(differs) << "map index must select its own random stream";
}

// Compares `actual` with tests/golden/<name>; RP_UPDATE_GOLDEN=1 rewrites the file instead.
void expectGolden(const std::string& name, const std::string& actual) {
    const std::string path = std::string(RP_SOURCE_DIR) + "/tests/golden/" + name;
    if (std::getenv("RP_UPDATE_GOLDEN")) {
        std::ofstream(path, std::ios::binary) << actual;
        return;
    }
    ASSERT_TRUE(fs::exists(path)) << path;
    EXPECT_EQ(actual, slurp(path)) << "golden file " << path;
}

TEST(Dump, GoldenOutputs) {
    TempDir dir;
    const std::string g = saveMap(dir, "g.pm", latticeMap(PhotonMapType::Global, 6));
    const std::string c = saveMap(dir, "c.pm", latticeMap(PhotonMapType::Caustic, 3, true));
    const std::string v = saveMap(dir, "v.pm", latticeMap(PhotonMapType::Volume, 40));
    DumpOptions colour, flux, sub;
    colour.colour = std::array<float, 3>{0.5f, 0.25f, 1};
    colour.radScale = 2;
    flux.fluxColour = true;
    sub.num = 5;  // pins the sampling stream too
    expectGolden("pmapdump_scene.expected", dumpText({{g, colour}, {c, flux}, {v, sub}}));
    DumpOptions a = flux, b = sub;
    a.ascii = b.ascii = true;
    expectGolden("pmapdump_ascii.expected", dumpText({{g, a}, {c, {}}, {v, b}}));
}

// A minimal PLY reader for exactly what writeDumpPly promises.
struct PlyCloud {
    std::vector<std::string> header;
    std::vector<std::array<float, 3>> pos;
    std::vector<std::array<uint8_t, 3>> rgb;
};

PlyCloud readPly(const std::string& data) {
    PlyCloud ply;
    size_t at = 0, vertices = 0;
    for (;;) {
        const size_t nl = data.find('\n', at);
        if (nl == std::string::npos) throw std::runtime_error("PLY header not terminated");
        ply.header.push_back(data.substr(at, nl - at));
        at = nl + 1;
        if (ply.header.back() == "end_header") break;
        if (ply.header.back().rfind("element vertex ", 0) == 0)
            vertices = std::stoul(ply.header.back().substr(15));
    }
    if (data.size() - at != vertices * 15) throw std::runtime_error("PLY body size");
    for (size_t i = 0; i < vertices; ++i, at += 15) {
        std::array<float, 3> p;
        for (size_t k = 0; k < 3; ++k) {
            uint32_t u = 0;
            for (size_t b = 0; b < 4; ++b) u |= uint32_t(uint8_t(data[at + 4 * k + b])) << (8 * b);
            std::memcpy(&p[k], &u, 4);
        }
        ply.pos.push_back(p);
        ply.rgb.push_back({uint8_t(data[at + 12]), uint8_t(data[at + 13]), uint8_t(data[at + 14])});
    }
    return ply;
}

TEST(Dump, PlyReadsBack) {
    TempDir dir;
    const PhotonMap gmap = latticeMap(PhotonMapType::Global, 500);
    const PhotonMap cmap = latticeMap(PhotonMapType::Caustic, 120, true);
    const std::string g = saveMap(dir, "g.pm", gmap), c = saveMap(dir, "c.pm", cmap);
    DumpOptions pg, pc;
    pg.ply = pc.ply = pc.fluxColour = true;
    const PlyCloud ply = readPly(dumpText({{g, pg}, {c, pc}}));
    ASSERT_GE(ply.header.size(), 12u);
    EXPECT_EQ(ply.header[0], "ply");
    EXPECT_EQ(ply.header[1], "format binary_little_endian 1.0");
    const std::vector<std::string> tail = {
        "element vertex 620", "property float x",     "property float y",    "property float z",
        "property uchar red", "property uchar green", "property uchar blue", "end_header"};
    EXPECT_EQ(std::vector<std::string>(ply.header.end() - 8, ply.header.end()), tail);
    ASSERT_EQ(ply.pos.size(), 620u);
    for (size_t i = 0; i < 500; ++i) {
        for (size_t k = 0; k < 3; ++k) EXPECT_EQ(ply.pos[i][k], gmap.photons()[i].pos[k]);
        EXPECT_EQ(ply.rgb[i], (std::array<uint8_t, 3>{32, 32, 255}));  // (0.25, 0.25, 2) / 2
    }
    size_t full = 0;
    for (size_t i = 0; i < 120; ++i) {
        for (size_t k = 0; k < 3; ++k) EXPECT_EQ(ply.pos[500 + i][k], cmap.photons()[i].pos[k]);
        full += ply.rgb[500 + i][2] == 255 ? 1 : 0;
    }
    // The 99th percentile maps to 255: at most ~2 % of points at full blue (ties aside).
    EXPECT_GE(full, 1u);
    EXPECT_LE(full, 6u);
}

TEST(Dump, PlyColourBytes) {
    EXPECT_EQ(plyColourBytes({0.5f, 0.25f, 1}, 1), (std::array<uint8_t, 3>{128, 64, 255}));
    EXPECT_EQ(plyColourBytes({1, 0.1f, 0.1f}, 1), (std::array<uint8_t, 3>{255, 26, 26}));
    EXPECT_EQ(plyColourBytes({4, 2, 0}, 1), (std::array<uint8_t, 3>{255, 128, 0}));  // hue kept
    EXPECT_EQ(plyColourBytes({0.25f, 0.5f, 0}, 2), (std::array<uint8_t, 3>{32, 64, 0}));
}

TEST(Dump, BadFilesWriteNothing) {
    TempDir dir;
    const std::string good = saveMap(dir, "g.pm", latticeMap(PhotonMapType::Global, 50));
    const std::string text = dir.file("notes.txt");
    std::ofstream(text) << "just some text\n";
    const std::string full = slurp(good);
    const std::string cut = dir.file("cut.pm");
    std::ofstream(cut, std::ios::binary) << full.substr(0, full.size() - 30);
    for (const std::string& bad : {text, cut, dir.file("missing.pm")}) {
        std::ostringstream out;
        try {
            runPmapdump({{good, {}}, {bad, {}}}, "pmapdump test", out);
            ADD_FAILURE() << "no error for " << bad;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(bad + ": ", 0), 0u) << e.what();
        }
        EXPECT_EQ(out.str(), "") << "output written before validating " << bad;
    }
}

}  // namespace
}  // namespace rp::pmap

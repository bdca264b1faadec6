// oconv's octree builder and writer against octrees RADIANCE's oconv made of the same
// files (tests/data/oconv, commands in its README.md): byte for byte, frozen and not,
// with -n, -r, -b and -i; our readers on those octrees; oconv's errors.
#include "scene/octree_build.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>

#include "scene/octree_file.h"
#include "scene/radiance_geom.h"
#include "scene/reader.h"
#include "scene/scene_file.h"
#include "scene/scene_load.h"
#include "util/temp_dir_for_tests.h"
#include "util/warnings.h"

namespace rp {
namespace {

const std::string kData = RP_SOURCE_DIR "/tests/data/oconv";

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs the test in `dir` and returns to where it was: RADIANCE's oconv stores scene file
// names as given, relative to the folder it runs in.
class InFolder {
public:
    explicit InFolder(const std::string& dir) {
        char buf[PATH_MAX];
        if (::getcwd(buf, sizeof buf)) old_ = buf;
        EXPECT_EQ(::chdir(dir.c_str()), 0) << dir;
    }
    ~InFolder() {
        if (!old_.empty() && ::chdir(old_.c_str()) != 0)
            ADD_FAILURE() << "cannot return to " << old_;
    }

private:
    std::string old_;
};

// The request tools/oconv.cpp makes of these arguments.
OconvRequest request(const std::vector<std::string>& args) {
    OconvRequest r;
    r.commandLine = "oconv";
    for (const auto& a : args) r.commandLine += " " + a;
    r.searchPath = {"."};
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "-f") {
            r.frozen = true;
        } else if (args[i] == "-n") {
            r.objlim = std::stoi(args[++i]);
        } else if (args[i] == "-r") {
            r.maxres = std::stoi(args[++i]);
        } else if (args[i] == "-i") {
            r.addTo = args[++i];
        } else if (args[i] == "-b") {
            std::array<double, 4> b{};
            for (double& v : b) v = std::stod(args[++i]);
            r.bounds = b;
        } else {
            r.files.push_back(args[i]);
        }
    }
    return r;
}

struct Reference {
    const char* file;
    std::vector<std::string> args;
};

// gtest prints a parameter's bytes otherwise (ctest -N would show pointers).
void PrintTo(const Reference& r, std::ostream* os) { *os << r.file; }

class OconvReference : public ::testing::TestWithParam<Reference> {};

TEST_P(OconvReference, SameBytesAsRadiance) {
    const Reference& ref = GetParam();
    const std::string expected = readBytes(kData + "/" + ref.file);
    ASSERT_FALSE(expected.empty()) << ref.file;
    setWarningSink([](const std::string&) {});  // the sliver and the shell warn
    std::string ours;
    {
        InFolder here(kData);
        ours = oconvOutput(request(ref.args));
    }
    setWarningSink(nullptr);
    ASSERT_EQ(ours.size(), expected.size()) << ref.file;
    EXPECT_TRUE(ours == expected) << ref.file << ": bytes differ";
}

INSTANTIATE_TEST_SUITE_P(
    TestsDataOconv, OconvReference,
    ::testing::Values(Reference{"box.octf", {"-f", "box.rad"}},
                      Reference{"shapes.oct", {"shapes.rad"}},
                      Reference{"shapes_f.oct", {"-f", "shapes.rad"}},
                      Reference{"shapes_n2r32_f.oct", {"-f", "-n", "2", "-r", "32", "shapes.rad"}},
                      Reference{"shapes_n1r8.oct", {"-n", "1", "-r", "8", "shapes.rad"}},
                      Reference{"shapes_b.oct", {"-b", "-5", "-5", "-1", "10", "shapes.rad"}},
                      Reference{"add.oct", {"-i", "shapes.oct", "add.rad"}},
                      Reference{"add_f.oct", {"-i", "shapes_f.oct", "add.rad"}}),
    // Named after the reference file ("shapes_n1r8_oct"): stable ctest names.
    [](const ::testing::TestParamInfo<Reference>& info) {
        std::string name = info.param.file;
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return name;
    });

// The octree reads back into the same tree, and writes out the same bytes again.
TEST(OctreeFile, DecodesWhatItEncodes) {
    const std::string bytes = readBytes(kData + "/shapes_f.oct");
    Header header;
    std::string_view rest;
    ASSERT_TRUE(splitHeader(bytes, header, rest));
    RadianceOctreeFile f = decodeRadianceOctree(rest, "shapes_f.oct");
    EXPECT_TRUE(f.files.empty());
    EXPECT_EQ(f.objectCount, int64_t(f.objects.prims.size()));
    EXPECT_EQ(encodeRadianceOctree(f.tree, f.objectCount, {}, &f.objects), std::string(rest));

    const std::string named = readBytes(kData + "/shapes.oct");
    ASSERT_TRUE(splitHeader(named, header, rest));
    f = decodeRadianceOctree(rest, "shapes.oct");
    ASSERT_EQ(f.files, std::vector<std::string>{"shapes.rad"});
    EXPECT_EQ(encodeRadianceOctree(f.tree, f.objectCount, f.files, nullptr), std::string(rest));
    // A damaged tree is an error naming the file, not a crash.
    std::string damaged(rest.substr(0, rest.size() - 3));
    EXPECT_THROW(decodeRadianceOctree(damaged, "x.oct"), InputError);
}

// Our readers load RADIANCE's octrees and ours alike: the same records either way.
TEST(OctreeFile, ReadersLoadFrozenAndNamedOctrees) {
    setWarningSink([](const std::string&) {});
    InFolder here(kData);
    const Scene named = loadScene({"shapes.oct"});
    const Scene frozen = loadScene({"shapes_f.oct"});
    setWarningSink(nullptr);
    // The frozen octree keeps the polygon without area that the text reader skips.
    ASSERT_EQ(frozen.ownCount(), named.ownCount() + 1);
    EXPECT_EQ(frozen.prims[3].name, "paint");
    EXPECT_EQ(frozen.prims[3].type, PrimType::Plastic);  // the alias, as its target
    EXPECT_EQ(frozen.objects.size(), named.objects.size());
}

TEST(Oconv, Errors) {
    setWarningSink([](const std::string&) {});
    InFolder here(kData);
    auto message = [](const OconvRequest& r) -> std::string {
        try {
            oconvOutput(r);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(message(request({"-b", "0", "0", "0", "1", "shapes.rad"})),
              "boundary does not encompass scene");
    EXPECT_EQ(message(request({"-i", "shapes.oct", "-b", "0", "0", "0", "1", "add.rad"})),
              "only one of '-b' or '-i'");
    EXPECT_EQ(message(request({"shapes.oct"})),
              "shapes.oct: not a scene description (FORMAT=Radiance_octree); an octree is "
              "added to with -i");
    EXPECT_EQ(message(request({"-i", "shapes.rad", "add.rad"})), "shapes.rad: not an octree");
    TempDir dir("rp_oconv");
    std::ofstream(dir.file("old.oct"), std::ios::binary)
        << "#?RADIANCE\noconv x.rad\nFORMAT=radphoton_scene\n\nRPSCENE";
    EXPECT_NE(message(request({"-i", dir.file("old.oct"), "add.rad"}))
                  .find("a scene file of an older oconv"),
              std::string::npos);
    std::ofstream(dir.file("far.rad")) << "void instance far 1 nowhere.oct 0 0\n";
    EXPECT_EQ(message(request({dir.file("far.rad")})),
              dir.file("far.rad") + ":1: instance 'far': cannot find octree file 'nowhere.oct'");
    setWarningSink(nullptr);
}

// An instance of a scene file of our older oconv (no cube of its own) gets the cube
// RADIANCE's oconv would have made for its records: the same octree as when it places
// RADIANCE's frozen octree of the same file.
// A scene smaller than maxres x FTINY (here 1 mm, under -r 16384's 1.6 cm) with more
// than objlim triangles meeting at a point: RADIANCE's split limit is negative there and
// its oconv recurses until the stack overflows; ours stops at size / maxres.
TEST(Oconv, TinySceneWithCoincidentObjectsEnds) {
    std::string text = "void plastic p 0 0 5 .5 .5 .5 0 0\n";
    for (int k = 0; k < 8; ++k) {
        const double a = k * 0.785398, b = a + 0.5;
        text += "p polygon t" + std::to_string(k) + " 0 0 9 0 0 0 " +
                std::to_string(0.001 * std::cos(a)) + " " + std::to_string(0.001 * std::sin(a)) +
                " 0 " + std::to_string(0.001 * std::cos(b)) + " " +
                std::to_string(0.001 * std::sin(b)) + " 0.0005\n";
    }
    OconvRequest r;
    r.files = {"-"};
    r.standardInput = text;
    r.frozen = true;
    r.commandLine = "oconv -f -";
    const std::string bytes = oconvOutput(r);
    EXPECT_NE(bytes.find("FORMAT=Radiance_octree"), std::string::npos);
    EXPECT_LT(bytes.size(), 1u << 20);
}

TEST(Oconv, InstanceOfAnOlderSceneFile) {
    TempDir dir("rp_oconv");
    setWarningSink([](const std::string&) {});
    saveSceneFile(dir.file("old.oct"), parseScene(readBytes(kData + "/box.rad"), "box.rad"),
                  {"oconv box.rad"});
    std::filesystem::copy_file(kData + "/box.octf", dir.file("new.oct"));
    std::string octrees[2];
    for (int k = 0; k < 2; ++k) {
        const std::string rad = dir.file(k ? "b.rad" : "a.rad");
        std::ofstream(rad) << "void instance crate 9 " << (k ? "new.oct" : "old.oct")
                           << " -s .8 -rz 30 -t 1 -3 0 0 0\n"
                           << "void plastic p 0 0 5 1 1 1 0 0\n"
                              "p sphere s 0 0 4 0 0 0 .5\n";
        OconvRequest r = request({rad});
        r.searchPath = {dir.path().string()};
        octrees[k] = oconvOutput(r);
    }
    setWarningSink(nullptr);
    Header h;
    std::string_view rest[2];
    ASSERT_TRUE(splitHeader(octrees[0], h, rest[0]) && splitHeader(octrees[1], h, rest[1]));
    const RadianceOctreeFile a = decodeRadianceOctree(rest[0], "a"),
                             b = decodeRadianceOctree(rest[1], "b");
    EXPECT_EQ(encodeRadianceOctree(a.tree, a.objectCount, {}, nullptr),
              encodeRadianceOctree(b.tree, b.objectCount, {}, nullptr));
}

// xf() and invxf() undo each other, mirror and iteration included.
TEST(RadianceGeom, TransformAndInverse) {
    const std::vector<std::string> args = {"x",   "-s", "2", "-rx", "30", "-t", "1", "2", "3",
                                           "-mz", "-i", "2", "-rz", "45", "-t", "0", "1", "0"};
    const radgeom::FullXf x = radgeom::fullTransform(args, 1);
    EXPECT_DOUBLE_EQ(x.forward.scale, 2.0);  // mirrored: the sign is dropped
    EXPECT_DOUBLE_EQ(x.backward.scale, 0.5);
    const radgeom::Vec p{0.3, -1.2, 4.5};
    const radgeom::Vec back = x.backward.point(x.forward.point(p));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[size_t(i)], p[size_t(i)], 1e-12);
}

}  // namespace
}  // namespace rp

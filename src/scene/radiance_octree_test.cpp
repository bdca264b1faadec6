// Frozen RADIANCE octrees (oconv -f) and the binary object records in them: the real
// porsche.octf checked against RADIANCE's own reader, a small hand-built octree with
// both kinds of alias, every truncation, damaged fields, and the octree/mesh cube.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scene/radiance_objects.h"
#include "scene/scene_file.h"
#include "scene/scene_load.h"
#include "scene/test_bytes.h"
#include "util/shared_for_tests.h"

namespace rp {
namespace {

namespace fs = std::filesystem;
using testing::PortableBytes;

const std::string kRenders = std::string(RP_SHARED_DIR) + "/radiance-tests/renders/";

// Reference: a one-off C program (not kept) linked with RADIANCE 5.4's librtrad.a called
// readoct("porsche.octf", IO_SCENE|IO_BOUNDS, &cube, NULL) and printed nobjects, the
// cube, and for some objects ofun[otype].funame, oname, omod, the string arguments and
// the real arguments with %.17g.
TEST(RadianceOctree, LoadsPorscheLikeRadiance) {
    RP_REQUIRE_SHARED("radiance-tests/renders");
    const std::string path = kRenders + "porsche.octf";
    Scene s = loadScene({path});
    ASSERT_EQ(s.prims.size(), 20445u);
    ASSERT_EQ(s.inputs.size(), 1u);
    EXPECT_EQ(s.inputs[0].path, path);

    const Primitive& p0 = s.prims[0];
    EXPECT_EQ(p0.type, PrimType::Metal);
    EXPECT_EQ(p0.name, "grey_metal_directional_diffuse");
    EXPECT_EQ(p0.modifier, kVoid);
    EXPECT_EQ(p0.modifierName, "void");
    EXPECT_EQ(p0.loc.file, path);
    ASSERT_EQ(p0.rargs.size(), 5u);
    EXPECT_TRUE(p0.sargs.empty());
    EXPECT_DOUBLE_EQ(p0.rargs[0], 0.41469999992507511);
    EXPECT_DOUBLE_EQ(p0.rargs[4], 0.14009999996754341);

    const Primitive& p2 = s.prims[2];
    EXPECT_EQ(p2.type, PrimType::Mixfunc);
    EXPECT_EQ(p2.name, "grey_metal");
    EXPECT_EQ(p2.sargs,
              (std::vector<std::string>{"grey_metal_mirror", "grey_metal_directional_diffuse",
                                        "0.04+0.96*exp(-6*Rdot)", "."}));
    EXPECT_TRUE(p2.rargs.empty());
    EXPECT_EQ(s.prims[11].type, PrimType::Glass);
    EXPECT_EQ(s.prims[11].name, "dark_glass");
    EXPECT_DOUBLE_EQ(s.prims[9].rargs[4], 0.080000000024447224);  // metal rough_chrome

    const Primitive& t = s.prims[5000];
    EXPECT_EQ(t.type, PrimType::Texfunc);
    EXPECT_EQ(t.name, "M-nor");
    EXPECT_EQ(t.modifier, 2);
    EXPECT_EQ(t.modifierName, "grey_metal");
    EXPECT_EQ(t.sargs, (std::vector<std::string>{"dx", "dy", "dz", "tmesh.cal"}));
    ASSERT_EQ(t.rargs.size(), 10u);
    EXPECT_DOUBLE_EQ(t.rargs[0], 2);
    EXPECT_DOUBLE_EQ(t.rargs[9], 4.560113258920663);

    const Primitive& last = s.prims[20444];
    EXPECT_EQ(last.type, PrimType::Polygon);
    EXPECT_EQ(last.name, "rfrim.4940");
    EXPECT_EQ(last.modifier, 20443);
    EXPECT_EQ(s.prims[20443].modifier, 9);  // its M-nor texfunc on rough_chrome
    ASSERT_EQ(last.rargs.size(), 9u);
    EXPECT_DOUBLE_EQ(last.rargs[0], 3.9332119999142421);
    EXPECT_DOUBLE_EQ(last.rargs[8], 2.1855859999477798);
}

// getinfo -d porsche.octf / woman.rtm (RADIANCE 5.4) printed these cubes.
TEST(RadianceOctree, CubeAsGetinfoPrintsIt) {
    RP_REQUIRE_SHARED("radiance-tests/renders");
    auto binary = [](const std::string& file) {
        std::ifstream in(kRenders + file, std::ios::binary);
        std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        Header h;
        std::string_view rest;
        EXPECT_TRUE(splitHeader(bytes, h, rest));
        return std::string(rest);
    };
    RadianceCube c = radianceCube(binary("porsche.octf"), false, "porsche.octf");
    EXPECT_EQ(c.text,
              (std::array<std::string, 4>{"-7.018318", "-6.9963735", "-7.0151235", "14.030247"}));
    EXPECT_DOUBLE_EQ(c.origin[1], -6.9963735);
    EXPECT_DOUBLE_EQ(c.size, 14.030247);
    RadianceCube m = radianceCube(binary("woman.rtm"), true, "woman.rtm");
    EXPECT_EQ(m.text[3], "0.71904138");
    EXPECT_THROW(radianceCube(binary("woman.rtm"), false, "woman.rtm"), InputError);
}

// A frozen octree built by hand: objects 0-5 below, an octree with one full node.
struct SmallOctree {
    int magic = 283 + 4;
    int64_t count = 6;
    int nodeKind = 1;
    int64_t setRef = 4;
    int64_t sphereType = 3;
    int64_t sphereMod = 1;
    std::string aliasTarget = "blue";
    std::string fileName;  // a non-empty one makes it not frozen

    std::string binary() const {
        PortableBytes b;
        b.i(magic, 2).str("0").str("0").str("0").str("4");
        if (!fileName.empty()) b.str(fileName);
        b.str("").i(count, 4);
        b.i(2, 1).i(nodeKind, 1).i(2, 4).i(5, 4).i(setRef, 4);
        for (int k = 0; k < 7; ++k) b.i(0, 1);
        b.str("plastic").str("polygon").str("alias").str("sphere").str("");
        auto object = [&](int64_t type, int64_t mod, const std::string& name) {
            b.i(type, 1).i(mod, 4).str(name);
        };
        object(0, -1, "red");
        b.i(0, 2).i(5, 2);
        for (double v : {0.5, 0.25, 0.125, 0.0, 0.0}) b.real(v);
        object(2, 0, "red2");  // "inherit alias red2 red": its modifier is the target
        b.i(0, 2).i(0, 2);
        object(0, -1, "blue");
        b.i(0, 2).i(5, 2);
        for (double v : {0.1, 0.2, 0.75, 0.0, 0.0}) b.real(v);
        object(2, 0, "blue on red");  // "red alias blue_on_red blue"
        b.i(1, 2).str(aliasTarget).i(0, 2);
        object(1, 3, "porsche #1");
        b.i(0, 2).i(9, 2);
        for (double v : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, -3.5}) b.real(v);
        object(sphereType, sphereMod, "ball");
        b.i(1, 2).str("a string").i(4, 2);
        for (double v : {1.0, 2.0, -0.75, 1e-3}) b.real(v);
        b.i(-1, 1);
        return b.s;
    }
};

TEST(RadianceOctree, DecodesSmallFrozenOctree) {
    Scene s = decodeRadianceFrozenOctree(SmallOctree{}.binary(), "small.oct");
    ASSERT_EQ(s.prims.size(), 6u);
    const Primitive& red2 = s.prims[1];
    EXPECT_EQ(red2.type, PrimType::Plastic);
    EXPECT_EQ(red2.name, "red2");
    EXPECT_EQ(red2.modifier, kVoid);
    EXPECT_EQ(red2.rargs, s.prims[0].rargs);
    const Primitive& bor = s.prims[3];
    EXPECT_EQ(bor.type, PrimType::Plastic);
    EXPECT_EQ(bor.name, "blue on red");
    EXPECT_EQ(bor.modifier, 0);
    EXPECT_EQ(bor.modifierName, "red");
    EXPECT_TRUE(bor.sargs.empty());
    EXPECT_EQ(bor.rargs, s.prims[2].rargs);
    EXPECT_NEAR(bor.rargs[0], 0.1, 1e-9);
    const Primitive& poly = s.prims[4];
    EXPECT_EQ(poly.type, PrimType::Polygon);
    EXPECT_EQ(poly.name, "porsche #1");
    EXPECT_EQ(poly.modifier, 3);
    EXPECT_EQ(poly.modifierName, "blue on red");
    EXPECT_EQ(poly.rargs.size(), 9u);
    EXPECT_NEAR(poly.rargs[8], -3.5, 1e-8);
    const Primitive& ball = s.prims[5];
    EXPECT_EQ(ball.type, PrimType::Sphere);
    EXPECT_EQ(ball.modifierName, "red2");
    EXPECT_EQ(ball.sargs, (std::vector<std::string>{"a string"}));
    EXPECT_NEAR(ball.rargs[2], -0.75, 1e-9);
    EXPECT_NEAR(ball.rargs[3], 1e-3, 1e-12);

    // Through loadScene, as a file with its header.
    std::string path =
        (fs::temp_directory_path() / ("rp_frozen_" + std::to_string(::getpid()) + ".oct")).string();
    std::ofstream(path, std::ios::binary)
        << "#?RADIANCE\noconv -f small.rad\nFORMAT=Radiance_octree\n\n" + SmallOctree{}.binary();
    Scene loaded = loadScene({path});
    fs::remove(path);
    EXPECT_EQ(loaded.prims.size(), 6u);
    EXPECT_EQ(loaded.prims[5].modifier, 1);
}

TEST(RadianceOctree, EveryTruncationIsAnError) {
    std::string bytes = SmallOctree{}.binary();
    for (size_t n = 0; n < bytes.size(); ++n) {
        try {
            decodeRadianceFrozenOctree(std::string_view(bytes).substr(0, n), "cut.oct");
            ADD_FAILURE() << "prefix of " << n << " bytes accepted";
        } catch (const InputError& e) {
            ASSERT_EQ(std::string(e.what()).rfind("cut.oct: ", 0), 0u) << n << ": " << e.what();
        }
    }
}

void expectOctreeError(const SmallOctree& oct, const std::string& part) {
    try {
        decodeRadianceFrozenOctree(oct.binary(), "bad.oct");
        ADD_FAILURE() << "no error, expected " << part;
    } catch (const InputError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind("bad.oct: ", 0), 0u) << what;
        EXPECT_NE(what.find(part), std::string::npos) << what;
    }
}

TEST(RadianceOctree, DamageIsAnError) {
    SmallOctree o;
    o.magic = 283;
    expectOctreeError(o, "incompatible octree format");
    o = {};
    o.count = 7;
    expectOctreeError(o, "6 objects, the octree says 7");
    o = {};
    o.count = 1 << 30;
    expectOctreeError(o, "impossible object count");
    o = {};
    o.nodeKind = 3;
    expectOctreeError(o, "octree node of unknown kind 3");
    o = {};
    o.setRef = 6;
    expectOctreeError(o, "octree object reference 6 out of range");
    o = {};
    o.sphereType = 4;
    expectOctreeError(o, "type index 4 of object 5 out of range");
    o = {};
    o.sphereMod = 6;
    expectOctreeError(o, "modifier reference 6 of object 5 is not an earlier object");
    o = {};
    o.sphereMod = 4;
    expectOctreeError(o, "modified by a surface");
    o = {};
    o.aliasTarget = "green";
    expectOctreeError(o, "refers to undefined modifier 'green'");
    o = {};
    o.fileName = "a.rad";
    expectOctreeError(o, "not a frozen octree");
    // A tree nested deeper than any real one, and an unknown type name.
    PortableBytes deep;
    deep.i(287, 2).str("0").str("0").str("0").str("1").str("").i(0, 4);
    for (int k = 0; k < 100; ++k) deep.i(2, 1);
    EXPECT_THROW(decodeRadianceFrozenOctree(deep.s, "deep.oct"), InputError);
    PortableBytes records;
    records.str("plastic").str("hologram").str("").i(1, 1).i(-1, 2).str("x").i(0, 2).i(0, 2);
    size_t pos = 0;
    try {
        decodeRadianceObjects(records.s, pos, 2, "h.rtm");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "h.rtm: unknown object type 'hologram' in object 0");
    }
}

}  // namespace
}  // namespace rp

// Tests for xform: argument parsing (arrays, -n/-m/-c, errors), per-type transforms of
// Primitive records, the text writer, and the cornell mirror box against the reference
// scene in ../shared/validation/cornell/scene.rad (genbox | xform output from RADIANCE).
#include "gen/xform_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "gen/xform_format.h"
#include "scene/reader.h"
#include "util/shared_for_tests.h"

namespace rp {
namespace {

XformOptions opts(std::vector<std::string> args) {
    args.insert(args.begin(), "xform");
    return parseXformArgs(args);
}

std::string run(std::vector<std::string> args, std::string_view text) {
    return xformText(opts(std::move(args)), text);
}

// The records of xform output, read back with the project's scene reader (modifiers are
// defined first so the reader accepts the fragments).
Scene readBack(const std::string& out,
               const std::string& defs = "void plastic m 0 0 5 .5 .5 .5 0 0\n") {
    return parseScene(defs + out);
}

Primitive prim(PrimType t, std::vector<double> r, std::vector<std::string> s = {}) {
    Primitive p;
    p.type = t;
    p.name = "x";
    p.modifierName = "m";
    p.rargs = std::move(r);
    p.sargs = std::move(s);
    return p;
}

void expectNear3(const std::vector<double>& r, size_t i, double x, double y, double z) {
    EXPECT_NEAR(r[i], x, 1e-12);
    EXPECT_NEAR(r[i + 1], y, 1e-12);
    EXPECT_NEAR(r[i + 2], z, 1e-12);
}

TEST(XformPrimitive, SphereCentreAndRadius) {
    Primitive p = prim(PrimType::Sphere, {1, 0, 0, 0.5});
    Transform xf = parseTransform({"-s", "2", "-rz", "90", "-t", "0", "0", "1"}, 0, {});
    transformPrimitive(p, xf, {});
    expectNear3(p.rargs, 0, 0, 2, 1);
    EXPECT_DOUBLE_EQ(p.rargs[3], 1.0);
    EXPECT_EQ(p.type, PrimType::Sphere);
}

TEST(XformPrimitive, PolygonOrderReversedByMirror) {
    std::vector<double> tri{0, 0, 0, 1, 0, 0, 0, 1, 0};
    Primitive p = prim(PrimType::Polygon, tri);
    transformPrimitive(p, Transform::translate(1, 0, 0), {});
    EXPECT_EQ(p.rargs, (std::vector<double>{1, 0, 0, 2, 0, 0, 1, 1, 0}));
    Primitive m = prim(PrimType::Polygon, tri);
    transformPrimitive(m, Transform::mirror(0), {});
    // Vertices mirrored then taken last to first: the normal stays +z, facing as before
    // relative to the mirrored geometry.
    EXPECT_EQ(m.rargs, (std::vector<double>{-0.0, 1, 0, -1, 0, 0, -0.0, 0, 0}));
    // Two mirrors make a rotation: no reversal.
    Primitive r = prim(PrimType::Polygon, tri);
    transformPrimitive(r, Transform::mirror(0).then(Transform::mirror(1)), {});
    expectNear3(r.rargs, 3, -1, 0, 0);
    // A negative scale mirrors too.
    Primitive s = prim(PrimType::Polygon, tri);
    transformPrimitive(s, Transform::uniformScale(-1), {});
    expectNear3(s.rargs, 0, 0, -1, 0);
    EXPECT_DOUBLE_EQ(s.rargs[3], -1);
}

TEST(XformPrimitive, RingNormalConeRadiiSourceDirection) {
    Primitive ring = prim(PrimType::Ring, {0, 0, 1, 0, 0, 1, 0.5, 1});
    Transform xf = parseTransform({"-ry", "90", "-s", "3"}, 0, {});
    transformPrimitive(ring, xf, {});
    expectNear3(ring.rargs, 0, 3, 0, 0);
    expectNear3(ring.rargs, 3, 3, 0, 0);  // directions scale with the matrix, as in RADIANCE
    EXPECT_DOUBLE_EQ(ring.rargs[6], 1.5);
    EXPECT_DOUBLE_EQ(ring.rargs[7], 3);

    Primitive cone = prim(PrimType::Cone, {0, 0, 0, 0, 0, 1, 1, 0.5});
    transformPrimitive(cone, Transform::uniformScale(2), {});
    expectNear3(cone.rargs, 3, 0, 0, 2);
    EXPECT_DOUBLE_EQ(cone.rargs[6], 2);
    EXPECT_DOUBLE_EQ(cone.rargs[7], 1);

    Primitive src = prim(PrimType::Source, {0, 0, 1, 0.5});
    transformPrimitive(src, Transform::rotateX(90).then(Transform::translate(5, 5, 5)), {});
    expectNear3(src.rargs, 0, 0, -1, 0);
    EXPECT_DOUBLE_EQ(src.rargs[3], 0.5);  // angle unchanged

    Primitive spot = prim(PrimType::Spotlight, {1, 1, 1, 30, 0, 0, -1});
    transformPrimitive(spot, Transform::rotateY(90), {});
    expectNear3(spot.rargs, 4, -1, 0, 0);
    EXPECT_DOUBLE_EQ(spot.rargs[3], 30);
}

TEST(XformPrimitive, MaterialsThatScale) {
    Transform s2 = Transform::uniformScale(2);
    Primitive glow = prim(PrimType::Glow, {1, 1, 1, 4});
    transformPrimitive(glow, s2, {});
    EXPECT_DOUBLE_EQ(glow.rargs[3], 8);
    Primitive mist = prim(PrimType::Mist, {0.2, 0.4, 0.8});
    transformPrimitive(mist, s2, {});
    EXPECT_DOUBLE_EQ(mist.rargs[1], 0.2);
    Primitive diel = prim(PrimType::Dielectric, {0.81, 0.81, 0.81, 1.5, 0});
    transformPrimitive(diel, s2, {});
    EXPECT_NEAR(diel.rargs[0], 0.9, 1e-15);
    EXPECT_DOUBLE_EQ(diel.rargs[3], 1.5);
    Primitive plastic = prim(PrimType::Plastic, {0.5, 0.5, 0.5, 0, 0.1});
    transformPrimitive(plastic, s2, {});
    EXPECT_EQ(plastic.rargs, (std::vector<double>{0.5, 0.5, 0.5, 0, 0.1}));
}

TEST(XformPrimitive, PatternGetsTransformAppended) {
    Primitive pat = prim(PrimType::Brightfunc, {},
                         {"foo", "bar.cal", "-s", "2", "-i", "3", "-t", "1", "0", "0"});
    transformPrimitive(pat, Transform::rotateZ(20), {"-rz", "20"});
    EXPECT_EQ(pat.sargs, (std::vector<std::string>{"foo", "bar.cal", "-s", "2", "-i", "3", "-t",
                                                   "1", "0", "0", "-i", "1", "-rz", "20"}));
    Primitive tex = prim(PrimType::Texfunc, {}, {"dx", "dy", "dz", "t.cal"});
    transformPrimitive(tex, Transform::rotateZ(20), {"-i", "2", "-rz", "10"});
    EXPECT_EQ(tex.sargs,
              (std::vector<std::string>{"dx", "dy", "dz", "t.cal", "-i", "2", "-rz", "10"}));
    Primitive inst = prim(PrimType::Instance, {}, {"chair.oct"});
    transformPrimitive(inst, Transform::translate(1, 2, 3));  // options derived from the matrix
    EXPECT_EQ(inst.sargs, (std::vector<std::string>{"chair.oct", "-i", "1", "-t", "1", "2", "3"}));
    Primitive ct = prim(PrimType::Colortext, {0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 1, 1, 0, 0, 0},
                        {"helvet.fnt", "hi"});
    transformPrimitive(ct, Transform::translate(0, 0, 2), {"-t", "0", "0", "2"});
    expectNear3(ct.rargs, 0, 0, 0, 2);
    expectNear3(ct.rargs, 6, 0, 0, -1);
    EXPECT_EQ(ct.sargs.size(), 2u);
}

TEST(XformPrimitive, TransformArgsRoundTrip) {
    Transform xf = parseTransform(
        {"-mz", "-s", "2.5", "-rx", "30", "-ry", "-40", "-rz", "75", "-t", "1", "-2", "3"}, 0, {});
    Transform back = parseTransform(transformArgs(xf), 0, {});
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(back.m[i][j], xf.m[i][j], 1e-12) << i << j;
    EXPECT_NEAR(back.scale, xf.scale, 1e-15);
    Transform lock = parseTransform({"-ry", "90", "-rz", "30"}, 0, {});
    Transform lockBack = parseTransform(transformArgs(lock), 0, {});
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(lockBack.m[i][j], lock.m[i][j], 1e-12);
    EXPECT_TRUE(transformArgs(Transform()).empty());
}

TEST(XformPrimitive, BadArgumentCounts) {
    Primitive p = prim(PrimType::Sphere, {0, 0, 0});
    p.loc = {"s.rad", 3};
    try {
        transformPrimitive(p, Transform(), {});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "s.rad:3: bad sphere 'x': expected 4 real arguments, got 3");
    }
    Primitive poly = prim(PrimType::Polygon, {0, 0, 0, 1});
    EXPECT_THROW(transformPrimitive(poly, Transform(), {}), InputError);
}

TEST(XformFormat, Layouts) {
    EXPECT_EQ(formatReal(2.5), "               2.5");
    EXPECT_EQ(formatWord("a b"), "\"a b\"");
    EXPECT_EQ(formatWord("say \"hi\""), "'say \"hi\"'");
    EXPECT_EQ(formatPrimitive(prim(PrimType::Sphere, {1, 2, 3, 0.5})),
              "m sphere x\n0\n0\n4                  1                  2                  3"
              "                0.5\n");
    EXPECT_EQ(formatPrimitive(prim(PrimType::Cylinder, {0, 0, 0, 0, 0, 1, 0.25})),
              "m cylinder x\n0\n0\n7\n"
              "                  0                  0                  0\n"
              "                  0                  0                  1\n"
              "               0.25\n");
    EXPECT_EQ(formatPrimitive(prim(PrimType::Spotlight, {1, 1, 1, 30, 0, 0, -1})),
              "m spotlight x\n0\n0\n7                  1                  1                  1"
              "                 30\n\t                 0                  0                 -1\n");
    EXPECT_EQ(formatPrimitive(prim(PrimType::Dielectric, {0.9, 0.9, 0.9, 1.5, 0})),
              "m dielectric x\n0\n0\n5          0.9          0.9          0.9          1.5"
              "            0\n");
    Primitive alias;
    alias.type = PrimType::Alias;
    alias.name = "new";
    alias.modifierName = "void";
    alias.sargs = {"old"};
    EXPECT_EQ(formatPrimitive(alias), "void alias new\n\told\n");
}

TEST(Xform, HeaderCommentsAndTypes) {
    std::string out = run({"-t", "1", "0", "0"},
                          "# a comment\nvoid plastic red 0 0 5 1 0 0 0 0\n"
                          "red sphere ball 0 0 4 0 0 0 1\n");
    EXPECT_EQ(out,
              "# xform -t 1 0 0\n"
              "# a comment\n"
              "\nvoid plastic red\n0\n0\n5                  1                  0                  0"
              "                  0                  0\n"
              "\nred sphere ball\n0\n0\n4                  1                  0                  0"
              "                  1\n");
}

TEST(Xform, NameAndModifierApplyToSurfacesOnly) {
    std::string out = run({"-n", "top", "-m", "gold", "-n", "sub"},
                          "void plastic red 0 0 5 1 0 0 0 0\nred sphere ball 0 0 4 0 0 0 1\n");
    EXPECT_NE(out.find("\nvoid plastic red\n"), std::string::npos) << out;
    EXPECT_NE(out.find("\ngold sphere top.sub.ball\n"), std::string::npos) << out;
    EXPECT_EQ(out.substr(0, out.find('\n')), "# xform -n top -m gold -n sub");
}

TEST(Xform, ArrayCopiesAndNames) {
    std::string out = run({"-a", "3", "-t", "1", "0", "0"}, "m sphere s 0 0 4 0 0 0 1\n");
    Scene s = readBack(out);
    ASSERT_EQ(s.prims.size(), 4u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(s.prims[k + 1].name, "a" + std::to_string(k) + ".s");
        EXPECT_DOUBLE_EQ(s.prims[k + 1].rargs[0], k);
    }
    EXPECT_EQ(out.substr(0, out.find('\n')), "# xform -n a0 -i 0 -t 1 0 0");
    EXPECT_NE(out.find("# xform -n a2 -i 2 -t 1 0 0\n"), std::string::npos);

    // Two-dimensional with a name and a final global move: 15 copies named name.i.j.
    out = run({"-n", "b", "-a", "5", "-t", "1", "0",  "0", "-a", "3",
               "-t", "0", "1",  "0", "-i", "1", "-t", "0", "0",  "10"},
              "m sphere s 0 0 4 0 0 0 1\n");
    s = readBack(out);
    ASSERT_EQ(s.prims.size(), 16u);
    EXPECT_EQ(s.prims[1].name, "b.0.0.s");
    EXPECT_EQ(s.prims[15].name, "b.4.2.s");
    expectNear3(s.prims[15].rargs, 0, 4, 2, 10);
    EXPECT_NE(out.find("# xform -n b.4.2 -i 4 -t 1 0 0 -i 2 -t 0 1 0 -i 1 -t 0 0 10\n"),
              std::string::npos);
}

TEST(Xform, ArrayAppendsIterationToPatterns) {
    std::string out = run({"-a", "2", "-rz", "90"}, "void brightfunc p 2 f f.cal 0 0\n");
    // The array's own "-i k" leads the options, so no "-i 1" reset is added.
    EXPECT_NE(out.find("\nvoid brightfunc p\n6 f f.cal -i 1 -rz 90\n0\n0\n"), std::string::npos)
        << out;
    EXPECT_NE(out.find("\nvoid brightfunc p\n6 f f.cal -i 0 -rz 90\n"), std::string::npos) << out;
}

TEST(Xform, IterationRepeatsFollowingTransform) {
    std::string out =
        run({"-i", "3", "-t", "1", "0", "0", "-i", "2", "-rz", "90"}, "m sphere s 0 0 4 0 0 0 1\n");
    Scene s = readBack(out);
    expectNear3(s.prims[1].rargs, 0, -3, 0, 0);  // (3,0,0) turned 180 degrees
}

TEST(Xform, CommandsExpandedByDefaultOrPassedOnWithC) {
    XformOptions o = opts({"-n", "n", "-t", "0", "0", "1"});
    o.commandHook = [](const std::string& cmd, const SourceLoc&,
                       const CommandContext&) -> std::optional<std::string> {
        EXPECT_EQ(cmd, "gen thing");
        return std::string("m sphere g 0 0 4 0 0 0 1\n");
    };
    std::string out = xformText(o, "!gen thing\n");
    EXPECT_NE(out.find("\nm sphere n.g\n0\n0\n4                  0                  0"
                       "                  1                  1\n"),
              std::string::npos)
        << out;
    out = run({"-c", "-n", "n", "-t", "0", "0", "1"}, "!gen thing\n");
    EXPECT_EQ(out, "# xform -c -n n -t 0 0 1\n\n!gen thing | xform -e -n n -t 0 0 1\n");
    // The shell runs what the hook declines.
    out = run({}, "!echo m sphere e 0 0 4 0 0 0 2\n");
    EXPECT_NE(out.find("\nm sphere e\n"), std::string::npos) << out;
}

TEST(Xform, InvertTurnsSurfacesInsideOut) {
    std::string out = run({"-I"},
                          "m sphere s 0 0 4 0 0 0 1\nm cone c 0 0 8 0 0 0 0 0 1 1 0\n"
                          "m polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
    Scene s = readBack(out);
    EXPECT_EQ(s.prims[1].type, PrimType::Bubble);
    EXPECT_EQ(s.prims[2].type, PrimType::Cup);
    expectNear3(s.prims[3].rargs, 0, 0, 1, 0);
}

TEST(Xform, BadInput) {
    EXPECT_THROW(opts({"-t", "1", "x", "0"}), InputError);
    EXPECT_THROW(opts({"-rx"}), InputError);  // missing value: not a transform, bad option
    EXPECT_THROW(opts({"-q", "file"}), InputError);
    EXPECT_THROW(opts({"-a", "0", "-t", "1", "0", "0"}), InputError);
    EXPECT_THROW(opts({"-a", "x"}), InputError);
    EXPECT_THROW(opts({"-s", "0"}), InputError);
    EXPECT_THROW(opts({"-f", "/nonexistent/args"}), InputError);
    try {
        opts({"-t", "1", "2", "3", "-q"});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "command line error at '-q'");
    }
    EXPECT_THROW(run({}, "m blob b 0 0 0\n"), InputError);
    EXPECT_THROW(run({}, "m sphere b 0 0 3 0 0 0\n"), InputError);
    EXPECT_THROW(run({}, "m sphere b 0 0 4 0 0 x 1\n"), InputError);
    EXPECT_THROW(run({}, "m sphere b 0 0 4 0 0 0\n"), InputError);
    try {
        run({}, "\n\nm polygon b 0 0 4 0 0 0 1\n");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "line 3: bad polygon 'b': expected a multiple of 3 real arguments, got 4");
    }
}

TEST(Xform, ArgumentFile) {
    std::string path = testing::TempDir() + "xform_args.txt";
    {
        std::ofstream f(path);
        f << "# copies\n-t 1 0 0\n\n!xform -rz 90\n";
    }
    std::string out = run({"-f", path}, "m sphere s 0 0 4 1 0 0 1\n");
    Scene s = readBack(out);
    ASSERT_EQ(s.prims.size(), 3u);
    EXPECT_EQ(s.prims[1].name, "i0.s");
    expectNear3(s.prims[1].rargs, 0, 2, 0, 0);
    EXPECT_EQ(s.prims[2].name, "i1.s");
    expectNear3(s.prims[2].rargs, 0, 0, 1, 0);
    EXPECT_NE(out.find("# xform -n i1 -rz 90\n"), std::string::npos) << out;
}

// The mirror box of the cornell validation scene: genbox output (written by hand here,
// genbox's corner numbering: bit 0 = x, bit 1 = y, bit 2 = z) through RADIANCE's xform.
TEST(Xform, CornellMirrorBox) {
    struct Face {
        const char* name;
        int corners[4];
    };
    const Face faces[] = {{"1540", {1, 5, 4, 0}}, {"4620", {4, 6, 2, 0}}, {"2310", {2, 3, 1, 0}},
                          {"3267", {3, 2, 6, 7}}, {"5137", {5, 1, 3, 7}}, {"6457", {6, 4, 5, 7}}};
    std::ostringstream genbox;
    genbox << "# genbox mirror_mat mbox 1.5 1.5 3.0\n";
    for (const Face& f : faces) {
        genbox << "\nmirror_mat polygon mbox." << f.name << "\n0\n0\n12\n";
        for (int c : f.corners)
            genbox << "\t\t" << (c & 1 ? 1.5 : 0) << "\t\t" << (c & 2 ? 1.5 : 0) << "\t\t"
                   << (c & 4 ? 3.0 : 0) << "\n";
    }
    std::string out =
        run({"-t", "-0.75", "-0.75", "0", "-rz", "20", "-t", "1.5", "3.6", "0"}, genbox.str());
    // scene.rad holds this output with the blank lines and header comments removed.
    std::string compact;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty() && line[0] != '#') compact += line + "\n";
    const std::string expected =
        "mirror_mat polygon mbox.1540\n0\n0\n12\n"
        "      2.46128457308       3.1517456419                  0\n"
        "      2.46128457308       3.1517456419                  3\n"
        "       1.0517456419      2.63871542692                  3\n"
        "       1.0517456419      2.63871542692                  0\n";
    EXPECT_EQ(compact.substr(0, expected.size()), expected);

    RP_REQUIRE_SHARED("validation/cornell/scene.rad");
    std::ifstream ref(std::string(RP_SHARED_DIR) + "/validation/cornell/scene.rad");
    std::string refText, refBox;
    for (std::string line; std::getline(ref, line);) refText += line + "\n";
    size_t at = refText.find("mirror_mat polygon mbox.1540");
    ASSERT_NE(at, std::string::npos);
    refBox = refText.substr(at, compact.size());
    EXPECT_EQ(compact, refBox);
}

}  // namespace
}  // namespace rp

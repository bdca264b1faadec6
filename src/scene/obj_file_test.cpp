// OBJ reading as RADIANCE's obj2mesh reads it: face forms, relative indices, the
// polygon splitter's triangle order, materials, and one-line errors.
#include "scene/obj_file.h"

#include <gtest/gtest.h>

#include "scene/reader.h"
#include "util/warning_capture_for_tests.h"

namespace rp {
namespace {

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

// Corner positions of triangle t as vertex numbers 1..4 of kSquare-like inputs, by
// matching x + 2y + 4z + 1 (unique for the unit-grid points used here).
std::array<int, 3> ids(const ObjMesh& m, size_t t) {
    std::array<int, 3> r{};
    for (int k = 0; k < 3; ++k) {
        const auto& v = m.triangles[t].v[k];
        r[k] = static_cast<int>(v[0] + 2 * v[1] + 4 * v[2]) + 1;
    }
    return r;
}

TEST(ObjFile, FaceFormsAndNegativeIndices) {
    WarningCapture warnings;
    std::string text = std::string(kSquare) +
                       "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 2\n"
                       "f 1 2 3\nf 1/1 2/2 3/3\nf 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/3/1\n"
                       "f -4/-3/-1 -3/-2/-1 -2/-1/-1\n";
    ObjMesh m = parseObj(text, "t.obj");
    ASSERT_EQ(m.triangles.size(), 5u);
    EXPECT_FALSE(m.triangles[0].hasUV || m.triangles[0].hasNormals);
    EXPECT_TRUE(m.triangles[1].hasUV && !m.triangles[1].hasNormals);
    EXPECT_TRUE(!m.triangles[2].hasUV && m.triangles[2].hasNormals);
    EXPECT_DOUBLE_EQ(m.triangles[2].n[0][2], 1.0);  // normalised
    EXPECT_TRUE(m.triangles[3].hasUV && m.triangles[3].hasNormals);
    for (int t = 0; t < 5; ++t) EXPECT_EQ(ids(m, t), (std::array<int, 3>{1, 2, 4})) << t;
    EXPECT_DOUBLE_EQ(m.triangles[4].uv[2][0], 1.0);
    EXPECT_DOUBLE_EQ(m.triangles[4].uv[2][1], 1.0);
}

// RADIANCE's ear clipper starts at the last corner: a quad 1 2 3 4 becomes
// (4 1 2) (2 3 4), a pentagon 1..5 becomes (5 1 2) (2 3 4) (4 5 2); a clockwise
// polygon is split the same way and its triangles keep its orientation.
TEST(ObjFile, PolygonsSplitAsRadiance) {
    WarningCapture warnings;
    ObjMesh q = parseObj(std::string(kSquare) + "f 1 2 3 4\n", "q.obj");
    ASSERT_EQ(q.triangles.size(), 2u);
    EXPECT_EQ(ids(q, 0), (std::array<int, 3>{3, 1, 2}));  // vertex 4 is (0,1): id 3
    EXPECT_EQ(ids(q, 1), (std::array<int, 3>{2, 4, 3}));  // vertex 3 is (1,1): id 4

    ObjMesh cw = parseObj(std::string(kSquare) + "f 4 3 2 1\n", "cw.obj");
    ASSERT_EQ(cw.triangles.size(), 2u);
    for (const auto& t : cw.triangles) {
        double cz = (t.v[1][0] - t.v[0][0]) * (t.v[2][1] - t.v[0][1]) -
                    (t.v[1][1] - t.v[0][1]) * (t.v[2][0] - t.v[0][0]);
        EXPECT_LT(cz, 0);  // still facing -z like the input
    }

    ObjMesh p = parseObj("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n", "p.obj");
    ASSERT_EQ(p.triangles.size(), 3u);
    auto first = [&](size_t t, int k) { return p.triangles[t].v[k]; };
    EXPECT_EQ(first(0, 0), (std::array<double, 3>{-1, 1, 0}));  // 5
    EXPECT_EQ(first(0, 1), (std::array<double, 3>{0, 0, 0}));   // 1
    EXPECT_EQ(first(1, 0), (std::array<double, 3>{2, 0, 0}));   // 2
    EXPECT_EQ(first(1, 2), (std::array<double, 3>{1, 2, 0}));   // 4
    EXPECT_EQ(first(2, 0), (std::array<double, 3>{1, 2, 0}));   // 4
    EXPECT_EQ(first(2, 2), (std::array<double, 3>{2, 0, 0}));   // 2

    // A non-convex face: no triangle may cover the notch at (4, -2).
    ObjMesh h =
        parseObj("v 3 -3 0\nv 5 -3 0\nv 5 -1 0\nv 4 -2 0\nv 3 -1 0\nf 1 2 3 4 5\n", "h.obj");
    ASSERT_EQ(h.triangles.size(), 3u);
}

TEST(ObjFile, MaterialsFollowUsemtlThenGroup) {
    WarningCapture warnings;
    std::string text = std::string(kSquare) +
                       "f 1 2 3\ng walls\nf 1 2 3\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 2 3\n"
                       "usemtl void\nf 1 2 3\nmtllib x.mtl\ns 1\n";
    ObjMesh m = parseObj(text, "m.obj");
    ASSERT_EQ(m.materialNames, (std::vector<std::string>{"", "walls", "red", "blue", "void"}));
    EXPECT_EQ(m.unrecognised, 2);
    ASSERT_EQ(warnings.lines.size(), 1u);
    EXPECT_EQ(warnings.lines[0], "m.obj: 2 of 15 statements unrecognized");
    Scene mats = parseScene(
        "void plastic red 0 0 5 1 0 0 0 0\nvoid plastic blue 0 0 5 0 0 1 0 0\n"
        "void plastic walls 0 0 5 1 1 1 0 0\nvoid plastic red 0 0 5 1 1 0 0 0\n");
    assignObjMaterials(m, mats);
    EXPECT_EQ(m.triangles[0].material, kVoid);
    EXPECT_EQ(m.triangles[1].material, 2);
    EXPECT_EQ(m.triangles[2].material, 3);  // the latest "red"
    EXPECT_EQ(m.triangles[3].material, 1);
    EXPECT_EQ(m.triangles[4].material, kVoid);
    // Without materials everything is void, as obj2mesh without -a.
    ObjMesh v = parseObj(text, "m.obj");
    assignObjMaterials(v, Scene{});
    for (const auto& t : v.triangles) EXPECT_EQ(t.material, kVoid);
}

TEST(ObjFile, UndefinedMaterialIsAnErrorAtTheFace) {
    WarningCapture warnings;
    ObjMesh m = parseObj(std::string(kSquare) + "usemtl green\nf 1 2 3\n", "g.obj");
    Scene mats = parseScene("void plastic red 0 0 5 1 0 0 0 0\n");
    try {
        assignObjMaterials(m, mats);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "g.obj:6: undefined modifier \"green\"");
    }
}

TEST(ObjFile, LineContinuationAndComments) {
    WarningCapture warnings;
    ObjMesh m =
        parseObj(std::string(kSquare) + "f 1 \\\n 2 3 # a comment\n# f 1 2 4\nf 1 2 4\n", "c.obj");
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1].loc.line, 8);
}

void expectError(const std::string& text, const std::string& message) {
    try {
        parseObj(text, "bad.obj");
        ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), message);
    }
}

TEST(ObjFile, BadInputsNameFileAndLine) {
    WarningCapture warnings;
    expectError("v 0 0 x\n", "bad.obj:1: bad vertex 'x'");
    expectError("v 0 0\n", "bad.obj:1: bad vertex");
    expectError("vn 0 0 0\n", "bad.obj:1: zero normal");
    expectError("vt a\n", "bad.obj:1: bad texture coordinate 'a'");
    expectError(std::string(kSquare) + "f 1 2 5\n",
                "bad.obj:5: vertex index 5 out of range (4 defined)");
    expectError(std::string(kSquare) + "f 1 2 -5\n",
                "bad.obj:5: vertex index -5 out of range (4 defined)");
    expectError(std::string(kSquare) + "f 1 2 0\n",
                "bad.obj:5: vertex index 0 out of range (4 defined)");
    expectError(std::string(kSquare) + "f 1/1 2 3\n",
                "bad.obj:5: texture vertex index 1 out of range (0 defined)");
    expectError(std::string(kSquare) + "f 1//2 2 3\n",
                "bad.obj:5: normal index 2 out of range (0 defined)");
    expectError(std::string(kSquare) + "f 1 2\n", "bad.obj:5: face with fewer than 3 vertices");
    expectError(std::string(kSquare) + "f 1 2 3 a\n", "bad.obj:5: bad vertex index 'a'");
}

TEST(ObjFile, MeshDataMergesEqualVertices) {
    WarningCapture warnings;
    ObjMesh m = parseObj(std::string(kSquare) + "f 1 2 3 4\n", "q.obj");
    assignObjMaterials(m, Scene{});
    MeshData d = objToMeshData(m, Scene{});
    EXPECT_EQ(d.vertexCount(), 4u);
    EXPECT_EQ(d.positions.size(), 13u);  // 3 per vertex and the pad
    EXPECT_EQ(d.triangleCount(), 2u);
    EXPECT_TRUE(d.triangleMaterial.empty());
    EXPECT_EQ(d.soleMaterial, kVoid);
}

}  // namespace
}  // namespace rp

// RADIANCE compiled mesh (.rtm) reading: real obj2mesh output checked against numbers
// RADIANCE's own reader gives, a small hand-built mesh, and damaged files.
#include "scene/mesh_file.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/test_bytes.h"
#include "util/shared_for_tests.h"

namespace rp {
namespace {

using testing::PortableBytes;

const std::string kRenders = std::string(RP_SHARED_DIR) + "/radiance-tests/renders/";

// One vertex of a triangle as RADIANCE's getmeshtri() gives it.
struct RefVertex {
    double p[3], n[3], uv[2];
};

void expectVertex(const MeshData& m, size_t tri, int k, const RefVertex& ref) {
    SCOPED_TRACE("triangle " + std::to_string(tri) + " vertex " + std::to_string(k));
    uint32_t v = m.triangles[3 * tri + k];
    for (int j = 0; j < 3; ++j) {
        // Floats hold the quantised positions to about 1e-7 of the cube.
        EXPECT_NEAR(m.positions[3 * v + j], ref.p[j], 1e-7 * m.cubeSize);
        EXPECT_NEAR(m.normals[v][j], ref.n[j], 1e-6);
    }
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(m.uvs[v][j], ref.uv[j], 1e-6);
    EXPECT_EQ(m.flagsOf(v), MeshData::kHasNormal | MeshData::kHasUV);
}

// The reference numbers below come from a one-off C program (not kept) linked with
// RADIANCE 5.4's librtrad.a: readmesh(&mesh, "woman.rtm", IO_BOUNDS|IO_SCENE), then
// the sums of nverts/ntris/nj1tris/nj2tris over the patches, and getmeshtri(tv, &mo,
// &mesh, id, MT_ALL) printed with %.9g for the triangle IDs that are our triangles 0,
// 1643 (patch 3's first single joiner, ID 3<<10|0x200) and 43209 (the last, patch 97's
// third double joiner, ID 97<<10|0x302). `getinfo -d woman.rtm` printed the cube.
TEST(MeshFile, ReadsWomanLikeRadiance) {
    RP_REQUIRE_SHARED("radiance-tests/renders");
    MeshData m = readMeshFile(kRenders + "woman.rtm");
    EXPECT_EQ(m.path, kRenders + "woman.rtm");
    EXPECT_EQ(m.vertexCount(), 25075u);
    EXPECT_EQ(m.positions.size(), 3 * 25075u + 1);
    EXPECT_EQ(m.triangleCount(), 43210u);  // 11180 single and 697 double joiners among them
    ASSERT_EQ(m.materials.prims.size(), 21u);
    EXPECT_EQ(m.normals.size(), 25075u);  // every vertex has a normal and (u, v)
    EXPECT_EQ(m.uvs.size(), 25075u);
    ASSERT_EQ(m.vertexFlags.size(), 25075u);
    for (uint8_t f : m.vertexFlags) ASSERT_EQ(f, MeshData::kHasNormal | MeshData::kHasUV);
    // getinfo -d woman.rtm: -0.35954959 -0.00265538 -0.34914834 0.71904138
    EXPECT_DOUBLE_EQ(m.cubeOrigin[0], -0.35954959);
    EXPECT_DOUBLE_EQ(m.cubeOrigin[2], -0.34914834);
    EXPECT_DOUBLE_EQ(m.cubeSize, 0.71904138);
    // mesh.uvlim: 0.00419769534 0.0145613678 (min) 0.997283305 0.985609632 (max)
    EXPECT_NEAR(m.uvLimits[0][0], 0.00419769534, 1e-11);
    EXPECT_NEAR(m.uvLimits[0][1], 0.0145613678, 1e-10);
    EXPECT_NEAR(m.uvLimits[1][0], 0.997283305, 1e-9);
    EXPECT_NEAR(m.uvLimits[1][1], 0.985609632, 1e-9);

    ASSERT_EQ(m.triangleMaterial.size(), 43210u);
    EXPECT_EQ(m.materials.prims[5].name, "hair");  // woman.mat via obj2mesh -a
    EXPECT_EQ(m.materials.prims[5].type, PrimType::Plastic);
    EXPECT_EQ(m.materialOf(0), 5);
    EXPECT_EQ(m.materials.prims[m.materialOf(1643)].name, "skin:1");
    EXPECT_EQ(m.materials.prims[m.materialOf(43209)].name, "sole:4");

    expectVertex(m, 0, 0,
                 {{0.013013, 0.696317, 0.038317},
                  {0.243515042, -0.323449437, 0.914374588},
                  {0.135581, 0.85148}});
    expectVertex(m, 0, 2,
                 {{0.010416, 0.695879, 0.037508},
                  {-0.458284777, -0.397945531, 0.79474173},
                  {0.120618, 0.860376}});
    expectVertex(m, 1643, 0,
                 {{0.020808, 0.682001, 0.0277489999},
                  {0.684680896, 0.356856144, 0.635504338},
                  {0.870222, 0.890555}});
    expectVertex(m, 1643, 2,
                 {{0.023183, 0.684797, 0.022239},
                  {0.856408409, 0.311709612, 0.411584445},
                  {0.878748, 0.900591}});
    expectVertex(m, 43209, 0,
                 {{-0.0709437, 0.00106002006, 0.010238},
                  {-0.308256722, -0.925485939, -0.220121714},
                  {0.617468, 0.609592}});
    expectVertex(m, 43209, 1,
                 {{-0.0712416, 0.00127497004, 0.0102276},
                  {-0.865342622, -0.425223359, -0.265268246},
                  {0.614678, 0.609583}});
    expectVertex(m, 43209, 2,
                 {{-0.0699676999, 0.00204993999, 0.00450557999},
                  {-0.864328655, -0.454313954, -0.21571928},
                  {0.624827, 0.663461}});
}

// Same program on vase.rtm (obj2mesh vase.obj, no materials: every triangle void).
// Triangles 422 and 470 are patch 0's first single and double joiners (IDs 0x200, 0x300).
TEST(MeshFile, ReadsVaseLikeRadiance) {
    RP_REQUIRE_SHARED("radiance-tests/renders");
    MeshData m = readMeshFile(kRenders + "vase.rtm");
    EXPECT_EQ(m.vertexCount(), 1617u);
    EXPECT_EQ(m.triangleCount(), 3072u);  // 444 single and 14 double joiners among them
    EXPECT_TRUE(m.materials.prims.empty());
    EXPECT_TRUE(m.triangleMaterial.empty());
    EXPECT_EQ(m.soleMaterial, kVoid);
    EXPECT_EQ(m.normals.size(), 1617u);
    EXPECT_EQ(m.uvs.size(), 1617u);
    // getinfo -d vase.rtm: -48.00001 -28.00001 -130.00001 46.00002
    EXPECT_DOUBLE_EQ(m.cubeOrigin[1], -28.00001);
    EXPECT_DOUBLE_EQ(m.cubeSize, 46.00002);
    EXPECT_NEAR(m.uvLimits[0][0], -3.15175781e-05, 1e-13);
    EXPECT_NEAR(m.uvLimits[1][1], 1.00003152, 1e-8);

    expectVertex(m, 0, 1,
                 {{-25.32464, -2.53411, -85.4375},
                  {-0.118175148, 0.897544765, 0.424791748},
                  {0.27083, 0.96875}});
    expectVertex(m, 422, 0,
                 {{-16.94875, -0.351610003, -102.6875},
                  {0.821061718, 0.473995425, 0.318097458},
                  {0.08333, 0.59375}});
    expectVertex(m, 470, 1,
                 {{-26.44856, 6.00288, -108.4375},
                  {-0.125598861, 0.953941922, 0.272432992},
                  {0.27083, 0.46875}});
    expectVertex(m, 3071, 2,
                 {{-37.36829, -8.31407, -118.5},
                  {-0.965881503, -0.258794078, 0.00992705771},
                  {0.54167, 0.25}});
}

// A small mesh built by hand: 2 patches, a material list with an alias, a normal and a
// (u, v) missing here and there, a single joiner pointing ahead to patch 1, a double
// joiner back into patch 0 with the void material. Fields are parameters so that tests
// can damage them one at a time.
struct SmallMesh {
    int magic = 319 + 4;
    std::string cubeSize = "2";
    int64_t patchCount = 2;
    int flags0 = 7;
    int64_t verts0 = 3;
    int local2 = 2;           // third vertex of patch 0's local triangle
    int64_t joinId = 1 << 8;  // patch 1, vertex 0
    int64_t joinMat = 1;
    int64_t soleMat = 0;
    std::string trailing;

    std::string bytes() const {
        PortableBytes b;
        b.s = "#?RADIANCE\nobj2mesh small.obj\nFORMAT=Radiance_tmesh\n\n";
        b.i(magic, 2).str("0").str("0").str("0").str(cubeSize);
        b.real(-1).real(1).real(0).real(4);         // umin umax vmin vmax
        b.i(2, 1).i(1, 1).i(2, 4).i(0, 4).i(1, 4);  // tree: one full child with set {0, 1}
        for (int k = 0; k < 7; ++k) b.i(0, 1);
        b.str("plastic").str("alias").str("");
        b.i(0, 1).i(-1, 4).str("red mat").i(0, 2).i(5, 2);
        for (double v : {0.5, 0.25, 0.125, 0.0, 0.0}) b.real(v);
        b.i(1, 1).i(0, 4).str("red2").i(0, 2).i(0, 2);  // inherit alias: a copy of red mat
        b.i(-1, 1);
        b.i(patchCount, 4);
        // patch 0
        b.i(flags0, 1).i(verts0, 2);
        const int64_t half = int64_t{1} << 31;
        b.i(0, 4).i(0, 4).i(0, 4);
        b.i(half, 4).i(0, 4).i(0, 4);
        b.i(0, 4).i(half, 4).i(0, 4);
        for (int64_t k = 3; k < verts0; ++k) b.i(0, 4).i(0, 4).i(0, 4);
        b.i(8, 4).i(0, 4).i(17, 4);  // normals: +z, none, -x
        for (int64_t k = 3; k < verts0; ++k) b.i(0, 4);
        b.i(0, 4).i(0, 4);            // no (u, v)
        b.i(half, 4).i(half / 2, 4);  // u = 0 + 1e-10, v = 1
        b.i(half / 2, 4).i(0, 4);     // u = -0.5
        for (int64_t k = 3; k < verts0; ++k) b.i(0, 4).i(0, 4);
        b.i(1, 2).i(0, 1).i(1, 1).i(local2, 1);  // local triangle 0 1 2
        b.i(1, 2).i(soleMat, 2);
        b.i(1, 2).i(joinId, 4).i(1, 1).i(2, 1).i(joinMat, 2);
        b.i(0, 2);
        // patch 1: positions only, no local triangles, a double joiner
        b.i(1, 1).i(2, 2);
        b.i(0, 4).i(0, 4).i(half, 4);
        b.i(half, 4).i(0, 4).i(half, 4);
        b.i(0, 2).i(1, 2).i(-1, 2);
        b.i(0, 2);
        b.i(1, 2).i(0, 4).i(1, 4).i(1, 1).i(-1, 2);
        return b.s + trailing;
    }
};

TEST(MeshFile, DecodesSmallMesh) {
    MeshData m = decodeMeshFile(SmallMesh{}.bytes(), "small.rtm");
    EXPECT_EQ(m.path, "small.rtm");
    ASSERT_EQ(m.vertexCount(), 5u);
    const float tiny = static_cast<float>(0.5 * 2 / 4294967296.0);
    EXPECT_EQ(m.positions[0], tiny);
    EXPECT_FLOAT_EQ(m.positions[3], 1.0f);
    EXPECT_FLOAT_EQ(m.positions[3 * 3 + 2], 1.0f);
    EXPECT_EQ(m.positions.back(), 0.0f);
    EXPECT_EQ(m.triangles, (std::vector<uint32_t>{0, 1, 2, 3, 1, 2, 0, 1, 4}));
    EXPECT_EQ(m.triangleMaterial, (std::vector<int32_t>{0, 1, kVoid}));
    ASSERT_EQ(m.materials.prims.size(), 2u);
    EXPECT_EQ(m.materials.prims[1].name, "red2");
    EXPECT_EQ(m.materials.prims[1].rargs.size(), 5u);
    EXPECT_DOUBLE_EQ(m.materials.prims[1].rargs[1], 0.25);
    EXPECT_EQ(m.vertexFlags, (std::vector<uint8_t>{2, 4, 6, 0, 0}));
    EXPECT_EQ(m.normals[0], (std::array<float, 3>{0, 0, 1}));
    EXPECT_EQ(m.normals[1], (std::array<float, 3>{0, 0, 0}));
    EXPECT_EQ(m.normals[2], (std::array<float, 3>{-1, 0, 0}));
    EXPECT_NEAR(m.uvs[1][0], 0.0, 1e-6);
    EXPECT_NEAR(m.uvs[1][1], 1.0, 1e-6);
    EXPECT_NEAR(m.uvs[2][0], -0.5, 1e-6);
    EXPECT_EQ(m.uvs[0], (std::array<float, 2>{0, 0}));
    EXPECT_DOUBLE_EQ(m.uvLimits[1][1], 4.0);  // vmax

    SmallMesh oneMaterial;
    oneMaterial.joinMat = 0;
    EXPECT_EQ(decodeMeshFile(oneMaterial.bytes(), "m").triangleMaterial.size(), 3u);  // void one
}

void expectMeshError(const SmallMesh& mesh, const std::string& part) {
    try {
        decodeMeshFile(mesh.bytes(), "bad.rtm");
        ADD_FAILURE() << "no error, expected " << part;
    } catch (const InputError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind("bad.rtm: ", 0), 0u) << what;
        EXPECT_NE(what.find(part), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(MeshFile, EveryTruncationIsAnError) {
    std::string bytes = SmallMesh{}.bytes();
    for (size_t n = 0; n < bytes.size(); ++n) {
        try {
            decodeMeshFile(std::string_view(bytes).substr(0, n), "cut.rtm");
            ADD_FAILURE() << "prefix of " << n << " bytes accepted";
        } catch (const InputError& e) {
            ASSERT_EQ(std::string(e.what()).rfind("cut.rtm: ", 0), 0u) << n << ": " << e.what();
        }
    }
}

TEST(MeshFile, DamageIsAnError) {
    SmallMesh m;
    m.magic = 319;
    expectMeshError(m, "incompatible mesh file format");
    m = {};
    m.cubeSize = "0";
    expectMeshError(m, "cube size");
    m = {};
    m.cubeSize = "two";
    expectMeshError(m, "not a number");
    m = {};
    m.patchCount = 0x7fffffff;
    expectMeshError(m, "impossible patch count");
    m = {};
    m.patchCount = 3;
    expectMeshError(m, "truncated mesh file");
    m = {};
    m.patchCount = -1;
    expectMeshError(m, "impossible patch count");
    m = {};
    m.verts0 = 0;
    expectMeshError(m, "0 vertices in patch 0");
    m = {};
    m.verts0 = 257;
    expectMeshError(m, "257 vertices in patch 0");
    m = {};
    m.flags0 = 6;
    expectMeshError(m, "flags 6 of patch 0");
    m = {};
    m.local2 = 3;
    expectMeshError(m, "vertex 3 of a triangle in patch 0 out of range");
    m = {};
    m.joinId = 1 << 8 | 2;  // patch 1 has 2 vertices
    expectMeshError(m, "refers to vertex 2 of patch 1");
    m = {};
    m.joinId = 2 << 8;
    expectMeshError(m, "of patch 2, which does not exist");
    m = {};
    m.joinId = -5;
    expectMeshError(m, "joiner vertex ID -5");
    m = {};
    m.joinMat = 2;
    expectMeshError(m, "material 2 of a triangle in patch 0 out of range (2 materials)");
    m = {};
    m.soleMat = -2;
    expectMeshError(m, "material -2");
    m = {};
    m.trailing = "x";
    expectMeshError(m, "unexpected bytes");
    EXPECT_THROW(decodeMeshFile("#?RADIANCE\nFORMAT=Radiance_octree\n\n\x01\x47", "o"), InputError);
    EXPECT_THROW(decodeMeshFile("plain text", "t"), InputError);
    try {
        readMeshFile("/nonexistent/m.rtm");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/m.rtm: cannot open mesh file", 0), 0u);
    }
}

}  // namespace
}  // namespace rp

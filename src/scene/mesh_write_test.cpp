// The .rtm writer against files that RADIANCE 5.4's obj2mesh writes byte for byte
// (tests/data/obj2mesh/README.md says how they were checked), and its building blocks.
#include "scene/mesh_write.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "scene/mesh_build.h"
#include "scene/mesh_file.h"
#include "scene/obj_file.h"
#include "scene/radiance_objects.h"
#include "scene/reader.h"
#include "util/warning_capture_for_tests.h"

namespace rp {
namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

const std::string kData = std::string(RP_SOURCE_DIR) + "/tests/data/obj2mesh/";

std::string convert(const std::string& name, bool withMaterials, MeshStats* stats = nullptr) {
    Scene mats;
    if (withMaterials) mats = parseScene(slurp(kData + "cube.rad"), "cube.rad");
    ObjMesh obj = parseObj(slurp(kData + name + ".obj"), name + ".obj");
    assignObjMaterials(obj, mats);
    MeshSource src{obj.triangles, mats};
    std::string cmd =
        "obj2mesh " + std::string(withMaterials ? "-a cube.rad " : "") + name + ".obj";
    return encodeMeshFile(src, MeshWriteOptions{}, {cmd}, stats);
}

TEST(MeshWrite, CubeMatchesRadianceBytes) {
    WarningCapture warnings;
    EXPECT_EQ(convert("cube", true), slurp(kData + "cube.rtm"));
}

// 676 vertices: three patches, single and double joiner triangles, two materials.
TEST(MeshWrite, GridMatchesRadianceBytes) {
    WarningCapture warnings;
    MeshStats s;
    EXPECT_EQ(convert("grid", true, &s), slurp(kData + "grid.rtm"));
    EXPECT_EQ(s.patches, 3);
    EXPECT_GT(s.joinerTris, 0);
    EXPECT_EQ(s.materials, 2);
    EXPECT_EQ(s.withNormal, 676);
}

// 5046 triangles: RADIANCE obj2mesh -v printed these numbers for dense.obj.
TEST(MeshWrite, DenseOctreeStatsMatchRadiance) {
    WarningCapture warnings;
    MeshStats s;
    convert("dense", false, &s);
    EXPECT_EQ(formatMeshStats(s),
              "Mesh statistics:\n\t0 materials\n\t10 patches (0.05 MBytes)\n"
              "\t2532 vertices (0.0% w/ normals, 0.0% w/ uv)\n"
              "\t5046 triangles (79.7% local, 19.7% joiner)\n"
              "\t12552 leaves in octree (45.6% empty, 4.92 avg. set size)\n");
}

TEST(MeshWrite, MeshDataPathGivesTheSameFile) {
    WarningCapture warnings;
    Scene mats = parseScene(slurp(kData + "cube.rad"), "cube.rad");
    ObjMesh obj = parseObj(slurp(kData + "cube.obj"), "cube.obj");
    assignObjMaterials(obj, mats);
    MeshData d = objToMeshData(obj, mats);  // cube coordinates are exact floats
    EXPECT_EQ(encodeMeshFile(d, 9, 16384, {"obj2mesh -a cube.rad cube.obj"}),
              slurp(kData + "cube.rtm"));
}

TEST(MeshWrite, DegenerateAndEmptyInput) {
    WarningCapture warnings;
    MeshSource src;
    MeshTriangleInput t;
    t.v = {{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}};  // collinear: zero area, dropped
    src.triangles.push_back(t);
    EXPECT_THROW(encodeMeshFile(src, {}, {}), InputError);
    t.material = 3;  // out of range
    t.v = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    src.triangles = {t};
    EXPECT_THROW(encodeMeshFile(src, {}, {}), InputError);
}

// dircode.c's code for the axes and a diagonal, worked by hand from its rule.
TEST(MeshWrite, DirectionCode) {
    WarningCapture warnings;
    using meshbuild::encodeDirection;
    // The largest component is implied; the two others are stored.
    EXPECT_EQ(encodeDirection({0, 0, 1}), 010);
    EXPECT_EQ(encodeDirection({0, 0, -1}), 04 | 010);
    EXPECT_EQ(encodeDirection({1, 0, 0}), 020 | (0 << 5) | (0 << 18));
    double r = 1 / std::sqrt(3.0);
    int c = static_cast<int>(r * 11584.5 + .5);
    EXPECT_EQ(encodeDirection({r, r, r}), 010 | c << 5 | 020 | c << 18);
    EXPECT_EQ(encodeDirection({0, 0, 0}), 0);
}

TEST(RadianceObjects, RecordLayout) {
    WarningCapture warnings;
    Scene s = parseScene("void plastic red 0 0 5 .5 0 0 0 0\nred plastic b 0 0 5 -2 0 0 0 0\n");
    std::string out;
    encodeRadianceObjects(s, 4, out);
    std::string table;
    for (const char* n : {"polygon", "cone", "sphere"}) table += std::string(n) + '\0';
    EXPECT_EQ(out.substr(0, table.size()), table);
    size_t start = out.find(std::string("ashik2\0\0", 8)) + 8;
    // plastic is type 12; void is -1 in 4 bytes; 5 reals: .5 = 0.5*2^0 -> mantissa
    // 0x3fffffff, exponent 0.
    std::string rec = out.substr(start);
    ASSERT_GE(rec.size(), 20u);
    EXPECT_EQ(static_cast<unsigned char>(rec[0]), 12);
    EXPECT_EQ(rec.substr(1, 4), std::string("\xff\xff\xff\xff", 4));
    EXPECT_EQ(rec.substr(5, 4), std::string("red\0", 4));
    EXPECT_EQ(rec.substr(9, 4), std::string("\0\0\0\x05", 4));  // 0 sargs, 5 rargs
    EXPECT_EQ(rec.substr(13, 5), std::string("\x3f\xff\xff\xff\x00", 5));
    // second record: modifier 0 (red); -2 = -0.5*2^2, mantissa truncated toward zero
    const size_t second = 38;
    EXPECT_EQ(static_cast<unsigned char>(rec[second]), 12);
    EXPECT_EQ(rec.substr(second + 1, 4), std::string("\0\0\0\0", 4));
    EXPECT_EQ(rec.substr(second + 5, 2), std::string("b\0", 2));
    EXPECT_EQ(rec.substr(second + 11, 5), std::string("\xc0\x00\x00\x01\x02", 5));
    EXPECT_EQ(static_cast<unsigned char>(out.back()), 0xff);  // end mark
}

}  // namespace
}  // namespace rp

namespace rp {
namespace {

// OBJ -> our obj2mesh -> our mesh reader: every OBJ triangle comes back once, with its
// corners in the same cyclic order (orientation), positions within the 32-bit
// quantisation of the mesh cube (and float), normals within the 32-bit direction code,
// (u, v) within the quantisation of their range.
struct Corner {
    std::array<double, 3> p, n;
    std::array<double, 2> uv;
};
using Tri = std::array<Corner, 3>;

double dist(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::fmax(std::fabs(a[0] - b[0]),
                     std::fmax(std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])));
}

// The corner of `w` that corner 0 of `got` is (cyclic order kept, or reversed when
// `reversed`), if every corner lies within tol; -1 otherwise.
int matchCorners(const Tri& got, const Tri& w, bool reversed, double tol) {
    for (int s = 0; s < 3; ++s) {
        bool ok = true;
        for (int k = 0; k < 3 && ok; ++k) {
            int j = reversed ? (s - k + 3) % 3 : (s + k) % 3;
            ok = dist(got[size_t(k)].p, w[size_t(j)].p) <= tol;
        }
        if (ok) return s;
    }
    return -1;
}

void expectRoundTrip(const std::string& name, bool materials) {
    WarningCapture quiet;
    ObjMesh obj = parseObj(slurp(kData + name + ".obj"), name + ".obj");
    MeshData back = decodeMeshFile(convert(name, materials), name + ".rtm");
    std::vector<Tri> want;
    std::vector<bool> faceAway;  // RADIANCE turns such triangles over (cvmesh.c cvtri)
    for (const MeshTriangleInput& t : obj.triangles) {
        Tri tri;
        for (size_t k = 0; k < 3; ++k)
            tri[k] = {t.v[k], t.hasNormals ? t.n[k] : std::array<double, 3>{},
                      t.hasUV ? t.uv[k] : std::array<double, 2>{}};
        want.push_back(tri);
        bool away = t.hasNormals;
        const std::array<double, 3> e1{t.v[1][0] - t.v[0][0], t.v[1][1] - t.v[0][1],
                                       t.v[1][2] - t.v[0][2]};
        const std::array<double, 3> e2{t.v[2][0] - t.v[1][0], t.v[2][1] - t.v[1][1],
                                       t.v[2][2] - t.v[1][2]};
        const std::array<double, 3> fn{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                       e1[0] * e2[1] - e1[1] * e2[0]};
        for (size_t k = 0; k < 3 && away; ++k)
            away = fn[0] * t.n[k][0] + fn[1] * t.n[k][1] + fn[2] * t.n[k][2] < 0;
        faceAway.push_back(away);
    }
    ASSERT_EQ(back.triangleCount(), obj.triangles.size()) << name;
    const double tol = 1e-6 * back.cubeSize + 1e-6;  // 32-bit cube positions, then float
    std::vector<bool> used(want.size(), false);
    int withNormals = 0, withUV = 0;
    for (size_t i = 0; i < back.triangleCount(); ++i) {
        Tri got;
        uint8_t flags = 0xff;
        for (size_t k = 0; k < 3; ++k) {
            uint32_t v = back.triangles[3 * i + k];
            const float* p = &back.positions[3 * size_t(v)];
            got[k].p = {p[0], p[1], p[2]};
            flags &= back.flagsOf(v);
            if (!back.normals.empty())
                got[k].n = {back.normals[v][0], back.normals[v][1], back.normals[v][2]};
            if (!back.uvs.empty()) got[k].uv = {back.uvs[v][0], back.uvs[v][1]};
        }
        size_t j = 0;
        int s = -1;
        for (; j < want.size() && s < 0; ++j)
            if (!used[j]) s = matchCorners(got, want[j], faceAway[j], tol);
        ASSERT_GE(s, 0) << name << ": triangle " << i << " not in the OBJ (or turned over)";
        --j;
        used[j] = true;
        for (int k = 0; k < 3; ++k) {
            const Corner& a = got[size_t(k)];
            const Corner& b = want[j][size_t(faceAway[j] ? (s - k + 3) % 3 : (s + k) % 3)];
            if (flags & MeshData::kHasNormal) {
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(a.n[size_t(c)], b.n[size_t(c)], 2e-4) << name;
            }
            if (flags & MeshData::kHasUV) {
                for (int c = 0; c < 2; ++c)
                    EXPECT_NEAR(a.uv[size_t(c)], b.uv[size_t(c)], 1e-6) << name;
            }
        }
        withNormals += (flags & MeshData::kHasNormal) != 0;
        withUV += (flags & MeshData::kHasUV) != 0;
    }
    std::printf("%s: %zu triangles back, %d with normals, %d with (u, v)\n", name.c_str(),
                back.triangleCount(), withNormals, withUV);
}

TEST(MeshRoundTrip, ObjThroughObj2meshAndTheReader) {
    expectRoundTrip("cube", true);
    expectRoundTrip("grid", true);
    expectRoundTrip("dense", false);
}

}  // namespace
}  // namespace rp

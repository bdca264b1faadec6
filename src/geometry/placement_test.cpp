// Instances and meshes in SceneGeometry: a placed octree gives the hits of the same
// surfaces written out transformed; RADIANCE's modifier rules (o_instance.c, o_mesh.c);
// nested instances; precision far from the origin and at millimetre scale; mesh vertex
// normals and (u, v).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "geometry/scene_geometry.h"
#include "scene/mesh_data.h"
#include "scene/reader.h"
#include "scene/scene_load.h"
#include "util/rng.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp {
namespace {

void write(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Freezes `text` into our scene file at path (what oconv writes).
void writeOctree(const std::string& path, const std::string& text, const std::string& name) {
    write(path + ".rad", text);
    OconvRequest r;
    r.files = {path + ".rad"};
    r.commandLine = "oconv " + name;
    r.searchPath = {std::filesystem::path(path).parent_path().string()};
    write(path, oconvOutput(r));
}

// "mod type name N file xf... 0 0" with the string count worked out.
std::string placing(const std::string& mod, const std::string& type, const std::string& name,
                    const std::string& file, const std::string& xf = "") {
    size_t n = 1;
    for (size_t i = 0; i < xf.size(); ++i)
        if (xf[i] != ' ' && (i == 0 || xf[i - 1] == ' ')) ++n;
    return mod + " " + type + " " + name + " " + std::to_string(n) + " " + file + " " + xf +
           " 0 0\n";
}

Scene sceneWithObjects(const std::string& text, const TempDir& dir) {
    Scene s = parseScene(text, dir.file("scene.rad"));
    attachObjects(s, {dir.path().string()});
    return s;
}

const char* kBox =
    "void plastic red 0 0 5 .8 .1 .1 0 0\n"
    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
    "red polygon floor 0 0 12 0 0 0  0 1 0  1 1 0  1 0 0\n"
    "grey polygon top 0 0 12 0 0 1  1 0 1  1 1 1  0 1 1\n"
    "grey polygon w1 0 0 12 0 0 0  1 0 0  1 0 1  0 0 1\n"
    "grey polygon w2 0 0 12 1 1 0  0 1 0  0 1 1  1 1 1\n"
    "grey polygon w3 0 0 12 0 1 0  0 0 0  0 0 1  0 1 1\n"
    "grey polygon w4 0 0 12 1 0 0  1 1 0  1 1 1  1 0 1\n"
    "red sphere ball 0 0 4 .5 .5 .5 .2\n";

// The box written out through `xf` by hand: each vertex and the ball's centre mapped.
std::string transformedBox(const Transform& xf) {
    Scene box = parseScene(kBox, "box.rad");
    std::string out;
    for (const Primitive& p : box.prims) {
        out += p.modifierName + " " + std::string(primTypeName(p.type)) + " " + p.name + " 0 0 " +
               std::to_string(p.rargs.size());
        if (p.type == PrimType::Polygon) {
            for (size_t i = 0; i < p.rargs.size(); i += 3) {
                auto q = xf.point({p.rargs[i], p.rargs[i + 1], p.rargs[i + 2]});
                char buf[128];
                std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g", q[0], q[1], q[2]);
                out += buf;
            }
        } else if (p.type == PrimType::Sphere) {
            auto q = xf.point({p.rargs[0], p.rargs[1], p.rargs[2]});
            char buf[160];
            std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g %.17g", q[0], q[1], q[2],
                          p.rargs[3] * xf.scale);
            out += buf;
        } else {
            for (double r : p.rargs) out += " " + std::to_string(r);
        }
        out += "\n";
    }
    return out;
}

Ray randomRay(Rng& rng, const Vec3& centre, double spread) {
    Vec3 o{centre.x + spread * (2 * rng.uniform() - 1), centre.y + spread * (2 * rng.uniform() - 1),
           centre.z + spread * (2 * rng.uniform() - 1)};
    double z = 2 * rng.uniform() - 1, phi = 2 * kPi * rng.uniform();
    double r = std::sqrt(1 - z * z);
    return Ray{o, {r * std::cos(phi), r * std::sin(phi), z}, HUGE_VAL};
}

TEST(Placement, InstanceHitsAsTheTransformedSurfaces) {
    TempDir dir;
    writeOctree(dir.file("box.oct"), kBox, "box");
    const char* xfArgs = "-rz 30 -rx 10 -s 2.5 -t 5 1 2";
    Scene placed = sceneWithObjects(placing("void", "instance", "b", "box.oct", xfArgs), dir);
    ASSERT_EQ(placed.objects.size(), 1u);
    Transform xf =
        parseTransform({"-rz", "30", "-rx", "10", "-s", "2.5", "-t", "5", "1", "2"}, 0, {});
    Scene flat = parseScene(transformedBox(xf), "flat.rad");
    SceneGeometry gp(placed), gf(flat);
    EXPECT_EQ(gp.placementCount(), 1u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(gp.bounds().min[k], gf.bounds().min[k], 3.0);  // the cube's corners
        EXPECT_LE(gp.bounds().min[k], gf.bounds().min[k]);
        EXPECT_GE(gp.bounds().max[k], gf.bounds().max[k]);
    }
    Rng rng(7, RngDomain::Test, 0);
    int hits = 0;
    const Vec3 centre = {xf.point({.5, .5, .5})[0], xf.point({.5, .5, .5})[1],
                         xf.point({.5, .5, .5})[2]};
    for (int i = 0; i < 4000; ++i) {
        Ray ray = randomRay(rng, centre, 3.0);
        auto a = gp.closestHit(ray), b = gf.closestHit(ray);
        ASSERT_EQ(bool(a), bool(b)) << i;
        if (!a) continue;
        ++hits;
        EXPECT_NEAR(a->t, b->t, 1e-9 * (1 + b->t));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(a->point[k], b->point[k], 1e-6);
            EXPECT_NEAR(a->normal[k], b->normal[k], 1e-9);
        }
        EXPECT_EQ(a->front, b->front);
        EXPECT_EQ(placed.prims[size_t(a->prim)].name, flat.prims[size_t(b->prim)].name);
        EXPECT_EQ(placed.prims[size_t(a->modifier)].name, flat.prims[size_t(b->modifier)].name);
        EXPECT_GE(a->offset, b->offset * 0.5);
        ASSERT_NE(a->objectSpace, nullptr);  // the box's own modifiers: patterns move with it
        EXPECT_NEAR(a->objectSpace->forward.scale, 2.5, 1e-12);
        // Occlusion agrees along the same segment.
        EXPECT_EQ(gp.occluded(ray.origin, ray.dir, a->t * 1.001), true);
        EXPECT_EQ(gp.occluded(ray.origin, ray.dir, a->t * 0.999),
                  gf.occluded(ray.origin, ray.dir, b->t * 0.999));
    }
    EXPECT_GT(hits, 600);
}

TEST(Placement, InstanceModifierOverridesAndNests) {
    TempDir dir;
    writeOctree(dir.file("box.oct"), kBox, "box");
    // An octree that places the box twice: once plain, once with its own modifier.
    writeOctree(dir.file("pair.oct"),
                "void plastic blue 0 0 5 .1 .1 .8 0 0\n" +
                    placing("void", "instance", "left", "box.oct", "-t 0 0 0") +
                    placing("blue", "instance", "right", "box.oct", "-t 2 0 0"),
                "pair");
    Scene s = sceneWithObjects("void metal gold 0 0 5 .8 .6 .2 0 0\n" +
                                   placing("void", "instance", "p1", "pair.oct", "-t 0 0 0") +
                                   placing("gold", "instance", "p2", "pair.oct", "-t 0 10 0"),
                               dir);
    ASSERT_EQ(s.objects.size(), 2u);  // pair.oct and box.oct, each loaded once
    SceneGeometry g(s);
    EXPECT_EQ(g.placementCount(), 6u);  // p1, its two boxes, p2, its two boxes
    auto name = [&](int32_t i) { return i < 0 ? std::string("void") : s.prims[size_t(i)].name; };
    auto down = [&](double x, double y) { return g.closestHit({{x, y, 5}, {0, 0, -1}}); };
    auto h = down(0.5, 0.1);  // p1/left: the box's own top
    ASSERT_TRUE(h);
    EXPECT_EQ(name(h->prim), "top");
    EXPECT_EQ(name(h->modifier), "grey");
    EXPECT_NEAR(h->t, 4, 1e-12);
    h = down(2.5, 0.1);  // p1/right: blue overrides inside pair.oct
    ASSERT_TRUE(h);
    EXPECT_EQ(name(h->prim), "right");
    EXPECT_EQ(name(h->modifier), "blue");
    h = down(2.5, 10.1);  // p2: gold overrides everything inside
    ASSERT_TRUE(h);
    EXPECT_EQ(name(h->prim), "p2");
    EXPECT_EQ(name(h->modifier), "gold");
    EXPECT_EQ(h->objectSpace, nullptr);  // an overriding instance at the top: world space
    EXPECT_FALSE(down(1.5, 0.5));        // the gap between the boxes
    // The skip set sees the modifier the hit reports.
    ModifierSet skipBlue{int32_t(std::find_if(s.prims.begin(), s.prims.end(),
                                              [](const Primitive& p) { return p.name == "blue"; }) -
                                 s.prims.begin())};
    EXPECT_FALSE(g.closestHit({{2.5, 0.1, 5}, {0, 0, -1}}, &skipBlue));
    EXPECT_FALSE(g.occluded({2.5, 0.1, 5}, {0, 0, -1}, 10, &skipBlue));
    EXPECT_TRUE(g.occluded({2.5, 0.1, 5}, {0, 0, -1}, 10));
}

TEST(Placement, FarFromTheOriginAndMillimetreScale) {
    // The box placed 20 km from the origin, at 1 mm near it, and at 1 km: random walks
    // inside it, each ray spawned from the last hit, never escape and never stall on the
    // surface they leave. (Far away and tiny at once is beyond float traversal, for
    // placed and own surfaces alike: the offsets are 2^-19 of the coordinates, ray.h.)
    TempDir dir;
    writeOctree(dir.file("box.oct"), kBox, "box");
    for (const char* t : {"-rz 20 -t 1e4 2e4 -3e3", "-s 0.001", "-s 0.001 -t 0.3 0 -0.1",
                          "-rz 45 -s 1000 -t 3 0 0"}) {
        Scene s = sceneWithObjects(placing("void", "instance", "b", "box.oct", t), dir);
        Transform to = parseTransform(s.prims[0].sargs, 1, {});
        SceneGeometry g(s);
        auto c = to.point({0.3, 0.3, 0.7});  // inside, outside the ball
        Rng rng(11, RngDomain::Test, 0);
        Ray ray = randomRay(rng, {c[0], c[1], c[2]}, 0);
        for (int bounce = 0; bounce < 20000; ++bounce) {
            auto h = g.closestHit(ray);
            ASSERT_TRUE(h) << t << " escaped at bounce " << bounce;
            ASSERT_GT(h->t, 0);
            // Diffuse-ish new direction on the side the ray came from.
            Vec3 n = h->front ? h->normal : -h->normal;
            Vec3 d = randomRay(rng, {0, 0, 0}, 0).dir;
            if (dot(d, n) < 0) d = -d;
            ray = spawnRay(*h, d);
        }
    }
}

// A mesh of two triangles (a unit square in z = 0) with normals tilted outwards at two
// vertices, (u, v) at all four, and per-triangle materials.
std::shared_ptr<MeshData> squareMesh() {
    auto m = std::make_shared<MeshData>();
    m->path = "square.rtm";
    m->cubeOrigin = {0, 0, -0.5};
    m->cubeSize = 1;
    m->positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0};
    const float s = float(std::sqrt(0.5));
    m->normals = {{0, 0, 1}, {s, 0, s}, {s, 0, s}, {0, 0, 1}};
    m->uvs = {{0, 0}, {2, 0}, {2, 4}, {0, 4}};
    m->vertexFlags.assign(4, MeshData::kHasNormal | MeshData::kHasUV);
    m->triangles = {0, 1, 2, 0, 2, 3};
    m->materials = parseScene("void plastic shirt 0 0 5 .2 .2 .6 0 0\n", "square.mat");
    m->triangleMaterial = {0, kVoid};
    return m;
}

Scene meshScene(const std::string& text) {
    Scene s = parseScene("void plastic paint 0 0 5 .5 .5 .5 0 0\n" + text, "m.rad");
    SceneObject o;
    o.kind = SceneObject::Kind::Mesh;
    o.path = "square.rtm";
    o.mesh = squareMesh();
    o.firstPrim = int32_t(s.prims.size());
    for (Primitive p : o.mesh->materials.prims) {
        p.object = 0;
        s.prims.push_back(p);
    }
    o.endPrim = int32_t(s.prims.size());
    s.objects.push_back(o);
    for (auto& p : s.prims)
        if (p.type == PrimType::Mesh) p.placed = 0;
    return s;
}

TEST(Placement, MeshNormalsUvAndMaterials) {
    Scene s = meshScene(placing("void", "mesh", "sq", "square.rtm", "-t 0 0 2"));
    SceneGeometry g(s);
    // Triangle 0 at (0.75, 0.25): weights 0.25 (v0), 0.5 (v1), 0.25 (v2).
    auto h = g.closestHit({{0.75, 0.25, 5}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3, 1e-12);
    EXPECT_NEAR(h->point.z, 2, 1e-12);
    EXPECT_NEAR(h->normal.z, 1, 1e-15);
    EXPECT_NEAR(h->u, 1.5, 1e-6);
    EXPECT_NEAR(h->v, 1.0, 1e-6);
    const double s2 = std::sqrt(0.5);
    Vec3 interp = normalize(Vec3{0.75 * s2, 0, 0.25 + 0.75 * s2});
    EXPECT_NEAR(h->perturbation.x, interp.x, 1e-6);
    EXPECT_NEAR(h->perturbation.z, interp.z - 1, 1e-6);
    EXPECT_EQ(s.prims[size_t(h->prim)].name, "sq");
    EXPECT_EQ(s.prims[size_t(h->modifier)].name, "shirt");  // the mesh's own material
    ASSERT_NE(h->objectSpace, nullptr);
    // Triangle 1 has no material: void.
    h = g.closestHit({{0.25, 0.75, 5}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->modifier, kVoid);
    EXPECT_NEAR(h->u, 0.5, 1e-6);
    EXPECT_NEAR(h->v, 3.0, 1e-6);
    // Triangle (v0, v2, v3) at (0.25, 0.75): weights 0.25, 0.25, 0.5.
    interp = normalize(Vec3{0.25 * s2, 0, 0.75 + 0.25 * s2});
    EXPECT_NEAR(h->perturbation.x, interp.x, 1e-6);
    EXPECT_NEAR(h->perturbation.z, interp.z - 1, 1e-6);
    // From below: back side, same normal.
    h = g.closestHit({{0.75, 0.25, -5}, {0, 0, 1}});
    ASSERT_TRUE(h);
    EXPECT_FALSE(h->front);
    // The mesh primitive's own modifier wins over the mesh's materials.
    Scene p = meshScene(placing("paint", "mesh", "sq", "square.rtm"));
    SceneGeometry gp(p);
    h = gp.closestHit({{0.75, 0.25, 5}, {0, 0, -1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(p.prims[size_t(h->modifier)].name, "paint");
    EXPECT_EQ(h->objectSpace, nullptr);
    EXPECT_NEAR(h->u, 1.5, 1e-6);  // (u, v) still from the mesh
    // Bounds: the mesh cube placed.
    EXPECT_NEAR(gp.bounds().min.z, -0.5, 1e-12);
    EXPECT_NEAR(gp.bounds().max.z, 0.5, 1e-12);
}

TEST(Placement, MissingAndWrongFiles) {
    TempDir dir;
    write(dir.file("plain.rad"), kBox);
    auto err = [&](const std::string& text) {
        try {
            sceneWithObjects(text, dir);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(err("void instance i 1 nowhere.oct 0 0\n"),
              dir.file("scene.rad") + ":1: instance 'i': cannot find octree file 'nowhere.oct'");
    EXPECT_NE(err("void instance i 1 plain.rad 0 0\n")
                  .find("instance 'i': " + dir.file("plain.rad") + ": not an octree"),
              std::string::npos);
    // An empty octree first: oconv reads the cube of the octree an instance places.
    writeOctree(dir.file("self.oct"), "", "self");
    writeOctree(dir.file("self.oct"), "void instance me 1 self.oct 0 0\n", "self");
    EXPECT_NE(err("void instance i 1 self.oct 0 0\n").find("places itself"), std::string::npos);
    EXPECT_NE(err("void light l 0 0 3 1 1 1\nl instance i 1 self.oct 0 0\n")
                  .find("instance 'i': cannot be modified by light material 'l'"),
              std::string::npos);
}

}  // namespace
}  // namespace rp

namespace rp {
namespace {

// RADIANCE's oconv bounds a placement by its object's cube, placed: the scene cubes of
// RADIANCE's porsches.rad (two instances of the frozen porsche.octf) and vase.rad (a
// mesh), from RADIANCE 5.4's `oconv porsches.rad > p.oct; getinfo -d p.oct` (and
// vase.rad) in ../shared/radiance-tests/renders.
TEST(Placement, SceneCubeAsRadianceOconv) {
    const std::string dir = std::string(RP_SHARED_DIR) + "/radiance-tests/renders";
    RP_REQUIRE_SHARED("radiance-tests/renders/porsche.octf");
    struct Case {
        const char* file;
        double cube[4];
    };
    for (const Case& c : {Case{"porsches.rad", {-5.5527577, 0.947721475, -0.549466025, 3.10455705}},
                          Case{"vase.rad", {-4.11501005, 2.38498995, 0.99998995, 0.2300201}}}) {
        // The objects are found in the models' folder, not along RAYPATH.
        SceneReader reader;
        reader.readFile(dir + "/" + c.file);
        Scene s = reader.take();
        attachObjects(s, {dir});
        SceneCube cube = SceneGeometry(s).sceneCube();
        EXPECT_NEAR(cube.origin.x, c.cube[0], 1e-7) << c.file;
        EXPECT_NEAR(cube.origin.y, c.cube[1], 1e-7) << c.file;
        EXPECT_NEAR(cube.origin.z, c.cube[2], 1e-7) << c.file;
        EXPECT_NEAR(cube.size, c.cube[3], 1e-7) << c.file;
    }
}

}  // namespace
}  // namespace rp

namespace rp {
namespace {

// A mesh placed as the scene's only object, given its triangles.
Scene meshOnly(std::shared_ptr<MeshData> m) {
    Scene s = parseScene("void mesh m 1 m.rtm 0 0\n", "m.rad");
    SceneObject o;
    o.kind = SceneObject::Kind::Mesh;
    o.mesh = std::move(m);
    o.firstPrim = o.endPrim = int32_t(s.prims.size());
    s.objects.push_back(o);
    s.prims[0].placed = 0;
    return s;
}

// A closed mesh is watertight: random walks inside a tessellated sphere (a UV sphere of
// 40 x 80 quads, split into triangles that share every edge and meet 80 at each pole),
// placed far from the origin, never escape in 200 k bounces. RADIANCE's o_mesh.c edge
// test cannot leak; Embree's fast float test let 1 ray in 200 k through a 10 M-triangle
// grid (bench/README_mesh.md), hence robust mode for meshes (embree_accel.cpp).
TEST(Placement, ClosedMeshDoesNotLeak) {
    auto m = std::make_shared<MeshData>();
    constexpr int kRings = 40, kSegs = 80;
    const Vec3 c{3000, -1200, 40};
    const double r = 1.3;
    auto add = [&](const Vec3& p) {
        m->positions.push_back(float(p.x));
        m->positions.push_back(float(p.y));
        m->positions.push_back(float(p.z));
    };
    add(c + Vec3{0, 0, r});
    for (int i = 1; i < kRings; ++i)
        for (int k = 0; k < kSegs; ++k) {
            double th = kPi * i / kRings, ph = 2 * kPi * k / kSegs;
            add(c + Vec3{r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                         r * std::cos(th)});
        }
    add(c + Vec3{0, 0, -r});
    m->positions.push_back(0);
    const uint32_t south = uint32_t(1 + (kRings - 1) * kSegs);
    auto ring = [&](int i, int k) { return uint32_t(1 + (i - 1) * kSegs + (k % kSegs)); };
    for (int k = 0; k < kSegs; ++k) {
        for (uint32_t v : {0u, ring(1, k), ring(1, k + 1)}) m->triangles.push_back(v);
        for (uint32_t v : {south, ring(kRings - 1, k + 1), ring(kRings - 1, k)})
            m->triangles.push_back(v);
        for (int i = 1; i + 1 < kRings; ++i)
            for (uint32_t v : {ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k),
                               ring(i + 1, k + 1), ring(i, k + 1)})
                m->triangles.push_back(v);
    }
    m->cubeOrigin = {c.x - 2, c.y - 2, c.z - 2};
    m->cubeSize = 4;
    SceneGeometry g(meshOnly(m));
    Rng rng(5, RngDomain::Test, 0);
    Ray ray{c, normalize(Vec3{0.3, -0.2, 0.5}), HUGE_VAL};
    int escapes = 0;
    for (int bounce = 0; bounce < 200000; ++bounce) {
        auto h = g.closestHit(ray);
        if (!h) {
            ++escapes;
            ray = Ray{c, randomRay(rng, {0, 0, 0}, 0).dir, HUGE_VAL};
            continue;
        }
        Vec3 n = h->front ? h->normal : -h->normal;
        Vec3 d = randomRay(rng, {0, 0, 0}, 0).dir;
        if (dot(d, n) < 0) d = -d;
        ray = spawnRay(*h, d);
    }
    EXPECT_EQ(escapes, 0);
}

// Rays aimed exactly at the edges that a mesh's triangles share (a wavy 40 x 40 grid, at
// the origin and 2 km from it; rays at random points of its shared edges, or vertices,
// from random directions) almost never pass between them. RADIANCE's o_mesh.c edge test
// is exactly watertight; Embree's robust float test, which meshes use, let 62 and 103 in
// 100 k such rays through here, its fast test 4602 and 176. A
// ray that is not aimed at an edge has practically no chance to meet one this closely
// (1 in 200 k random rays leaked on a 10 M-triangle grid with the fast test).
TEST(Placement, MeshEdgesAreAlmostWatertight) {
    for (double x0 : {0.0, 2000.0}) {
        auto m = std::make_shared<MeshData>();
        constexpr int kN = 40;
        const double y0 = -0.35 * x0;
        auto z = [](int i, int j) { return 0.3 * std::sin(0.7 * i) * std::cos(0.45 * j); };
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i)
                for (double v : {x0 + 0.37 * i, y0 + 0.29 * j, z(i, j)})
                    m->positions.push_back(float(v));
        m->positions.push_back(0);
        for (int j = 0; j + 1 < kN; ++j)
            for (int i = 0; i + 1 < kN; ++i) {
                uint32_t a = uint32_t(j * kN + i), b = a + 1, c = a + kN + 1, d = a + kN;
                for (uint32_t v : {a, b, c, a, c, d}) m->triangles.push_back(v);
            }
        m->cubeOrigin = {x0 - 1, y0 - 1, -10};
        m->cubeSize = 20;
        SceneGeometry g(meshOnly(m));
        auto p = [&](uint32_t v) {
            return Vec3{m->positions[3 * v], m->positions[3 * v + 1], m->positions[3 * v + 2]};
        };
        Rng rng(5, RngDomain::Test, 0);
        int misses = 0;
        for (int k = 0; k < 100000; ++k) {
            // A point on a shared edge: a diagonal or an inner grid line.
            int i = 1 + int(rng.uniform() * (kN - 3)), j = 1 + int(rng.uniform() * (kN - 3));
            uint32_t a = uint32_t(j * kN + i);
            uint32_t b = rng.uniform() < 0.5 ? a + kN + 1 : (rng.uniform() < 0.5 ? a + 1 : a + kN);
            double t = rng.uniform();
            Vec3 target = p(a) * (1 - t) + p(b) * t;
            Ray ray = randomRay(rng, {0, 0, 0}, 0);
            ray.dir.z = -std::fabs(ray.dir.z) - 0.05;
            ray.dir = normalize(ray.dir);
            ray.origin = target - ray.dir * (5 + 10 * rng.uniform());
            misses += !g.closestHit(ray);
        }
        EXPECT_LT(misses, 200) << "at x = " << x0;  // 0.2 %: robust (0.06-0.1 %), not fast
    }
}

}  // namespace
}  // namespace rp

namespace rp {
namespace {

// Rays that start beyond what Embree handles (|coordinate| above about 1.8e18, where it
// aborts) or hold NaN are misses, as outside RADIANCE's octree cube; never a crash.
TEST(Placement, RaysFromBeyondTheAcceleratorsRangeMiss) {
    TempDir dir;
    writeOctree(dir.file("box.oct"), kBox, "box");
    Scene s = sceneWithObjects(
        std::string(kBox) + placing("void", "instance", "b", "box.oct", "-t 5 0 0"), dir);
    SceneGeometry g(s);
    ASSERT_TRUE(g.closestHit({{0.5, 0.5, 5}, {0, 0, -1}}));
    for (const Vec3& o : {Vec3{2e18, 0.5, 0.5}, Vec3{0.5, -3e30, 0.5}, Vec3{0.5, 0.5, NAN},
                          Vec3{1e308, 1e308, 1e308}}) {
        EXPECT_FALSE(g.closestHit({o, {-1, 0, 0}}));
        EXPECT_FALSE(g.occluded(o, {-1, 0, 0}, 1e30));
    }
    EXPECT_FALSE(g.closestHit({{0.5, 0.5, 5}, {0, NAN, -1}}));
}

}  // namespace
}  // namespace rp

// Tests for pkgBSDF with hand-built BsdfData (the XML loader is tested in bsdf/): the
// scene RADIANCE's pkgBSDF prints for the validation blinds (Klems, with MGF and back
// reflection; tests/data/gen_radiance/pkgbsdf_blinds_klems.rad, made by
// `RAYPATH=. pkgBSDF -s blinds_klems.xml` beside shared/validation/bsdf/blinds_klems.xml)
// and for a BSDF without geometry (the tensor-tree blinds); the -i octree; bad input.
#include "gen/pkgbsdf.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "gen/test_reference.h"
#include "scene/scene_load.h"
#include "util/error.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::gen {
namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream all;
    all << in.rdbuf();
    return all.str();
}

bsdf::BsdfData blinds(bool withMgf, bool backReflection) {
    bsdf::BsdfData b;
    b.name = withMgf ? "blinds_klems" : "blinds_ttree";
    b.materialName = "Name";
    b.manufacturer = "Manufacturer";
    b.width = 3;
    b.height = 1;
    b.thickness = 0.025;
    if (withMgf)
        b.mgf = readText(std::string(RP_SOURCE_DIR) + "/tests/data/mgf/genbsdf_blinds.mgf");
    if (backReflection) b.rb.emplace();
    return b;
}

TEST(PkgBsdf, KlemsBlindsWithGeometryMatchRadiance) {
    std::string want = testing::readReferenceOutput("pkgbsdf_blinds_klems.rad").text;
    // RADIANCE's mgf2rad ran on a temporary file; we name the XML's MGF block instead.
    size_t at = want.find("## mgf2rad /tmp/");
    ASSERT_NE(at, std::string::npos);
    size_t end = want.find(' ', at + 11);
    want.replace(at + 11, end - at - 11, "blinds_klems.xml:MGFblock");
    EXPECT_EQ(pkgBsdfScene(blinds(true, true), false, "some/folder/blinds_klems.xml"), want);
}

TEST(PkgBsdf, WithoutGeometryOneRectangleAtZero) {
    // RADIANCE: RAYPATH=. pkgBSDF -s blinds_ttree.xml
    EXPECT_EQ(pkgBsdfScene(blinds(false, true), false, "blinds_ttree.xml"),
              "# Produced by: pkgBSDF blinds_ttree.xml\n"
              "# Material 'Name' by 'Manufacturer'\n\n"
              "void BSDF m_blinds_ttree\n6 0 blinds_ttree.xml 0 1 0 .\n0\n0\n\n"
              "m_blinds_ttree polygon blinds_ttree\n0\n0\n12\n"
              "\t-1.500000e+00\t-5.000000e-01\t0.000000e+00\n"
              "\t1.500000e+00\t-5.000000e-01\t0.000000e+00\n"
              "\t1.500000e+00\t5.000000e-01\t0.000000e+00\n"
              "\t-1.500000e+00\t5.000000e-01\t0.000000e+00\n\n");
}

TEST(PkgBsdf, BackFaceOnlyWithBackReflectionAndNoMaterialLineWithoutMaker) {
    bsdf::BsdfData b = blinds(true, false);
    b.manufacturer.clear();
    std::string s = pkgBsdfScene(b, false, "blinds_klems.xml");
    EXPECT_NE(s.find("void BSDF m_blinds_klems_f\n6 0.025001 blinds_klems.xml"), std::string::npos);
    EXPECT_EQ(s.find("m_blinds_klems_b"), std::string::npos);
    EXPECT_EQ(s.find("# Material"), std::string::npos);
}

TEST(PkgBsdf, InstanceLinePlacesAFrozenOctreeOfTheGeometry) {
    bsdf::BsdfData b = blinds(true, true);
    std::string s = pkgBsdfScene(b, true, "blinds_klems.xml");
    const std::string tail = "void instance blinds_klems_g\n1 blinds_klems.oct\n0\n0\n\n";
    ASSERT_GE(s.size(), tail.size());
    EXPECT_EQ(s.substr(s.size() - tail.size()), tail);
    EXPECT_EQ(s.find("polygon blinds20"), std::string::npos);  // no geometry in the scene

    TempDir dir;
    std::string geometry = pkgBsdfGeometry(b, "blinds_klems.xml");
    writeBsdfOctree(geometry, dir.file("blinds_klems.oct"), "pkgBSDF -i blinds_klems.xml");
    // A frozen RADIANCE octree, which RADIANCE's tools read as well as ours.
    std::ifstream oct(dir.file("blinds_klems.oct"), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(oct), std::istreambuf_iterator<char>()};
    EXPECT_NE(bytes.find("\nFORMAT=Radiance_octree\n"), std::string::npos);
    Scene frozen = loadScene({dir.file("blinds_klems.oct")});
    size_t polygons = 0;
    for (const Primitive& p : frozen.prims) polygons += p.type == PrimType::Polygon;
    EXPECT_EQ(polygons, 45u);    // as many as RADIANCE's mgf2rad writes for this MGF
    EXPECT_EQ(dir.count(), 1u);  // nothing but the octree
}

// The command end to end: the validation XML found along RAYPATH, loaded by the bsdf
// module, gives RADIANCE's scene (the reference above) and, with -i, NAME.oct.
TEST(PkgBsdf, CommandLoadsTheXmlAlongRaypath) {
    std::string dir = std::string(RP_SHARED_DIR) + "/validation/bsdf";
    RP_REQUIRE_SHARED("validation/bsdf/blinds_klems.xml");
    const std::vector<std::string> raypath{dir};
    std::vector<std::string> w;
    std::string got = pkgBSDF({"pkgBSDF", "-s", "blinds_klems.xml"}, w, raypath);
    std::string want = testing::readReferenceOutput("pkgbsdf_blinds_klems.rad").text;
    size_t at = want.find("## mgf2rad /tmp/");
    want.replace(at + 11, want.find(' ', at + 11) - at - 11, "blinds_klems.xml:MGFblock");
    EXPECT_EQ(got, want);
    TempDir tmp;  // as if run in tmp (by xform in-process, in the folder of a scene file)
    got = pkgBSDF({"pkgBSDF", "-i", "blinds_klems.xml"}, w, raypath, tmp.path().string());
    EXPECT_EQ(got, "");  // without -s: written to NAME.rad
    EXPECT_NE(readText(tmp.file("blinds_klems.rad")).find("void instance blinds_klems_g"),
              std::string::npos);
    EXPECT_EQ(loadScene({tmp.file("blinds_klems.oct")}).prims.size(), 46u);  // paint + 45
}

TEST(PkgBsdf, BadInput) {
    bsdf::BsdfData b = blinds(false, false);
    b.width = 0;
    EXPECT_THROW(pkgBsdfScene(b, false, "x.xml"), InputError);
    std::vector<std::string> w;
    const std::vector<std::string> here{"."};
    EXPECT_THROW(pkgBSDF({"pkgBSDF", "-s", "blinds.txt"}, w, here), InputError);
    EXPECT_THROW(pkgBSDF({"pkgBSDF", "-s", "no_such_file_here.xml"}, w, here), InputError);
    EXPECT_THROW(pkgBSDF({"pkgBSDF", "-s"}, w, here), InputError);
    EXPECT_THROW(pkgBSDF({"pkgBSDF", "-s", "a.xml", "b.xml"}, w, here), InputError);
    EXPECT_THROW(pkgBSDF({"pkgBSDF", "-q", "a.xml"}, w, here), InputError);
}

}  // namespace
}  // namespace rp::gen

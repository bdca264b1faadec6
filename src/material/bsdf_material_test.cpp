// BSDF material: photon energy against the data, the flux a sampled direction carries,
// shadow rays, thick proxies.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "bsdf/bsdf.h"
#include "material/test_util.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::material {
namespace {

using test::expectMeanNear;
using test::photonStats;

const std::string kKlems = std::string(RP_SHARED_DIR) + "/validation/bsdf/blinds_klems.xml";

// A surface with normal +z, up +y: the BSDF's local frame is the world's.
SurfacePoint hitAt(const bsdf::BsdfData& sd, const Vec3& dir, double thickness = 0) {
    const bool front = dir.z < 0;
    SurfacePoint sp = makeSurfacePoint(dir, front ? Vec3{0, 0, 1} : Vec3{0, 0, -1}, front);
    sp.bsdf = &sd;
    sp.uDir = {0, 1, 0};
    sp.bsdfThickness = thickness;
    return sp;
}

// The mean flux factor of scattered photons equals the data's reflectance plus
// transmittance for that incidence (Lambertian and non-diffuse parts), from either side.
TEST(BsdfMaterial, PhotonsCarryTheDataAlbedo) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = bsdf::loadBsdfFile(kKlems);
    const MaterialParams m = BsdfParams{};
    for (double th : {0.0, 35.0, 70.0})
        for (bool fromFront : {true, false}) {
            Vec3 dir = test::incident(th);  // travelling towards -z: hits the front
            if (!fromFront) dir = -dir;
            const Vec3 away = -dir;  // RADIANCE's incident vector, local frame = world
            const bool f = away.z > 0;
            const double albedo =
                (f ? sd->rLambFront : sd->rLambBack).g + (f ? sd->tLambFront : sd->tLambBack).g +
                sd->nonDiffuseHemispherical(away, false) + sd->nonDiffuseHemispherical(away, true);
            const auto st = photonStats(m, 200000, 3, [&](Rng&) { return hitAt(*sd, dir); });
            expectMeanNear(st, Color::grey(albedo), fromFront ? "front" : "back");
            EXPECT_GT(albedo, 0.3);
        }
}

TEST(BsdfMaterial, ShadowRaysStopAtAThinBsdfAndPassAThickOne) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = bsdf::loadBsdfFile(kKlems);
    const BsdfParams m;
    Color c;
    EXPECT_FALSE(bsdfShadowPass(m, hitAt(*sd, {0, 0, -1}), true, c));
    EXPECT_TRUE(bsdfShadowPass(m, hitAt(*sd, {0, 0, -1}, .025), true, c));
    EXPECT_EQ(c.g, 1);
}

// A thick proxy hides itself from unscattered rays and from its hidden side; scattered
// rays on its side see it, with transmitted light gathered past the geometry.
TEST(BsdfMaterial, ThickProxyShowsOnlyToScatteredRaysOnItsSide) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = bsdf::loadBsdfFile(kKlems);
    const MaterialParams m = BsdfParams{};
    Rng rng(1, RngDomain::Test, 0);
    SurfacePoint sp = hitAt(*sd, test::incident(20), .025);
    EXPECT_TRUE(shadeBackward(m, sp, {}, rng).transparent);
    sp.scatteredRay = true;
    const BackwardResult r = shadeBackward(m, sp, {}, rng);
    EXPECT_FALSE(r.transparent);
    EXPECT_DOUBLE_EQ(r.transmitOffset, -.025);
    EXPECT_TRUE(r.directFromBehind);
    SurfacePoint back = hitAt(*sd, -test::incident(20), .025);
    back.scatteredRay = true;
    EXPECT_TRUE(shadeBackward(m, back, {}, rng).transparent);
}

// pmapmat.c: without -bv, a photon meeting the back of a BSDF that has neither back
// reflection nor front-to-back transmission (nor back diffuse arguments) is absorbed;
// with -bv it goes on with what the back has (here: back-to-front transmission).
TEST(BsdfMaterial, EmptyBackAbsorbsPhotonsOnlyWithoutBackVisibility) {
    TempDir dir;
    std::string vals;
    for (int k = 0; k < 41 * 41; ++k) vals += "0.1 ";
    const std::string p = dir.file("tb.xml");
    std::ofstream(p)
        << "<?xml version=\"1.0\"?>\n<WindowElement><FileType>BSDF</FileType>"
           "<Optical><Layer><DataDefinition><IncidentDataStructure>Columns"
           "</IncidentDataStructure></DataDefinition><WavelengthData><Wavelength>Visible"
           "</Wavelength><WavelengthDataBlock><WavelengthDataDirection>Transmission Front"
           "</WavelengthDataDirection><ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>"
           "<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis><ScatteringData>"
        << vals
        << "</ScatteringData></WavelengthDataBlock></WavelengthData></Layer>"
           "</Optical></WindowElement>\n";
    const auto sd = bsdf::loadBsdfFile(p);
    ASSERT_TRUE(!sd->tf && !sd->rb && sd->tLambBack.g > .3);  // all Lambertian: 0.1 pi
    const MaterialParams m = BsdfParams{};
    for (bool bv : {true, false}) {
        const auto st = photonStats(m, 20000, 5, [&](Rng&) {
            SurfacePoint sp = hitAt(*sd, -test::incident(30));  // from behind
            sp.backVisible = bv;
            return sp;
        });
        const long absorbed = st.counts[int(ScatterKind::Absorbed)];
        if (bv)
            EXPECT_LT(absorbed, 20000 * .8);  // ~69 % transmitted (0.1 pi, Lambertian)
        else
            EXPECT_EQ(absorbed, 20000);
    }
}

}  // namespace
}  // namespace rp::material

// BSDF material: photon energy against the data, the flux a sampled direction carries,
// shadow rays, thick proxies.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "bsdf/bsdf.h"
#include "bsdf/coloured_klems_for_tests.h"
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

// Coloured data (CIE-X and CIE-Z beside Y) in a spectral pass: each band takes the data's
// RGB primary its centre falls in, as RADIANCE 6 turns a BSDF colour into a spectrum
// (setscolor). A pass of bands in red, red and blue gets the RGB result's (r, r, b) for
// direct light, the ambient coefficients and sampled rays, and for photons' mean flux.
TEST(BsdfMaterial, ColouredDataInASpectralPassTakeTheirBandsPrimaries) {
    TempDir dir;
    const std::string p = dir.file("c.xml");
    std::ofstream(p) << bsdf::colouredKlemsXml();
    const auto sd = bsdf::loadBsdfFile(p);
    ASSERT_TRUE(sd->coloured());
    BsdfParams rgb, pass;
    pass.dataBands = {0, 0, 2};
    auto pick = [](const Color& c) { return Color{c.r, c.r, c.b}; };
    auto expectSame = [](const Color& a, const Color& b, const char* what) {
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-12 * (1 + std::abs(b[i]))) << what;
    };
    for (double th : {10.0, 40.0, 65.0}) {
        const SurfacePoint sp = hitAt(*sd, test::incident(th));
        const Vec3 light = normalize(Vec3{0.3, -0.2, 0.9});
        const Color d = evaluate(MaterialParams{rgb}, sp, light, 1e-3);
        EXPECT_GT(d.r, 0);
        expectSame(evaluate(MaterialParams{pass}, sp, light, 1e-3), pick(d), "direct");
        Rng r1(3, RngDomain::Test, 0), r2(3, RngDomain::Test, 0);
        const BackwardResult a = shadeBackward(MaterialParams{rgb}, sp, {}, r1);
        const BackwardResult b = shadeBackward(MaterialParams{pass}, sp, {}, r2);
        expectSame(b.ambientReflect, pick(a.ambientReflect), "ambient");
        ASSERT_EQ(a.numRays, b.numRays);
        for (size_t k = 0; k < size_t(a.numRays); ++k)
            expectSame(b.rays[k].weight, pick(a.rays[k].weight), "sampled ray");
    }
    // Photons: the roulette weighs the pass's own bands, so their paths differ from the
    // RGB pass's; the mean flux agrees within the two runs' noise.
    const auto rgbStats = photonStats(MaterialParams{rgb}, 40000, 9,
                                      [&](Rng&) { return hitAt(*sd, test::incident(30)); });
    const auto passStats = photonStats(MaterialParams{pass}, 40000, 9,
                                       [&](Rng&) { return hitAt(*sd, test::incident(30)); });
    for (int i : {0, 2}) {
        const int j = pass.dataBands[size_t(i)];
        const double tol = 4 * std::hypot(passStats.stderr_[i], rgbStats.stderr_[j]);
        EXPECT_NEAR(passStats.mean[i], rgbStats.mean[j], tol) << "photon flux, band " << i;
    }
    EXPECT_GT(rgbStats.mean.r, 1.5 * rgbStats.mean.b);  // the data's colour shows
}

}  // namespace
}  // namespace rp::material

// Klems data: loading, energy, sampling against the tabulated distribution, bad files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "bsdf/bsdf.h"
#include "bsdf/coloured_klems_for_tests.h"
#include "bsdf/multi_sample.h"
#include "util/error.h"
#include "util/rng.h"
#include "util/shared_for_tests.h"
#include "util/temp_dir_for_tests.h"

namespace rp::bsdf {
namespace {

const std::string kKlems = std::string(RP_SHARED_DIR) + "/validation/bsdf/blinds_klems.xml";

// The Klems full basis, written out again here (independent of klems.cpp): band lower
// edges in degrees and patch counts.
const double kTheta[] = {0, 5, 15, 25, 35, 45, 55, 65, 75, 90};
const int kPhis[] = {1, 8, 16, 20, 24, 24, 24, 16, 12};

double bandOmega(int band) {
    const double a = std::cos(kTheta[band] * kPi / 180), b = std::cos(kTheta[band + 1] * kPi / 180);
    return kPi * (a * a - b * b) / kPhis[band];
}
int bandOf(int patch) {
    int band = 0;
    while (patch >= kPhis[band]) patch -= kPhis[band++];
    return band;
}
// The centre direction of a patch of the +Z hemisphere (azimuth of patch j is j*360/n).
Vec3 patchCentre(int patch) {
    int band = 0;
    while (patch >= kPhis[band]) patch -= kPhis[band++];
    const double t = band == 0 ? 0 : (kTheta[band] + kTheta[band + 1]) / 2 * kPi / 180;
    const double a = 2 * kPi * patch / kPhis[band];
    return {std::cos(a) * std::sin(t), std::sin(a) * std::sin(t), std::cos(t)};
}

// The raw matrix of one WavelengthDataDirection, read with a plain scan of the file
// (columns: incident index runs fastest).
std::vector<double> rawMatrix(const std::string& direction) {
    std::ifstream f(kKlems);
    std::stringstream ss;
    ss << f.rdbuf();
    const std::string s = ss.str();
    const std::size_t at = s.find("<WavelengthDataDirection>" + direction);
    const std::size_t beg = s.find("<ScatteringData>", at) + 16;
    std::istringstream vals(s.substr(beg, s.find("</ScatteringData>", beg) - beg));
    std::vector<double> v;
    std::string tok;
    while (vals >> tok) {
        if (tok.back() == ',') tok.pop_back();
        if (!tok.empty()) v.push_back(std::max(0.0, std::stod(tok)));
    }
    return v;
}

TEST(Klems, LoadsGeometryAndFourSets) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = loadBsdfFile(kKlems);
    EXPECT_EQ(sd->name, "blinds_klems");
    EXPECT_NEAR(sd->width, 3, 1e-12);
    EXPECT_NEAR(sd->height, 1, 1e-12);
    EXPECT_NEAR(sd->thickness, .025, 1e-12);
    EXPECT_NE(sd->mgf.find("blinds20"), std::string::npos);
    EXPECT_TRUE(sd->rf && sd->rb && sd->tf && sd->tb);
    EXPECT_NEAR(sd->rf->minProjSA, bandOmega(8), 1e-9);
}

// Light from front patch i (incident vectors point away from the surface, so a patch of
// the front-incident side is the +Z patch turned by 180 degrees) through to the back:
// "Transmission Back" in WINDOW's terms.
TEST(Klems, ValuesAndHemisphericalMatchTheFile) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = loadBsdfFile(kKlems);
    const std::vector<double> raw = rawMatrix("Transmission Back");
    ASSERT_EQ(raw.size(), 145u * 145u);
    double minv = 1e30;
    for (double v : raw) minv = std::min(minv, v);
    const double lamb = minv > .01 / kPi ? minv : 0;
    EXPECT_NEAR(sd->tLambFront.r, kPi * lamb, 1e-6);
    for (int i : {0, 7, 40, 100, 144}) {
        const Vec3 c = patchCentre(i);
        const Vec3 in{-c.x, -c.y, c.z};
        double hemi = 0;
        for (int o = 0; o < 145; ++o) {
            const Vec3 co = patchCentre(o);
            const Vec3 out{co.x, co.y, -co.z};
            const double want = raw[o * 145 + i];
            EXPECT_NEAR(sd->evaluate(in, out).g, want, 1e-5 * (1 + want)) << i << " " << o;
            hemi += (want - lamb) * bandOmega(bandOf(o));
        }
        EXPECT_NEAR(sd->nonDiffuseHemispherical(in, true), hemi, 1e-6 * (1 + hemi));
    }
}

// A uniform random direction (in projected solid angle) inside a +Z patch.
Vec3 inPatch(int patch, Rng& rng) {
    int band = 0;
    while (patch >= kPhis[band]) patch -= kPhis[band++];
    const double a = std::cos(kTheta[band] * kPi / 180), b = std::cos(kTheta[band + 1] * kPi / 180);
    const double c2 = a * a + (b * b - a * a) * rng.uniform();
    const double az = 2 * kPi * (patch + rng.uniform() - .5) / kPhis[band];
    const double z = std::sqrt(c2), r = std::sqrt(1 - c2);
    return {r * std::cos(az), r * std::sin(az), z};
}

// The patch of a +Z direction: band by polar angle, patch by azimuth (centred on j/n).
int patchOf(const Vec3& v) {
    const double pol = std::acos(std::min(1.0, v.z)) * 180 / kPi;
    int band = 0, first = 0;
    while (band < 8 && pol >= kTheta[band + 1]) first += kPhis[band++];
    double az = std::atan2(v.y, v.x) / (2 * kPi);
    if (az < 0) az += 1;
    return first + static_cast<int>(std::floor(az * kPhis[band] + .5)) % kPhis[band];
}

// Energy: the integral of the BSDF (all of it) times |cos| over the sphere, with random
// points inside every patch (so the patch boundaries of the lookup are checked too),
// equals the file's hemispherical reflectance plus transmittance.
TEST(Klems, IntegralOverPatchesMatchesTheFile) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = loadBsdfFile(kKlems);
    const std::vector<double> rRaw = rawMatrix("Reflection Back"),
                              tRaw = rawMatrix("Transmission Back");
    Rng rng(11, RngDomain::Test, 0);
    for (int i : {0, 30, 90}) {
        const Vec3 c = patchCentre(i);
        const Vec3 in{-c.x, -c.y, c.z};
        double file = 0, sum = 0;
        for (int o = 0; o < 145; ++o) {
            file += (rRaw[o * 145 + i] + tRaw[o * 145 + i]) * bandOmega(bandOf(o));
            const int m = 20;
            double acc = 0;
            for (int k = 0; k < m; ++k) {
                const Vec3 up = inPatch(o, rng);
                acc += sd->evaluate(in, up).g + sd->evaluate(in, {up.x, up.y, -up.z}).g;
            }
            sum += acc / m * bandOmega(bandOf(o));
        }
        EXPECT_NEAR(sum, file, 1e-4 * file) << "incident patch " << i;
    }
}

// Sampling: the outgoing patches drawn for an incident patch follow the tabulated
// value * projected solid angle (chi-square, 1 % significance).
TEST(Klems, SamplingFollowsTheTable) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const auto sd = loadBsdfFile(kKlems);
    const std::vector<double> raw = rawMatrix("Transmission Back");
    const Distribution& d = *sd->tf->components.front();
    Rng rng(5, RngDomain::Test, 0);
    for (int i : {0, 12, 60}) {
        const Vec3 c = patchCentre(i);
        const Vec3 in{-c.x, -c.y, c.z};
        std::vector<double> p(145);
        double total = 0;
        const double lamb = sd->tLambFront.g / kPi;
        for (int o = 0; o < 145; ++o)
            total += p[o] = (raw[o * 145 + i] - lamb) * bandOmega(bandOf(o));
        const int n = 200000;
        std::vector<int> count(145);
        for (int k = 0; k < n; ++k) {
            Vec3 out;
            ASSERT_TRUE(d.sample(in, rng.uniform(), rng.uniform(), out));
            ASSERT_LT(out.z, 0);
            ++count[patchOf({out.x, out.y, -out.z})];
        }
        // Bins merged so that each expects at least 20 draws.
        double chi2 = 0, expAcc = 0, obsAcc = 0;
        int dof = -1;
        for (int o = 0; o < 145; ++o) {
            expAcc += n * p[o] / total;
            obsAcc += count[o];
            if (expAcc >= 20) {
                chi2 += (obsAcc - expAcc) * (obsAcc - expAcc) / expAcc;
                expAcc = obsAcc = 0;
                ++dof;
            }
        }
        ASSERT_GT(dof, 5);
        // The 1 % point of chi-square (normal approximation).
        EXPECT_LT(chi2, dof + 2.33 * std::sqrt(2.0 * dof)) << "incident patch " << i;
    }
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// CIE-X and CIE-Z matrices beside the visible one colour the data: a constant ratio
// X : Y : Z = 1.2 : 1 : 0.5 gives that colour everywhere, in RADIANCE RGB (Y = its
// brightness), and the Lambertian part takes the coloured minimum.
TEST(Klems, CieXAndZColourTheData) {
    TempDir dir;
    const std::string p = dir.file("c.xml");
    writeFile(p, colouredKlemsXml());
    const auto sd = loadBsdfFile(p);
    // RADIANCE RGB of XYZ (1.2, 1, 0.5), from its primaries (0.640 0.330, 0.290 0.600,
    // 0.150 0.060) and equal-energy white: the XYZ -> RGB matrix applied by hand.
    const double m[9] = {2.5653, -1.1668, -0.3985, -1.0220, 1.9782,
                         0.0438, 0.0747,  -0.2519, 1.1772};
    const Color unit{m[0] * 1.2 + m[1] + m[2] * .5, m[3] * 1.2 + m[4] + m[5] * .5,
                     m[6] * 1.2 + m[7] + m[8] * .5};
    EXPECT_NEAR(unit.brightness(), 1, 2e-3);
    Rng rng(6, RngDomain::Test, 0);
    for (int k = 0; k < 200; ++k) {
        auto dir = [&]() {
            const double r = std::sqrt(rng.uniform()), a = 2 * kPi * rng.uniform();
            return Vec3{r * std::cos(a), r * std::sin(a), std::sqrt(1 - r * r)};
        };
        const Color v = sd->evaluate(dir(), dir());
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c] / v.brightness(), unit[c], 2e-3) << c;
    }
    const Color lamb = sd->rLambFront;
    EXPECT_NEAR(lamb.brightness(), kPi * 0.05, 1e-3);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(lamb[c] / lamb.brightness(), unit[c], 2e-3) << c;
}

// One transmission matrix serves both directions by reciprocity (bsdf_m.c): light from
// the back to the front sees the front-to-back data with the pair swapped.
TEST(Klems, OneTransmissionIsReciprocal) {
    TempDir dir;
    std::string vals;
    for (int k = 0; k < 41 * 41; ++k) vals += std::to_string(0.05 + 0.001 * ((k * 37) % 101)) + " ";
    const std::string p = dir.file("t.xml");
    writeFile(
        p,
        "<?xml version=\"1.0\"?>\n<WindowElement><FileType>BSDF</FileType><Optical><Layer>"
        "<DataDefinition><IncidentDataStructure>Columns</IncidentDataStructure></DataDefinition>"
        "<WavelengthData><Wavelength>Visible</Wavelength><WavelengthDataBlock>"
        "<WavelengthDataDirection>Transmission Back</WavelengthDataDirection>"
        "<ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>"
        "<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis><ScatteringData>" +
            vals +
            "</ScatteringData></WavelengthDataBlock></WavelengthData></Layer></Optical></"
            "WindowElement>\n");
    const auto sd = loadBsdfFile(p);
    ASSERT_TRUE(sd->tf && !sd->tb);
    Rng rng(4, RngDomain::Test, 0);
    for (int k = 0; k < 1000; ++k) {
        auto dir = [&](double zs) {
            const double r = std::sqrt(rng.uniform()), a = 2 * kPi * rng.uniform();
            return Vec3{r * std::cos(a), r * std::sin(a), zs * std::sqrt(1 - r * r)};
        };
        const Vec3 a = dir(1), b = dir(-1);
        EXPECT_EQ(sd->evaluate(a, b).g, sd->evaluate(b, a).g);
        EXPECT_GT(sd->evaluate(a, b).g, 0);
    }
}

std::string errorOf(const std::string& path) {
    try {
        loadBsdfFile(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const char* kHead =
    "<?xml version=\"1.0\"?>\n<WindowElement>\n<FileType>BSDF</FileType>\n<Optical>\n<Layer>\n"
    "<DataDefinition>\n<IncidentDataStructure>Columns</IncidentDataStructure>\n"
    "</DataDefinition>\n<WavelengthData>\n<Wavelength>Visible</Wavelength>\n"
    "<WavelengthDataBlock>\n<WavelengthDataDirection>Reflection Back</WavelengthDataDirection>\n";

TEST(Klems, BadFilesGiveOneLineErrors) {
    TempDir dir;
    const std::string p = dir.file("b.xml");
    EXPECT_NE(errorOf(dir.file("missing.xml")).find("missing.xml: cannot open"), std::string::npos);
    writeFile(p, std::string(kHead) + "<ColumnAngleBasis>LBNL/Klems Full");  // truncated
    EXPECT_NE(errorOf(p).find("b.xml:"), std::string::npos);
    EXPECT_NE(errorOf(p).find("bad XML"), std::string::npos);
    writeFile(p, "<?xml version=\"1.0\"?>\n<Scene/>\n");
    EXPECT_NE(errorOf(p).find("b.xml:2: not a BSDF file"), std::string::npos);
    writeFile(p, std::string(kHead) +
                     "<ColumnAngleBasis>LBNL/Klems Eighth</ColumnAngleBasis>\n"
                     "<RowAngleBasis>LBNL/Klems Full</RowAngleBasis>\n"
                     "<ScatteringData>1 2 3</ScatteringData>\n"
                     "</WavelengthDataBlock></WavelengthData></Layer></Optical></WindowElement>\n");
    EXPECT_NE(errorOf(p).find("b.xml:13: unknown ColumnAngleBasis 'LBNL/Klems Eighth'"),
              std::string::npos)
        << errorOf(p);
    writeFile(p, std::string(kHead) +
                     "<ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>\n"
                     "<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis>\n"
                     "<ScatteringData>\n1 2 3\n4 5\n</ScatteringData>\n"
                     "</WavelengthDataBlock></WavelengthData></Layer></Optical></WindowElement>\n");
    EXPECT_NE(errorOf(p).find("b.xml:18: too few values in ScatteringData (5 of 1681)"),
              std::string::npos)
        << errorOf(p);
    writeFile(p, std::string(kHead) +
                     "<ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>\n"
                     "<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis>\n"
                     "<ScatteringData>\n1 2 x 3\n</ScatteringData>\n"
                     "</WavelengthDataBlock></WavelengthData></Layer></Optical></WindowElement>\n");
    EXPECT_NE(errorOf(p).find("b.xml:16: bad number in ScatteringData (2 of 1681)"),
              std::string::npos)
        << errorOf(p);
    // Beyond float (found by fuzz_bsdf_xml: an infinite value made the sampling sums NaN).
    writeFile(p, std::string(kHead) +
                     "<ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>\n"
                     "<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis>\n"
                     "<ScatteringData>\n1 2 1e50 3\n</ScatteringData>\n"
                     "</WavelengthDataBlock></WavelengthData></Layer></Optical></WindowElement>\n");
    EXPECT_NE(errorOf(p).find("b.xml:16: value out of range in ScatteringData (2 of 1681)"),
              std::string::npos)
        << errorOf(p);
    // A tensor tree likewise.
    writeFile(p,
              "<?xml version=\"1.0\"?>\n<WindowElement><Optical><Layer><DataDefinition>"
              "<IncidentDataStructure>TensorTree3</IncidentDataStructure></DataDefinition>\n"
              "<WavelengthData><Wavelength>Visible</Wavelength><WavelengthDataBlock>"
              "<WavelengthDataDirection>Transmission Back</WavelengthDataDirection>"
              "<AngleBasis>LBNL/Shirley-Chiu</AngleBasis><ScatteringData>\n"
              "{ 1 2 3 4\n 888888888888888888888888888888888888888888888.5 6 7 8 }\n"
              "</ScatteringData></WavelengthDataBlock></WavelengthData></Layer></Optical>"
              "</WindowElement>\n");
    EXPECT_NE(errorOf(p).find("b.xml:5: value '888888888888888888888888888888888888888888888.5' "
                              "out of range in tensor tree"),
              std::string::npos)
        << errorOf(p);
}

}  // namespace
}  // namespace rp::bsdf

namespace rp::bsdf {
namespace {
// multiSample2 against RADIANCE's hilbert_i2c(2, 31, x * 2^62, c), c / 2^31 printed by a
// throwaway program linked with RADIANCE's src/common/hilbert.c (not in this repository).
TEST(MultiSample, FollowsRadiancesHilbertCurve) {
    const double ref[][3] = {{0.0123, 0.103979163, 0.034775954},
                             {0.1, 0.166666668, 0.499999996},
                             {0.25, 0.5, 0.0},
                             {0.37, 0.758064516, 0.151515149},
                             {0.5, 0.5, 0.5},
                             {0.61, 0.850731708, 0.723414637},
                             {0.77, 0.303030297, 0.983870968},
                             {0.999, 0.037639372, 0.997236140}};
    for (const auto& r : ref) {
        double t[2];
        multiSample2(r[0], t);
        EXPECT_NEAR(t[0], r[1], 1e-8) << r[0];
        EXPECT_NEAR(t[1], r[2], 1e-8) << r[0];
    }
}

// rmtxop's and dctimestep's view of a Klems file (cmbsdf.c). Entries (row, column) and
// the sum of all 145 x 145 x 3 from RADIANCE 5.4: `rmtxop -fa [-rf|-rb] blinds_klems.xml`,
// and for the reciprocal path the same file without its "Transmission Front" block.
TEST(Klems, CoefficientMatricesAreRadiances) {
    RP_REQUIRE_SHARED("validation/bsdf");
    struct Pick {
        int r, c;
        double v;
    };
    struct Case {
        MatrixPart part;
        bool withoutTransmissionFront;
        double total;
        std::vector<Pick> picks;
    };
    const std::vector<Case> cases = {
        {MatrixPart::Transmission,
         false,
         226.410327,
         {{0, 0, 5.908707976341248e-01},
          {10, 20, 3.914254557457753e-05},
          {72, 5, 6.761297117918730e-04},
          {144, 144, 4.666657745838165e-02}}},
        {MatrixPart::ReflectionFront,
         false,
         107.488993,
         {{0, 0, 8.758060284890234e-04},
          {10, 20, 2.068023895844817e-03},
          {100, 3, 8.657445432618260e-04}}},
        {MatrixPart::ReflectionBack,
         false,
         107.720843,
         {{0, 0, 8.987153996713459e-04},
          {10, 20, 4.665984306484461e-05},
          {100, 3, 1.197162433527410e-03}}},
        {MatrixPart::Transmission,
         true,
         226.277684,
         {{0, 0, 5.884844064712524e-01},
          {10, 20, 5.877956573385745e-05},
          {144, 144, 2.286855317652225e-02}}},
    };
    std::ifstream f(kKlems);
    std::stringstream text;
    text << f.rdbuf();
    std::string reduced = text.str();
    const size_t front = reduced.find("Transmission Front");
    ASSERT_NE(front, std::string::npos);
    const size_t from = reduced.rfind("<WavelengthData>", front);
    const size_t to = reduced.find("</WavelengthData>", front) + std::strlen("</WavelengthData>");
    reduced.erase(from, to - from);
    const auto full = loadBsdfFile(kKlems);
    const auto tfOnly = parseBsdfText(reduced, "tf_only.xml");
    ASSERT_FALSE(tfOnly->tb);
    for (const Case& c : cases) {
        const CoefficientMatrix m =
            klemsCoefficients(c.withoutTransmissionFront ? *tfOnly : *full, c.part);
        ASSERT_EQ(m.rows, 145);
        ASSERT_EQ(m.cols, 145);
        double total = 0;
        for (const Color& v : m.values) total += v.r + v.g + v.b;
        EXPECT_NEAR(total, c.total, 1e-6 * c.total) << int(c.part);
        for (const Pick& p : c.picks)
            EXPECT_NEAR(m.values[size_t(p.r) * 145 + size_t(p.c)].g, p.v, 1e-6 * p.v)
                << int(c.part) << " " << p.r << " " << p.c;
    }
}

// The same on tests/data/bsdf/klems_quarter.xml (Klems Quarter, grey, transmission and
// back reflection), no ../shared needed: RADIANCE 5.4's `rmtxop -fa [-rf]` entries,
// among them (0, 0) and (2, 19) at the data's minimum, which RADIANCE gives the
// Lambertian part alone, and the sums of all 41 x 41 x 3. -rb finds no data and is the
// Lambertian part on Klems Full, zero here.
TEST(Klems, CoefficientMatricesOfASmallFile) {
    const auto sd = loadBsdfFile(std::string(RP_SOURCE_DIR) + "/tests/data/bsdf/klems_quarter.xml");
    struct Pick {
        int r, c;
        double v;
    };
    const auto check = [](const CoefficientMatrix& m, double total, std::vector<Pick> picks) {
        ASSERT_EQ(m.rows, 41);
        ASSERT_EQ(m.cols, 41);
        double sum = 0;
        for (const Color& v : m.values) sum += v.r + v.g + v.b;
        EXPECT_NEAR(sum, total, 1e-6 * total);
        for (const Pick& p : picks)
            EXPECT_NEAR(m.values[size_t(p.r) * 41 + size_t(p.c)].r, p.v, 1e-6 * p.v)
                << p.r << " " << p.c;
    };
    check(klemsCoefficients(*sd, MatrixPart::Transmission), 38.626363,
          {{0, 0, 3.844012506306171e-03},
           {2, 19, 4.075462464243174e-03},
           {0, 1, 6.205548532307148e-03},
           {20, 7, 1.048523839563131e-02},
           {40, 40, 6.171775050461292e-03}});
    check(klemsCoefficients(*sd, MatrixPart::ReflectionFront), 19.3095338,
          {{0, 0, 1.922006253153086e-03},
           {2, 19, 2.037731232121587e-03},
           {0, 1, 3.673399565741420e-03},
           {40, 40, 3.540649777278304e-03}});
    const CoefficientMatrix none = klemsCoefficients(*sd, MatrixPart::ReflectionBack);
    EXPECT_EQ(none.rows, 145);
    for (const Color& v : none.values) ASSERT_EQ(v, Color{});
}

}  // namespace
}  // namespace rp::bsdf

// Tensor-tree BSDF data (tensor_tree.cpp): lookups against an independent walk of the
// tree text, values against RADIANCE's own library, sampling against the tabulated
// distribution (chi-square), energy, file:line errors, concurrency and throughput.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <pugixml.hpp>
#include <random>
#include <sstream>
#include <thread>

#include "bsdf/colour.h"
#include "bsdf/xml_detail.h"
#include "util/shared_for_tests.h"

namespace rp::bsdf {
namespace {

const std::string kBlinds = std::string(RP_SHARED_DIR) + "/validation/bsdf/blinds_ttree.xml";
const std::string kTree3 = std::string(RP_SOURCE_DIR) + "/tests/data/bsdf/ttree3.xml";
const std::string kTree4 = std::string(RP_SOURCE_DIR) + "/tests/data/bsdf/ttree4.xml";

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

BsdfData loadText(const std::string& text, const std::string& name) {
    const detail::XmlContext ctx(name, text);
    pugi::xml_document doc;
    if (!doc.load_buffer(text.data(), text.size())) throw std::runtime_error("bad XML in test");
    BsdfData sd;
    sd.path = name;
    detail::loadTensorTree(doc.child("WindowElement").child("Optical").child("Layer"), ctx, sd);
    return sd;
}

BsdfData loadFile(const std::string& path) { return loadText(readFile(path), path); }

const Distribution& dist(const std::optional<ScatteringSet>& s) {
    EXPECT_TRUE(s.has_value());
    EXPECT_EQ(s->components.size(), 1u);
    return *s->components.at(0);
}

// ---------------------------------------------------------------------------------
// Independent reference: the tree text walked directly, positions from directions by
// the concentric map written out here.

struct RefNode {
    std::vector<RefNode> kids;
    std::vector<double> vals;
};

RefNode readRef(const std::string& s, size_t& p) {
    const auto skip = [&] {
        while (p < s.size() && (std::isspace(static_cast<unsigned char>(s[p])) || s[p] == ',')) ++p;
    };
    skip();
    EXPECT_EQ(s.at(p), '{');
    ++p;
    skip();
    RefNode n;
    if (s[p] == '{') {
        while (skip(), s[p] == '{') n.kids.push_back(readRef(s, p));
    } else {
        while (skip(), s[p] != '}') {
            char* end;
            n.vals.push_back(
                std::max(0.0, static_cast<double>(static_cast<float>(std::strtod(&s[p], &end)))));
            p = static_cast<size_t>(end - s.c_str());
        }
    }
    ++p;
    return n;
}

double refValue(const RefNode& n, int nd, std::array<double, 4> x) {
    if (!n.kids.empty()) {
        int c = 0;
        for (int i = 0; i < nd; ++i) {
            const bool up = x[i] >= .5;
            c |= up << i;
            x[i] = 2 * x[i] - (up ? 1 : 0);
        }
        return refValue(n.kids.at(size_t(c)), nd, x);
    }
    const int res = static_cast<int>(std::lround(std::pow(double(n.vals.size()), 1.0 / nd)));
    size_t idx = 0;
    for (int i = 0; i < nd; ++i) idx = idx * size_t(res) + size_t(x[i] * res);
    return n.vals.at(idx);
}

double refMin(const RefNode& n) {
    double m = HUGE_VAL;
    for (const RefNode& k : n.kids) m = std::min(m, refMin(k));
    for (double v : n.vals) m = std::min(m, v);
    return m;
}

// The minimum over what 3-D lookups reach: incident coordinate below .5 (root children
// without bit 0; the handcrafted 3-D trees have a branch at the root).
double refLiveMin(const RefNode& n, int nd) {
    if (nd == 4) return refMin(n);
    EXPECT_EQ(n.kids.size(), 8u);
    double m = HUGE_VAL;
    for (size_t c = 0; c < n.kids.size(); c += 2) m = std::min(m, refMin(n.kids[c]));
    return m;
}

RefNode refTree(const std::string& xmlText, const char* direction) {
    pugi::xml_document doc;
    doc.load_buffer(xmlText.data(), xmlText.size());
    for (pugi::xml_node wd :
         doc.child("WindowElement").child("Optical").child("Layer").children("WavelengthData"))
        for (pugi::xml_node b : wd.children("WavelengthDataBlock"))
            if (detail::trimmedText(b.child("WavelengthDataDirection")) == direction) {
                const std::string s = b.child_value("ScatteringData");
                size_t p = 0;
                return readRef(s, p);
            }
    ADD_FAILURE() << "no " << direction;
    return {};
}

// Shirley-Chiu concentric map, square -> disk, in the paper's form.
void squareToDisc(double u, double v, double& x, double& y) {
    const double a = 2 * u - 1, b = 2 * v - 1;
    double r = 0, phi = 0;
    if (a * a > b * b) {
        r = a;
        phi = kPi / 4 * (b / a);
    } else if (b != 0) {
        r = b;
        phi = kPi / 2 - kPi / 4 * (a / b);
    }
    x = r * std::cos(phi);
    y = r * std::sin(phi);
}

// Its inverse, for binning sampled directions.
void discToSquare(double x, double y, double& u, double& v) {
    const double r = std::hypot(x, y);
    double phi = std::atan2(y, x);
    if (phi < -kPi / 4) phi += 2 * kPi;
    double a, b;
    if (phi < kPi / 4)
        a = r, b = r * phi / (kPi / 4);
    else if (phi < 3 * kPi / 4)
        b = r, a = -r * (phi - kPi / 2) / (kPi / 4);
    else if (phi < 5 * kPi / 4)
        a = -r, b = -r * (phi - kPi) / (kPi / 4);
    else
        b = -r, a = r * (phi - 3 * kPi / 2) / (kPi / 4);
    u = .5 * (a + 1);
    v = .5 * (b + 1);
}

Vec3 hemi(double x, double y, bool up) {
    const double z = std::sqrt(std::max(0.0, 1 - x * x - y * y));
    return {x, y, up ? z : -z};
}

Vec3 rotZ(const Vec3& v, double t) {
    return {v.x * std::cos(t) - v.y * std::sin(t), v.x * std::sin(t) + v.y * std::cos(t), v.z};
}

// The pair (tree incident vector, outgoing vector) at tree position p. inUp/outUp: the
// sides of the two vectors for the set's tree; phiIn: azimuth for 3-D trees.
void pairAt(const std::array<double, 4>& p, int nd, bool inUp, bool outUp, double phiIn, Vec3& in,
            Vec3& out) {
    double x, y;
    if (nd == 4) {
        squareToDisc(p[0], p[1], x, y);
        in = hemi(-x, -y, inUp);
        squareToDisc(p[2], p[3], x, y);
        out = hemi(x, y, outUp);
        return;
    }
    const double r = 2 * (.5 - 1e-6 - p[0]);
    in = hemi(r * std::cos(phiIn), r * std::sin(phiIn), inUp);
    squareToDisc(p[1], p[2], x, y);
    out = rotZ(hemi(x, y, outUp), std::atan2(-in.y, -in.x));
}

struct SetCase {
    const char* direction;  // WINDOW's name in the file
    const std::optional<ScatteringSet> BsdfData::*set;
    bool inUp, outUp;  // sides of the tree's incident and outgoing vectors
    double lamb;       // expected Lambertian part (hemispherical)
};

// Lookups at random cell centres (2^-8 grid) against the walked text, less the minimum.
void checkLookups(const std::string& path, int nd, const SetCase& c) {
    SCOPED_TRACE(path + " " + c.direction);
    const std::string text = readFile(path);
    const BsdfData sd = loadFile(path);
    const RefNode ref = refTree(text, c.direction);
    const double vmin = c.lamb > 0 ? static_cast<float>(c.lamb / kPi) : 0.0;
    if (c.lamb > 0) {
        EXPECT_NEAR(refLiveMin(ref, nd) * kPi, c.lamb, 1e-6);
    }
    const Distribution& d = dist(sd.*c.set);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uni(0, 1);
    for (int k = 0; k < 3000; ++k) {
        std::array<double, 4> p{};
        for (int i = 0; i < nd; ++i) p[i] = (std::floor(uni(rng) * 256) + .5) / 256;
        if (nd == 3) p[0] *= .5;  // the used half
        Vec3 in, out;
        pairAt(p, nd, c.inUp, c.outUp, 2 * kPi * uni(rng), in, out);
        const double expect = std::max(0.0, double(float(refValue(ref, nd, p)) - float(vmin)));
        ASSERT_NEAR(d.value(in, out).r, expect, 1e-6 * std::max(1.0, expect)) << k;
        EXPECT_EQ(d.value(in, out).g, d.value(in, out).r);
        if (c.inUp != c.outUp) {  // reciprocity
            EXPECT_EQ(d.value(out, in).r, d.value(in, out).r);
        }
        // nothing for pairs of the other kinds
        const Vec3 flipped = c.inUp != c.outUp ? Vec3{in.x, in.y, -in.z} : -in;
        EXPECT_TRUE(d.value(flipped, c.inUp != c.outUp ? out : -out).isBlack());
    }
}

TEST(TensorTree, LookupsMatchTreeText4D) {
    checkLookups(kTree4, 4, {"Reflection Back", &BsdfData::rf, true, true, .05 * kPi});
    checkLookups(kTree4, 4, {"Transmission Front", &BsdfData::tb, false, true, .2 * kPi});
    RP_REQUIRE_SHARED("validation/bsdf");
    checkLookups(kBlinds, 4, {"Transmission Back", &BsdfData::tf, true, false, 0});
    checkLookups(kBlinds, 4, {"Reflection Back", &BsdfData::rf, true, true, 0});
    checkLookups(kBlinds, 4, {"Reflection Front", &BsdfData::rb, false, false, 0});
}

TEST(TensorTree, LookupsMatchTreeText3D) {
    checkLookups(kTree3, 3, {"Transmission Back", &BsdfData::tf, true, false, .08 * kPi});
    checkLookups(kTree3, 3, {"Reflection Back", &BsdfData::rf, true, true, 0});
}

// ---------------------------------------------------------------------------------
// RADIANCE's own numbers. The set choice and Lambertian parts follow bsdf.c (SDevalBSDF,
// SDdirectHemi with SDsampSp, SDsizeBSDF), written out here since BsdfData's own
// versions live in bsdf.cpp.

const ScatteringSet* pick(const BsdfData& sd, bool inFront, bool outFront) {
    if (inFront == outFront)
        return inFront ? (sd.rf ? &*sd.rf : nullptr) : (sd.rb ? &*sd.rb : nullptr);
    const std::optional<ScatteringSet>& a = inFront ? sd.tf : sd.tb;
    const std::optional<ScatteringSet>& b = inFront ? sd.tb : sd.tf;
    return a ? &*a : (b ? &*b : nullptr);
}

double evalLike(const BsdfData& sd, const Vec3& in, const Vec3& out) {
    const bool fi = in.z > 0, fo = out.z > 0;
    double v =
        (fi == fo ? (fi ? sd.rLambFront : sd.rLambBack) : (fi ? sd.tLambFront : sd.tLambBack)).r /
        kPi;
    if (const ScatteringSet* s = pick(sd, fi, fo)) v += s->components[0]->value(in, out).r;
    return v;
}

double hemiLike(const BsdfData& sd, const Vec3& in, bool xmit) {
    const ScatteringSet* s = pick(sd, in.z > 0, xmit ? in.z <= 0 : in.z > 0);
    return s ? s->components[0]->hemispherical(in) : 0;
}

void sizeLike(const BsdfData& sd, const Vec3& v1, const Vec3* v2, double psa[2]) {
    psa[0] = 10, psa[1] = 0;
    const ScatteringSet* r = pick(sd, v1.z > 0, v1.z > 0);
    const ScatteringSet* t = pick(sd, v1.z > 0, v1.z <= 0);
    if (v2) ((v1.z > 0) != (v2->z > 0) ? r : t) = nullptr;
    if (!r && !t) psa[0] = psa[1] = kPi;
    for (const ScatteringSet* s : {r, t})
        if (s) s->components[0]->projectedSolidAngle(v1, v2, SizeQuery::MinMax, psa);
    if ((r || t) && psa[0] > psa[1]) psa[0] = psa[1];
}

Vec3 polar(double thetaDeg, double phiDeg, bool up) {
    const double t = thetaDeg * kPi / 180, p = phiDeg * kPi / 180;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), up ? std::cos(t) : -std::cos(t)};
}

struct RadianceRow {
    double ti, pi;
    int iu;
    double to, po;
    int ou;
    double value, hemiR, hemiT, psa2, psa1min, psa1max;
};

// Printed by a throwaway program (not in this repository) linked against RADIANCE 5.4's
// librtrad.a: SDloadFile, then per line SDevalBSDF(&sv, in, out), SDdirectHemi(in,
// SDsampSp|SDsampR) and (..|SDsampT), SDsizeBSDF(psa, in, out, SDqueryMin+SDqueryMax) and
// SDsizeBSDF(psa, in, NULL, ..), for in = polar(ti, pi, iu), out = polar(to, po, ou):
//   ./ref blinds_ttree.xml < pairs.txt    (also ttree3.xml, ttree4.xml)
void checkAgainstRadiance(const std::string& path, const std::vector<RadianceRow>& rows) {
    SCOPED_TRACE(path);
    const BsdfData sd = loadFile(path);
    for (const RadianceRow& r : rows) {
        SCOPED_TRACE(::testing::Message() << r.ti << " " << r.pi << " " << r.iu << " " << r.to
                                          << " " << r.po << " " << r.ou);
        const Vec3 in = polar(r.ti, r.pi, r.iu), out = polar(r.to, r.po, r.ou);
        EXPECT_NEAR(evalLike(sd, in, out), r.value, 2e-7 * std::max(1.0, r.value));
        EXPECT_NEAR(hemiLike(sd, in, false), r.hemiR, 1e-8 * std::max(1.0, r.hemiR));
        EXPECT_NEAR(hemiLike(sd, in, true), r.hemiT, 1e-8 * std::max(1.0, r.hemiT));
        double psa[2];
        sizeLike(sd, in, &out, psa);
        EXPECT_NEAR(psa[0], r.psa2, 1e-8);
        if (r.psa1min < 0) continue;  // RADIANCE reads past an empty table there
        sizeLike(sd, in, nullptr, psa);
        EXPECT_NEAR(psa[0], r.psa1min, 1e-8);
        EXPECT_NEAR(psa[1], r.psa1max, 1e-8);
    }
}

TEST(TensorTree, MatchesRadianceBlinds) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const BsdfData sd = loadFile(kBlinds);
    EXPECT_TRUE(sd.rLambFront.isBlack() && sd.rLambBack.isBlack());
    EXPECT_TRUE(sd.tLambFront.isBlack() && sd.tLambBack.isBlack());
    ASSERT_TRUE(sd.rf && sd.rb && sd.tf && !sd.tb);
    EXPECT_NEAR(sd.rf->maxHemi, 0.516687569, 1e-8);
    EXPECT_NEAR(sd.rb->maxHemi, 0.518381464, 1e-8);
    EXPECT_NEAR(sd.tf->maxHemi, 0.991610507, 1e-8);
    for (const auto* s : {&sd.rf, &sd.rb, &sd.tf}) EXPECT_NEAR((*s)->minProjSA, 0.0122718463, 1e-9);
    // clang-format off
    checkAgainstRadiance(kBlinds, {
        {0, 0, 1, 0, 0, 0, 56.8699989, 0.0975607992, 0.758019746, 0.0122718463, 0.0122718463, 0.196349541},
        {30, 90, 1, 30, 270, 0, 0.434003115, 0.410958876, 0.213435941, 0.0122718463, 0.0122718463, 0.785398163},
        {45, 10, 1, 20, 200, 0, 0.0330980085, 0.199669941, 0.5316808, 0.196349541, 0.0122718463, 0.785398163},
        {60, 45, 1, 70, 100, 0, 0.105162203, 0.438212912, 0.192919099, 0.0122718463, 0.0122718463, 0.785398163},
        {10, 300, 1, 80, 250, 0, 0.0149667496, 0.096971812, 0.881527095, 0.196349541, 0.0122718463, 0.196349541},
        {30, 90, 0, 30, 270, 1, 59.0400009, 0.103986343, 0.901494492, 0.0122718463, 0.0122718463, 0.196349541},
        {50, 135, 0, 15, 20, 1, 0.119741797, 0.21082585, 0.619913401, 0.0490873852, 0.0122718463, 0.196349541},
        {20, 0, 1, 20, 180, 1, 0.0312640294, 0.0964765094, 0.763154787, 0.0490873852, 0.0122718463, 0.196349541},
        {40, 60, 1, 65, 250, 1, 0.0780152529, 0.39909848, 0.216828485, 0.0490873852, 0.0122718463, 0.785398163},
        {75, 300, 1, 5, 0, 1, 0.0362942293, 0.296269923, 0.287444151, 0.0490873852, 0.0122718463, 0.196349541},
        {35, 200, 0, 35, 20, 0, 0.00787276588, 0.294510417, 0.486232241, 0.0490873852, 0.0122718463, 0.785398163},
        {55, 80, 0, 10, 150, 0, 0.0119289802, 0.252270068, 0.384144421, 0.196349541, 0.0122718463, 0.196349541},
    });
    // clang-format on
}

TEST(TensorTree, MatchesRadianceHandcrafted3D) {
    const BsdfData sd = loadFile(kTree3);
    ASSERT_TRUE(sd.rf && sd.tf && !sd.rb && !sd.tb);
    EXPECT_NEAR(sd.tLambFront.r, 0.251327407, 1e-8);  // the unused half's .001 ignored
    EXPECT_NEAR(sd.tLambBack.r, 0.251327407, 1e-8);   // copied across
    EXPECT_TRUE(sd.rLambFront.isBlack());             // minimum .001 < .01/pi
    EXPECT_NEAR(sd.rf->maxHemi, 3.16927793, 1e-7);
    EXPECT_NEAR(sd.tf->maxHemi, 3.71591505, 1e-7);
    EXPECT_NEAR(sd.tf->minProjSA, 0.0490873852, 1e-9);
    // clang-format off
    checkAgainstRadiance(kTree3, {
        {20, 30, 1, 40, 200, 0, 0.88000001, 3.0760119, 3.71591501, 0.196349541, 0.0490873852, 0.785398163},
        {50, 170, 1, 10, 10, 0, 1.87999995, 3.03674197, 3.56374408, 0.0490873852, 0.0490873852, 0.785398163},
        {70, 250, 1, 60, 90, 0, 1.6799999, 3.03674197, 3.56374408, 0.0490873852, 0.0490873852, 0.785398163},
        // transmission by reciprocity: evaluated, not sampled (hemiT 0), as RADIANCE
        {40, 200, 0, 30, 10, 1, 0.980000034, 0, 0, 0.0490873852, -1, -1},
        {25, 60, 1, 35, 250, 1, 2.00099993, 3.0760119, 3.71591501, 0.0490873852, 0.0490873852, 0.785398163},
        {65, 300, 1, 20, 120, 1, 0.601000011, 3.03674197, 3.56374408, 0.196349541, 0.0490873852, 0.785398163},
    });
    // clang-format on
}

TEST(TensorTree, MatchesRadianceHandcrafted4D) {
    const BsdfData sd = loadFile(kTree4);
    ASSERT_TRUE(sd.rf && sd.tb && !sd.rb && !sd.tf);
    EXPECT_NEAR(sd.rLambFront.r, 0.157079635, 1e-8);
    EXPECT_TRUE(sd.rLambBack.isBlack());
    EXPECT_NEAR(sd.tLambFront.r, 0.62831854, 1e-8);
    EXPECT_NEAR(sd.tLambBack.r, 0.62831854, 1e-8);
    EXPECT_NEAR(sd.rf->maxHemi, 3.73064127, 1e-7);
    EXPECT_NEAR(sd.tb->maxHemi, 4.31968993, 1e-7);
    // clang-format off
    checkAgainstRadiance(kTree4, {
        {20, 30, 1, 40, 200, 1, 1.25000005, 2.57217904, 4.08407028, 0.196349541, 0.196349541, 0.785398163},
        {50, 170, 1, 10, 10, 1, 1.04999994, 3.0630528, 4.90873844, 0.785398163, 0.196349541, 0.785398163},
        {70, 250, 1, 60, 90, 1, 1.65000002, 2.74889368, 3.3379421, 0.196349541, 0.196349541, 0.785398163},
        {40, 200, 0, 30, 10, 1, 1.39999993, 0, 3.65210139, 0.196349541, 0.196349541, 0.785398163},
        {25, 60, 0, 35, 250, 1, 2.29999991, 0, 3.71100619, 0.196349541, 0.196349541, 0.785398163},
        {65, 300, 1, 20, 120, 0, 1.00000001, 3.35757722, 2.4740042, 0.196349541, 0.196349541, 0.785398163},
        {10, 100, 0, 80, 330, 0, 0, 0, 2.88633822, kPi, 0.196349541, 0.785398163},
    });
    // clang-format on
}

// ---------------------------------------------------------------------------------
// Sampling: outgoing directions binned on the 16 x 16 grid of the Shirley-Chiu square
// (tree cells are aligned squares no larger than the bins or covering whole bins, and the
// map preserves area, so a bin's probability is exactly the sum of value * pi * area over
// the 256 x 256 sub-cells in it, divided by the total).

// Wilson-Hilferty approximation of the chi-square quantile at significance 0.001.
double chiSquareCritical(int dof) {
    const double z = 3.090, a = 2.0 / (9.0 * dof);
    return dof * std::pow(1 - a + z * std::sqrt(a), 3);
}

struct Incident {
    Vec3 in;
    bool outUp;
};

void checkSampling(const Distribution& d, const Incident& c, bool iso) {
    SCOPED_TRACE(::testing::Message() << "in " << c.in.x << " " << c.in.y << " " << c.in.z);
    constexpr int kBins = 16, kSub = 256;
    const double spin = iso ? std::atan2(-c.in.y, -c.in.x) : 0;
    std::vector<double> expect(kBins * kBins, 0.0);
    double total = 0;
    for (int i = 0; i < kSub; ++i)
        for (int j = 0; j < kSub; ++j) {
            double x, y;
            squareToDisc((i + .5) / kSub, (j + .5) / kSub, x, y);
            const double v = d.value(c.in, rotZ(hemi(x, y, c.outUp), spin)).r;
            expect[size_t(i / (kSub / kBins) * kBins + j / (kSub / kBins))] += v;
            total += v;
        }
    EXPECT_NEAR(total * kPi / (kSub * kSub), d.hemispherical(c.in), 1e-9);
    constexpr int kN = 200000;
    std::vector<double> seen(expect.size(), 0.0);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(0, 1);
    for (int k = 0; k < kN; ++k) {
        Vec3 out;
        ASSERT_TRUE(d.sample(c.in, uni(rng), uni(rng), out));
        ASSERT_NEAR(length(out), 1, 1e-9);
        ASSERT_EQ(out.z > 0, c.outUp);
        const Vec3 o = rotZ(out, -spin);
        double u, v;
        discToSquare(o.x, o.y, u, v);
        const int bu = std::clamp(int(u * kBins), 0, kBins - 1),
                  bv = std::clamp(int(v * kBins), 0, kBins - 1);
        seen[size_t(bu * kBins + bv)] += 1;
    }
    double chi2 = 0, restE = 0, restO = 0;
    int dof = -1;
    for (size_t b = 0; b < expect.size(); ++b) {
        const double e = expect[b] / total * kN;
        if (e < 5) {  // pooled
            restE += e, restO += seen[b];
            continue;
        }
        chi2 += (seen[b] - e) * (seen[b] - e) / e;
        ++dof;
    }
    if (restE >= 5)
        chi2 += (restO - restE) * (restO - restE) / restE, ++dof;
    else
        EXPECT_LE(restO, 20);
    ASSERT_GT(dof, 5);
    EXPECT_LT(chi2, chiSquareCritical(dof)) << "dof " << dof;
}

TEST(TensorTree, SamplingFollowsTable4D) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const BsdfData sd = loadFile(kBlinds);
    for (const Vec3& in : {polar(0, 0, true), polar(35, 70, true), polar(62, 200, true)}) {
        checkSampling(dist(sd.tf), {in, false}, false);  // as stored
        checkSampling(dist(sd.rf), {in, true}, false);
        checkSampling(dist(sd.rb), {-in, false}, false);
        checkSampling(dist(sd.tf), {-in, true}, false);  // by reciprocity
    }
    const BsdfData hand = loadFile(kTree4);
    checkSampling(dist(hand.tb), {polar(40, 250, false), true}, false);
    checkSampling(dist(hand.tb), {polar(40, 250, true), false}, false);
}

TEST(TensorTree, SamplingFollowsTable3D) {
    const BsdfData sd = loadFile(kTree3);
    for (const Vec3& in : {polar(5, 0, true), polar(35, 70, true), polar(62, 200, true)}) {
        checkSampling(dist(sd.tf), {in, false}, true);
        checkSampling(dist(sd.rf), {in, true}, true);
    }
    Vec3 out;  // reciprocity of 3-D trees is not sampled, as in RADIANCE
    EXPECT_FALSE(dist(sd.tf).sample(polar(30, 0, false), .5, .5, out));
    EXPECT_EQ(dist(sd.tf).hemispherical(polar(30, 0, false)), 0);
    EXPECT_FALSE(dist(sd.rf).sample(polar(30, 0, false), .5, .5, out));
}

// Energy: a stratified Monte-Carlo integral of the whole BSDF * |cos| over the outgoing
// hemisphere (uniform in solid angle) against hemispherical() plus the Lambertian part.
double integrate(const Distribution& d, const Vec3& in, bool outUp, double lamb) {
    constexpr int kN = 1024;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(0, 1);
    double sum = 0;
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
            const double z = (i + uni(rng)) / kN, phi = 2 * kPi * (j + uni(rng)) / kN;
            const double s = std::sqrt(1 - z * z);
            const Vec3 out{s * std::cos(phi), s * std::sin(phi), outUp ? z : -z};
            sum += (d.value(in, out).r + lamb / kPi) * z;
        }
    return sum * 2 * kPi / (double(kN) * kN);
}

TEST(TensorTree, EnergyMatchesHemispherical) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const BsdfData sd = loadFile(kBlinds);
    for (const Vec3& in : {polar(0, 0, true), polar(40, 120, true), polar(70, 300, true)}) {
        for (const auto& [d, i, up] :
             {std::tuple{&dist(sd.tf), in, false}, std::tuple{&dist(sd.tf), -in, true},
              std::tuple{&dist(sd.rf), in, true}, std::tuple{&dist(sd.rb), -in, false}}) {
            const double h = d->hemispherical(i);
            EXPECT_GT(h, .01);
            EXPECT_NEAR(integrate(*d, i, up, 0), h, .01 * h);
        }
    }
    const BsdfData t3 = loadFile(kTree3);
    const Vec3 in = polar(50, 20, true);
    const double h3 = dist(t3.tf).hemispherical(in) + t3.tLambFront.r;
    EXPECT_NEAR(integrate(dist(t3.tf), in, false, t3.tLambFront.r), h3, .01 * h3);
    const BsdfData t4 = loadFile(kTree4);
    const Vec3 in4 = polar(30, 160, true);
    const double h4 = dist(t4.rf).hemispherical(in4) + t4.rLambFront.r;
    EXPECT_NEAR(integrate(dist(t4.rf), in4, true, t4.rLambFront.r), h4, .01 * h4);
}

// ---------------------------------------------------------------------------------
// Bad input: InputError "file:line: ..." with the line of the offending text.

std::string treeDoc(int nd, const std::string& basis, const std::string& data) {
    return "<?xml version=\"1.0\"?>\n<WindowElement>\n<Optical>\n<Layer>\n"
           "<DataDefinition><IncidentDataStructure>TensorTree" +
           std::to_string(nd) +
           "</IncidentDataStructure></DataDefinition>\n"
           "<WavelengthData>\n<Wavelength>Visible</Wavelength>\n<WavelengthDataBlock>\n"
           "<WavelengthDataDirection>Reflection Back</WavelengthDataDirection>\n"
           "<AngleBasis>" +
           basis +
           "</AngleBasis>\n"
           "<ScatteringData>\n" +
           data +
           "\n</ScatteringData>\n"
           "</WavelengthDataBlock>\n</WavelengthData>\n</Layer>\n</Optical>\n</WindowElement>\n";
}

int lineOf(const std::string& text, const std::string& marker) {
    const size_t at = text.find(marker);
    EXPECT_NE(at, std::string::npos) << marker;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + long(at), '\n'));
}

// 2^ndim children, child `special` replaced by `text`.
std::string branch(int nd, int special, const std::string& text) {
    std::string s = "{\n";
    for (int c = 0; c < (1 << nd); ++c) s += c == special ? text + "\n" : "  { 0.25 }\n";
    return s + "}";
}

std::string repeat(const std::string& v, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += v + " ";
    return s;
}

void expectError(const std::string& text, const std::string& marker, const std::string& what) {
    const std::string name = "bad_tree.xml";
    const std::string where = name + ":" + std::to_string(lineOf(text, marker)) + ":";
    try {
        loadText(text, name);
        ADD_FAILURE() << "no error for " << what;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
}

TEST(TensorTree, BadInputNamesFileAndLine) {
    const std::string sc = "LBNL/Shirley-Chiu";
    expectError(treeDoc(4, sc, branch(4, 7, "  { " + repeat("0.5", 15) + "} <!--x-->")), "{ 0.5",
                "15 values");
    expectError(treeDoc(3, sc, branch(3, 2, "  { " + repeat("0.5", 16) + "}")), "{ 0.5",
                "16 values");  // 16 is 4-D's count, not 3-D's
    expectError(
        treeDoc(4, sc, branch(4, 3, "  { 0.5 0.5 0.5 0.5\n 0.5 0.5x " + repeat("0.5", 10) + "}")),
        "0.5x", "bad number '0.5x'");
    expectError(treeDoc(4, sc, branch(4, 0, "  { - }")), "{ - }", "bad number '-'");
    expectError(treeDoc(4, "LBNL/Klems Full", "{ 1 }"), "<AngleBasis>", "unsupported angle basis");
    expectError(treeDoc(4, sc, "{\n" + repeat("{ 1 }\n", 15) + "}"), "}\n</Scat", "15 subtrees");
    expectError(treeDoc(4, sc, "{\n" + repeat("{ 1 }\n", 16) + "{ 2 }\n}"), "{ 2 }",
                "more than 16 subtrees");
    expectError(treeDoc(4, sc, "{ 1 }\n{ 3 }"), "{ 3 }", "extra characters");
    expectError(treeDoc(4, sc, "{ 1 }\n{ }"), "{ }", "extra characters");
    expectError(treeDoc(4, sc, "{\n  { }\n" + repeat("{ 1 }\n", 15) + "}"), "{ }", "0 values");
    expectError(treeDoc(4, sc, "{ " + repeat("0.5", 16)), "</ScatteringData>", "expected '}'");
    expectError(treeDoc(4, sc, "{\n  { 1 }\n"), "</ScatteringData>", "branch has 1 subtrees");
    expectError(treeDoc(4, sc, "  "), "<ScatteringData>", "missing BSDF ScatteringData");
}

TEST(TensorTree, AcceptsCommasAndSingleLeaf) {
    const BsdfData sd = loadText(treeDoc(4, "lbnl/shirley-chiu", "{ 0.4 }"), "one.xml");
    ASSERT_TRUE(sd.rf);
    EXPECT_NEAR(sd.rLambFront.r, float(0.4) * kPi, 1e-6);  // all Lambertian
    EXPECT_NEAR(dist(sd.rf).hemispherical(polar(30, 0, true)), 0, 1e-6);
    const std::string commas =
        "{\n" + repeat("{ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16 },", 16) + "\n}";
    const BsdfData c = loadText(treeDoc(4, "LBNL/Shirley-Chiu", commas), "commas.xml");
    ASSERT_TRUE(c.rf);
    EXPECT_NEAR(c.rf->minProjSA, kPi / 16, 1e-12);
}

// ---------------------------------------------------------------------------------
// Many threads filling and reading the tables at once get what one thread gets.
TEST(TensorTree, ConcurrentUseMatchesSequential) {
    RP_REQUIRE_SHARED("validation/bsdf");
    const BsdfData seq = loadFile(kBlinds), par = loadFile(kBlinds);
    constexpr int kThreads = 6, kPer = 4000;
    const auto run = [](const BsdfData& sd, int t, std::vector<double>& res) {
        std::mt19937_64 rng(100 + t);
        std::uniform_real_distribution<double> uni(0, 1);
        for (int k = 0; k < kPer; ++k) {
            const Vec3 in = polar(89 * uni(rng), 360 * uni(rng), uni(rng) < .5);
            const Distribution& d = dist(k % 2 ? sd.tf : (in.z > 0 ? sd.rf : sd.rb));
            Vec3 out;
            const double x = uni(rng), y = uni(rng);
            res.push_back(d.hemispherical(in));
            res.push_back(d.sample(in, x, y, out) ? out.x + 2 * out.y + 3 * out.z : -9);
            double psa[2] = {10, 0};
            d.projectedSolidAngle(in, nullptr, SizeQuery::MinMax, psa);
            res.push_back(psa[0] + 7 * psa[1]);
        }
    };
    std::vector<std::vector<double>> a(kThreads), b(kThreads);
    for (int t = 0; t < kThreads; ++t) run(seq, t, a[size_t(t)]);
    std::vector<std::thread> pool;
    for (int t = 0; t < kThreads; ++t)
        pool.emplace_back(run, std::cref(par), t, std::ref(b[size_t(t)]));
    for (std::thread& th : pool) th.join();
    for (int t = 0; t < kThreads; ++t) EXPECT_EQ(a[size_t(t)], b[size_t(t)]) << t;
}

// Evaluations per second (printed; not a pass/fail criterion).
// CIE-u and CIE-v trees colour the data (constant u' v' here): every value and the
// Lambertian part have that chromaticity in RADIANCE RGB, and the brightness stays the
// visible tree's.
TEST(TensorTree, CieUvTreesColourTheData) {
    std::string text = readFile(kTree4);
    auto uv = [](const char* wl, const char* value) {
        return std::string("<WavelengthData><Wavelength>") + wl +
               "</Wavelength><WavelengthDataBlock><WavelengthDataDirection>Reflection Back"
               "</WavelengthDataDirection><AngleBasis>LBNL/Shirley-Chiu</AngleBasis>"
               "<ScatteringData>{ " +
               value + " }</ScatteringData></WavelengthDataBlock></WavelengthData>\n";
    };
    text.insert(text.find("</Layer>"), uv("CIE-u", "0.15") + uv("CIE-v", "0.50"));
    const BsdfData grey = loadFile(kTree4), colour = loadText(text, "colour.xml");
    // u' v' (0.15, 0.50) is x y (0.27551, 0.40816): XYZ (0.675, 1, 0.775) per unit Y,
    // through RADIANCE's XYZ -> RGB (primaries 0.640 0.330, 0.290 0.600, 0.150 0.060).
    const Color unit = rgbOfXyz(0.675, 1, 0.775);
    EXPECT_GT(unit.b, 1.2 * unit.r);  // a clearly coloured test
    EXPECT_NEAR(unit.brightness(), 1, 2e-3);
    EXPECT_NEAR(colour.rLambFront.brightness(), grey.rLambFront.g, 1e-3);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(colour.rLambFront[c], unit[c] * grey.rLambFront.g, 2e-3) << c;
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> uni(0, 1);
    for (int k = 0; k < 500; ++k) {
        const Vec3 in = polar(80 * uni(rng), 360 * uni(rng), true);
        const Vec3 out = polar(80 * uni(rng), 360 * uni(rng), true);
        const Color g = grey.evaluate(in, out), c = colour.evaluate(in, out);
        EXPECT_NEAR(c.brightness(), g.g, 1e-3 * (1 + g.g));
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], unit[i] * g.g, 2e-3 * (1 + g.g)) << i;
    }
}

}  // namespace
}  // namespace rp::bsdf

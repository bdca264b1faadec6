// `#@rfluxmtx` settings, file scanning and receiver/sender grouping, with RADIANCE's
// quirks and one test per kind of bad input.
#include "flux/flux_params.h"

#include <gtest/gtest.h>

#include "flux/flux_scan.h"
#include "flux/flux_surfaces.h"
#include "util/warning_capture_for_tests.h"

namespace rp::flux {
namespace {

const SourceLoc kLoc{"f.rad", 3};

std::string errorOf(const std::string& line) {
    FluxParams p;
    try {
        applyParamLine(line, kLoc, p);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FluxParams, ReadsBasisUpAndOutput) {
    FluxParams p;
    applyParamLine(" h=kf u=+Z o='my out.mtx'\n", kLoc, p);
    EXPECT_EQ(p.sign, '+');
    EXPECT_EQ(p.hemis, "kf");
    EXPECT_EQ(p.size, 1);
    EXPECT_EQ(p.up.z, 1);
    ASSERT_TRUE(p.outSpec);
    EXPECT_EQ(*p.outSpec, "my out.mtx");
    applyParamLine("h=-r4", kLoc, p);
    EXPECT_EQ(p.sign, '-');
    EXPECT_EQ(p.size, 4);
    EXPECT_EQ(basisOf(p.hemis), BasisKind::Reinhart);
    applyParamLine("h=sc12", kLoc, p);
    EXPECT_EQ(p.size, 12);
}

TEST(FluxParams, BasisNames) {
    EXPECT_EQ(basisOf("u"), BasisKind::Uniform);
    EXPECT_EQ(basisOf("1"), BasisKind::Uniform);
    EXPECT_EQ(basisOf("SC5"), BasisKind::ShirleyChiu);
    EXPECT_EQ(basisOf("t"), BasisKind::Reinhart);
    EXPECT_EQ(basisOf("k"), BasisKind::KlemsFull);
    EXPECT_EQ(basisOf("k2"), BasisKind::KlemsHalf);
    EXPECT_EQ(basisOf("kQ"), BasisKind::KlemsQuarter);
    EXPECT_FALSE(basisOf("kx"));
    EXPECT_FALSE(basisOf("x"));
}

TEST(FluxParams, UpDirectionQuirks) {
    EXPECT_EQ(parseUpDirection("-Y")->y, -1);
    EXPECT_EQ(parseUpDirection("--x")->x, 1);
    // RADIANCE: the sign of a vector applies to its x component only.
    const Vec3 v = *parseUpDirection("-1,0,1");
    EXPECT_NEAR(v.x, -std::sqrt(.5), 1e-12);
    EXPECT_NEAR(v.z, std::sqrt(.5), 1e-12);
    EXPECT_EQ(parseUpDirection("-0,0,2")->z, 1);
    EXPECT_FALSE(parseUpDirection("Zed"));
    EXPECT_FALSE(parseUpDirection("0,0,0"));
    EXPECT_FALSE(parseUpDirection("1,2"));
}

TEST(FluxParams, BadLinesNameFileAndLine) {
    EXPECT_EQ(errorOf("h="), "f.rad:3: bad parameter string: h=");
    EXPECT_EQ(errorOf("x=1"), "f.rad:3: bad parameter string: x=1");
    EXPECT_EQ(errorOf("h kf"), "f.rad:3: bad parameter string: h kf");
    EXPECT_EQ(errorOf("u=up"), "f.rad:3: bad parameter string: u=up");
    EXPECT_EQ(errorOf("o=\"open"), "f.rad:3: bad parameter string: o=\"open");
    EXPECT_EQ(errorOf("h=q"), "f.rad:3: unrecognized hemisphere sampling: h=q");
}

const char* kSky = R"(# sky receiver
#@rfluxmtx h=u
void glow groundglow 0 0 4 1 1 1 0
groundglow source ground 0 0 4 0 0 -1 180
#@rfluxmtx h=t u=+Y
void glow skyglow 0 0 4 1 1 1 0
skyglow alias other skyglow
skyglow source sky 0 0 4 0 0 1 180
)";

TEST(FluxScan, FindsSettingsAndSurfaces) {
    const auto items = scanFluxText(kSky, "sky.rad");
    ASSERT_EQ(items.size(), 4u);
    EXPECT_TRUE(items[0].isParams);
    EXPECT_EQ(items[0].loc.line, 2);
    EXPECT_EQ(items[1].surface.name, "ground");
    EXPECT_EQ(items[1].surface.normal.z, 1);  // a source's direction reversed
    EXPECT_NEAR(items[1].surface.area, kPi, 1e-12);
    EXPECT_EQ(items[2].paramText, " h=t u=+Y");
    EXPECT_EQ(items[3].loc.line, 8);
}

TEST(FluxScan, PolygonAndRingGeometry) {
    const auto items = scanFluxText(
        "m polygon p 0 0 12 0 0 0 2 0 0 2 1 0 0 1 0\n"
        "m ring r 0 0 8 0 0 1 0 -1 0 2 1\n",
        "s.rad");
    ASSERT_EQ(items.size(), 2u);
    EXPECT_NEAR(items[0].surface.area, 2, 1e-12);
    EXPECT_EQ(items[0].surface.normal.z, 1);
    EXPECT_NEAR(items[1].surface.area, 3 * kPi, 1e-12);  // radii swapped to 1, 2
    EXPECT_EQ(items[1].surface.normal.y, -1);
}

std::string scanError(const std::string& text) {
    try {
        scanFluxText(text, "s.rad");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FluxScan, BadSurfaces) {
    EXPECT_EQ(scanError("\nm polygon p 0 0 6 0 0 0 1 0 0"),
              "s.rad:2: bad argument count for surface element 'p'");
    EXPECT_EQ(scanError("m ring r 0 0 8 0 0 0 0 0 0 0 1"),
              "s.rad:1: bad orientation for surface element 'r'");
    EXPECT_EQ(scanError("m source s 0 0 4 0 0 1 x"), "s.rad:1: error reading arguments for 's'");
    EXPECT_EQ(scanError("m plastic s 0 0 a"), "s.rad:1: error reading arguments for 's'");
    WarningCapture w;
    EXPECT_TRUE(scanFluxText("m polygon z 0 0 9 0 0 0 1 0 0 2 0 0", "s.rad").empty());
    EXPECT_TRUE(w.any("zero area for surface 'z'"));
}

TEST(FluxSurfaces, ReceiversTakeTheirSettings) {
    const auto r = receiversOf(scanFluxText(kSky, "sky.rad"), "sky.rad");
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0].modifier, "groundglow");
    EXPECT_EQ(r[0].basis, BasisKind::Uniform);
    EXPECT_EQ(r[0].up.y, 1);  // default for a normal along Z
    EXPECT_EQ(r[1].basis, BasisKind::Reinhart);
    EXPECT_EQ(r[1].normal.z, -1);
    EXPECT_EQ(r[1].up.y, 1);
}

TEST(FluxSurfaces, HemisphereCarriesOverButUpAndOutputDoNot) {
    const auto r = receiversOf(scanFluxText("#@rfluxmtx h=kh u=-X o=a.mtx\n"
                                            "a polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"
                                            "b polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n",
                                            "r.rad"),
                               "r.rad");
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[1].basis, BasisKind::KlemsHalf);
    EXPECT_EQ(r[0].up.x, -1);
    EXPECT_EQ(r[1].up.y, 1);
    EXPECT_TRUE(r[0].params.outSpec);
    EXPECT_FALSE(r[1].params.outSpec);
}

std::string receiverError(const std::string& text) {
    try {
        receiversOf(scanFluxText(text, "r.rad"), "r.rad");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FluxSurfaces, BadReceivers) {
    EXPECT_EQ(receiverError("#@rfluxmtx h=kf\nvoid glow g 0 0 4 1 1 1 0\n"),
              "r.rad: missing receiver surface");
    EXPECT_EQ(receiverError("g source s 0 0 4 0 0 1 180\n"),
              "r.rad:1: missing hemisphere sampling type");
    EXPECT_EQ(receiverError("#@rfluxmtx h=r\ng source s 0 0 4 0 0 1 90\n"),
              "r.rad:2: source 's' must be 180-degrees");
    EXPECT_EQ(receiverError("#@rfluxmtx h=sc\ng polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
              "r.rad:1: missing size for Shirley-Chiu sampling");
    EXPECT_EQ(receiverError("#@rfluxmtx h=u\ng source s 0 0 4 0 0 1 180\n"
                            "h polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
              "r.rad:3: cannot mix source/non-source receivers");
    EXPECT_EQ(receiverError("#@rfluxmtx h=u\ng source s 0 0 4 0 0 1 180\n"
                            "h source t 0 0 4 0 0 -1 180\ng source u 0 0 4 1 0 0 180\n"),
              "r.rad:4: duplicate receiver modifier 'g' (keep a receiver's surfaces together)");
    EXPECT_EQ(receiverError("#@rfluxmtx h=u\ng polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"
                            "g polygon q 0 0 9 0 0 0 0 1 0 1 0 0\n"),
              "r.rad:2: undefined normal for hemisphere sampling");
    EXPECT_EQ(receiverError("\n\n#@rfluxmtx h=kf u=+Q\ng source s 0 0 4 0 0 1 180\n"),
              "r.rad:3: bad parameter string: h=kf u=+Q");
}

std::string senderError(const std::string& text) {
    try {
        senderOf(scanFluxText(text, "s.rad"), "s.rad");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(FluxSurfaces, SenderFrame) {
    const FluxGroup s = senderOf(scanFluxText("#@rfluxmtx h=-kf u=Z\n"
                                              "w polygon p 0 0 12 0 0 0 1 0 0 1 0 1 0 0 1\n",
                                              "s.rad"),
                                 "s.rad");
    EXPECT_EQ(s.normal.y, -1);
    // u = up x normal = (1, 0, 0), reversed for the left-handed basis.
    EXPECT_NEAR(s.uAxis.x, -1, 1e-12);
    EXPECT_NEAR(s.vAxis.z, 1, 1e-12);
}

TEST(FluxSurfaces, BadSenders) {
    EXPECT_EQ(senderError("#@rfluxmtx h=kf\n"), "s.rad: no sender surface");
    EXPECT_EQ(senderError("#@rfluxmtx h=kf\ng source s 0 0 4 0 0 1 180\n"),
              "s.rad:2: cannot use source as a sender");
    EXPECT_EQ(senderError("g polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
              "s.rad:1: missing sender sampling type");
    EXPECT_EQ(senderError("#@rfluxmtx h=kf u=-Z\ng polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
              "s.rad:2: up vector coincides with sender normal");
}

}  // namespace
}  // namespace rp::flux

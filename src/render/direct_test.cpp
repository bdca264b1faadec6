// The direct calculation against closed-form irradiance: parallel squares (form factor),
// spheres, disks, distant sources, occluders, glass, spotlights, the -dt/-dc source test
// and mirror- and prism-relayed virtual sources. The oracle here is a stand-in for the
// renderer: light materials emit their radiance, glass transmits 0.9, mirrors reflect
// 0.9, prisms turn light by a fixed angle (TurningFilm), anything else is opaque.
#include "render/direct.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "light/light_sources.h"
#include "render/source_polygon.h"
#include "render/source_sampling.h"
#include "scene/reader.h"

namespace rp::render {
namespace {

// The per-thread working memory the renderer keeps (one thread here).
DirectScratch scratch;
PolygonScratch polygon;

class TestOracle : public ShadowOracle {
public:
    TestOracle(const Scene& scene, const SceneGeometry& geo) : scene_(scene), geo_(geo) {}
    std::optional<Hit> closestHit(const Ray& ray) override {
        ++rays;
        return geo_.closestHit(ray);
    }
    ShadowEvent event(const Hit& hit, const Vec3&, ShadowPath&, bool) override {
        int32_t mat = light::findMaterial(scene_, hit.prim);
        if (mat == kVoid) return {};
        const Primitive& m = scene_.prims[size_t(mat)];
        switch (m.type) {
            case PrimType::Light:
            case PrimType::Spotlight:
            case PrimType::Glow:
            case PrimType::Illum:
                return {ShadowEvent::Kind::Emit, {m.rargs[0], m.rargs[1], m.rargs[2]}, {}, {}};
            case PrimType::Glass:
                return {ShadowEvent::Kind::Transmit, Color::grey(0.9), {}, {}};
            case PrimType::Mirror:
                return {ShadowEvent::Kind::Reflect, Color::grey(0.9), {}, {}};
            default:
                return {};
        }
    }
    Color distantRadiance(int32_t source, const Vec3&) override {
        int32_t mat = light::findMaterial(scene_, geo_.sources()[size_t(source)].prim);
        const Primitive& m = scene_.prims[size_t(mat)];
        return {m.rargs[0], m.rargs[1], m.rargs[2]};
    }
    long rays = 0;

private:
    const Scene& scene_;
    const SceneGeometry& geo_;
};

// Irradiance coefficient for a surface with normal n: cos (compute() adds omega).
DirectCoefficient cosine(const Vec3& n) {
    return [n](const Vec3& toLight, double) {
        double c = dot(toLight, n);
        return c > 0 ? Color::grey(c) : Color{};
    };
}

// Form factor from a differential area to a parallel rectangle [0,x]x[0,y] at height h
// with a corner above it (Howell's catalogue, C-12), extended as an odd function of x, y.
double cornerFactor(double x, double y, double h) {
    double X = x / h, Y = y / h;
    double sx = std::sqrt(1 + X * X), sy = std::sqrt(1 + Y * Y);
    return (X / sx * std::atan(Y / sx) + Y / sy * std::atan(X / sy)) / (2 * kPi);
}
// Irradiance from a parallel rectangle [x1,x2]x[y1,y2] (relative to the foot of the
// point) of radiance L at height h.
double rectIrradiance(double L, double x1, double x2, double y1, double y2, double h) {
    double f = cornerFactor(x2, y2, h) - cornerFactor(x1, y2, h) - cornerFactor(x2, y1, h) +
               cornerFactor(x1, y1, h);
    return L * kPi * f;
}

// A downward-facing square of side s centred above the origin at height h.
std::string squareDown(const std::string& mod, const std::string& name, double cx, double cy,
                       double s, double h) {
    double a = s / 2;
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s polygon %s 0 0 12 %g %g %g %g %g %g %g %g %g %g %g %g\n",
                  mod.c_str(), name.c_str(), cx - a, cy - a, h, cx - a, cy + a, h, cx + a, cy + a,
                  h, cx + a, cy - a, h);
    return buf;
}

struct Fixture {
    explicit Fixture(const std::string& text) : scene(parseScene(text)), geo(scene) {}
    Color irradiance(const DirectOptions& opt, const Vec3& p, const Vec3& n, uint64_t seed = 1,
                     bool virtualSources = true, long* rays = nullptr) {
        DirectLighting direct(scene, geo, opt, virtualSources);
        TestOracle oracle(scene, geo);
        DirectPoint at;
        at.point = p;
        at.normal = at.geomNormal = n;
        Rng rng(seed, RngDomain::Test, 0);
        Color c = direct.compute(at, cosine(n), oracle, rng, scratch);
        if (rays) *rays = oracle.rays;
        return c;
    }
    Scene scene;
    SceneGeometry geo;
};

const std::string kLight = "void light bright 0 0 3 100 100 100\n";

TEST(DirectSquare, MatchesFormFactor) {
    Fixture f(kLight + squareDown("bright", "lamp", 0, 0, 0.5, 1));
    double exact = rectIrradiance(100, -0.25, 0.25, -0.25, 0.25, 1);
    DirectOptions opt;
    opt.sampling = 0.01;
    EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, exact, 0.005 * exact);
    // RADIANCE's answers: cells' area times cosine over squared distance, at their
    // centres (`rtrace -h -I -ab 0 -dj 0 -ds 0.2` and `-ds 0` at "0 0 0 0 0 1", RADIANCE 5.4:
    // 23.1914 and 25.005; -I measures 1e-4 above the point, hence the 5e-4 tolerance, and
    // 25 = 100 * 0.25 exactly at the point).
    opt.sampling = 0.2;
    EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 23.1914, 5e-4 * 23.1914);
    opt.sampling = 0;
    EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 25, 1e-9);
}

TEST(DirectPolygon, NearLuminaireAsRadiance) {
    // RADIANCE's test model trans: the 1.16 x 0.55 m luminaire of rect_fixture.rad (as a
    // plain light) 0.74 m from a point on a ball. At -ds 0 RADIANCE takes the whole source
    // as one sample at its centre, 31 % above the exact 13.0: the plastic2 and plasfunc
    // balls under it read 20 % low until we did the same. RADIANCE 5.4,
    // `echo -3.95 2.08 2.388 0.1236 0.2047 0.971 | rtrace -h -I -ab 0 -dj 0 -ds D`:
    // 17.02549 (D = 0) and 13.00642 (D = 0.2), measured 1e-4 off the point (5e-4 tolerance).
    Fixture f(
        "void light bright 0 0 3 20 20 20\n"
        "bright polygon luminaire 0 0 12 -3.42215031167 2.22695014727 2.999"
        " -4.57784968833 2.22695014728 2.999 -4.57784968833 2.77304985273 2.999"
        " -3.42215031167 2.77304985272 2.999\n");
    const Vec3 p{-3.95, 2.08, 2.388}, n = normalize(Vec3{0.1236, 0.2047, 0.971});
    DirectOptions opt;
    opt.sampling = 0;
    EXPECT_NEAR(f.irradiance(opt, p, n).r, 17.02549, 5e-4 * 17.02549);
    opt.sampling = 0.2;
    EXPECT_NEAR(f.irradiance(opt, p, n).r, 13.00642, 5e-4 * 13.00642);
}

TEST(DirectSquare, OffAxisAndTilted) {
    // Point off to the side: the square spans x in [0.75, 1.25] relative to it.
    Fixture f(kLight + squareDown("bright", "lamp", 0, 0, 0.5, 1));
    double exact = rectIrradiance(100, -1.25, -0.75, -0.25, 0.25, 1);
    DirectOptions opt;
    opt.sampling = 0.01;
    EXPECT_NEAR(f.irradiance(opt, {1, 0, 0}, {0, 0, 1}).r, exact, 0.005 * exact);
}

TEST(DirectSquare, ConcavePolygonCellsCoverItsArea) {
    // An L-shaped light: three unit-ish squares; the areas of the cells (clipped exactly)
    // must sum to the L's, their solid angles nearly to the L's, and irradiance must
    // equal the sum over its three squares.
    std::string text =
        kLight + "bright polygon ell 0 0 18  0 0 1  0 1 1  0.5 1 1  0.5 0.5 1  1 0.5 1  1 0 1\n";
    Fixture f(text);
    double exact = rectIrradiance(100, 0, 0.5, 0, 1, 1) + rectIrradiance(100, 0.5, 1, 0, 0.5, 1);
    DirectOptions opt;
    opt.sampling = 0.01;
    EXPECT_NEAR(
        f.irradiance(opt, {0.1, 0.1, 0}, {0, 0, 1}).r,
        rectIrradiance(100, -0.1, 0.4, -0.1, 0.9, 1) + rectIrradiance(100, 0.4, 0.9, -0.1, 0.4, 1),
        0.005 * exact);
    // Sum of sample solid angles = exact solid angle of the L (triangles from the point).
    DirectLighting direct(f.scene, f.geo, opt);
    std::vector<SourceSample> samples;
    Rng rng(3, RngDomain::Test, 0);
    Vec3 from{0.1, 0.1, 0};
    opt.jitter = 1;
    sampleSource(direct.sourceList(), direct.sourceList().sources[0], f.geo.shapes(), from, opt, 1,
                 rng, polygon, samples);
    double sum = 0, area = 0;
    for (const auto& s : samples) {
        sum += s.omega;
        area += s.omega * s.dist * s.dist / s.dir.z;  // the light faces down
    }
    EXPECT_NEAR(area, 0.75, 1e-9);
    auto tri = [&](Vec3 a, Vec3 b, Vec3 c) { return triangleSolidAngle(from, a, b, c); };
    double omega =
        tri({0, 0, 1}, {0, 1, 1}, {0.5, 1, 1}) + tri({0, 0, 1}, {0.5, 1, 1}, {0.5, 0, 1}) +
        tri({0.5, 0, 1}, {0.5, 0.5, 1}, {1, 0.5, 1}) + tri({0.5, 0, 1}, {1, 0.5, 1}, {1, 0, 1});
    // 64 cells of about 1/8 m at 1 m: area cos / d^2 per cell is within 1.5 % of exact.
    EXPECT_NEAR(sum, omega, 0.015 * omega);
    for (const auto& s : samples) {
        // Jittered samples stay on the L.
        bool inLeft = s.target.x >= -1e-9 && s.target.x <= 0.5 + 1e-9 && s.target.y >= -1e-9 &&
                      s.target.y <= 1 + 1e-9;
        bool inRight = s.target.x >= 0.5 - 1e-9 && s.target.x <= 1 + 1e-9 && s.target.y >= -1e-9 &&
                       s.target.y <= 0.5 + 1e-9;
        EXPECT_TRUE(inLeft || inRight) << s.target.x << " " << s.target.y;
    }
}

TEST(DirectSphere, MatchesSinSquared) {
    Fixture f(kLight + "bright sphere ball 0 0 4 0 0 2 0.1\n");
    double exact = 100 * kPi * 0.01 / 4;  // L pi (r/d)^2
    DirectOptions opt;
    for (double ds : {0.0, 0.01, 0.2}) {
        opt.sampling = ds;
        EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, exact, 0.005 * exact) << ds;
    }
    // Inside the sphere: nothing (it emits outward).
    EXPECT_EQ(f.irradiance(opt, {0, 0, 2.05}, {0, 0, 1}).r, 0);
}

TEST(DirectRing, DiskOnAxis) {
    Fixture f(kLight + "bright ring disk 0 0 8 0 0 2 0 0 -1 0 0.5\n");
    double exact = 100 * kPi * 0.25 / (0.25 + 4);  // L pi r^2 / (r^2 + h^2)
    DirectOptions opt;
    opt.sampling = 0.01;
    EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, exact, 0.01 * exact);
    // -ds 0 (RADIANCE nopart): a point at the centre, omega = A cos / d^2 = pi r^2 / h^2.
    opt.sampling = 0;
    EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 100 * kPi * 0.25 / 4, 1e-9);
}

TEST(DirectCylinder, FarAwayLooksLikeItsProjection) {
    // A thin tube far away: omega ~ projected area (2 r L) / d^2.
    Fixture f(kLight + "bright cylinder tube 0 0 7 -0.5 0 10 0.5 0 10 0.05\n");
    double exact = 100 * (2 * 0.05 * 1.0) / 100;
    DirectOptions opt;
    for (double ds : {0.0, 0.01, 0.2}) {
        opt.sampling = ds;
        EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, exact, 0.02 * exact) << ds;
    }
}

TEST(DirectDistant, OmegaTimesCosine) {
    Fixture f(
        "void light sun 0 0 3 1000 1000 1000\n"
        "sun source s 0 0 4 0 1 1 0.5\n"
        "void glow sky 0 0 4 1 1 1 0\nsky source skydome 0 0 4 0 0 1 180\n");
    double omega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
    double exact = 1000 * omega * std::cos(kPi / 4);
    DirectOptions opt;
    for (double ds : {0.0, 0.2, 0.001}) {
        opt.sampling = ds;
        EXPECT_NEAR(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, exact, 0.002 * exact) << ds;
    }
    DirectLighting direct(f.scene, f.geo, opt);
    EXPECT_EQ(direct.sourceCount(), 1u);  // the sky glow is left to the ambient calculation
    EXPECT_TRUE(direct.isDistantSource(0));
    EXPECT_FALSE(direct.isDistantSource(1));
}

// The penumbra of a straight edge under a distant disk (issue 42): a black half-plane
// x < 0 at z = 1 under a zenith sun (or a light sphere) of angular radius a. A sample is
// a direction uniform over the part of the disk -dj allows (a disk of radius dj a about
// the centre), so the lit fraction at (x0, 0, 0) is the part of that disk beyond the edge:
// F(s) = 1/2 + (s sqrt(1 - s^2) + asin s) / pi, s = x0 / (dj a) (small angles: tan and
// sin of 0.27 degrees differ from the angle by 1e-5). With -ds 0.001 the disk has 8 x 8
// cells, each sampled within dj of its own extent: with -dj 1 the whole disk again.
// Estimated over N independent calls; the tolerance is 4 sigma of the binomial (one
// sample per call with the default -ds; for 64 cells, which are stratified, the binomial
// bounds it from above). Before the fix the concentric map folded the left and lower
// half of the disk onto the right and upper one: 0.75 at the edge.
TEST(DirectDistant, PenumbraOfAStraightEdgeIsAUniformDisk) {
    // The same disk as a distant source and as a light sphere 100 m up (RADIANCE samples
    // both through the concentric map of a jittered cell).
    const double alpha = 0.5 * 0.533 * kPi / 180;
    const std::string edge =
        "void plastic black 0 0 5 0 0 0 0 0\n"
        "black polygon edge 0 0 12 -10 -10 1 0 -10 1 0 10 1 -10 10 1\n";
    const std::string sphere =
        "void light bulb 0 0 3 1000 1000 1000\nbulb sphere ball 0 0 4 0 0 100 " +
        std::to_string(100 * std::sin(alpha)) + "\n";
    const std::string sun = "void light sun 0 0 3 1000 1000 1000\nsun source s 0 0 4 0 0 1 0.533\n";
    auto exact = [](double s) {
        s = std::clamp(s, -1.0, 1.0);
        return 0.5 + (s * std::sqrt(1 - s * s) + std::asin(s)) / kPi;
    };
    struct Case {
        double ds, dj;
        int calls, samplesPerCall;
    };
    for (const std::string& source : {sun, sphere}) {
        Fixture f(source + edge);
        for (const Case c : {Case{0.2, 0.1, 4000, 1}, Case{0.2, 0.5, 4000, 1},
                             Case{0.2, 1, 4000, 1}, Case{0.001, 1, 400, 64}}) {
            DirectOptions opt;
            opt.sampling = c.ds;
            opt.jitter = c.dj;
            DirectLighting direct(f.scene, f.geo, opt);
            TestOracle oracle(f.scene, f.geo);
            // The unshadowed value, from a point far from the edge.
            DirectPoint open;
            open.point = {5, 0, 0};
            open.normal = open.geomNormal = {0, 0, 1};
            Rng rng0(1, RngDomain::Test, 7);
            const double full = direct.compute(open, cosine(open.normal), oracle, rng0, scratch).r;
            ASSERT_GT(full, 0);
            for (double s : {-0.9, -0.5, -0.2, 0.0, 0.3, 0.7}) {
                DirectPoint at;
                at.point = {s * c.dj * alpha, 0, 0};
                at.normal = at.geomNormal = {0, 0, 1};
                double sum = 0;
                for (int i = 0; i < c.calls; ++i) {
                    Rng rng(uint64_t(i), RngDomain::Test, 7);
                    sum += direct.compute(at, cosine(at.normal), oracle, rng, scratch).r / full;
                }
                const double want = exact(s);
                const double sigma =
                    std::sqrt(std::fmax(want * (1 - want), 0.01) / (c.calls * c.samplesPerCall));
                EXPECT_NEAR(sum / c.calls, want, 4 * sigma)
                    << (source == sun ? "sun" : "sphere") << " -ds " << c.ds << " -dj " << c.dj
                    << " s " << s;
            }
        }
    }
}

TEST(DirectShadow, OccluderGlassAndBackSide) {
    const std::string lamp = kLight + squareDown("bright", "lamp", 0, 0, 0.5, 1);
    DirectOptions opt;
    opt.sampling = 0.01;
    double open = Fixture(lamp).irradiance(opt, {0, 0, 0}, {0, 0, 1}).r;
    ASSERT_GT(open, 0);
    std::string board =
        "void plastic grey 0 0 5 .5 .5 .5 0 0\n" + squareDown("grey", "board", 0, 0, 2, 0.5);
    EXPECT_EQ(Fixture(lamp + board).irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 0);
    std::string pane =
        "void glass clear 0 0 3 .96 .96 .96\n" + squareDown("clear", "pane", 0, 0, 2, 0.5);
    EXPECT_NEAR(Fixture(lamp + pane).irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 0.9 * open,
                1e-9 * open);
    // Two panes: 0.81.
    std::string pane2 = squareDown("clear", "pane2", 0, 0, 2, 0.7);
    EXPECT_NEAR(Fixture(lamp + pane + pane2).irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 0.81 * open,
                1e-9 * open);
    // Above the lamp, looking down at its back: nothing.
    EXPECT_EQ(Fixture(lamp).irradiance(opt, {0, 0, 2}, {0, 0, -1}).r, 0);
    // Another light in between blocks (it is not the source being sampled). With -dt 0:
    // a blocked bright source lowers the estimate of untested samples of the other.
    opt.threshold = 0;
    std::string other = "void light dim 0 0 3 1 1 1\n" + squareDown("dim", "other", 0, 0, 2, 0.5);
    Color c = Fixture(lamp + other).irradiance(opt, {0, 0, 0}, {0, 0, 1});
    double otherOnly =
        Fixture("void light dim 0 0 3 1 1 1\n" + squareDown("dim", "other", 0, 0, 2, 0.5))
            .irradiance(opt, {0, 0, 0}, {0, 0, 1})
            .r;
    EXPECT_NEAR(c.r, otherOnly, 1e-9);
}

TEST(DirectSpotlight, OutsideConeIsDark) {
    Fixture f("void spotlight spot 0 0 7 100 100 100 30 0 0 -1\n" +
              squareDown("spot", "lamp", 0, 0, 0.2, 2));
    DirectOptions opt;
    double below = f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r;
    // The unit-length aim vector puts the focus 1 m behind the lamp: (d / (d + 1))^2.
    double focus = (2.0 / 3.0) * (2.0 / 3.0);
    EXPECT_NEAR(below, focus * rectIrradiance(100, -0.1, 0.1, -0.1, 0.1, 2), 0.01 * below);
    EXPECT_EQ(f.irradiance(opt, {5, 0, 0}, {0, 0, 1}).r, 0);
}

TEST(DirectGlow, OnlyWithinItsRadius) {
    Fixture f("void glow warm 0 0 4 10 10 10 3\n" + squareDown("warm", "panel", 0, 0, 0.5, 1));
    DirectOptions opt;
    EXPECT_GT(f.irradiance(opt, {0, 0, 0}, {0, 0, 1}).r, 0);
    EXPECT_EQ(f.irradiance(opt, {5, 0, 0}, {0, 0, 1}).r, 0);
    DirectLighting direct(f.scene, f.geo, opt);
    int32_t panel = direct.sourceList().sources[0].light.prim;
    EXPECT_TRUE(direct.isSourceSurface(panel, {0, 0, 0}));
    EXPECT_FALSE(direct.isSourceSurface(panel, {5, 0, 0}));
    // A glow of radius 0 is no direct source at all.
    Fixture g("void glow faint 0 0 4 10 10 10 0\n" + squareDown("faint", "panel", 0, 0, 0.5, 1));
    EXPECT_EQ(DirectLighting(g.scene, g.geo, opt).sourceCount(), 0u);
}

std::string severalLights() {
    std::string t =
        "void light a 0 0 3 100 100 100\nvoid light b 0 0 3 5 5 5\n"
        "void light c 0 0 3 1 1 1\nvoid plastic grey 0 0 5 .5 .5 .5 0 0\n";
    t += squareDown("a", "la", 0, 0, 0.3, 1.5);
    t += squareDown("b", "lb", 1, 0, 0.3, 1.5);
    t += squareDown("b", "lb2", -1, 1, 0.3, 1.2);
    t += squareDown("c", "lc", 0, -2, 0.3, 1);
    t += squareDown("c", "lc2", 2, 2, 0.3, 1);
    t += squareDown("grey", "shade", 0.667, 0, 0.4, 1);  // hides lb from the origin
    return t;
}

TEST(DirectThreshold, DefaultCloseToTestingAll) {
    Fixture f(severalLights());
    DirectOptions all;
    all.threshold = 0;
    long raysAll = 0, raysDefault = 0;
    double exact = f.irradiance(all, {0, 0, 0}, {0, 0, 1}, 1, true, &raysAll).r;
    DirectOptions def;
    double approx = f.irradiance(def, {0, 0, 0}, {0, 0, 1}, 1, true, &raysDefault).r;
    EXPECT_NEAR(approx, exact, 0.05 * exact);
    EXPECT_LE(raysDefault, raysAll);
    // dt = 0 tests every sample: as many shadow rays as samples of lights in view.
    DirectLighting direct(f.scene, f.geo, all);
    EXPECT_EQ(direct.sourceCount(), 5u);
    // -dc 1: what is left untested is bounded by dt times the result.
    DirectOptions sure;
    sure.certainty = 1;
    double certain = f.irradiance(sure, {0, 0, 0}, {0, 0, 1}).r;
    EXPECT_NEAR(certain, exact, sure.threshold * exact);
}

TEST(DirectThreshold, HighThresholdEstimatesUntested) {
    Fixture f(severalLights());
    DirectOptions all;
    all.threshold = 0;
    long raysAll = 0, raysFew = 0;
    double exact = f.irradiance(all, {0, 0, 0}, {0, 0, 1}, 1, true, &raysAll).r;
    DirectOptions few;
    few.threshold = 0.5;
    few.certainty = 0;
    double approx = f.irradiance(few, {0, 0, 0}, {0, 0, 1}, 1, true, &raysFew).r;
    EXPECT_LT(raysFew, raysAll);
    EXPECT_NEAR(approx, exact, 0.2 * exact);
}

TEST(DirectVirtual, MirrorRelaysTheLight) {
    // Lamp 2 above a mirror floor; the point faces down so it sees the lamp only in the
    // mirror: the image is the lamp reflected to z = -2, 3 below the point.
    std::string text = kLight + squareDown("bright", "lamp", 0, 0, 0.5, 2) +
                       "void mirror silver 0 0 3 .9 .9 .9\n"
                       "silver polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";
    Fixture f(text);
    DirectOptions opt;
    opt.sampling = 0.01;
    double exact = 0.9 * rectIrradiance(100, -1.25, -0.75, -0.25, 0.25, 3);
    EXPECT_NEAR(f.irradiance(opt, {1, 0, 1}, {0, 0, -1}).r, exact, 0.01 * exact);
    DirectLighting direct(f.scene, f.geo, opt);
    EXPECT_EQ(direct.sourceCount(), 1u);
    EXPECT_EQ(direct.virtualSourceCount(), 1u);
    opt.relays = 0;
    EXPECT_EQ(f.irradiance(opt, {1, 0, 1}, {0, 0, -1}).r, 0);
    opt.relays = 2;
    EXPECT_EQ(f.irradiance(opt, {1, 0, 1}, {0, 0, -1}, 1, /*virtualSources=*/false).r, 0);
    // Facing up, the point sees the lamp directly and not its image.
    double direct1 = f.irradiance(opt, {1, 0, 1}, {0, 0, 1}).r;
    EXPECT_NEAR(direct1, rectIrradiance(100, -1.25, -0.75, -0.25, 0.25, 1), 0.01 * direct1);
}

TEST(DirectVirtual, SmallMirrorOnlyWhereItIs) {
    // A small mirror: the image is seen only through it.
    std::string text = kLight + squareDown("bright", "lamp", 0, 0, 0.5, 2) +
                       "void mirror silver 0 0 3 .9 .9 .9\n"
                       "silver polygon m 0 0 12 -0.2 -0.2 0 0.2 -0.2 0 0.2 0.2 0 -0.2 0.2 0\n";
    Fixture f(text);
    DirectOptions opt;
    EXPECT_GT(f.irradiance(opt, {0, 0, 1}, {0, 0, -1}).r, 0);
    EXPECT_EQ(f.irradiance(opt, {3, 0, 1}, {0, 0, -1}).r, 0);
}

TEST(DirectVirtual, DistantSourceInAMirror) {
    Fixture f(
        "void light sun 0 0 3 1000 1000 1000\nsun source s 0 0 4 0 1 1 0.5\n"
        "void mirror silver 0 0 3 .9 .9 .9\n"
        "silver polygon floor 0 0 12 -50 -50 0 50 -50 0 50 50 0 -50 50 0\n");
    double omega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
    double exact = 0.9 * 1000 * omega * std::cos(kPi / 4);
    DirectOptions opt;
    EXPECT_NEAR(f.irradiance(opt, {0, 0, 1}, {0, 0, -1}).r, exact, 0.002 * exact);
    // Under the mirror the sun is blocked and no image is seen.
    EXPECT_EQ(f.irradiance(opt, {0, 0, -1}, {0, 0, 1}).r, 0);
}

TEST(DirectVirtual, TwoRelays) {
    // A corner of two mirrors: floor (x in [0,5]) and wall x = 0 facing +x. Each single
    // reflection and both orders of the double one make a virtual source.
    std::string text = kLight + squareDown("bright", "lamp", 1, 0, 0.5, 2) +
                       "void mirror silver 0 0 3 .9 .9 .9\n"
                       "silver polygon floor 0 0 12 0 -5 0 5 -5 0 5 5 0 0 5 0\n"
                       "silver polygon wall 0 0 12 0 -5 0 0 5 0 0 5 5 0 -5 5\n";
    Fixture f(text);
    DirectOptions opt;
    opt.relays = 1;
    EXPECT_EQ(DirectLighting(f.scene, f.geo, opt).virtualSourceCount(), 2u);
    const Vec3 n = normalize(Vec3{-1, 0, -1});
    double one = f.irradiance(opt, {2, 0, 1}, n).r;
    opt.relays = 2;
    EXPECT_EQ(DirectLighting(f.scene, f.geo, opt).virtualSourceCount(), 4u);
    double two = f.irradiance(opt, {2, 0, 1}, n).r;
    EXPECT_GT(one, 0);
    EXPECT_GT(two, one);  // the doubly reflected image (below, behind the wall) adds light
}

TEST(DirectVirtual, PretestDropsHiddenMirrors) {
    // An opaque board between the mirror floor and the lamp: no mirror point sees it.
    std::string base = kLight + squareDown("bright", "lamp", 0, 0, 0.5, 2) +
                       "void mirror silver 0 0 3 .9 .9 .9\n"
                       "silver polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";
    Fixture opaque(base + "void plastic grey 0 0 5 .5 .5 .5 0 0\n" +
                   squareDown("grey", "board", 0, 0, 12, 1));
    DirectOptions opt;
    EXPECT_EQ(DirectLighting(opaque.scene, opaque.geo, opt).virtualSourceCount(), 0u);
    opt.pretest = 0;  // -dp 0: always keep (and always test) the full path
    EXPECT_EQ(DirectLighting(opaque.scene, opaque.geo, opt).virtualSourceCount(), 1u);
    opt.pretest = 512;
    Fixture glass(base + "void glass clear 0 0 3 .96 .96 .96\n" +
                  squareDown("clear", "pane", 0, 0, 12, 1));
    EXPECT_EQ(DirectLighting(glass.scene, glass.geo, opt).virtualSourceCount(), 1u);
}

TEST(DirectVirtual, BackOfAMirrorRelaysNothing) {
    // The mirror faces down, away from the lamp above it.
    Fixture f(kLight + squareDown("bright", "lamp", 0, 0, 0.5, 2) +
              "void mirror silver 0 0 3 .9 .9 .9\n"
              "silver polygon floor 0 0 12 -5 -5 0 -5 5 0 5 5 0 5 -5 0\n");
    DirectOptions opt;
    EXPECT_EQ(DirectLighting(f.scene, f.geo, opt).virtualSourceCount(), 0u);
}

TEST(DirectPointOnSurface, SpawnsOffTheHitSurface) {
    Fixture f(kLight + squareDown("bright", "lamp", 0, 0, 0.5, 1) +
              "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
              "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n");
    std::optional<Hit> hit = f.geo.closestHit({{0.1, 0, 0.5}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    DirectOptions opt;
    opt.sampling = 0.01;
    DirectLighting direct(f.scene, f.geo, opt);
    TestOracle oracle(f.scene, f.geo);
    DirectPoint at;
    at.point = hit->point;
    at.normal = at.geomNormal = {0, 0, 1};
    at.hit = &*hit;
    Rng rng(1, RngDomain::Test, 0);
    double e = direct.compute(at, cosine(at.normal), oracle, rng, scratch).r;
    double exact = rectIrradiance(100, -0.35, 0.15, -0.25, 0.25, 1);
    EXPECT_NEAR(e, exact, 0.005 * exact);
}

TEST(DirectDeterminism, SameSeedSameResult) {
    Fixture f(severalLights());
    DirectOptions opt;
    opt.jitter = 1;
    opt.sampling = 0.05;
    Color a = f.irradiance(opt, {0.1, 0.2, 0}, {0, 0, 1}, 7);
    Color b = f.irradiance(opt, {0.1, 0.2, 0}, {0, 0, 1}, 7);
    EXPECT_EQ(a, b);
    Color c = f.irradiance(opt, {0.1, 0.2, 0}, {0, 0, 1}, 8);
    EXPECT_NEAR(c.r, a.r, 0.05 * a.r);  // jitter moves samples, not the total much
}

TEST(DirectJitter, StaysWithinTheCell) {
    Fixture f(kLight + squareDown("bright", "lamp", 0, 0, 0.5, 1));
    DirectOptions opt;
    opt.sampling = 0.01;  // 64 cells of 0.0625
    DirectLighting direct(f.scene, f.geo, opt);
    const DirectSource& src = direct.sourceList().sources[0];
    std::vector<SourceSample> centred, jittered;
    Rng rng(5, RngDomain::Test, 0);
    sampleSource(direct.sourceList(), src, f.geo.shapes(), {0, 0, 0}, opt, 1, rng, polygon,
                 centred);
    opt.jitter = 0.5;
    sampleSource(direct.sourceList(), src, f.geo.shapes(), {0, 0, 0}, opt, 1, rng, polygon,
                 jittered);
    ASSERT_EQ(centred.size(), 64u);
    ASSERT_EQ(jittered.size(), centred.size());
    for (size_t i = 0; i < centred.size(); ++i) {
        // Jitter 0.5 moves a sample at most a quarter cell along each axis.
        EXPECT_LE(std::fabs(jittered[i].target.x - centred[i].target.x), 0.0625 / 4 + 1e-12);
        EXPECT_LE(std::fabs(jittered[i].target.y - centred[i].target.y), 0.0625 / 4 + 1e-12);
        // Each sample stands for its whole cell, seen from where the sample lies.
        const SourceSample& s = jittered[i];
        EXPECT_NEAR(s.omega * s.dist * s.dist / s.dir.z, 0.0625 * 0.0625, 1e-15);
    }
}

// A prism1 film (z = 0) standing in for a prism's functions: it turns light about the x
// axis by `angle`, the sign following the side the light crosses from, so the reversed
// ray retraces the path (what virtual sources need); coefficient 0.8, and 0.5 for a
// second redirection turning the other way.
struct TurningFilm {
    double angle = 10 * kPi / 180;
    std::vector<Vec3> toSource;  // DxA DyA DzA of each redirection of a shadow ray
    material::Redirection operator()(const Hit&, const Vec3& d, int projection,
                                     const Vec3& towards) {
        if (lengthSquared(towards) > 0) toSource.push_back(towards);
        double a = (d.z < 0 ? angle : -angle) * (projection == 0 ? 1 : -1);
        material::Redirection r;
        r.coef = projection == 0 ? 0.8 : 0.5;
        r.dir = {d.x, d.y * std::cos(a) - d.z * std::sin(a), d.y * std::sin(a) + d.z * std::cos(a)};
        r.ok = true;
        return r;
    }
};

class FilmOracle : public TestOracle {
public:
    FilmOracle(const Scene& scene, const SceneGeometry& geo, TurningFilm& film)
        : TestOracle(scene, geo), film_(film) {}
    material::Redirection redirect(const Hit& hit, const Vec3& dir, int projection,
                                   const Vec3& toSource) override {
        return film_(hit, dir, projection, toSource);
    }

private:
    TurningFilm& film_;
};

const std::string kSunAndFilm =
    "void light sun 0 0 3 1000 1000 1000\nsun source s 0 0 4 0 -0.5 0.8660254 0.5\n"
    "void prism1 film 5 c dx dy dz f.cal 0 0\n"
    "film polygon panel 0 0 12 -50 -50 0 50 -50 0 50 50 0 -50 50 0\n";

TEST(DirectVirtual, DistantSourceThroughAPrism) {
    Fixture f(kSunAndFilm);
    TurningFilm film;
    RedirectFunction redirect = [&film](const Hit& h, const Vec3& d, int k, const Vec3& a) {
        return film(h, d, k, a);
    };
    DirectOptions opt;
    DirectLighting direct(f.scene, f.geo, opt, true, redirect);
    ASSERT_EQ(direct.virtualSourceCount(), 1u);
    // Below the film, facing up: the sun only through its image, the light arriving
    // turned by the film, with the sun's solid angle (as RADIANCE's virtual sources).
    const Vec3 sun = normalize(Vec3{0, -0.5, 0.8660254});
    material::Redirection through = film(Hit{}, -sun, 0, {});
    const Vec3 n{0, 0, 1};
    double omega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
    double exact = 0.8 * 1000 * omega * dot(-through.dir, n);
    FilmOracle oracle(f.scene, f.geo, film);
    DirectPoint at;
    at.point = {0, 0, -1};
    at.normal = at.geomNormal = n;
    Rng rng(1, RngDomain::Test, 0);
    film.toSource.clear();
    EXPECT_NEAR(direct.compute(at, cosine(n), oracle, rng, scratch).r, exact, 1e-6 * exact);
    // DxA DyA DzA aim at the sun (m_direct.c: the source the virtual one was made from).
    ASSERT_FALSE(film.toSource.empty());
    for (const Vec3& a : film.toSource) EXPECT_NEAR(dot(a, sun), 1, 1e-12);
    // Without the prism's functions there is no image and the film blocks the sun.
    EXPECT_EQ(f.irradiance(opt, {0, 0, -1}, n).r, 0);
    // Photon-map mode: no virtual sources.
    EXPECT_EQ(DirectLighting(f.scene, f.geo, opt, false, redirect).virtualSourceCount(), 0u);
    // Above the film the sun is seen directly, not its image.
    at.point = {0, 0, 1};
    double sunDirect = 1000 * omega * dot(sun, n);
    EXPECT_NEAR(direct.compute(at, cosine(n), oracle, rng, scratch).r, sunDirect, 1e-6 * sunDirect);
}

TEST(DirectVirtual, Prism2MakesAnImagePerRedirection) {
    std::string text = kSunAndFilm;
    text.replace(text.find("prism1 film 5 c dx dy dz"), 24, "prism2 film 9 c dx dy dz c dx dy dz");
    Fixture f(text);
    TurningFilm film;
    RedirectFunction redirect = [&film](const Hit& h, const Vec3& d, int k, const Vec3& a) {
        return film(h, d, k, a);
    };
    DirectOptions opt;
    DirectLighting direct(f.scene, f.geo, opt, true, redirect);
    ASSERT_EQ(direct.virtualSourceCount(), 2u);
    const Vec3 sun = normalize(Vec3{0, -0.5, 0.8660254});
    const Vec3 n{0, 0, 1};
    double omega = 2 * kPi * (1 - std::cos(0.25 * kPi / 180));
    double exact = 0;
    for (int k = 0; k < 2; ++k) {
        material::Redirection r = film(Hit{}, -sun, k, {});
        exact += r.coef * 1000 * omega * dot(-r.dir, n);
    }
    FilmOracle oracle(f.scene, f.geo, film);
    DirectPoint at;
    at.point = {0, 0, -1};
    at.normal = at.geomNormal = n;
    Rng rng(1, RngDomain::Test, 0);
    EXPECT_NEAR(direct.compute(at, cosine(n), oracle, rng, scratch).r, exact, 1e-6 * exact);
}

}  // namespace
}  // namespace rp::render

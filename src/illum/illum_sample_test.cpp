// mkillum's sampling against a fake renderer whose radiance is a known function of
// direction: RADIANCE's grids, where rays start and go, bin averages against their
// integrals, the l+ source weighting, the "bad aspect" rule and thread independence.
#include "illum/illum_sample.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cmath>

namespace rp::illum {
namespace {

// Radiance L(d) = f(d) of the way the light travels (-dir of the ray); checks that every
// ray starts in front of `front` (a plane) and travels into it.
class FakeTracer : public IllumTracer {
public:
    std::function<double(const Vec3& out)> f = [](const Vec3&) { return 1.0; };
    Vec3 planeNormal;  // zero: no check
    double planeOffset = 0;
    mutable std::atomic<int> misplaced{0};
    // l+: one source in direction `toSource` giving `radianceOmega`.
    Vec3 toSource{-1, 0, 0};
    Color radianceOmega;

    Color radiance(const Vec3& origin, const Vec3& dir, uint64_t) const override {
        if (lengthSquared(planeNormal) > 0 &&
            (dot(origin, planeNormal) <= planeOffset || dot(dir, planeNormal) >= 0))
            ++misplaced;
        return Color::grey(f(-dir));
    }
    void sourceSamples(const Vec3&, double, uint64_t, const SourceVisit& visit) const override {
        if (radianceOmega.max() > 0) visit(toSource, radianceOmega);
    }
};

InputObject polygon(std::vector<double> xyz) {
    InputObject o;
    o.typeName = "polygon";
    o.name = "p";
    o.rargs = std::move(xyz);
    return o;
}

// A 2 x 1 window in the plane x = 0 facing +x, as in tests/data/mkillum.
Face window() { return makeFace(polygon({0, -1, .5, 0, 1, .5, 0, 1, 1.5, 0, -1, 1.5})); }

TEST(IllumSample, GridsAsRadiance) {
    int nalt, nazi;
    flatGrid(20, nalt, nazi);  // RADIANCE mkillum d=20: "1.125000 0.125000 5", 14 azimuths
    EXPECT_EQ(nalt, 4);
    EXPECT_EQ(nazi, 13);
    flatGrid(100, nalt, nazi);
    EXPECT_EQ(nalt, 10);
    EXPECT_EQ(nazi, 31);
    flatGrid(0, nalt, nazi);
    EXPECT_EQ(nalt * nazi, 1);
    roundGrid(10, nalt, nazi);  // d=10 sphere: 11 altitude rows with the poles, 15 azimuths
    EXPECT_EQ(nalt, 9);
    EXPECT_EQ(nazi, 14);
}

TEST(IllumSample, FlatIndexInvertsFlatDirection) {
    const int nalt = 5, nazi = 16;
    for (int i = 0; i < nalt; ++i)
        for (int j = 0; j < nazi; ++j) {
            const Vec3 d = flatDirection((i + .3) / nalt, (j + .2) / nazi);
            EXPECT_NEAR(length(d), 1, 1e-12);
            EXPECT_EQ(flatIndex(d, nalt, nazi), i * nazi + j);
        }
    EXPECT_EQ(flatIndex({1, -1e-9, 0}, nalt, nazi), (nalt - 1) * nazi);  // grazing, azimuth ~0
}

TEST(IllumSample, FaceGeometryAsRadiance) {
    const Face f = window();
    EXPECT_DOUBLE_EQ(f.area, 2);
    EXPECT_EQ(f.normal, (Vec3{1, 0, 0}));
    EXPECT_EQ(f.axis, 0);
    EXPECT_TRUE(f.contains({0, 0.5, 1}));
    EXPECT_FALSE(f.contains({0, 1.5, 1}));
    // A repeated closing vertex is dropped; a line has no area.
    EXPECT_EQ(makeFace(polygon({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0})).vertices.size(), 3u);
    EXPECT_EQ(makeFace(polygon({0, 0, 0, 1, 1, 1, 2, 2, 2})).area, 0);
    EXPECT_THROW(makeFace(polygon({0, 0, 0, 1, 0, 0})), InputError);
}

TEST(IllumSample, ConstantRadianceFillsEveryBin) {
    FakeTracer t;
    t.planeNormal = {1, 0, 0};
    IllumSettings s;
    s.density = 20;
    s.samples = 16;
    uint64_t next = 100;
    FlatFrame frame;
    const auto d = sampleFace(window(), s, t, next, frame);
    ASSERT_TRUE(d);
    EXPECT_EQ(next, 100u + 52 * 16);
    EXPECT_EQ(t.misplaced.load(), 0);
    // The frame follows the first edge at least sqrt(area) long: +y, then v = w x u.
    EXPECT_EQ(frame.u, (Vec3{0, 1, 0}));
    EXPECT_EQ(frame.v, (Vec3{0, 0, 1}));
    EXPECT_EQ(frame.w, (Vec3{1, 0, 0}));
    for (const Color& c : d->sums) EXPECT_DOUBLE_EQ(c.r, 16);
    EXPECT_DOUBLE_EQ(d->average().g, 1);
}

TEST(IllumSample, BinAveragesMatchTheirIntegrals) {
    // L = cos(theta) of the outgoing direction: over a bin of sin^2 in [a, b] (uniform in
    // projected solid angle) the mean of sqrt(1 - x) is 2/3 ((1-a)^1.5 - (1-b)^1.5)/(b-a).
    FakeTracer t;
    t.f = [](const Vec3& out) { return out.x; };
    IllumSettings s;
    s.density = 20;
    s.samples = 256;
    uint64_t next = 0;
    FlatFrame frame;
    const auto d = sampleFace(window(), s, t, next, frame);
    ASSERT_TRUE(d);
    for (int i = 0; i < d->altitudes; ++i) {
        const double a = double(i) / d->altitudes, b = double(i + 1) / d->altitudes;
        const double want = 2.0 / 3 * (std::pow(1 - a, 1.5) - std::pow(1 - b, 1.5)) / (b - a);
        for (int j = 0; j < d->azimuths; ++j)  // strata: far inside Monte Carlo noise
            EXPECT_NEAR(d->sums[size_t(i * d->azimuths + j)].r / s.samples, want, 2e-3);
    }
}

TEST(IllumSample, AzimuthFollowsTheFrame) {
    // Light only toward +y (the frame's u): the bins about azimuth 0 get it.
    FakeTracer t;
    t.f = [](const Vec3& out) { return out.y > 0.9 ? 1.0 : 0.0; };
    IllumSettings s;
    s.density = 20;
    s.samples = 64;
    uint64_t next = 0;
    FlatFrame frame;
    const auto d = sampleFace(window(), s, t, next, frame);
    ASSERT_TRUE(d);
    const int last = (d->altitudes - 1) * d->azimuths;  // the most grazing ring
    EXPECT_GT(d->sums[size_t(last)].r, 0);
    EXPECT_EQ(d->sums[size_t(last + d->azimuths / 2)].r, 0);
    EXPECT_EQ(d->sums[0].r, 0);  // about the normal
}

TEST(IllumSample, SourcesAddOmegaCosOverTheBinsProjectedSolidAngle) {
    FakeTracer t;
    t.f = [](const Vec3&) { return 0.0; };
    t.toSource = normalize(Vec3{-2, 1, 1});  // behind the window (-x)
    t.radianceOmega = Color{3, 2, 1};
    IllumSettings s;
    s.density = 20;
    s.samples = 8;
    s.light = true;
    uint64_t next = 0;
    FlatFrame frame;
    const auto d = sampleFace(window(), s, t, next, frame);
    ASSERT_TRUE(d);
    EXPECT_EQ(next, 52u * 8 + 8);
    const Vec3 out = -t.toSource;
    const Vec3 local{dot(out, frame.u), dot(out, frame.v), dot(out, frame.w)};
    const int bin = flatIndex(local, d->altitudes, d->azimuths);
    const double each = 52 / kPi * local.z;
    EXPECT_NEAR(d->sums[size_t(bin)].r, 8 * 3 * each, 1e-9);
    EXPECT_NEAR(d->sums[size_t(bin)].b, 8 * 1 * each, 1e-9);
    Color rest;
    for (size_t k = 0; k < d->sums.size(); ++k)
        if (int(k) != bin) rest += d->sums[k];
    EXPECT_EQ(rest.r, 0);
    // A source in front of the surface is not seen through it.
    t.toSource = {1, 0, 0};
    next = 0;
    const auto front = sampleFace(window(), s, t, next, frame);
    ASSERT_TRUE(front);
    for (const Color& c : front->sums) EXPECT_EQ(c.r, 0);
}

TEST(IllumSample, ThinPolygonIsGivenUp) {
    // An L of two 1 x .01 arms fills 2 % of its bounding square (RADIANCE: "bad aspect").
    const Face l =
        makeFace(polygon({0, 0, 0, 1, 0, 0, 1, .01, 0, .01, .01, 0, .01, 1, 0, 0, 1, 0}));
    FakeTracer t;
    IllumSettings s;
    s.density = 5;
    s.samples = 16;
    uint64_t next = 0;
    FlatFrame frame;
    EXPECT_FALSE(sampleFace(l, s, t, next, frame));
}

TEST(IllumSample, RingAndSphereRaysLookBackThroughThem) {
    InputObject r;
    r.typeName = "ring";
    r.name = "r";
    r.rargs = {1, 0, 3, 0, 0, -1, .5, 0};  // radii in either order
    const Ring ring = makeRing(r);
    EXPECT_EQ(ring.inner, 0);
    EXPECT_EQ(ring.outer, .5);
    FakeTracer t;
    t.planeNormal = {0, 0, -1};
    t.planeOffset = -3;
    IllumSettings s;
    s.density = 10;
    s.samples = 8;
    uint64_t next = 0;
    FlatFrame frame;
    const Distribution d = sampleRing(ring, s, t, next, frame);
    EXPECT_EQ(t.misplaced.load(), 0);
    EXPECT_EQ(frame.w, (Vec3{0, 0, -1}));
    EXPECT_NEAR(dot(frame.u, frame.w), 0, 1e-15);
    EXPECT_DOUBLE_EQ(d.average().r, 1);
    r.rargs = {1, 0, 3, 0, 0, -1, .5, .5};
    EXPECT_THROW(makeRing(r), InputError);

    // Sphere: each ray starts outside and heads for the sphere.
    class SphereCheck : public FakeTracer {
    public:
        Color radiance(const Vec3& o, const Vec3& dir, uint64_t) const override {
            const Vec3 c{3, 0, 1};
            const double b = dot(o - c, dir), cc = lengthSquared(o - c) - .09;
            if (cc <= 0 || b >= 0 || b * b - cc < 0) ++misplaced;
            return Color::grey(1);
        }
    } sphereTracer;
    InputObject sp;
    sp.typeName = "sphere";
    sp.rargs = {3, 0, 1, .3};
    const Distribution round = sampleSphere(makeSphere(sp), s, sphereTracer, next);
    EXPECT_EQ(sphereTracer.misplaced.load(), 0);
    EXPECT_EQ(round.altitudes * round.azimuths, int(round.sums.size()));
    EXPECT_DOUBLE_EQ(round.average().r, 1);
}

TEST(IllumSample, ResultDoesNotDependOnThreads) {
    FakeTracer t;
    t.f = [](const Vec3& out) { return out.x * out.x + 0.1 * out.y; };
    IllumSettings s;
    s.density = 20;
    s.samples = 64;
    auto run = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
        uint64_t next = 0;
        FlatFrame frame;
        return sampleFace(window(), s, t, next, frame)->sums;
    };
    const auto one = run(1);
    const auto four = run(4);
    ASSERT_EQ(one.size(), four.size());
    for (size_t k = 0; k < one.size(); ++k) EXPECT_EQ(one[k].r, four[k].r);
}

}  // namespace
}  // namespace rp::illum

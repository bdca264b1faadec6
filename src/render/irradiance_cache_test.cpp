#include "render/irradiance_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "util/rng.h"

namespace rp::render {
namespace {

AmbientRecord record(const Vec3& p, const Vec3& n, double value, double radius) {
    AmbientRecord r;
    r.position = p;
    r.normal = normalize(n);
    r.value = Color::grey(value);
    r.radius = radius;
    return r;
}

// The grid must find exactly the records a scan of all of them accepts: radii over
// three decades put records on many grid levels, and queries land near cell borders.
TEST(IrradianceCacheTest, LookupMatchesBruteForce) {
    const double aa = 0.2, minRadius = 0.01;
    IrradianceCache cache(aa, minRadius, 10);
    std::vector<AmbientRecord> all;
    Rng rng(21, RngDomain::Test, 0);
    for (int i = 0; i < 3000; ++i) {
        Vec3 p{rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 0.2};
        Vec3 n{0.3 * (rng.uniform() - 0.5), 0.3 * (rng.uniform() - 0.5), 1};
        double radius = minRadius * std::pow(1000.0, rng.uniform());
        AmbientRecord r = record(p, n, 1 + rng.uniform(), radius);
        r.gradPosition = {0.1 * rng.uniform(), -0.1 * rng.uniform(), 0};
        cache.insert(r);
        all.push_back(r);
    }
    EXPECT_EQ(cache.size(), 3000);
    int found = 0;
    for (int i = 0; i < 2000; ++i) {
        CacheQuery q;
        q.point = {rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 0.2};
        q.normal = normalize(Vec3{0.2 * (rng.uniform() - 0.5), 0, 1});
        Color sum;
        double wsum = 0;
        const double maxAngle = 10 * kPi / 180 + aa;  // weight 1
        for (const AmbientRecord& r : all) {
            Vec3 d = q.point - r.position;
            double t = length(d) / r.radius;
            double angle = std::sqrt(2 - 2 * dot(q.normal, r.normal));
            if (dot(d, r.normal) < -(minRadius * aa + 1e-3)) continue;
            if (t >= aa || angle >= maxAngle) continue;
            std::optional<Color> v = extrapolate(r, q.point, q.normal, true);
            if (!v) continue;
            double w = (1 - t / aa) * (1 - angle / maxAngle);
            sum += *v * w;
            wsum += w;
        }
        Color got;
        bool ok = cache.lookup(q, got);
        ASSERT_EQ(ok, wsum > 1e-6) << "query " << i;
        if (ok) {
            ++found;
            EXPECT_NEAR(got.r, sum.r / wsum, 1e-9);
        }
    }
    EXPECT_GT(found, 100);
}

TEST(IrradianceCacheTest, RejectsRecordsInFrontAndOfDeeperLevels) {
    IrradianceCache cache(0.2, 0.01, 10);
    AmbientRecord above = record({0, 0, 0.05}, {0, 0, 1}, 7, 1);
    cache.insert(above);
    CacheQuery q;
    q.point = {0, 0, 0};
    q.normal = {0, 0, 1};
    Color c;
    EXPECT_FALSE(cache.lookup(q, c)) << "a record 5 cm above the point";

    AmbientRecord deep = record({0, 0, 0}, {0, 0, 1}, 3, 1);
    deep.level = 1;
    deep.weight = 0.5;
    cache.insert(deep);
    EXPECT_FALSE(cache.lookup(q, c));
    q.level = 1;
    q.weight = 0.5;
    ASSERT_TRUE(cache.lookup(q, c));
    EXPECT_DOUBLE_EQ(c.r, 3);
}

// RADIANCE 5's hat weights fall to zero at a record's reach, so the cached value is
// continuous where one record's reach ends inside another's (Ward's 1/e weight jumps
// there, which RADIANCE 3 hid by jittering the limit).
TEST(IrradianceCacheTest, ValueIsContinuousAcrossAReachBoundary) {
    const double aa = 0.1;
    IrradianceCache cache(aa, 0.01, 10);
    cache.insert(record({0, 0, 0}, {0, 0, 1}, 1, 10));     // reaches 1
    cache.insert(record({0.5, 0, 0}, {0, 0, 1}, 3, 2.5));  // reaches 0.25: to x = 0.75
    CacheQuery q;
    q.normal = {0, 0, 1};
    Color inside, outside;
    q.point = {0.75 - 1e-7, 0, 0};
    ASSERT_TRUE(cache.lookup(q, inside));
    q.point = {0.75 + 1e-7, 0, 0};
    ASSERT_TRUE(cache.lookup(q, outside));
    EXPECT_NEAR(inside.r, 1, 1e-5);
    EXPECT_DOUBLE_EQ(outside.r, 1);
    q.point = {0.5, 0, 0};  // both: weights 1 - 0.5 and 1
    ASSERT_TRUE(cache.lookup(q, inside));
    EXPECT_NEAR(inside.r, (0.5 * 1 + 1 * 3) / 1.5, 1e-12);
}

// RADIANCE's corral (ambient.c plugaleak): a record whose corral flags the query's
// direction is used only if no surface stops the test ray; other directions are not
// tested. tangentFrame((0, 0, 1)) has u = +x, so sector 0 covers azimuths 0-11.25 degrees.
class FakeLeakTest : public LeakTest {
public:
    bool blocked(const Vec3& from, const Vec3& to) override {
        ++calls;
        lastFrom = from;
        lastTo = to;
        return wall;
    }
    bool wall = true;
    int calls = 0;
    Vec3 lastFrom, lastTo;
};

TEST(IrradianceCacheTest, CorralledRecordsAreTestedForLeaks) {
    IrradianceCache cache(0.2, 0.01, 10);
    AmbientRecord r = record({0, 0, 0}, {0, 0, 1}, 5, 2);  // reach 0.4
    r.corral = 1u;
    cache.insert(r);
    FakeLeakTest leaks;
    CacheQuery q;
    q.normal = {0, 0, 1};
    q.leaks = &leaks;
    const double a = 5 * kPi / 180;
    q.point = {0.3 * std::cos(a), 0.3 * std::sin(a), 0};
    q.origin = q.point + Vec3{0, 0, 1e-6};
    Color c;
    EXPECT_FALSE(cache.lookup(q, c)) << "behind a wall in a flagged direction";
    EXPECT_EQ(leaks.calls, 1);
    EXPECT_EQ(leaks.lastFrom, q.origin);
    // The target lies on the record's normal line, 20 degrees above the query's plane.
    EXPECT_NEAR(leaks.lastTo.x, 0, 1e-12);
    EXPECT_NEAR(leaks.lastTo.z, 0.3 * std::tan(20 * kPi / 180),
                1e-7);  // RADIANCE: cos^2 70 to 7 digits
    leaks.wall = false;
    ASSERT_TRUE(cache.lookup(q, c));
    EXPECT_DOUBLE_EQ(c.r, 5);
    leaks.wall = true;
    q.point = {0, 0.3, 0};  // azimuth 90 degrees: sector 8, not flagged
    q.origin = q.point;
    EXPECT_TRUE(cache.lookup(q, c));
    EXPECT_EQ(leaks.calls, 2);
    q.leaks = nullptr;  // no test asked for: used
    q.point = {0.3 * std::cos(a), 0.3 * std::sin(a), 0};
    EXPECT_TRUE(cache.lookup(q, c));
}

TEST(IrradianceCacheTest, ExtrapolationUsesBothGradients) {
    AmbientRecord r = record({0, 0, 0}, {0, 0, 1}, 2, 1);
    r.gradPosition = {0.5, 0, 0};
    r.gradDirection = {0, 0.25, 0};
    double a = 0.1;
    Vec3 n{std::sin(a), 0, std::cos(a)};  // N_i x N = (0, sin a, 0)
    std::optional<Color> c = extrapolate(r, {0.2, 0, 0}, n, true);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->r, 2 * (1 + 0.1 + 0.25 * std::sin(a)), 1e-12);
    EXPECT_EQ(extrapolate(r, {0.2, 0, 0}, n, false), Color::grey(2));
    r.gradPosition = {200, 0, 0};                                             // factor 41
    EXPECT_EQ(extrapolate(r, {0.2, 0, 0}, r.normal, true), Color::grey(40));  // at most 20x
    r.gradPosition = {-4.76, 0, 0};  // factor 0.048: too little to trust
    EXPECT_FALSE(extrapolate(r, {0.2, 0, 0}, r.normal, true));
    r.gradPosition = {-4.74, 0, 0};  // factor 0.052
    EXPECT_TRUE(extrapolate(r, {0.2, 0, 0}, r.normal, true));
}

TEST(IrradianceCacheTest, NewRecordsKeepOrderAndSkipLoaded) {
    IrradianceCache cache(0.1, 0.01, 10);
    cache.insert(record({0, 0, 0}, {0, 0, 1}, 1, 1), false);
    cache.insert(record({1, 0, 0}, {0, 0, 1}, 2, 1));
    cache.insert(record({2, 0, 0}, {0, 0, 1}, 3, 1));
    std::vector<AmbientRecord> n = cache.newRecords();
    ASSERT_EQ(n.size(), 2u);
    EXPECT_EQ(n[0].value.r, 2);
    EXPECT_EQ(n[1].value.r, 3);
    EXPECT_EQ(cache.size(), 3);
}

}  // namespace
}  // namespace rp::render

// View options: parsing, formatting, validation, and rays for every view type at the
// image centre and corners against closed-form directions.
#include "image/view.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "util/error.h"

namespace rp {
namespace {

View parse(const std::string& s) {
    View v;
    applyViewString(v, s);
    return v;
}

// tol: 1e-12 for closed forms; 1e-7 where RADIANCE's formula takes sqrt(1 - r^2) at
// r = 1, which turns a 1e-16 rounding error into 1e-8.
void expectVec(const Vec3& a, const Vec3& b, const char* what, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

Vec3 dirAt(const View& v, double x, double y) {
    auto r = ViewRays(v).ray(x, y);
    EXPECT_TRUE(r);
    return r ? r->direction : Vec3{};
}

TEST(View, DefaultsAreRpicts) {
    View v;
    EXPECT_EQ(formatView(v),
              " -vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0");
    EXPECT_EQ(formatViewMinimal(v), "");
}

TEST(View, ParseArgv) {
    const char* argv[] = {"-vth", "-vp", "1", "2.5", "-3", "-vh", "180", "-vf"};
    View v;
    EXPECT_EQ(parseViewOption(v, 8, argv), 1);
    EXPECT_EQ(v.type, ViewType::kHemispherical);
    EXPECT_EQ(parseViewOption(v, 7, argv + 1), 4);
    EXPECT_EQ(v.point, (Vec3{1, 2.5, -3}));
    EXPECT_EQ(parseViewOption(v, 3, argv + 5), 2);
    EXPECT_EQ(v.horizontal, 180);
    const char* other[] = {"-x", "512"};
    EXPECT_EQ(parseViewOption(v, 2, other), 0);  // not a view option
    const char* unknown[] = {"-vq", "1"};
    EXPECT_EQ(parseViewOption(v, 2, unknown), 0);
    EXPECT_THROW(parseViewOption(v, 1, argv + 7), InputError);  // -vf without file
    const char* shortVp[] = {"-vp", "1", "2"};
    EXPECT_THROW(parseViewOption(v, 3, shortVp), InputError);
    const char* badNum[] = {"-vh", "wide"};
    EXPECT_THROW(parseViewOption(v, 2, badNum), InputError);
    const char* badType[] = {"-vtx"};
    EXPECT_THROW(parseViewOption(v, 1, badType), InputError);
}

TEST(View, FormatParseRoundTrip) {
    View v;
    v.type = ViewType::kCylindrical;
    v.point = {1.5, -2, 3e-3};
    v.direction = {0.25, 2, -0.5};
    v.up = {0, 0.1, 1};
    v.horizontal = 270;
    v.vertical = 60.5;
    v.fore = 0.5;
    v.aft = 100;
    v.shift = -0.25;
    v.lift = 1;
    EXPECT_EQ(parse(viewHeaderLine(v)), v);  // "VIEW= -vtc ..." parses back
    EXPECT_EQ(parse(formatViewMinimal(v)), v);
    View d;
    d.vertical = 30;
    EXPECT_EQ(formatViewMinimal(d), " -vv 30");
    // Command lines: other options are skipped, later values win, -vf is not followed.
    View c = parse("rpict -x 512 -vf missing.vf -vtl -vh 10 -ab 2 -vh 12 scene.oct");
    EXPECT_EQ(c.type, ViewType::kParallel);
    EXPECT_EQ(c.horizontal, 12);
}

TEST(View, FromHeaderAndFile) {
    Header h;
    h.lines = {"oconv x.rad", "rpict -vp 1 1 1 -vh 60", "VIEW= -vta -vh 180", "VIEW= -vv 180",
               "EXPOSURE=2"};
    auto v = viewFromHeader(h);
    ASSERT_TRUE(v);
    EXPECT_EQ(v->type, ViewType::kAngular);
    EXPECT_EQ(v->point, (Vec3{1, 1, 1}));
    EXPECT_EQ(v->horizontal, 180);
    EXPECT_EQ(v->vertical, 180);
    EXPECT_FALSE(viewFromHeader(Header{{"oconv x.rad"}}));

    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("rp_view_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string plain = (dir / "plain.vf").string(), hdr = (dir / "h.vf").string(),
                empty = (dir / "e.vf").string(), bad = (dir / "bad.vf").string();
    std::ofstream(plain) << "# saved view\nrvu -vtv -vp 0 -5 1 -vd 0 1 0\n-vh 50 -vv 40\n";
    std::ofstream(hdr) << "#?RADIANCE\nVIEW= -vth -vh 170\n\n-Y 2 +X 2\n";
    std::ofstream(empty) << "nothing here\n";
    std::ofstream(bad) << "-vp 1 2\n";
    View a;
    const char* argv[] = {"-vf", plain.c_str()};
    EXPECT_EQ(parseViewOption(a, 2, argv), 2);
    EXPECT_EQ(a.point, (Vec3{0, -5, 1}));
    EXPECT_EQ(a.vertical, 40);
    View b;
    readViewFile(b, hdr);
    EXPECT_EQ(b.type, ViewType::kHemispherical);
    EXPECT_EQ(b.horizontal, 170);
    View c;
    EXPECT_THROW(readViewFile(c, empty), InputError);
    try {
        readViewFile(c, bad);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().file, bad);
        EXPECT_EQ(e.loc().line, 1);
    }
    EXPECT_THROW(readViewFile(c, (dir / "missing.vf").string()), InputError);
    fs::remove_all(dir);
}

TEST(View, Validation) {
    auto message = [](const std::string& s) {
        try {
            ViewRays r(parse(s));
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("ok");
    };
    EXPECT_EQ(message(""), "ok");
    EXPECT_EQ(message("-vd 0 0 0"), "zero view direction");
    EXPECT_EQ(message("-vu 0 0 0"), "zero view up vector");
    EXPECT_EQ(message("-vd 0 0 -2"), "view up parallel to view direction");
    EXPECT_EQ(message("-vh 0"), "illegal horizontal view size");
    EXPECT_EQ(message("-vv -5"), "illegal vertical view size");
    EXPECT_EQ(message("-vtv -vh 180"), "illegal horizontal view size");
    EXPECT_EQ(message("-vth -vv 181"), "illegal vertical view size");
    EXPECT_EQ(message("-vth -vh 180 -vv 180"), "ok");
    EXPECT_EQ(message("-vta -vh 360 -vv 360"), "ok");
    EXPECT_EQ(message("-vta -vh 361"), "illegal horizontal view size");
    EXPECT_EQ(message("-vts -vh 360"), "illegal horizontal view size");
    EXPECT_EQ(message("-vtc -vh 360 -vv 179"), "ok");
    EXPECT_EQ(message("-vtc -vv 180"), "illegal vertical view size");
    EXPECT_EQ(message("-vtl -vh 1000 -vv 1000"), "ok");
    EXPECT_EQ(message("-vo 2 -va 1"), "illegal fore/aft clipping plane");
    EXPECT_EQ(message("-vo -1"), "illegal fore/aft clipping plane");
}

TEST(ViewRays, Perspective) {
    View v = parse("-vp 1 2 3 -vd 0 2 0 -vh 90 -vv 60");
    ViewRays rays(v);
    EXPECT_DOUBLE_EQ(rays.focalDistance(), 2);
    auto c = rays.ray(0.5, 0.5);
    ASSERT_TRUE(c);
    expectVec(c->origin, {1, 2, 3}, "origin");
    expectVec(c->direction, {0, 1, 0}, "centre");
    // Image-plane half-sizes at distance 1: tan(45) = 1 wide, tan(30) tall; right is
    // direction x up = +x, image up is +z.
    const double t = std::tan(kPi / 6);
    expectVec(dirAt(v, 0, 0), normalize({-1, 1, -t}), "lower left");
    expectVec(dirAt(v, 1, 1), normalize({1, 1, t}), "upper right");
    expectVec(dirAt(v, 1, 0), normalize({1, 1, -t}), "lower right");
    // Shift by one image width: x=0 then looks where x=1 did.
    expectVec(dirAt(parse("-vh 90 -vv 60 -vs 1"), 0, 0.5), dirAt(v, 1, 0.5), "shift");
    expectVec(dirAt(parse("-vh 90 -vv 60 -vl -1"), 0.5, 1), dirAt(v, 0.5, 0), "lift");
    // Fore clipping plane: origins lie on the plane 1 unit ahead.
    View f = parse("-vh 90 -vv 60 -vo 1 -va 3");
    auto corner = ViewRays(f).ray(1, 1);
    expectVec(corner->origin, {1, 1, t}, "fore plane");
    EXPECT_NEAR(corner->maxDistance, 2 * length(Vec3{1, 1, t}), 1e-12);
}

TEST(ViewRays, Parallel) {
    View v = parse("-vtl -vp 0 0 0 -vd 1 0 0 -vu 0 0 1 -vh 4 -vv 2");
    auto r = ViewRays(v).ray(0, 0);
    ASSERT_TRUE(r);
    // Right = (1,0,0) x (0,0,1) = (0,-1,0).
    expectVec(r->origin, {0, 2, -1}, "lower left origin");
    expectVec(r->direction, {1, 0, 0}, "direction");
    expectVec(ViewRays(v).ray(1, 1)->origin, {0, -2, 1}, "upper right origin");
    expectVec(ViewRays(v).ray(0.5, 0.5)->origin, {0, 0, 0}, "centre origin");
}

TEST(ViewRays, AngularFisheye) {
    View v = parse("-vta -vh 180 -vv 180");
    expectVec(dirAt(v, 0.5, 0.5), {0, 1, 0}, "centre");
    expectVec(dirAt(v, 1, 0.5), {1, 0, 0}, "right edge: 90 degrees");
    expectVec(dirAt(v, 0.5, 0), {0, 0, -1}, "bottom edge");
    // Corner: radius sqrt(2)/2 of the half-width, angle = 90 * sqrt(2) degrees.
    double a = kPi / 2 * std::sqrt(2.0);
    expectVec(dirAt(v, 0, 0),
              {-std::sin(a) / std::sqrt(2.0), std::cos(a), -std::sin(a) / std::sqrt(2.0)},
              "corner");
    // A full 360 fisheye: the corners are outside the circle; the edge looks backwards.
    View w = parse("-vta -vh 360 -vv 360");
    EXPECT_FALSE(ViewRays(w).ray(0, 0));
    expectVec(dirAt(w, 1, 0.5), {0, -1, 0}, "edge of 360");
}

TEST(ViewRays, HemisphericalFisheye) {
    View v = parse("-vth -vh 180 -vv 180");
    expectVec(dirAt(v, 0.5, 0.5), {0, 1, 0}, "centre");
    expectVec(dirAt(v, 1, 0.5), {1, 0, 0}, "right edge", 1e-7);
    expectVec(dirAt(v, 0.5, 1), {0, 0, 1}, "top edge", 1e-7);
    EXPECT_FALSE(ViewRays(v).ray(0, 0));  // outside the circle
    // Image radius is sin(angle): with -vh 90 -vv 90 the corner's sideways components
    // are each -sin(45 deg), leaving nothing along the view direction.
    View n = parse("-vth -vh 90 -vv 90");
    expectVec(dirAt(n, 0, 0), {-std::sqrt(0.5), 0, -std::sqrt(0.5)}, "corner of 90", 1e-7);
}

TEST(ViewRays, Planisphere) {
    // Stereographic: image radius 2 tan(angle/2), scaled so the edge of -vh is at 0.5.
    View v = parse("-vts -vh 180 -vv 180");
    expectVec(dirAt(v, 0.5, 0.5), {0, 1, 0}, "centre");
    expectVec(dirAt(v, 1, 0.5), {1, 0, 0}, "right edge");
    // Corner radius sqrt(2) in units where the edge is 1: tan(angle/2) = sqrt(2), so
    // cos(angle) = -1/3 and the sideways part is 2/3 along each axis.
    expectVec(dirAt(v, 0, 0), {-2.0 / 3, -1.0 / 3, -2.0 / 3}, "corner");
}

TEST(ViewRays, CylindricalPanorama) {
    View v = parse("-vtc -vh 180 -vv 90");
    expectVec(dirAt(v, 0.5, 0.5), {0, 1, 0}, "centre");
    expectVec(dirAt(v, 1, 0.5), {1, 0, 0}, "right edge: 90 degrees around");
    expectVec(dirAt(v, 0.5, 1), normalize({0, 1, 1}), "top: perspective 45 degrees");
    expectVec(dirAt(v, 0, 0), normalize({-1, 0, -1}), "lower left");
}

// locate() inverts ray(): points along the rays through a grid of image positions come
// back to those positions, at the distance travelled from the ray's origin, for every view
// type with shift, lift and clipping planes (1e-9: a few roundings of acos/atan2).
TEST(ViewRays, LocateInvertsRay) {
    const char* views[] = {
        "-vtv -vp 1 2 3 -vd 0.3 1 0.2 -vh 70 -vv 50 -vs 0.1 -vl -0.2 -vo 0.5",
        "-vtl -vp 1 2 3 -vd 1 0 0 -vh 4 -vv 2 -vs 0.2 -vo 1",
        "-vth -vd 0 1 0.3 -vh 170 -vv 160 -vo 0.2",
        "-vta -vd 1 1 0 -vh 200 -vv 180 -vs 0.05 -vo 0.3",
        "-vts -vd 0 0 1 -vu 0 1 0 -vh 200 -vv 150",
        "-vtc -vd 0 1 0 -vh 300 -vv 100 -vl 0.1 -vo 0.4",
    };
    for (const char* text : views) {
        ViewRays rays(parse(text));
        for (double x : {0.1, 0.37, 0.5, 0.83})
            for (double y : {0.12, 0.5, 0.64, 0.9}) {
                auto r = rays.ray(x, y);
                if (!r) continue;  // outside a fisheye's circle
                auto loc = rays.locate(r->origin + 3.5 * r->direction);
                ASSERT_TRUE(loc) << text;
                EXPECT_NEAR(loc->x, x, 1e-9) << text << " at " << x << "," << y;
                EXPECT_NEAR(loc->y, y, 1e-9) << text << " at " << x << "," << y;
                EXPECT_NEAR(loc->depth, 3.5, 1e-9) << text;
                EXPECT_TRUE(loc->good()) << text;
            }
    }
}

TEST(ViewRays, LocateFlags) {
    ViewRays rays(parse("-vp 0 0 0 -vd 0 1 0 -vh 90 -vv 90 -va 10"));
    auto ahead = rays.locate({0.5, 4, -0.5});
    ASSERT_TRUE(ahead);
    EXPECT_NEAR(ahead->x, 0.5 + 0.5 / 4 / 2, 1e-12);  // half-width tan(45) = 1 at distance 1
    EXPECT_NEAR(ahead->y, 0.5 - 0.5 / 4 / 2, 1e-12);
    EXPECT_TRUE(ahead->good());
    EXPECT_TRUE(rays.locate({0, -4, 0})->behind);
    EXPECT_TRUE(rays.locate({0, 12, 0})->beyond);
    EXPECT_TRUE(rays.locate({5, 4, 0})->outside);
    EXPECT_FALSE(rays.locate({1, 0, 0}));  // in the view point's plane
    ViewRays fish(parse("-vta -vd 0 1 0 -vh 180 -vv 180"));
    auto back = fish.locate({0, -1, 0});  // straight behind: the edge of the circle
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, 1.5, 1e-12);
    EXPECT_TRUE(back->outside);
    EXPECT_FALSE(ViewRays(parse("-vts -vd 0 1 0")).locate({0, -1, 0}));
}

}  // namespace
}  // namespace rp

#include "rays/vwrays.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "util/error.h"

namespace rp::rays {
namespace {

std::string all(const VwraysOptions& o) {
    std::ostringstream out;
    Vwrays(o).writeAll(out);
    return out.str();
}

TEST(Vwrays, AsciiRaysMatchRadiance) {
    // RADIANCE 5.4: vwrays -x 3 -y 2 -va 10 -vo 1 (a square view: 2 x 2 pixels; the aft
    // plane's distance is the direction's length).
    VwraysOptions o;
    o.xres = 3;
    o.yres = 2;
    o.view.aft = 10;
    o.view.fore = 1;
    EXPECT_EQ(all(o),
              "-2.07107e-01 1.00000e+00 2.07107e-01 -1.86396e+00 9.00000e+00 1.86396e+00\n"
              "2.07107e-01 1.00000e+00 2.07107e-01 1.86396e+00 9.00000e+00 1.86396e+00\n"
              "-2.07107e-01 1.00000e+00 -2.07107e-01 -1.86396e+00 9.00000e+00 -1.86396e+00\n"
              "2.07107e-01 1.00000e+00 -2.07107e-01 1.86396e+00 9.00000e+00 -1.86396e+00\n");
}

TEST(Vwrays, DimensionsFollowTheViewAspect) {
    VwraysOptions o;
    o.xres = 100;
    o.yres = 50;
    o.view.type = ViewType::kHemispherical;
    o.view.horizontal = 180;
    o.view.vertical = 90;
    EXPECT_EQ(Vwrays(o).dimensionsLine(), "-x 71 -y 50 -ld-");
    // RADIANCE compat: a view from options never gets -ld+, even with an aft plane.
    o.view.aft = 5;
    EXPECT_EQ(Vwrays(o).dimensionsLine(), "-x 71 -y 50 -ld-");
}

TEST(Vwrays, OutsideTheFisheyeCircleIsZeros) {
    VwraysOptions o;
    o.xres = o.yres = 4;
    o.view.type = ViewType::kAngular;
    o.view.horizontal = o.view.vertical = 360;  // RADIANCE: the corners are outside
    const std::string out = all(o);
    EXPECT_EQ(out.substr(0, out.find('\n')),
              "0.00000e+00 0.00000e+00 0.00000e+00 0.00000e+00 0.00000e+00 0.00000e+00");
}

TEST(Vwrays, InputPositionsGiveRpictsJitteredRays) {
    // Positions fed in rpict's pixel order use the same streams as the pixels, so the
    // jittered, aperture-blurred rays equal the ones rpict traces (render::pixelRay).
    VwraysOptions o;
    o.xres = 5;
    o.yres = 4;
    o.pixelAspect = 0;
    o.jitter = 1;
    o.aperture = 0.2;
    o.format = 'd';
    o.view.type = ViewType::kCylindrical;
    o.view.horizontal = 120;
    std::ostringstream in;
    for (int row = 0; row < 4; ++row)
        for (int x = 0; x < 5; ++x) in << x << ' ' << 3 - row << '\n';
    std::istringstream positions(in.str());
    std::ostringstream out;
    Vwrays(o).writeFromInput(positions, out);
    EXPECT_EQ(out.str(), all(o));
    EXPECT_EQ(out.str().size(), 20u * 6 * sizeof(double));
}

TEST(Vwrays, RepeatsAndFormats) {
    VwraysOptions o;
    o.xres = o.yres = 2;
    o.repeat = 3;
    o.format = 'f';
    EXPECT_EQ(all(o).size(), 4u * 3 * 6 * sizeof(float));
    o.repeat = 0;
    EXPECT_EQ(all(o), "");
}

TEST(Vwrays, BadInputPositionIsAnError) {
    VwraysOptions o;
    o.fromInput = true;
    std::istringstream in("1 2\nx y\n");
    std::ostringstream out;
    try {
        Vwrays(o).writeFromInput(in, out);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "expected px py on input");
    }
    const std::string written = out.str();
    EXPECT_EQ(std::count(written.begin(), written.end(), '\n'), 1);
}

TEST(Vwrays, InvalidViewIsAnError) {
    VwraysOptions o;
    o.view.direction = {0, 0, 0};
    EXPECT_THROW(Vwrays{o}, InputError);
}

}  // namespace
}  // namespace rp::rays

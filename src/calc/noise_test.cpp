// The noise builtins against RADIANCE 5.4's own values. Reference numbers: a glow
// polygon at z = 0 modified by `void brightfunc p 2 'F(Px,Py,Z)' .`, traced with
// `rtrace -h -ab 0 -ov` on rays (x y 1  0 0 -1) (RADIANCE's rtrace, so the pattern is
// evaluated at exactly (x, y)); RADIANCE prints 7 significant digits from float colours.
#include "calc/noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "calc/builtins.h"

namespace rp::calc {
namespace {

constexpr double kTol = 2e-6;  // RADIANCE's printed precision (float colour, 7 digits)

struct Point {
    double x, y, z;
};
constexpr Point kPoints[] = {{0.3, 0.7, 0.37},        {-1.25, 2.5, 0.37},   {5.1, -3.3, 0.37},
                             {-0.0004, 0.0001, 0.37}, {12.34, 56.78, 0.37}, {0.3, 0.7, -2.6},
                             {-1.25, 2.5, -2.6},      {5.1, -3.3, -2.6},    {-0.0004, 0.0001, -2.6},
                             {12.34, 56.78, -2.6}};

// Rows: noise3, noise3x, noise3y, noise3z, fnoise3; columns: kPoints.
constexpr double kRadiance[5][10] = {{-0.1270623, -0.03095204, -0.3212111, 0.4392368, -0.3044625,
                                      0.333977, -0.1523758, 0.2116849, -0.2725922, 0.08789693},
                                     {-0.2285687, 1.049575, -0.3015866, 0.4659969, -0.9014183,
                                      -0.4461724, 0.7725168, -0.03519218, -1.000014, 1.010595},
                                     {0.08936508, 0.148962, -0.2054471, 9.976785e-07, -0.4012813,
                                      0.4477536, -0.0495865, 0.6385233, 0.3174396, 0.2412548},
                                     {-0.2754418, -0.792497, 0.1558531, 0.8924892, 1.739657,
                                      0.135253, -1.629115, 0.4977131, 0.007660648, 0.02985374},
                                     {-0.2916901, -0.1497681, 0.1846315, -0.4960119, 0.4634735,
                                      -0.3012506, 0.2184754, 0.4657826, 0.3378585, 0.2834723}};

TEST(Noise, Noise3MatchesRadiance) {
    for (int i = 0; i < 10; ++i) {
        const Point& p = kPoints[i];
        EXPECT_NEAR(noise3(p.x, p.y, p.z), kRadiance[0][i], kTol) << i;
    }
}

TEST(Noise, PartialsMatchRadiance) {
    for (int axis = 0; axis < 3; ++axis)
        for (int i = 0; i < 10; ++i) {
            const Point& p = kPoints[i];
            EXPECT_NEAR(noise3Partial(p.x, p.y, p.z, axis), kRadiance[1 + axis][i], kTol)
                << "axis " << axis << " point " << i;
        }
}

TEST(Noise, Fnoise3MatchesRadiance) {
    for (int i = 0; i < 10; ++i) {
        const Point& p = kPoints[i];
        EXPECT_NEAR(fnoise3(p.x, p.y, p.z), kRadiance[4][i], kTol) << i;
    }
}

TEST(Noise, Noise3VanishesOnLatticePoints) {
    EXPECT_EQ(noise3(1, 2, 3), 0);
    EXPECT_EQ(noise3(-4, 0, 7), 0);
}

TEST(Noise, PartialIsABackwardDifference) {
    // Close to the slope for a smooth function: compare with a central difference.
    const double h = 1e-6, x = 0.3, y = 0.7, z = 0.37;
    double slope = (noise3(x + h, y, z) - noise3(x - h, y, z)) / (2 * h);
    EXPECT_NEAR(noise3Partial(x, y, z, 0), slope, 0.01);
}

TEST(Noise, Fnoise3IsConstantWithinALatticeCell) {
    // RADIANCE's fractal works on a lattice of step 1/2000 and ignores the position
    // within the last cell.
    EXPECT_EQ(fnoise3(0.30001, 0.70001, 0.37001), fnoise3(0.30004, 0.70004, 0.37004));
    for (int i = 0; i < 200; ++i) {
        double v = fnoise3(0.01 * i - 1, 0.013 * i, -0.007 * i);
        EXPECT_GT(v, -1.5);
        EXPECT_LT(v, 1.5);
    }
}

TEST(Noise, RandMatchesRadiance) {
    // Same rtrace set-up with the expression rand(7*Px + Py) at the first five points.
    const double expected[5] = {0.8939549, 0.7582951, 0.1046806, 0.6415514, 0.1289286};
    for (int i = 0; i < 5; ++i) {
        const Point& p = kPoints[i];
        EXPECT_NEAR(randOf(7 * p.x + p.y), expected[i], kTol) << i;
    }
}

}  // namespace
}  // namespace rp::calc

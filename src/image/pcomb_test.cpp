// pcomb: default sums, -s/-c/-o, header, expressions, offsets and option parsing.
#include "image/pcomb.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace rp {
namespace {

// A w x h picture whose pixel (x, y from the top) is (x, y, k).
PcombPicture ramp(const std::string& name, int w, int h, float k) {
    PcombPicture p;
    p.name = name;
    p.input.name = name;
    p.picture = Picture(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) p.picture.at(x, y) = {float(x), float(y), k};
    return p;
}

Picture combine(std::vector<PcombPicture> in, const std::vector<std::string>& args) {
    PcombOptions o = parsePcombArgs(args);
    for (size_t i = 0; i < in.size() && i < o.inputs.size(); ++i) in[i].input = o.inputs[i];
    return runPcomb(in, o, "pcomb", 0, {});
}

TEST(Pcomb, ParsesGlobalOptionsThenPerInputFactors) {
    const PcombOptions o = parsePcombArgs(
        {"-h", "-x", "10", "-e", "ro=1", "a", "-o", "-s", "2", "-c", "1", "2", "3", "-"});
    EXPECT_FALSE(o.echoHeader);
    ASSERT_EQ(o.sources.size(), 2u);
    EXPECT_EQ(o.sources[0].first, 'x');
    ASSERT_EQ(o.inputs.size(), 2u);
    EXPECT_FALSE(o.inputs[0].original);
    EXPECT_TRUE(o.inputs[1].original);
    EXPECT_EQ(o.inputs[1].coef, (std::array<double, 3>{2, 4, 6}));
    EXPECT_EQ(o.inputs[1].name, "-");
    EXPECT_THROW(parsePcombArgs({"a", "-q"}), InputError);
    EXPECT_THROW(parsePcombArgs({"-s", "x", "a"}), InputError);
}

TEST(Pcomb, DefaultIsTheScaledSumAndNegativesBecomeZero) {
    const Picture p = combine({ramp("a", 4, 3, 1), ramp("b", 4, 3, 2)}, {"a", "-s", "-2", "b"});
    ASSERT_EQ(p.width, 4);
    ASSERT_EQ(p.height, 3);
    EXPECT_FLOAT_EQ(p.at(3, 0)[0], 0);  // 3 - 6 < 0
    EXPECT_FLOAT_EQ(p.at(0, 0)[2], 0);  // 1 - 4
    const Picture q = combine({ramp("a", 4, 3, 1)}, {"-c", "1", "1", "5", "a"});
    EXPECT_FLOAT_EQ(q.at(2, 1)[0], 2);
    EXPECT_FLOAT_EQ(q.at(2, 1)[2], 5);
}

TEST(Pcomb, OriginalUndoesExposureAndHeaderEchoesInputs) {
    PcombPicture a = ramp("a", 2, 2, 4);
    a.picture.header.lines = {"EXPOSURE=2", "VIEW= -vtv -vh 40 -vv 40"};
    const Picture p = combine({a}, {"-o", "a"});
    EXPECT_FLOAT_EQ(p.at(0, 0)[2], 2);
    const auto& h = p.header.lines;
    ASSERT_GE(h.size(), 7u);
    EXPECT_EQ(h[2], "a:");
    EXPECT_EQ(h[3], "\tEXPOSURE=2");
    EXPECT_EQ(h[5], "pcomb");
    EXPECT_EQ(h[6].rfind("VIEW= -vtv", 0), 0u);
    const Picture q = combine({ramp("a", 2, 2, 4)}, {"-h", "a"});
    EXPECT_EQ(q.header.lines.size(), 3u);  // CAPDATE GMT command
}

TEST(Pcomb, ExpressionsSeeInputsPositionsAndNeighbours) {
    // y counts from the bottom: output row 0 (top) is y = 2.
    const Picture p = combine({ramp("a", 4, 3, 1), ramp("b", 4, 3, 7)},
                              {"-e", "ro=x+10*y;go=bi(2)+ri(0);bo=ri(1,-1,1)", "a", "b"});
    EXPECT_FLOAT_EQ(p.at(3, 0)[0], 23);
    EXPECT_FLOAT_EQ(p.at(1, 2)[0], 1);
    EXPECT_FLOAT_EQ(p.at(0, 0)[1], 9);
    EXPECT_FLOAT_EQ(p.at(2, 1)[2], 1);  // left 1 and up 1 of (2, 1): x = 1
    EXPECT_FLOAT_EQ(p.at(0, 0)[2], 0);  // clamped at the corner
    const Picture g = combine({ramp("a", 4, 3, 1)}, {"-e", "lo=gi(1,0,1)", "a"});
    EXPECT_FLOAT_EQ(g.at(0, 2)[0], 1);  // the row above the bottom one
}

TEST(Pcomb, OutputSizeFromExpressionsAndWithoutInputs) {
    const Picture p = combine({ramp("a", 4, 4, 1)}, {"-x", "xmax/2", "-y", "3", "a"});
    EXPECT_EQ(p.width, 2);
    EXPECT_EQ(p.height, 3);
    const Picture q = combine({}, {"-x", "5", "-y", "2", "-e", "ro=xres;go=yres;bo=nfiles"});
    EXPECT_FLOAT_EQ(q.at(4, 1)[0], 5);
    EXPECT_FLOAT_EQ(q.at(4, 1)[1], 2);
    EXPECT_THROW(combine({}, {"-e", "ro=1"}), InputError);
    EXPECT_THROW(combine({ramp("a", 4, 4, 1), ramp("b", 4, 3, 1)}, {"a", "b"}), InputError);
}

}  // namespace
}  // namespace rp

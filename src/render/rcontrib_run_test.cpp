#include "render/rcontrib_run.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"
#include "util/warning_capture_for_tests.h"

namespace rp::render {
namespace {

// Each ray contributes its input position (index + 1) to bin 0 and 1 to bin 1.
void byIndex(const Vec3&, const Vec3&, uint64_t i, double, std::vector<Color>& v) {
    v[0] = Color::grey(double(i + 1));
    v[1] = Color::grey(1);
}

std::vector<std::string> run(RcontribRunSettings s, const std::string& input, int threads = 1) {
    RcontribOptions o = rcontribDefaults();
    ContribModifier m;
    m.name = "lamp";
    m.bins = 2;
    m.binExpr = "b";
    o.modifiers = {m};
    o.header = false;
    s.values = 2;
    s.threads = threads;
    s.batchSize = 2;  // batches smaller than the input
    std::ostringstream out;
    std::istringstream in(input);
    ContribOutput co(o, {}, out);
    runRcontrib(s, in, &co, byIndex);
    std::vector<std::string> lines;
    std::istringstream text(out.str());
    for (std::string l; std::getline(text, l);) lines.push_back(l.substr(0, l.find('\t')));
    return lines;
}

const std::string kFourRays = "0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n";

TEST(RcontribRun, OneRecordPerRayInInputOrder) {
    EXPECT_EQ(run({}, kFourRays, 2), (std::vector<std::string>{"1.000000e+00", "2.000000e+00",
                                                               "3.000000e+00", "4.000000e+00"}));
}

TEST(RcontribRun, AccumulationAveragesAndAShortLastRecordWarns) {
    // rcontrib.1 -c: records average -c rays; the final short record averages what it
    // holds, with RADIANCE's warning.
    WarningCapture w;
    RcontribRunSettings s;
    s.accumulate = 3;
    EXPECT_EQ(run(s, kFourRays), (std::vector<std::string>{"2.000000e+00", "4.000000e+00"}));
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_NE(w.lines[0].find("partial accumulation in final record"), std::string::npos);
}

TEST(RcontribRun, ZeroAccumulationSumsEverythingAndIgnoresZeroRays) {
    WarningCapture w;
    RcontribRunSettings s;
    s.accumulate = 0;
    EXPECT_EQ(run(s, "0 0 0 0 0 1\n0 0 0 0 0 0\n0 0 0 0 0 1\n"),
              (std::vector<std::string>{"4.000000e+00"}));  // rays 1 and 3 (1 + 3)
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_NE(w.lines[0].find("dummy ray(s) ignored during accumulation"), std::string::npos);
}

TEST(RcontribRun, ZeroDirectionRayIsAnEmptyRecord) {
    // With -c 1 a zero-direction ray writes a record of zeros (and flushes).
    EXPECT_EQ(run({}, "0 0 0 0 0 1\n0 0 0 0 0 0\n0 0 0 0 0 1\n"),
              (std::vector<std::string>{"1.000000e+00", "0.000000e+00", "3.000000e+00"}));
}

TEST(RcontribRun, ResolutionCountsRaysAndShortInputFails) {
    RcontribRunSettings s;
    s.xres = 0;
    s.yres = 2;  // two records, the rest of the input is not read
    EXPECT_EQ(run(s, kFourRays).size(), 2u);
    s.yres = 5;
    EXPECT_THROW(run(s, kFourRays), InputError);  // "unexpected EOF on input"
}

TEST(RcontribRun, BadInputIsAnErrorAfterTheRecordsBeforeIt) {
    EXPECT_THROW(run({}, "0 0 0 0 0 1\n0 0 zero 0 0 1\n"), InputError);
}

}  // namespace
}  // namespace rp::render

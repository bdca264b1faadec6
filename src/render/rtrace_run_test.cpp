// rtrace's batch loop with a fake tracer (rtrace_run.h): order with several threads,
// bogus records, flushing, -x/-y counts and bad input.
#include "render/rtrace_run.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <streambuf>

#include "util/error.h"
#include "util/thread_cluster_for_tests.h"
#include "util/warnings.h"

namespace rp::render {
namespace {

// The value encodes the input: red = rayIndex, green = origin.x, blue = direction.z.
RayResult fake(const Vec3& o, const Vec3& d, uint64_t index, std::vector<TracedRay>*, double) {
    RayResult r;
    r.value = {double(index), o.x, d.z};
    return r;
}

// Counts flushes (sync) and what had been written at each.
class FlushCounter : public std::stringbuf {
public:
    std::vector<size_t> flushedAt;

protected:
    int sync() override {
        flushedAt.push_back(str().size());
        return 0;
    }
};

std::string rays(int n) {
    std::string s;
    for (int k = 0; k < n; ++k) s += std::to_string(k) + " 0 0 0 0 1\n";
    return s;
}

TEST(RtraceRun, OrderWithThreads) {
    const std::string input = rays(1000);
    RtraceRunSettings s;
    s.threads = 4;
    s.batchSize = 37;
    RayWriter w(parseOutputSpec("v", 'a'), 'a', nullptr);
    std::atomic<int> calls{0};
    RayTraceFn slowFirst = [&](const Vec3& o, const Vec3& d, uint64_t i, std::vector<TracedRay>* t,
                               double) {
        ++calls;
        if (i % 37 == 0) {  // make the first of each batch finish last
            volatile double x = 0;
            for (int k = 0; k < 200000; ++k) x = x + k;
        }
        return fake(o, d, i, t, HUGE_VAL);
    };
    std::istringstream in(input);
    std::ostringstream out;
    RtraceRunStats st = runRtrace(s, in, out, w, slowFirst);
    EXPECT_EQ(st.rays, 1000u);
    EXPECT_EQ(calls.load(), 1000);

    s.threads = 1;
    std::istringstream in1(input);
    std::ostringstream out1;
    runRtrace(s, in1, out1, w, fake);
    EXPECT_EQ(out.str(), out1.str());
    std::istringstream lines(out.str());
    std::string line;
    for (int k = 0; k < 1000; ++k) {
        ASSERT_TRUE(std::getline(lines, line));
        char buf[100];
        std::snprintf(buf, sizeof buf, "%e\t%e\t%e\t", double(k), double(k), 1.0);
        ASSERT_EQ(line, buf);
    }
}

// Ranks of a cluster (threads here, MPI ranks in tools/mpi): the root's output is one
// process's, bogus records and a ray tree included; the others write nothing.
TEST(RtraceRun, SameOutputOverRanks) {
    std::string input = rays(500);
    input += "7 7 7 0 0 0\n" + rays(33);
    RayWriter w(parseOutputSpec("vo", 'a'), 'a', nullptr);
    RtraceRunSettings s;
    s.threads = 2;
    std::istringstream in1(input);
    std::ostringstream expected;
    runRtrace(s, in1, expected, w, fake);
    for (int ranks : {2, 3}) {
        for (size_t batch : {size_t(0), size_t(37)}) {
            std::ostringstream outs[3];
            testing::runRanks(ranks, [&](Cluster& c) {
                RtraceRunSettings rs = s;
                rs.cluster = &c;
                rs.batchSize = batch;
                std::istringstream in(c.isRoot() ? input : "");
                RtraceRunStats st = runRtrace(rs, in, outs[c.rank()], w, fake);
                EXPECT_EQ(st.rays, c.isRoot() ? 533u : 0u);
            });
            EXPECT_EQ(outs[0].str(), expected.str()) << ranks << " ranks, batch " << batch;
            for (int r = 1; r < ranks; ++r) EXPECT_EQ(outs[r].str(), "");
        }
    }
}

TEST(RtraceRun, BogusRecordsFlush) {
    std::istringstream in("0 0 0 0 0 1\n1 1 1 0 0 0\n2 0 0 0 0 1\n");
    FlushCounter buf;
    std::ostream out(&buf);
    RtraceRunSettings s;
    RayWriter w(parseOutputSpec("v", 'a'), 'a', nullptr);
    RtraceRunStats st = runRtrace(s, in, out, w, fake);
    EXPECT_EQ(st.rays, 2u);
    EXPECT_EQ(st.bogus, 1u);
    const std::string z = "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n";
    const std::string first = "0.000000e+00\t0.000000e+00\t1.000000e+00\t\n";
    // Index counts the bogus record too: the third ray is record 2.
    EXPECT_EQ(buf.str(), first + z + "2.000000e+00\t2.000000e+00\t1.000000e+00\t\n");
    ASSERT_GE(buf.flushedAt.size(), 1u);
    EXPECT_EQ(buf.flushedAt[0], first.size() + z.size());  // flushed right after the bogus one
}

TEST(RtraceRun, FlushEveryX) {
    std::istringstream in(rays(7));
    FlushCounter buf;
    std::ostream out(&buf);
    RtraceRunSettings s;
    s.xres = 3;
    s.batchSize = 100;
    RayWriter w(parseOutputSpec("w", 'a'), 'a', nullptr);
    runRtrace(s, in, out, w, fake);
    const size_t line = std::string("1.000000e+00\t\n").size();
    ASSERT_GE(buf.flushedAt.size(), 3u);
    EXPECT_EQ(buf.flushedAt[0], 3 * line);
    EXPECT_EQ(buf.flushedAt[1], 6 * line);
    EXPECT_EQ(buf.flushedAt.back(), 7 * line);
}

TEST(RtraceRun, NonFiniteInputWarnsOnce) {
    std::vector<std::string> warnings;
    setWarningSink([&](const std::string& m) { warnings.push_back(m); });
    std::istringstream in("nan 0 0 0 0 1\n0 0 0 inf 0 1\n1 0 0 0 0 1\n");
    std::ostringstream out;
    RtraceRunSettings s;
    RayWriter w(parseOutputSpec("v", 'a'), 'a', nullptr);
    RtraceRunStats st = runRtrace(s, in, out, w, fake);
    setWarningSink(nullptr);
    EXPECT_EQ(st.nonFinite, 2u);
    EXPECT_EQ(st.bogus, 2u);
    EXPECT_EQ(st.rays, 1u);
    EXPECT_EQ(warnings.size(), 1u);
    const std::string z = "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n";
    EXPECT_EQ(out.str(), z + z + "2.000000e+00\t1.000000e+00\t1.000000e+00\t\n");
}

TEST(RtraceRun, BadInputAfterCompleteResults) {
    std::istringstream in(rays(5) + "1 2 3 4 oops 6\n" + rays(2));
    std::ostringstream out;
    RtraceRunSettings s;
    s.threads = 2;
    s.batchSize = 2;
    RayWriter w(parseOutputSpec("w", 'a'), 'a', nullptr);
    try {
        runRtrace(s, in, out, w, fake);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "bad ray at input line 6: 'oops' is not a number");
    }
    std::string expect;
    for (int k = 0; k < 5; ++k) expect += "1.000000e+00\t\n";
    EXPECT_EQ(out.str(), expect);
}

TEST(RtraceRun, ResolutionAndCount) {
    RtraceRunSettings s;
    s.xres = 2;
    s.yres = 2;
    RayWriter w(parseOutputSpec("w", 'a'), 'a', nullptr);
    std::istringstream in(rays(6));  // extra rays are not read
    std::ostringstream out;
    RtraceRunStats st = runRtrace(s, in, out, w, fake);
    EXPECT_EQ(st.rays, 4u);
    EXPECT_EQ(out.str().substr(0, 11), "-Y 2 +X 2\n1");
    std::istringstream shortIn(rays(3));
    std::ostringstream out2;
    EXPECT_THROW(runRtrace(s, shortIn, out2, w, fake), InputError);
}

TEST(RtraceRun, TreeRequestedOnlyWhenWanted) {
    std::istringstream in(rays(2));
    std::ostringstream out;
    RtraceRunSettings s;
    RayWriter w(parseOutputSpec("vtw", 'a'), 'a', nullptr);
    int withTree = 0;
    RayTraceFn f = [&](const Vec3& o, const Vec3& d, uint64_t i, std::vector<TracedRay>* t,
                       double) {
        if (t) {
            ++withTree;
            TracedRay tr;
            tr.result.weight = 0.5;
            t->push_back(tr);
        }
        return fake(o, d, i, t, HUGE_VAL);
    };
    runRtrace(s, in, out, w, f);
    EXPECT_EQ(withTree, 2);
    EXPECT_EQ(out.str().substr(0, 14), "5.000000e-01\t\n");
}

TEST(RtraceRun, BinaryInputNormalisesDirection) {
    double d[6] = {0, 0, 0, 0, 0, 4};
    std::istringstream in(std::string(reinterpret_cast<const char*>(d), sizeof d));
    std::ostringstream out;
    RtraceRunSettings s;
    s.inputFormat = 'd';
    RayWriter w(parseOutputSpec("v", 'd'), 'd', nullptr);
    runRtrace(s, in, out, w, fake);
    ASSERT_EQ(out.str().size(), 3 * sizeof(double));
    double v[3];
    std::memcpy(v, out.str().data(), sizeof v);
    EXPECT_EQ(v[2], 1.0);  // unit direction z
}

// -ld: the trace function gets the direction's length as the ray's limit (and a unit
// direction); without it, no limit.
TEST(RtraceRun, LimitDistancePassesTheDirectionLength) {
    for (bool limit : {true, false}) {
        RtraceRunSettings s;
        s.limitDistance = limit;
        RayWriter w(parseOutputSpec("v", 'a'), 'a', nullptr);
        std::vector<double> seen;
        RayTraceFn f = [&](const Vec3& o, const Vec3& d, uint64_t i, std::vector<TracedRay>* t,
                           double maxDistance) {
            seen.push_back(maxDistance);
            EXPECT_NEAR(length(d), 1, 1e-12);
            return fake(o, d, i, t, maxDistance);
        };
        std::istringstream in("0 0 0 0 0 2\n0 0 0 3 4 0\n");
        std::ostringstream out;
        runRtrace(s, in, out, w, f);
        ASSERT_EQ(seen.size(), 2u);
        if (limit) {
            EXPECT_DOUBLE_EQ(seen[0], 2);
            EXPECT_DOUBLE_EQ(seen[1], 5);
        } else {
            EXPECT_EQ(seen[0], HUGE_VAL);
        }
    }
}

}  // namespace
}  // namespace rp::render

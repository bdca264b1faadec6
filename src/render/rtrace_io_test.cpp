// rtrace input reading and output formatting (rtrace_io.h).
#include "render/rtrace_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <vector>

#include "util/error.h"

namespace rp::render {
namespace {

Scene namedScene() {
    Scene s;
    s.prims.resize(3);
    s.prims[0].name = "white";
    s.prims[1].name = "pattern";
    s.prims[2].name = "floor";
    return s;
}

RayResult fabricated() {
    RayResult r;
    r.origin = {1, 2, 3};
    r.direction = {0, 0, -1};
    r.value = {0.5, 0.25, 0.125};
    r.coefficient = {1, 0.5, 2};
    r.weight = 0.75;
    r.hit = true;
    r.distance = 2;
    r.effectiveLength = 2.5;
    r.point = {1, 2, 1};
    r.normal = {0, 0, 1};
    r.unperturbedNormal = {0, 1, 0};
    r.u = 0.25;
    r.v = 0.5;
    r.prim = 2;
    r.modifier = 1;
    r.material = 0;
    r.mirrored = {1, 1, 1};
    r.unmirrored = {2, 2, 2};
    r.mirroredLength = 3;
    r.unmirroredLength = 4;
    return r;
}

std::string ascii(const std::string& spec, const RayResult& r) {
    Scene scene = namedScene();
    RayWriter w(parseOutputSpec(spec, 'a'), 'a', &scene);
    std::string out;
    w.write(out, r, nullptr);
    return out;
}

TEST(RtraceIo, AsciiEachSpecifier) {
    const RayResult r = fabricated();
    EXPECT_EQ(ascii("v", r), "5.000000e-01\t2.500000e-01\t1.250000e-01\t\n");
    EXPECT_EQ(ascii("o", r), "1.000000e+00\t2.000000e+00\t3.000000e+00\t\n");
    EXPECT_EQ(ascii("d", r), "0.000000e+00\t0.000000e+00\t-1.000000e+00\t\n");
    EXPECT_EQ(ascii("V", r), "5.000000e-01\t1.250000e-01\t2.500000e-01\t\n");
    EXPECT_EQ(ascii("w", r), "7.500000e-01\t\n");
    EXPECT_EQ(ascii("W", r), "1.000000e+00\t5.000000e-01\t2.000000e+00\t\n");
    EXPECT_EQ(ascii("l", r), "2.500000e+00\t\n");
    EXPECT_EQ(ascii("L", r), "2.000000e+00\t\n");
    EXPECT_EQ(ascii("c", r), "2.500000e-01\t5.000000e-01\t\n");
    EXPECT_EQ(ascii("p", r), "1.000000e+00\t2.000000e+00\t1.000000e+00\t\n");
    EXPECT_EQ(ascii("n", r), "0.000000e+00\t0.000000e+00\t1.000000e+00\t\n");
    EXPECT_EQ(ascii("N", r), "0.000000e+00\t1.000000e+00\t0.000000e+00\t\n");
    EXPECT_EQ(ascii("s", r), "floor\t\n");
    EXPECT_EQ(ascii("m", r), "pattern\t\n");
    EXPECT_EQ(ascii("M", r), "white\t\n");
    EXPECT_EQ(ascii("r", r), "1.000000e+00\t1.000000e+00\t1.000000e+00\t\n");
    EXPECT_EQ(ascii("x", r), "2.000000e+00\t2.000000e+00\t2.000000e+00\t\n");
    EXPECT_EQ(ascii("R", r), "3.000000e+00\t\n");
    EXPECT_EQ(ascii("X", r), "4.000000e+00\t\n");
    EXPECT_EQ(ascii("~", r), "~\t\n");
    EXPECT_EQ(ascii("Lsw", r), "2.000000e+00\tfloor\t7.500000e-01\t\n");
}

TEST(RtraceIo, MissAndVoid) {
    RayResult miss;  // left the scene
    miss.point = {5, 5, 5};
    EXPECT_EQ(ascii("psmM", miss), "0.000000e+00\t0.000000e+00\t0.000000e+00\t*\t*\t*\t\n");
    EXPECT_EQ(ascii("L", miss), "1.000000e+10\t\n");
    RayResult r = fabricated();
    r.modifier = kVoid;
    r.material = kVoid;
    EXPECT_EQ(ascii("mM", r), "void\tvoid\t\n");
}

// Text numbers are written as RADIANCE's printf("%e") writes them, for any double:
// wide and tiny exponents, subnormals, signed zeros, halfway cases, inf and nan.
TEST(RtraceIo, TextNumbersAsPrintf) {
    RayWriter w(parseOutputSpec("L", 'a'), 'a', nullptr);
    std::vector<double> values = {0.0,       -0.0,   1.0,      -1.0,      0.5,
                                  1e10,      1e-300, 5e-324,   1.2345675, 9.9999995,
                                  9999999.5, 1e308,  HUGE_VAL, -HUGE_VAL, std::nan("")};
    std::mt19937_64 rng(3);
    for (int i = 0; i < 20000; ++i) {
        uint64_t bits = rng();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        if (std::isfinite(d)) values.push_back(d);
        values.push_back(std::ldexp(double(rng() % 10000000) + 0.5, -int(rng() % 40)));
    }
    for (double v : values) {
        RayResult r;
        r.distance = v;
        std::string out;
        w.write(out, r, nullptr);
        char want[64];
        std::snprintf(want, sizeof want, "%e\t\n", v);
        ASSERT_EQ(out, want) << v;
    }
}

TEST(RtraceIo, BinaryFormats) {
    const RayResult r = fabricated();
    RayWriter f(parseOutputSpec("vw", 'f'), 'f', nullptr);
    std::string out;
    f.write(out, r, nullptr);
    ASSERT_EQ(out.size(), 4 * sizeof(float));
    float fv[4];
    std::memcpy(fv, out.data(), out.size());
    EXPECT_EQ(fv[0], 0.5f);
    EXPECT_EQ(fv[2], 0.125f);
    EXPECT_EQ(fv[3], 0.75f);
    RayWriter d(parseOutputSpec("L", 'd'), 'd', nullptr);
    out.clear();
    d.write(out, r, nullptr);
    ASSERT_EQ(out.size(), sizeof(double));
    double dv;
    std::memcpy(&dv, out.data(), sizeof dv);
    EXPECT_EQ(dv, 2.0);
    // Names stay text with a tab in binary output (RADIANCE oputs).
    Scene scene = namedScene();
    RayWriter s(parseOutputSpec("s", 'f'), 'f', &scene);
    out.clear();
    s.write(out, r, nullptr);
    EXPECT_EQ(out, "floor\t");
}

TEST(RtraceIo, RgbeFormat) {
    RayResult r;
    r.value = {1, 0.5, 0.25};
    RayWriter c(parseOutputSpec("v", 'c'), 'c', nullptr);
    std::string out;
    c.write(out, r, nullptr);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(uint8_t(out[0]), 128);  // 1 = 0.5 * 2^1: mantissa 128, exponent 129
    EXPECT_EQ(uint8_t(out[1]), 64);
    EXPECT_EQ(uint8_t(out[3]), 129);
    EXPECT_THROW(parseOutputSpec("vw", 'c'), InputError);
    EXPECT_NO_THROW(parseOutputSpec("vVWrx", 'c'));
}

TEST(RtraceIo, SpecErrorsAndTree) {
    EXPECT_THROW(parseOutputSpec("vq", 'a'), InputError);
    OutputSpec s = parseOutputSpec("vtLw", 'a');
    EXPECT_EQ(s.primary, "v");
    EXPECT_EQ(s.tree, "Lw");
    EXPECT_FALSE(s.traceSources);
    EXPECT_TRUE(parseOutputSpec("oT~v", 'a').traceSources);
    EXPECT_FALSE(parseOutputSpec("vt", 'a').wantsTree());  // trailing t ignored

    RayWriter w(s, 'a', nullptr);
    std::vector<TracedRay> tree(2);
    tree[0].depth = 0;
    tree[0].result.distance = 1;
    tree[1].depth = 1;
    tree[1].result.distance = 2;
    tree[1].result.weight = 0.5;
    std::string out;
    w.write(out, fabricated(), &tree);
    EXPECT_EQ(out,
              "1.000000e+00\t1.000000e+00\t\n"
              "\t2.000000e+00\t5.000000e-01\t\n"
              "5.000000e-01\t2.500000e-01\t1.250000e-01\t\n");
}

TEST(RtraceIo, TraceFilterChoosesTreeRecords) {
    // Tree, as the renderer lists it (each ray after the rays it spawned): a grandchild
    // that leaves the scene, a child that hits 'white' (modifier 0), the input ray that
    // hits 'pattern' (1). The input ray's own record is always written.
    Scene scene = namedScene();
    std::vector<TracedRay> tree(3);
    for (int k = 0; k < 3; ++k) {
        tree[size_t(k)].depth = 2 - k;
        tree[size_t(k)].result.distance = 3 - k;
        tree[size_t(k)].result.hit = k > 0;
    }
    tree[1].result.modifier = 0;
    tree[2].result.modifier = 1;
    auto written = [&](TraceFilter::Mode mode, std::vector<std::string> mods) {
        RayWriter w(parseOutputSpec("LtL", 'a'), 'a', &scene);
        w.setTraceFilter(TraceFilter{mode, std::move(mods)});
        std::string out;
        w.write(out, fabricated(), &tree);
        return out;
    };
    const std::string one = "1.000000e+00\t\n", two = "\t2.000000e+00\t\n",
                      three = "\t\t3.000000e+00\t\n", own = "2.000000e+00\t\n";
    EXPECT_EQ(written(TraceFilter::Mode::kAll, {}), three + two + one + own);
    EXPECT_EQ(written(TraceFilter::Mode::kInclude, {"white"}), two + own);
    EXPECT_EQ(written(TraceFilter::Mode::kInclude, {"white", "pattern"}), two + one + own);
    // Surfaces are chosen by their modifier, not by their own name ('floor' is prim 2).
    EXPECT_EQ(written(TraceFilter::Mode::kInclude, {"floor"}), own);
    EXPECT_EQ(written(TraceFilter::Mode::kExclude, {"white"}), three + one + own);
    EXPECT_EQ(written(TraceFilter::Mode::kExclude, {"nothing"}), three + two + one + own);
}

TEST(RtraceIo, BogusRecord) {
    RayWriter w(parseOutputSpec("vodLw", 'a'), 'a', nullptr);
    std::string out;
    w.writeBogus(out);
    std::string zeros;
    for (int k = 0; k < 11; ++k) zeros += "0.000000e+00\t";
    EXPECT_EQ(out, zeros + "\n");
}

TEST(RtraceIo, ReadAscii) {
    std::istringstream in("0 0 0 0 0 1\n1e0 2 3\n 4 5 6\n");
    RayReader r(in, 'a');
    InputRay ray;
    ASSERT_EQ(r.next(ray), RayReader::Status::Ok);
    EXPECT_EQ(ray.direction, Vec3(0, 0, 1));
    ASSERT_EQ(r.next(ray), RayReader::Status::Ok);
    EXPECT_EQ(ray.origin, Vec3(1, 2, 3));
    EXPECT_EQ(ray.direction, Vec3(4, 5, 6));
    EXPECT_EQ(r.next(ray), RayReader::Status::End);
}

// Every word reads as strtod reads it: signs, hex, out-of-range and long mantissas, and
// random doubles written with 17 digits.
TEST(RtraceIo, ReadAsciiNumbersAsStrtod) {
    std::vector<std::string> words = {
        "+1",     "-0",  "0x1p3", "1e400",    "-1e400",
        "1e-400", "inf", "-inf",  "infinity", "3.14159265358979323846264",
        ".5",     "5.",  "1E5",   "4.9e-324"};
    std::mt19937_64 rng(5);
    for (int i = 0; i < 6000; ++i) {
        uint64_t bits = rng();
        double d;
        std::memcpy(&d, &bits, sizeof d);
        if (!std::isfinite(d)) continue;
        char buf[40];
        std::snprintf(buf, sizeof buf, i % 2 ? "%.17g" : "%.6e", d);
        words.push_back(buf);
    }
    while (words.size() % 6) words.push_back("1");
    std::string text;
    for (const std::string& w : words) text += w + (text.size() % 3 ? " " : "\n");
    std::istringstream in(text);
    RayReader r(in, 'a');
    InputRay ray;
    for (size_t i = 0; i < words.size(); i += 6) {
        ASSERT_EQ(r.next(ray), RayReader::Status::Ok) << i;
        const double got[6] = {ray.origin.x,    ray.origin.y,    ray.origin.z,
                               ray.direction.x, ray.direction.y, ray.direction.z};
        for (int k = 0; k < 6; ++k) {
            const double want = std::strtod(words[i + size_t(k)].c_str(), nullptr);
            ASSERT_EQ(std::memcmp(&got[k], &want, sizeof want), 0) << words[i + size_t(k)];
        }
    }
    EXPECT_EQ(r.next(ray), RayReader::Status::End);
}

TEST(RtraceIo, ReadAsciiErrors) {
    std::istringstream in("0 0 0 0 0 1\n\n1 2 3 x 5 6\n");
    RayReader r(in, 'a');
    InputRay ray;
    ASSERT_EQ(r.next(ray), RayReader::Status::Ok);
    ASSERT_EQ(r.next(ray), RayReader::Status::Bad);
    EXPECT_EQ(r.error(), "bad ray at input line 3: 'x' is not a number");
    std::istringstream cut("0 0 0 0 0 1\n1 2 3\n");
    RayReader c(cut, 'a');
    ASSERT_EQ(c.next(ray), RayReader::Status::Ok);
    ASSERT_EQ(c.next(ray), RayReader::Status::Bad);
    EXPECT_NE(c.error().find("incomplete"), std::string::npos);
    // Non-finite numbers are numbers: the runner turns them into bogus records.
    std::istringstream nan("nan 0 0 0 0 1\n");
    RayReader n(nan, 'a');
    EXPECT_EQ(n.next(ray), RayReader::Status::Ok);
}

TEST(RtraceIo, ReadBinary) {
    float f[12] = {1, 2, 3, 0, 0, 1, 4, 5, 6, 1, 0, 0};
    std::istringstream fin(std::string(reinterpret_cast<const char*>(f), sizeof f));
    RayReader rf(fin, 'f');
    InputRay ray;
    ASSERT_EQ(rf.next(ray), RayReader::Status::Ok);
    EXPECT_EQ(ray.origin, Vec3(1, 2, 3));
    ASSERT_EQ(rf.next(ray), RayReader::Status::Ok);
    EXPECT_EQ(ray.direction, Vec3(1, 0, 0));
    EXPECT_EQ(rf.next(ray), RayReader::Status::End);

    double d[6] = {0.5, 0, 0, 0, -1, 0};
    std::string bytes(reinterpret_cast<const char*>(d), sizeof d);
    std::istringstream din(bytes + bytes.substr(0, 20));
    RayReader rd(din, 'd');
    ASSERT_EQ(rd.next(ray), RayReader::Status::Ok);
    EXPECT_EQ(ray.origin, Vec3(0.5, 0, 0));
    EXPECT_EQ(ray.direction, Vec3(0, -1, 0));
    EXPECT_EQ(rd.next(ray), RayReader::Status::Bad);  // 20 of 48 bytes
}

TEST(RtraceIo, HeaderAndResolution) {
    std::string h = rtraceHeader("rtrace -ab 1", 'f');
    EXPECT_EQ(h.substr(0, 24), "#?RADIANCE\nrtrace -ab 1\n");
    EXPECT_NE(h.find("SOFTWARE= radphoton\n"), std::string::npos);
    EXPECT_NE(h.find("\nCAPDATE= "), std::string::npos);
    EXPECT_EQ(h.substr(h.size() - 14), "FORMAT=float\n\n");
    EXPECT_EQ(resolutionLine(640, 480), "-Y 480 +X 640\n");
}

}  // namespace
}  // namespace rp::render

#include "render/ambient_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "render/ambient.h"
#include "render/ambient_test_tracers.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"
#include "util/warnings.h"

namespace rp::render {
namespace {

using testing::FunctionTracer;

AmbientOptions cachedOptions(const std::string& file) {
    AmbientOptions o;
    o.bounces = 1;
    o.accuracy = 0.1;
    o.divisions = 64;
    o.supersamples = 0;
    o.resolution = 100;
    o.file = file;
    return o;
}

AmbientPoint pointAt(const Vec3& p) {
    AmbientPoint at;
    at.point = p;
    at.normal = {0, 0, 1};
    at.offsetOrigin = p + Vec3{0, 0, 1e-6};
    return at;
}

// Radiance varying with position and direction, so records differ and carry gradients.
FunctionTracer::Fn varied() {
    return [](const Vec3& o, const Vec3& d) {
        return HemisphereTracer::Sample{Color{1 + o.x + d.x, 2 + d.y, 0.5}, 1 + o.y, {}};
    };
}

void expectSame(const AmbientRecord& a, const AmbientRecord& b) {
    // Positions are stored as doubles, the rest as floats.
    EXPECT_EQ(a.position, b.position);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(float(a.normal[i]), float(b.normal[i]));
        EXPECT_FLOAT_EQ(float(a.value[i]), float(b.value[i]));
        EXPECT_FLOAT_EQ(float(a.gradPosition[i]), float(b.gradPosition[i]));
        EXPECT_FLOAT_EQ(float(a.gradDirection[i]), float(b.gradDirection[i]));
    }
    EXPECT_FLOAT_EQ(float(a.radius), float(b.radius));
    EXPECT_FLOAT_EQ(float(a.weight), float(b.weight));
    EXPECT_EQ(a.level, b.level);
}

TEST(AmbientFileTest, RecordEncodingRoundTrip) {
    AmbientRecord r;
    r.position = {1.0 / 3, -2e5, 7.25};
    r.normal = normalize(Vec3{1, 2, 3});
    r.value = {0.1, 0.2, 0.3};
    r.radius = 0.75;
    r.gradPosition = {0.5, -0.25, 0};
    r.gradDirection = {0, 0.125, -1};
    r.level = 3;
    r.weight = 0.125;
    r.corral = 0x80000005u;
    unsigned char buf[kAmbientRecordBytes];
    encodeAmbientRecord(r, buf);
    EXPECT_EQ(buf[24 + 12 + 12 + 4 + 12 + 12 + 4], 3);  // level, little endian
    EXPECT_EQ(buf[84], 5);                              // corral, little endian
    EXPECT_EQ(buf[87], 0x80);
    expectSame(decodeAmbientRecord(buf), r);
    EXPECT_EQ(decodeAmbientRecord(buf).corral, r.corral);
    // Legacy records have no corral: read as none.
    unsigned char legacy[kLegacyAmbientRecordBytes];
    encodeAmbientRecord(r, legacy, kLegacyAmbientRecordBytes);
    EXPECT_EQ(decodeAmbientRecord(legacy, kLegacyAmbientRecordBytes).corral, 0u);
    expectSame(decodeAmbientRecord(legacy, kLegacyAmbientRecordBytes), r);
}

// A file written before records kept their corral (84-byte records) is read, and
// appended to in its own record size, so that runs sharing it keep working.
TEST(AmbientFileTest, LegacyRecordSizeIsReadAndKept) {
    TempDir dir;
    const std::string file = dir.file("old.amb");
    AmbientRecord r;
    r.position = {1, 2, 3};
    r.normal = {0, 0, 1};
    r.value = {0.5, 0.5, 0.5};
    r.radius = 1;
    {
        std::ofstream out(file, std::ios::binary);
        out << "#?RADIANCE\nAMBIENT_OPTIONS=-aa 0.1\nRECORD_BYTES=84\nBYTE_ORDER=little\n"
               "FORMAT=radphoton_ambient\n\n";
        unsigned char buf[kLegacyAmbientRecordBytes];
        encodeAmbientRecord(r, buf, kLegacyAmbientRecordBytes);
        out.write(reinterpret_cast<const char*>(buf), sizeof buf);
    }
    const auto before = std::filesystem::file_size(file);
    r.corral = 7;
    appendAmbientFile(file, "-aa 0.1", {r});
    EXPECT_EQ(std::filesystem::file_size(file), before + kLegacyAmbientRecordBytes);
    AmbientFileContents f = readAmbientFile(file);
    ASSERT_EQ(f.records.size(), 2u);
    EXPECT_EQ(f.records[1].position, r.position);
    EXPECT_EQ(f.records[1].corral, 0u);
}

TEST(AmbientFileTest, SaveThenLoadGivesSameRecords) {
    TempDir dir;
    std::string file = dir.file("scene.amb");
    Scene scene;
    std::vector<AmbientRecord> made;
    {
        Ambient amb(cachedOptions(file), 10, scene);
        FunctionTracer tracer(varied());
        Rng rng(31, RngDomain::Test, 0);
        // Points 20 apart: beyond any record's reach in this 10-unit scene (maxarad 5).
        for (int i = 0; i < 10; ++i) amb.indirect(pointAt({i * 20.0, 0, 0}), tracer, rng);
        EXPECT_EQ(amb.recordCount(), 10);
        amb.save();
        // A second save adds only what is new since the first.
        for (int i = 0; i < 5; ++i) amb.indirect(pointAt({i * 20.0, 30, 0}), tracer, rng);
        amb.save();
        amb.save();
    }
    AmbientFileContents f = readAmbientFile(file);
    EXPECT_EQ(f.options, "-aa 0.1 -ar 100 -ad 64 -as 0 -ab 1");
    ASSERT_EQ(f.records.size(), 15u);
    EXPECT_EQ(f.records[0].position, (Vec3{0, 0, 0}));
    EXPECT_EQ(f.records[14].position, (Vec3{80, 30, 0}));

    // Loading: the records are found again (no tracing at those points), with the same
    // values; nothing is written again unless new records come.
    Ambient again(cachedOptions(file), 10, scene);
    EXPECT_EQ(again.recordCount(), 15);
    FunctionTracer tracer(varied());
    Rng rng(32, RngDomain::Test, 0);
    Color c = again.indirect(pointAt({40, 0, 0}), tracer, rng);
    EXPECT_EQ(tracer.calls, 0);
    EXPECT_NEAR(c.r, f.records[2].value.r, 1e-6);
    again.save();
    EXPECT_EQ(readAmbientFile(file).records.size(), 15u);

    // Re-saving what was loaded reproduces the bytes exactly.
    std::string copy = dir.file("copy.amb");
    appendAmbientFile(copy, f.options, f.records);
    AmbientFileContents g = readAmbientFile(copy);
    ASSERT_EQ(g.records.size(), f.records.size());
    for (size_t i = 0; i < g.records.size(); ++i) expectSame(g.records[i], f.records[i]);
}

TEST(AmbientFileTest, TruncatedFileIsAnInputErrorNamingIt) {
    TempDir dir;
    std::string file = dir.file("cut.amb");
    Scene scene;
    {
        Ambient amb(cachedOptions(file), 10, scene);
        FunctionTracer tracer(varied());
        Rng rng(33, RngDomain::Test, 0);
        for (int i = 0; i < 3; ++i) amb.indirect(pointAt({i * 1.0, 0, 0}), tracer, rng);
        amb.save();
    }
    std::filesystem::resize_file(file, std::filesystem::file_size(file) - 10);
    try {
        Ambient amb(cachedOptions(file), 10, scene);
        FAIL() << "no error for a truncated file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("cut.amb"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

TEST(AmbientFileTest, ForeignFileIsAnInputError) {
    TempDir dir;
    Scene scene;
    std::string picture = dir.file("picture.hdr");
    std::ofstream(picture) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\nxxxx";
    EXPECT_THROW(Ambient(cachedOptions(picture), 10, scene), InputError);
    std::string text = dir.file("notes.txt");
    std::ofstream(text) << "hello\n";
    EXPECT_THROW(Ambient(cachedOptions(text), 10, scene), InputError);
    // save() refuses to append to a foreign file too.
    EXPECT_THROW(appendAmbientFile(picture, "", {}), InputError);
}

TEST(AmbientFileTest, DifferentOptionsWarnButLoad) {
    TempDir dir;
    std::string file = dir.file("opts.amb");
    Scene scene;
    {
        Ambient amb(cachedOptions(file), 10, scene);
        FunctionTracer tracer(varied());
        Rng rng(34, RngDomain::Test, 0);
        amb.indirect(pointAt({0, 0, 0}), tracer, rng);
        amb.save();
    }
    std::vector<std::string> warnings;
    setWarningSink([&](const std::string& m) { warnings.push_back(m); });
    AmbientOptions o = cachedOptions(file);
    o.divisions = 128;
    Ambient amb(o, 10, scene);
    setWarningSink([](const std::string& m) { fprintf(stderr, "warning: %s\n", m.c_str()); });
    EXPECT_EQ(amb.recordCount(), 1);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("-ad 64"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace rp::render

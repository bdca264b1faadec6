// rpict's frames, files and recovery with a fake scene: an interrupted picture finished
// with -r/-ro is byte for byte the uninterrupted one, -S frames and their files as
// RADIANCE names and skips them, and depth of field (-pd) blurs away from the focus only.
#include "render/rpict_run.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "image/picture.h"
#include "util/error.h"
#include "util/temp_dir_for_tests.h"
#include "util/warnings.h"

namespace rp::render {
namespace {

// A wall at y = 5 with a checker of 0.5-unit squares over a gradient, seen along +y:
// edges everywhere for the adaptive sampling, the hit distance as depth.
Color wall(const Vec3& org, const Vec3& dir, double* distance) {
    const double t = (5 - org.y) / dir.y;
    *distance = t;
    const Vec3 p = org + t * dir;
    const bool odd = (int(std::floor(2 * p.x)) + int(std::floor(2 * p.z))) & 1;
    const double g = 0.2 + 0.05 * p.x;
    return odd ? Color(g, 2 * g, 0.5) : Color(0.9, 0.1 + g, 0.05);
}

PixelTracerFactory wallFactory(std::atomic<long>* calls = nullptr) {
    return [calls]() -> PixelTracer {
        return [calls](const Vec3& org, const Vec3& dir, uint64_t, double, double* d) {
            if (calls) ++*calls;
            return wall(org, dir, d);
        };
    };
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void spit(const std::string& path, const std::string& data) {
    std::ofstream(path, std::ios::binary) << data;
}

// The bytes after the header (resolution line and scanlines): headers carry dates.
std::string pixelBytes(const std::string& picture) {
    const size_t end = picture.find("\n\n");
    return end == std::string::npos ? "" : picture.substr(end + 2);
}

RpictOptions wallOptions(int ps) {
    RpictOptions o;
    o.xres = 48;
    o.yres = 40;
    o.view.horizontal = 60;
    o.view.vertical = 50;
    o.sampleSpacing = ps;
    return o;
}

RpictIo quietIo(std::ostream& out, std::istream* views = nullptr) {
    RpictIo io;
    io.out = &out;
    io.views = views;
    io.commandLine = "rpict -x 48 -y 40";
    io.clock = [] { return std::time_t(0); };
    return io;
}

struct WarningLog {
    WarningLog() {
        setWarningSink([this](const std::string& m) { messages.push_back(m); });
    }
    ~WarningLog() { setWarningSink({}); }
    std::vector<std::string> messages;
};

TEST(RpictRun, RecoveredPictureIsTheUninterruptedOne) {
    TempDir dir;
    for (int ps : {1, 4, 9}) {
        for (int threads : {1, 3}) {
            RpictOptions o = wallOptions(ps);
            o.render.threads = threads;
            o.outputFile = dir.file("whole.hdr");
            o.zFile = dir.file("whole.z");
            std::ostringstream unused;
            RpictIo io = quietIo(unused);
            std::atomic<long> wholeCalls{0};
            ASSERT_EQ(runRpict(o, wallFactory(&wholeCalls), {}, io), 1);
            EXPECT_TRUE(unused.str().empty());
            const std::string whole = slurp(o.outputFile), wholeZ = slurp(o.zFile);
            ASSERT_EQ(readPicture(o.outputFile).height, 39);  // the view's aspect
            ASSERT_EQ(wholeZ.size(), 48u * 39u * sizeof(float));
            std::filesystem::remove(o.outputFile);
            std::filesystem::remove(o.zFile);

            // Cut anywhere: in the header, at the resolution line, mid-scanline, at the end.
            const size_t header = whole.size() - pixelBytes(whole).size();
            const size_t head = whole.find('\n', header) + 1;  // and the resolution line
            for (size_t cut : {header - 3, header + 5, head + 700, whole.size() / 2,
                               whole.size() - 10, whole.size()}) {
                SCOPED_TRACE("ps " + std::to_string(ps) + " threads " + std::to_string(threads) +
                             " cut " + std::to_string(cut));
                WarningLog warnings;
                RpictOptions r = o;
                r.outputFile = r.recoverFile = dir.file("part.hdr");  // -ro part.hdr
                r.zFile = dir.file("part.z");
                if (cut >= head) {  // other command-line view and size: the file decides
                    r.xres = r.yres = 99;
                    r.view.point = Vec3(7, 7, 7);
                }
                spit(r.recoverFile, whole.substr(0, cut));
                // The z-file is written ahead of the picture, as RADIANCE's: cut it later.
                spit(r.zFile, cut == whole.size() ? wholeZ : wholeZ.substr(0, wholeZ.size() - 100));
                std::atomic<long> calls{0};
                ASSERT_EQ(runRpict(r, wallFactory(&calls), {}, io), 1);
                EXPECT_TRUE(pixelBytes(slurp(r.outputFile)) == pixelBytes(whole));
                EXPECT_TRUE(slurp(r.zFile) == wholeZ);
                // The renamed partial file is gone; RADIANCE keeps one it cannot read.
                EXPECT_EQ(dir.count(), cut < head ? 3u : 2u);
                if (cut >= whole.size() / 2) {  // past the first band
                    EXPECT_LT(calls.load(), wholeCalls.load());
                }
                if (cut == whole.size()) {
                    EXPECT_EQ(calls.load(), 0);
                }
                if (cut < head) {  // nothing to recover: warnings, the command line's view
                    ASSERT_EQ(warnings.messages.size(), 2u);
                    EXPECT_NE(warnings.messages[0].find("cannot recover view"), std::string::npos);
                    EXPECT_NE(warnings.messages[1].find("not removed"), std::string::npos);
                    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
                        if (e.path().filename().string().rfind("rf", 0) == 0)
                            std::filesystem::remove(e.path());
                } else {
                    EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
                }
                std::filesystem::remove(r.outputFile);
                std::filesystem::remove(r.zFile);
            }
        }
    }
}

TEST(RpictRun, RecoverToStandardOutputKeepsTheFile) {
    TempDir dir;
    RpictOptions o = wallOptions(4);
    std::ostringstream whole;
    RpictIo io = quietIo(whole);
    runRpict(o, wallFactory(), {}, io);
    RpictOptions r = o;
    r.recoverFile = dir.file("part.hdr");  // -r part.hdr, picture on standard output
    spit(r.recoverFile, whole.str().substr(0, whole.str().size() / 3));
    std::ostringstream out;
    RpictIo io2 = quietIo(out);
    runRpict(r, wallFactory(), {}, io2);
    EXPECT_TRUE(pixelBytes(out.str()) == pixelBytes(whole.str()));
    // RADIANCE compat (salvage): the recovered file is removed once copied.
    EXPECT_FALSE(std::filesystem::exists(r.recoverFile));
}

TEST(RpictRun, RecoverErrors) {
    TempDir dir;
    RpictOptions o = wallOptions(4);
    std::ostringstream out;
    RpictIo io = quietIo(out);
    {  // A missing -ro file: a new picture with a warning.
        WarningLog warnings;
        RpictOptions r = o;
        r.outputFile = r.recoverFile = dir.file("new.hdr");
        EXPECT_EQ(runRpict(r, wallFactory(), {}, io), 1);
        ASSERT_FALSE(warnings.messages.empty());
        EXPECT_NE(warnings.messages[0].find("new output file"), std::string::npos);
        EXPECT_EQ(readPicture(r.outputFile).width, 48);
    }
    {  // A recover file of another size while its view cannot be read: RADIANCE's error.
        std::ostringstream small;
        RpictOptions s = o;
        s.xres = s.yres = 8;
        RpictIo io2 = quietIo(small);
        runRpict(s, wallFactory(), {}, io2);
        std::string data = small.str();
        const size_t at = data.find("VIEW=");
        data.replace(at, 5, "XIEW=");
        RpictOptions r = o;
        r.recoverFile = dir.file("other.hdr");
        spit(r.recoverFile, data);
        WarningLog warnings;
        try {
            runRpict(r, wallFactory(), {}, io);
            ADD_FAILURE() << "no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("resolution mismatch"), std::string::npos);
        }
    }
    {  // -o never clobbers a single picture.
        RpictOptions r = o;
        r.outputFile = dir.file("new.hdr");
        EXPECT_THROW(runRpict(r, wallFactory(), {}, io), InputError);
    }
}

TEST(RpictRun, FrameFileNames) {
    EXPECT_EQ(frameFileName("frame%03d.hdr", 7), "frame007.hdr");
    EXPECT_EQ(frameFileName("f%d.hdr", 12), "f12.hdr");
    EXPECT_EQ(frameFileName("f%4d.hdr", 5), "f   5.hdr");
    EXPECT_EQ(frameFileName("%-3d|", 5), "5  |");
    EXPECT_EQ(frameFileName("100%%_%i", 2), "100%_2");
    EXPECT_EQ(frameFileName("plain.hdr", 3), "plain.hdr");
    EXPECT_THROW(frameFileName("f%d_%d", 1), InputError);
    EXPECT_THROW(frameFileName("f%s", 1), InputError);
    EXPECT_THROW(frameFileName("f%", 1), InputError);
}

// Views on the input, as rvu's "view" command or a header writes them; other lines and
// lines with no view option are skipped.
const char* kViewLines =
    "# a comment\n"
    "VIEW= -vtv -vp 0 0 0 -vd 0 1 0 -vh 60 -vv 50\n"
    "-vp 1 0 0 is not a view line\n"
    "rpict -vp 0.5 0 0.25\n"
    "VIEW= nothing\n"
    "rview -vp -0.5 0 0 -vh 40\n";

TEST(RpictRun, SequenceFramesFromViewLines) {
    TempDir dir;
    RpictOptions o = wallOptions(4);
    o.sequenceStart = 3;
    o.outputFile = dir.file("frame%02d.hdr");
    std::istringstream views(kViewLines);
    std::ostringstream unused;
    RpictIo io = quietIo(unused, &views);
    std::vector<int> announced;
    io.frameStarted = [&](int frame, const View&) { announced.push_back(frame); };
    EXPECT_EQ(runRpict(o, wallFactory(), {}, io), 3);
    EXPECT_EQ(announced, (std::vector<int>{3, 4, 5}));
    Picture f3 = readPicture(dir.file("frame03.hdr"));
    Picture f4 = readPicture(dir.file("frame04.hdr"));
    Picture f5 = readPicture(dir.file("frame05.hdr"));
    EXPECT_EQ(dir.count(), 3u);
    // FRAME= after the command line and SOFTWARE=, before VIEW=, as RADIANCE's.
    ASSERT_GE(f4.header.lines.size(), 4u);
    EXPECT_EQ(f4.header.lines[0], "rpict -x 48 -y 40");
    EXPECT_EQ(f4.header.lines[2], "FRAME=4");
    // Each line applies on top of the previous view.
    EXPECT_EQ(f3.header.lines[3],
              "VIEW= -vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 60 -vv 50 -vo 0 -va 0 -vs 0 -vl 0");
    EXPECT_EQ(
        f4.header.lines[3],
        "VIEW= -vtv -vp 0.5 0 0.25 -vd 0 1 0 -vu 0 0 1 -vh 60 -vv 50 -vo 0 -va 0 -vs 0 -vl 0");
    EXPECT_EQ(f5.header.lines[3],
              "VIEW= -vtv -vp -0.5 0 0 -vd 0 1 0 -vu 0 0 1 -vh 40 -vv 50 -vo 0 -va 0 -vs 0 -vl 0");
    // The same view as a single picture gives the same pixels.
    RpictOptions single = wallOptions(4);
    single.view.point = Vec3(0.5, 0, 0.25);
    std::ostringstream one;
    RpictIo io1 = quietIo(one);
    runRpict(single, wallFactory(), {}, io1);
    EXPECT_TRUE(pixelBytes(one.str()) == pixelBytes(slurp(dir.file("frame04.hdr"))));

    // Existing frames are skipped, not clobbered (RADIANCE: several processes can share
    // one sequence); the others are rendered.
    std::filesystem::remove(dir.file("frame03.hdr"));
    std::filesystem::remove(dir.file("frame05.hdr"));
    const std::string kept = slurp(dir.file("frame04.hdr"));
    std::istringstream again(kViewLines);
    RpictIo io2 = quietIo(unused, &again);
    EXPECT_EQ(runRpict(o, wallFactory(), {}, io2), 2);
    EXPECT_TRUE(slurp(dir.file("frame04.hdr")) == kept);
    EXPECT_EQ(dir.count(), 3u);
    {  // All there: nothing to do, as RADIANCE says.
        WarningLog warnings;
        std::istringstream third(kViewLines);
        RpictIo io3 = quietIo(unused, &third);
        EXPECT_EQ(runRpict(o, wallFactory(), {}, io3), 0);
        ASSERT_EQ(warnings.messages.size(), 1u);
        EXPECT_EQ(warnings.messages[0], "no output produced");
    }
}

TEST(RpictRun, SequenceOnStandardOutputAndFrameRecovery) {
    TempDir dir;
    RpictOptions o = wallOptions(4);
    o.sequenceStart = 1;
    std::istringstream views(kViewLines);
    std::ostringstream out;
    RpictIo io = quietIo(out, &views);
    EXPECT_EQ(runRpict(o, wallFactory(), {}, io), 3);
    // Frames follow each other on the stream, each a whole picture.
    std::istringstream in(out.str());
    std::vector<Picture> frames;
    for (int k = 0; k < 3; ++k) frames.push_back(readPicture(in, "frames"));
    EXPECT_EQ(in.peek(), std::char_traits<char>::eof());
    EXPECT_EQ(frames[2].header.lines[2], "FRAME=3");

    // -S 1 -r 3 -o f%d.hdr: frames 1 and 2 are skipped on the input and frame 3 is
    // finished from its interrupted file.
    o.outputFile = dir.file("f%d.hdr");
    std::istringstream views1(kViewLines);
    RpictIo io1 = quietIo(out, &views1);
    EXPECT_EQ(runRpict(o, wallFactory(), {}, io1), 3);
    const std::string whole3 = slurp(dir.file("f3.hdr"));
    spit(dir.file("f3.hdr"), whole3.substr(0, whole3.size() / 2));
    RpictOptions r = o;
    r.recoverFile = "3";
    std::istringstream views2(kViewLines);
    RpictIo io2 = quietIo(out, &views2);
    EXPECT_EQ(runRpict(r, wallFactory(), {}, io2), 1);
    EXPECT_TRUE(pixelBytes(slurp(dir.file("f3.hdr"))) == pixelBytes(whole3));
    EXPECT_EQ(dir.count(), 3u);

    r.recoverFile = "0";  // before the start frame
    std::istringstream views3(kViewLines);
    RpictIo io3 = quietIo(out, &views3);
    EXPECT_THROW(runRpict(r, wallFactory(), {}, io3), InputError);
    r.recoverFile = "9";  // past the input
    std::istringstream views4(kViewLines);
    RpictIo io4 = quietIo(out, &views4);
    EXPECT_THROW(runRpict(r, wallFactory(), {}, io4), InputError);
    r.recoverFile = "2";
    r.outputFile.clear();
    EXPECT_THROW(runRpict(r, wallFactory(), {}, io4), InputError);
}

TEST(RpictRun, MotionBlurMovesRaysTowardsThePreviousView) {
    // Frame 1 is blurred towards the command line's view, 10 units to the left: with
    // -pm 0.5 the ray origins spread over [-2.5, 2.5] around the frame's own point.
    RpictOptions o = wallOptions(1);
    o.view.point = Vec3(-10, 0, 0);
    o.sequenceStart = 1;
    o.motionBlur = 0.5;
    std::istringstream views("VIEW= -vp 0 0 0\n");
    std::ostringstream out;
    RpictIo io = quietIo(out, &views);
    std::mutex m;
    double lo = 1e9, hi = -1e9;
    PixelTracerFactory f = [&]() -> PixelTracer {
        return [&](const Vec3& org, const Vec3& dir, uint64_t, double, double* d) {
            std::lock_guard<std::mutex> lock(m);
            lo = std::min(lo, org.x);
            hi = std::max(hi, org.x);
            return wall(org, dir, d);
        };
    };
    runRpict(o, f, {}, io);
    EXPECT_GE(lo, -2.5);
    EXPECT_LT(lo, -2.3);
    EXPECT_LE(hi, 2.5);
    EXPECT_GT(hi, 2.3);
}

}  // namespace
}  // namespace rp::render

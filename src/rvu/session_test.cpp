// rvu's commands on a small lit room: each command changes the view, exposure or
// picture as RADIANCE's rvu does, asks for the pointer when it needs it, and answers bad
// input with an error instead of ending the session.
#include "rvu/session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "calc/search_path.h"
#include "image/picture.h"
#include "image/tonemap.h"
#include "rvu/view_moves.h"
#include "scene/reader.h"
#include "util/paths.h"
#include "util/temp_dir_for_tests.h"

namespace rp::rvu {
namespace {

// A 4 x 4 x 3 room (inside faces) lit by a ceiling panel; the view from the middle of
// one wall looks +y at the far wall (y = 4).
const char* kRoom = R"(
void light bright 0 0 3 10 10 10
void plastic white 0 0 5 .7 .7 .7 0 0
white polygon floor 0 0 12  0 0 0  0 4 0  4 4 0  4 0 0
white polygon ceiling 0 0 12  0 0 3  4 0 3  4 4 3  0 4 3
white polygon far 0 0 12  0 4 0  4 4 0  4 4 3  0 4 3
white polygon near 0 0 12  0 0 0  4 0 0  4 0 3  0 0 3
white polygon left 0 0 12  0 0 0  0 0 3  0 4 3  0 4 0
white polygon right 0 0 12  4 0 0  4 4 0  4 4 3  4 0 3
bright polygon lamp 0 0 12  1.5 1.5 2.9  1.5 2.5 2.9  2.5 2.5 2.9  2.5 1.5 2.9
)";

struct Fixture {
    Fixture() : scene(parseScene(kRoom, "room.rad")), geometry(scene) {}
    std::unique_ptr<Session> start(int xres = 32) {
        SessionSetup s;
        s.scene = &scene;
        s.geometry = &geometry;
        s.searchPath = calc::defaultSearchPath(projectLibDir());
        s.options = rvuDefaults();
        s.options.picture.view.point = {2, 0.5, 1.5};
        s.options.picture.view.horizontal = s.options.picture.view.vertical = 60;
        s.options.picture.xres = s.options.picture.yres = xres;
        s.options.picture.sampleSpacing = 1;
        s.sceneName = "room.rad";
        return std::make_unique<Session>(s);
    }
    static void finish(Session& s) {
        for (int i = 0; i < 64 && !s.done(); ++i) s.refine({}, {});
        ASSERT_TRUE(s.done());
    }
    Scene scene;
    SceneGeometry geometry;
};

TEST(RvuSession, BadInputIsAnErrorNotAnEnd) {
    Fixture f;
    auto s = f.start();
    for (const char* line :
         {"nosuch", "aim zz", "aim 0", "rotate", "rotate x", "move 1 2", "exposure =x", "set zz 1",
          "set ab x", "frame 1 2", "new 0", "trace 1 2 3", "pivot", "origin 1 2", "L", "write"}) {
        const CommandResult r = s->execute(line);
        EXPECT_FALSE(r.ok) << line;
        EXPECT_FALSE(r.error.empty()) << line;
        EXPECT_FALSE(r.quit) << line;
    }
    EXPECT_EQ(s->execute("nosuch").error, "nosuch: unknown command");
    EXPECT_EQ(s->execute("aim 0").error, "illegal magnification");
    EXPECT_TRUE(s->execute("").ok);     // an empty line just continues
    EXPECT_TRUE(s->execute("q").quit);  // commands abbreviate
}

TEST(RvuSession, PointerCommandsAskForThePointer) {
    Fixture f;
    auto s = f.start();
    for (const char* line :
         {"aim", "aim 2", "move", "pivot 30", "trace", "exposure", "focus", "origin"}) {
        const CommandResult r = s->execute(line);
        EXPECT_FALSE(r.pick.empty()) << line;
        EXPECT_EQ(r.points, 1) << line;
    }
    EXPECT_EQ(s->execute("frame").points, 2);
}

TEST(RvuSession, AimAtThePointerLooksThere) {
    Fixture f;
    auto s = f.start();
    const View before = s->view();
    // The picture's right edge, middle height: the view turns right (towards +x).
    const CommandResult r = s->execute("aim 1", {{31, 16}});
    ASSERT_TRUE(r.ok) << r.error;
    const Vec3 d = normalize(s->view().direction);
    EXPECT_GT(d.x, 0.4);
    EXPECT_NEAR(d.z, 0, 0.05);
    EXPECT_EQ(s->view().point, before.point);
    ASSERT_TRUE(s->execute("last").ok);  // and back
    EXPECT_EQ(s->view(), before);
    EXPECT_TRUE(s->execute("aim 2 2 4 1.5").ok);  // a point: straight ahead, zoomed 2x
    EXPECT_NEAR(s->view().horizontal, 2 * std::atan(std::tan(kPi / 6) / 2) * 180 / kPi, 1e-9);
}

TEST(RvuSession, MoveAndPivotAboutTheSurfacePicked) {
    Fixture f;
    auto s = f.start();
    // The middle of the picture is the far wall at (2, 4, 1.5), 3.5 away.
    ASSERT_TRUE(s->execute("move 2", {{16, 16}}).ok);
    EXPECT_NEAR(s->view().point.y, 4 - 3.5 / 2, 0.02);
    const double distance = length(s->view().point - Vec3{2, 4, 1.5});
    ASSERT_TRUE(s->execute("pivot 90 0 1 2 4 1.5").ok);
    // A quarter turn about the point: the view point is beside it, as far, looking at it.
    EXPECT_NEAR(length(s->view().point - Vec3{2, 4, 1.5}), distance, 1e-9);
    EXPECT_NEAR(s->view().point.x, 2 + 1.75, 0.02);
    EXPECT_NEAR(dot(normalize(s->view().direction), normalize(Vec3{2, 4, 1.5} - s->view().point)),
                1, 1e-9);
}

TEST(RvuSession, TraceReportsWhatIsHit) {
    Fixture f;
    auto s = f.start();
    const CommandResult r = s->execute("trace 1 2 2 0 1 0");
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_NE(r.output.find("ray hit white polygon \"far\""), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("at (1 4 2) (2)"), std::string::npos) << r.output;
    EXPECT_NE(s->execute("trace 1 2 2 0 -1 0").output.find("back of white polygon \"near\""),
              std::string::npos);
    EXPECT_EQ(s->execute("trace 2 2 1.5 0 0 0").error, "zero ray direction");
}

TEST(RvuSession, ExposureAsRvu) {
    Fixture f;
    auto s = f.start();
    Fixture::finish(*s);
    double sum = 0;
    for (const Pixel& p : s->image().pixels()) sum += p[0];  // grey room: r = g = b
    const double average = sum / double(s->image().pixels().size());
    ASSERT_TRUE(s->execute("exposure 1").ok);
    EXPECT_NEAR(s->exposure(), 0.5 / average, 1e-4 / average);
    ASSERT_TRUE(s->execute("exposure +1").ok);  // one stop over the normalised exposure
    EXPECT_NEAR(s->exposure(), 1.0 / average, 2e-4 / average);
    ASSERT_TRUE(s->execute("exposure =2").ok);  // absolute
    EXPECT_EQ(s->exposure(), 2);
    ASSERT_TRUE(s->execute("exposure =-1").ok);
    EXPECT_EQ(s->exposure(), 0.5);
    EXPECT_TRUE(s->done());  // exposure never restarts the picture
}

TEST(RvuSession, WriteSavesTheExposedPictureWithItsView) {
    TempDir dir;
    Fixture f;
    auto s = f.start();
    Fixture::finish(*s);
    ASSERT_TRUE(s->execute("exposure =2").ok);
    const std::string path = dir.file("a.hdr");
    ASSERT_TRUE(s->execute("write " + path).ok);
    Picture pic = readPicture(path);
    ASSERT_EQ(pic.width, 32);
    EXPECT_EQ(pic.header.lines.front().rfind("rvu -vtv -vp 2 0.5 1.5 ", 0), 0u);
    EXPECT_NE(pic.header.lines.front().find(" room.rad"), std::string::npos);
    bool exposure = false;
    for (const auto& l : pic.header.lines) exposure |= l.rfind("EXPOSURE=2", 0) == 0;
    EXPECT_TRUE(exposure);
    const Pixel& shown = s->image().pixels()[16 * 32 + 16];
    EXPECT_NEAR(pic.at(16, 16)[0], 2 * shown[0], 0.01 * shown[0]);  // RGBE rounding
    EXPECT_TRUE(s->execute("write").ok);                            // the same file again
    EXPECT_FALSE(s->execute("write /nonexistent-folder/x.hdr").ok);
}

TEST(RvuSession, SetChangesRenderingOnNew) {
    Fixture f;
    auto s = f.start();
    EXPECT_EQ(s->execute("set ab").output, "ambient bounces (0)");
    const CommandResult r = s->execute("set ab 1");
    ASSERT_TRUE(r.ok);
    EXPECT_NE(r.output.find("new"), std::string::npos);
    EXPECT_EQ(s->execute("set ab").output, "ambient bounces (1)");
    Fixture::finish(*s);
    const std::vector<Pixel> direct = s->image().pixels();
    ASSERT_TRUE(s->execute("new").ok);
    EXPECT_FALSE(s->done());
    Fixture::finish(*s);
    // One bounce brightens the unlit corners of the room.
    EXPECT_GT(s->image().pixels()[31][0], direct[31][0]);
    EXPECT_TRUE(s->execute("set b y").ok);
    EXPECT_TRUE(s->greyscale());
}

TEST(RvuSession, ViewsGoToFilesAndComeBack) {
    TempDir dir;
    Fixture f;
    auto s = f.start();
    const std::string rif = dir.file("room.rif");
    ASSERT_TRUE(s->execute("view -vh 40 -vv 30").ok);
    const View saved = s->view();
    EXPECT_TRUE(s->execute("V mine " + rif).ok);
    ASSERT_TRUE(s->execute("rotate 90").ok);
    EXPECT_NE(s->view(), saved);
    ASSERT_TRUE(s->execute("L mine").ok) << s->execute("L mine").error;
    EXPECT_NEAR(s->view().horizontal, saved.horizontal, 1e-9);
    EXPECT_NEAR(length(s->view().point - saved.point), 0, 1e-9);
    const std::string vf = dir.file("v.vf");
    ASSERT_TRUE(s->execute("view " + vf + " a comment").ok);
    ASSERT_TRUE(s->execute("rotate -45 10").ok);
    ASSERT_TRUE(s->execute("last " + vf).ok);
    EXPECT_NEAR(s->view().vertical, 30, 1e-9);
    EXPECT_EQ(s->execute("L nosuch").error, "rad error -- no such view?");
}

TEST(RvuSession, FrameFocusAndStatus) {
    Fixture f;
    auto s = f.start(64);
    EXPECT_EQ(s->status(), "8 refining...");
    ASSERT_TRUE(s->execute("frame 0 0 31 63").ok);
    Fixture::finish(*s);
    EXPECT_EQ(s->status(), "done");
    EXPECT_TRUE(s->image().traced(5, 5));
    EXPECT_FALSE(s->image().traced(40, 5));
    ASSERT_TRUE(s->execute("focus 2.5").ok);
    EXPECT_NEAR(length(s->view().direction), 2.5, 1e-12);
    EXPECT_TRUE(s->done());  // the focal distance does not change the picture
}

}  // namespace
}  // namespace rp::rvu

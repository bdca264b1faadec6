// mkillum's pass over its input with a fake renderer (constant radiance): what is
// copied, converted, dropped and warned about, in RADIANCE 5.4 mkillum's layout (the
// expected text is what RADIANCE printed for the same input, its numbers aside).
#include "illum/illum_filter.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/temp_dir_for_tests.h"
#include "util/warning_capture_for_tests.h"

namespace rp::illum {
namespace {

class Constant : public IllumTracer {
public:
    Color radiance(const Vec3&, const Vec3&, uint64_t) const override { return {0.5, 1, 2}; }
    void sourceSamples(const Vec3&, double, uint64_t, const SourceVisit&) const override {}
};

std::string run(const std::string& input, const std::string& dir = {}) {
    Constant tracer;
    std::ostringstream out;
    IllumFilter filter(tracer, out, "mkillum -ab 0 scene.oct", dir);
    filter.process(input, "in.rad");
    return out.str();
}

TEST(IllumFilter, CopiesAndConverts) {
    WarningCapture warnings;
    const std::string out =
        run("# first comment\n"
            "void alias other paint\n"
            "#@mkillum i=glass d=0 s=4\n"
            "void glass glass\n0\n0\n3 .9 .9 .9\n"
            "glass polygon pane\n0\n0\n9 0 0 0 1 0 0 0 1 0\n"
            "void polygon hole\n0\n0\n9 0 0 0 1 0 0 0 1 0\n"
            "glass cone cone\n0\n0\n8 0 0 0 0 0 1 1 0\n");
    EXPECT_EQ(
        out,
        "# first comment\n"
        "\nvoid alias other\tpaint\n"  // before the command line, as in RADIANCE
        "# mkillum -ab 0 scene.oct\n#@mkillum !\n"
        "# mkillum i=glass d=0 s=4\n"
        "\nvoid glass glass\n0\n0\n3\n                0.9                0.9                0.9\n"
        "\nvoid illum illum_mat\n1 glass\n0\n3 0.950500 0.950500 0.950500\n"
        "\nillum_mat polygon pane\n0\n0\n9\n"
        "                  0                  0                  0\n"
        "                  1                  0                  0\n"
        "                  0                  1                  0\n"
        "\nglass cone cone\n0\n0\n8\n"
        "                  0                  0                  0\n"
        "                  0                  0                  1\n"
        "                  1                  0\n");
    ASSERT_EQ(warnings.lines.size(), 1u);
    EXPECT_EQ(warnings.lines[0], "in.rad:16: cannot make illum for cone 'cone'");
}

TEST(IllumFilter, VoidSurfacesConvertedOrDropped) {
    const std::string out =
        run("#@mkillum i=void d=0 l+ c=n\n"
            "void polygon hole\n0\n0\n9 0 0 0 1 0 0 0 1 0\n"
            "#@mkillum n\n"
            "void polygon gone\n0\n0\n9 0 0 0 1 0 0 0 1 0\n");
    // c=n: the brightness of (.5, 1, 2) in every channel, .263 .5 + .655 + .082 2.
    EXPECT_NE(out.find("\nvoid light illum_mat\n0\n0\n3 0.950500 0.950500 0.950500\n"
                       "\nillum_mat polygon hole\n"),
              std::string::npos);
    EXPECT_EQ(out.find("gone"), std::string::npos);
}

TEST(IllumFilter, DistributionFilesAndTooDarkSurfaces) {
    TempDir dir;
    const std::string out =
        run("#@mkillum m=win d=5 s=2\n"
            "glass polygon a\n0\n0\n9 0 0 0 1 0 0 0 1 0\n"
            "glass polygon b\n0\n0\n9 0 0 0 1 0 0 0 1 0\n"
            "#@mkillum b=2\n"
            "glass polygon dark\n0\n0\n9 0 0 0 1 0 0 0 1 0\n",
            dir.path().string());
    EXPECT_NE(out.find("\nvoid brightdata win.dist\n5 noneg win.dat\n"), std::string::npos);
    EXPECT_NE(out.find("\nvoid brightdata win.dist\n5 noneg win1.dat\n"), std::string::npos);
    EXPECT_NE(out.find("\nglass polygon dark\n"), std::string::npos);
    EXPECT_EQ(dir.count(), 2u);
}

TEST(IllumFilter, ProcessedInputIsCopied) {
    WarningCapture warnings;
    const std::string out =
        run("# mkillum -ab 0 old.oct\n#@mkillum !\n"
            "glass polygon pane\n0\n0\n9 0 0 0 1 0 0 0 1 0\n");
    EXPECT_NE(out.find("\nglass polygon pane\n"), std::string::npos);
    EXPECT_TRUE(warnings.any("in.rad:2: already processed"));
}

TEST(IllumFilter, ErrorsNameTheLine) {
    auto errorOf = [](const std::string& in) {
        try {
            run(in);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(errorOf("# ok\n#@mkillum c=x\n"),
              "in.rad:2: bad #@mkillum option 'c=x': expected c=a, c=d or c=n");
    EXPECT_EQ(errorOf("\n\nglass ring r\n0\n0\n7 0 0 0 0 0 1 1\n"),
              "in.rad:3: ring 'r': expected 8 real arguments, got 7");
    EXPECT_EQ(errorOf("glass sphere s\n0\n0\n3 0 0 0\n"),
              "in.rad:1: sphere 's': expected 4 real arguments, got 3");
    EXPECT_NE(errorOf("!exit 3\n").find("in.rad:1: command failed"), std::string::npos);
}

}  // namespace
}  // namespace rp::illum

// rfluxmtx's command line, the rcontrib run it sets up (checked against the rcontrib
// command line RADIANCE 5.3's rfluxmtx wrote into ref/rfmirror.mtx of RADIANCE's tests),
// and the sender's ray stream.
#include "flux/rfluxmtx.h"

#include <gtest/gtest.h>

#include <fstream>

#include "flux/sender_rays.h"
#include "util/temp_dir_for_tests.h"

namespace rp::flux {
namespace {

std::string joined(const std::vector<std::string>& w, size_t from, size_t to) {
    std::string s;
    for (size_t i = from; i < to; ++i) s += (i > from ? " " : "") + w[i];
    return s;
}

TEST(RfluxmtxArgs, PassesRcontribOptions) {
    const RfluxmtxCommand c =
        parseRfluxmtxArgs({"rfluxmtx", "-n", "2", "-ab", "2", "-lw", "1e-4", "-ffc", "-w", "-av",
                           "1", "1", "1", "mirror.rad", "sky.rad", "basic.mat", "walls.rad"});
    EXPECT_EQ(joined(c.rcontribArgs, 0, c.rcontribArgs.size()),
              "rcontrib -fo+ -n 2 -ab 2 -lw 1e-4 -w -av 1 1 1 -fdc -c 10000");
    EXPECT_FALSE(c.warnings);
    EXPECT_EQ(c.senderFile, "mirror.rad");
    EXPECT_EQ(c.receiverFile, "sky.rad");
    EXPECT_EQ(c.systemArgs, (std::vector<std::string>{"basic.mat", "walls.rad"}));
}

TEST(RfluxmtxArgs, PassThroughKeepsViewOptions) {
    const RfluxmtxCommand c = parseRfluxmtxArgs(
        {"rfluxmtx", "-x", "4", "-y", "3", "-ld-", "-I+", "-ffd", "-", "sky.rad", "-i", "s.oct"});
    EXPECT_EQ(joined(c.rcontribArgs, 0, c.rcontribArgs.size()),
              "rcontrib -fo+ -I+ -x 4 -y 3 -ld- -ffd -c 1");
    EXPECT_TRUE(c.senderFile.empty());
    EXPECT_EQ(c.samples, 1);
}

std::string argsError(const std::vector<std::string>& args) {
    try {
        parseRfluxmtxArgs(args);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(RfluxmtxArgs, Refusals) {
    const std::string usage = rfluxmtxUsage("rfluxmtx");
    EXPECT_EQ(argsError({"rfluxmtx", "-e", "a=1", "s.rad", "r.rad"}),
              "unsupported option '-e'; " + usage);
    EXPECT_EQ(argsError({"rfluxmtx", "-m", "x", "s.rad", "r.rad"}),
              "unsupported option '-m'; " + usage);
    EXPECT_EQ(argsError({"rfluxmtx", "-c", "0", "s.rad", "r.rad"}),
              "unsupported option '-c'; " + usage);
    EXPECT_EQ(argsError({"rfluxmtx", "r.rad"}), usage);
    EXPECT_EQ(argsError({"rfluxmtx", "-I", "s.rad", "r.rad"}),
              "-i, -I supported for pass-through only");
}

const char* kMirror = R"(#@rfluxmtx h=kf u=+Z
void plastic pink 0 0 5 .9 .5 .6 .8 .015
void mirror wall_mirror 1 pink 0 3 .8 .8 .8
wall_mirror polygon mirror 0 0 12 -5 4.99 1 -2 4.99 1 -2 4.99 2 -5 4.99 2
)";
const char* kSky = R"(#@rfluxmtx h=u
void glow groundglow 0 0 4 1 1 1 0
groundglow source ground 0 0 4 0 0 -1 180
#@rfluxmtx h=t u=+Y
void glow skyglow 0 0 4 1 1 1 0
skyglow source sky 0 0 4 0 0 1 180
)";

TEST(RfluxmtxSetup, BuildsRadiancesRcontribCommand) {
    TempDir dir;
    std::ofstream(dir.file("mirror.rad")) << kMirror;
    std::ofstream(dir.file("sky.rad")) << kSky;
    const RfluxmtxCommand c =
        parseRfluxmtxArgs({"rfluxmtx", "-n", "12", "-ab", "2", "-lw", "1e-4",
                           dir.file("mirror.rad"), dir.file("sky.rad"), "basic.mat"});
    const RfluxmtxSetup s = setupRfluxmtx(c, {});
    // ref/rfmirror.mtx: RADIANCE's rfluxmtx ran this rcontrib (the octree word left out).
    EXPECT_EQ(joined(s.commandLine, 0, s.commandLine.size() - 1),
              "rcontrib -fo+ -n 12 -ab 2 -lw 1e-4 -fda -c 10000 -bn 1 -b "
              "if(-Dx*0-Dy*0-Dz*1,0,-1) -m groundglow -f reinhartb.cal -p "
              "MF=1,rNx=0,rNy=0,rNz=-1,Ux=0,Uy=1,Uz=0,RHS=+1 -bn Nrbins -b rbin -m skyglow -y 145");
    EXPECT_EQ(s.scene.files, (std::vector<std::string>{"basic.mat", dir.file("sky.rad")}));
    EXPECT_EQ(s.scene.headerLines,
              (std::vector<std::string>{"oconv -f basic.mat " + dir.file("sky.rad")}));
    ASSERT_EQ(s.options.modifiers.size(), 2u);
    EXPECT_EQ(s.options.modifiers[1].bins, 145);
    EXPECT_EQ(s.options.accumulate, 10000);
    EXPECT_EQ(s.options.yres, 145);
    EXPECT_EQ(s.options.inputFormat, 'd');
}

TEST(RfluxmtxSetup, BinCountsFollowTheParameters) {
    TempDir dir;
    std::ofstream(dir.file("sky.rad")) << "#@rfluxmtx h=r4 u=Y\n"
                                          "void glow sky 0 0 4 1 1 1 0\n"
                                          "sky source s 0 0 4 0 0 1 180\n"
                                          "#@rfluxmtx h=sc6\n"
                                          "void glow g 0 0 4 1 1 1 0\n"
                                          "g source t 0 0 4 0 0 -1 180\n";
    const RfluxmtxSetup s =
        setupRfluxmtx(parseRfluxmtxArgs({"rfluxmtx", "-", dir.file("sky.rad")}), {});
    ASSERT_EQ(s.options.modifiers.size(), 2u);
    EXPECT_EQ(s.options.modifiers[0].bins, 2305);
    EXPECT_EQ(s.options.modifiers[1].bins, 36);
    EXPECT_EQ(s.options.modifiers[1].binExpr, "scbin");
}

TEST(SenderRays, StreamsEachBinsRaysFromTheBack) {
    const auto sender = senderOf(scanFluxText(kMirror, "m.rad"), "m.rad");
    SenderRayBuffer buffer(sender, 50, 7);
    std::istream in(&buffer);
    double ray[6];
    int n = 0;
    while (in.read(reinterpret_cast<char*>(ray), sizeof ray)) {
        ++n;
        EXPECT_NEAR(ray[1], 4.99, 1e-9);
        EXPECT_TRUE(ray[0] >= -5 && ray[0] <= -2 && ray[2] >= 1 && ray[2] <= 2);
        EXPECT_GT(ray[4], 0);  // the mirror faces -Y; its rays leave towards +Y
        EXPECT_NEAR(ray[3] * ray[3] + ray[4] * ray[4] + ray[5] * ray[5], 1, 1e-12);
    }
    EXPECT_EQ(n, 145 * 50);
}

}  // namespace
}  // namespace rp::flux

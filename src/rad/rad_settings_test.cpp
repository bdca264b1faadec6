// rad's derived settings: the numbers RADIANCE 5.4's rad.c derives (quality tables,
// -ar from the octree cube, -av from EXPOSURE or the zone, standard views).
#include "rad/rad_settings.h"

#include <gtest/gtest.h>

namespace rp::rad {
namespace {

RifVars vars(std::initializer_list<const char*> assignments) {
    RifVars v;
    for (const char* a : assignments) EXPECT_TRUE(v.assign(a, SourceLoc{"t.rif", 1}));
    v.check(false);
    v.setDefault(Var::kIndirect, "0");
    v.setDefault(Var::kQuality, "L");
    v.setDefault(Var::kDetail, "M");
    v.setDefault(Var::kPenumbras, "F");
    v.setDefault(Var::kVariability, "L");
    return v;
}

TEST(RadSettings, MediumQualityAsRadiance) {
    Programs p;
    // The inst.rif case: zone 8 x 5 x 3, the scene's box 8.2 across, rad prints -ar 24
    // -ms 0.27 (16 x 8.2 / 5.33 = 24.6, truncated).
    const RifVars v = vars({"ZONE= I -8 0 0 5 0 3", "QUAL= Med", "DET= Low", "VAR= Hi", "IND= 1",
                            "PEN= True", "AMB= x.amb", "EXP= +1"});
    const RenderSettings s = renderSettings(v, 8.2, false, p);
    EXPECT_EQ(s.render,
              " -dp 256 -ar 24 -ms 0.27 -ds .2 -dj .9 -dt .1 -dc .5 -dr 1 -ss 1 -st .1 -ab 1 "
              "-af x.amb -aa .1 -ad 1536 -as 392 -av 0.09 0.09 0.09 -lr 8 -lw 1e-4");
    EXPECT_EQ(s.picture, " -ps 4 -pt .08");
    EXPECT_TRUE(s.overture);
}

TEST(RadSettings, OvertureNeedsAnAmbientFileAndAveragingAndBounces) {
    Programs p;
    EXPECT_FALSE(renderSettings(vars({"ZONE= I 0 1 0 1 0 1", "QUAL= M", "IND= 1"}), 1, false, p)
                     .overture);  // no AMBFILE
    EXPECT_FALSE(renderSettings(vars({"ZONE= I 0 1 0 1 0 1", "QUAL= M", "AMB= a"}), 1, false, p)
                     .overture);  // INDIRECT 0
    EXPECT_FALSE(renderSettings(vars({"ZONE= I 0 1 0 1 0 1", "QUAL= H", "AMB= a", "render= -aa 0"}),
                                1, false, p)
                     .overture);
    EXPECT_TRUE(renderSettings(vars({"ZONE= I 0 1 0 1 0 1", "QUAL= H", "AMB= a"}), 1, false, p)
                    .overture);  // high quality adds a bounce
    EXPECT_FALSE(
        renderSettings(vars({"ZONE= I 0 1 0 1 0 1", "QUAL= L", "AMB= a", "IND= 2"}), 1, false, p)
            .overture);  // low quality computes no indirect light
}

TEST(RadSettings, LowAndHighQuality) {
    Programs p;
    const RenderSettings low =
        renderSettings(vars({"ZONE= E 0 2 0 2 0 2", "DET= H", "PEN= T"}), 4, false, p);
    EXPECT_EQ(low.render,
              " -dp 256 -ar 64 -ds .4 -dt .2 -dc .25 -dr 0 -ss 0 -st .5 -aa .3 -ad 256 -as 0 "
              "-av 10 10 10 -lr 6 -lw .003");
    EXPECT_EQ(low.picture, " -ps 4 -pt .16");
    const RenderSettings high = renderSettings(
        vars({"ZONE= I 0 2 0 2 0 2", "QUAL= H", "DET= L", "VAR= M", "IND= 2", "EXP= 0.5"}), 4,
        false, p);
    EXPECT_EQ(high.render,
              " -dp 1024 -ar 64 -ms 0.05 -ds .2 -dt .05 -dc .75 -dr 3 -ss 16 -st .01 -ab 3 "
              "-aa .1 -ad 1536 -as 768 -av 0.36 0.36 0.36 -lr 12 -lw 1e-5");
    EXPECT_EQ(high.picture, " -ps 8 -pt .04");
}

TEST(RadSettings, PhotonMapsAroundTheQualityOptions) {
    Programs p;
    const RenderSettings s =
        renderSettings(vars({"ZONE= I 0 1 0 1 0 1", "PGMAP= g.pm 1M 40", "PCMAP= c.pm 10k",
                             "render= -ab 1", "rpict= -ps 1"}),
                       1, false, p);
    EXPECT_EQ(s.render.substr(0, 14), " -ap g.pm 40 -");
    EXPECT_NE(s.render.find("-lw .003 -ap c.pm -ab 1"), std::string::npos) << s.render;
    EXPECT_EQ(s.picture, " -ps 8 -pt .16 -ps 1");
}

TEST(RadSettings, AmbientValueFromExposureOrZone) {
    EXPECT_DOUBLE_EQ(ambientValue(vars({"ZONE= I 0 1 0 1 0 1"})), .01);
    EXPECT_DOUBLE_EQ(ambientValue(vars({"ZONE= Ext 0 1 0 1 0 1"})), 10.);
    EXPECT_DOUBLE_EQ(ambientValue(vars({"EXP= +2"})), .18 / 4);
    EXPECT_DOUBLE_EQ(ambientValue(vars({"EXP= 2"})), .09);
    EXPECT_THROW(ambientValue(vars({"ZONE= Q 0 1 0 1 0 1"})), InputError);
}

TEST(RadSettings, ToolVariablesMayNameTheProgram) {
    Programs p;
    RifVars v = vars({"pfilt= mypfilt -r 1", "mkillum= -ab 2", "EXP= -1", "QUAL= Hi"});
    EXPECT_EQ(pfiltOptions(v, p), " -1 -e -1 -m .25 -r 1");
    EXPECT_EQ(p.pfilt, "mypfilt");
    EXPECT_EQ(parallelToolOptions(v, Var::kMkillum, 4, p.mkillum), " -n 4 -ab 2");
    EXPECT_EQ(p.mkillum, "mkillum");
}

TEST(RadSettings, StandardViewsAroundTheZone) {
    const RifVars in = vars({"ZONE= I 0 10 0 4 0 2"});
    EXPECT_EQ(*viewOptions(in, "X"), "-vtv -vp 9.5 2 1 -vd -10 0 0 -vu 0 0 1 -vh 45 -vv 45");
    EXPECT_EQ(*viewOptions(in, "Zl -vh 3"),
              "-vtl -vp 5 2 1.9 -vd 0 0 -2 -vu 0 1 0 -vh 11 -vv 11 -vh 3");
    const RifVars ext = vars({"ZONE= E 0 10 0 4 0 2", "UP= -Y"});
    EXPECT_EQ(*viewOptions(ext, "xYa"), "-vta -vp -15 10 1 -vd 10 -4 0 -vu 0 -1 0 -vh 180 -vv 180");
    EXPECT_EQ(*viewOptions(ext, "def -vf a.vf"), "-vu 0 -1 0 -vf a.vf");
    EXPECT_EQ(*viewOptions(in, "def -vf a.vf"), "-vf a.vf");
    EXPECT_FALSE(viewOptions(in, "bare").has_value());
    EXPECT_EQ(*viewOptions(in, "-vp 1 2 3"), "-vp 1 2 3");
}

TEST(RadSettings, ViewsByNumberNameOrOptions) {
    const RifVars v = vars({"ZONE= I 0 1 0 1 0 1", "view= def -vf a.vf", "view= -vp 1 1 1"});
    std::string name;
    EXPECT_EQ(*selectView(v, nullptr, 0, &name), "-vf a.vf");
    EXPECT_EQ(name, "def");
    EXPECT_EQ(*selectView(v, nullptr, 1, &name), "-vp 1 1 1");
    EXPECT_EQ(name, "2");
    EXPECT_FALSE(selectView(v, nullptr, 2, &name).has_value());
    const std::string two = "2", def = "def", opts = "-vh 10", stdv = "Z";
    EXPECT_EQ(*selectView(v, &two, 0, &name), "-vp 1 1 1");
    EXPECT_FALSE(selectView(v, &two, 1, &name).has_value());  // one view only
    EXPECT_EQ(*selectView(v, &def, 0, &name), "-vf a.vf");
    EXPECT_EQ(*selectView(v, &opts, 0, &name), "-vh 10");
    EXPECT_EQ(name, "0");
    EXPECT_EQ(selectView(v, &stdv, 0, &name)->substr(0, 4), "-vtv");
    EXPECT_EQ(name, "Z");
}

TEST(RadSettings, BadZoneNamesTheVariable) {
    Programs p;
    try {
        renderSettings(vars({"ZONE= I 0 1 0 1 0"}), 1, false, p);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "t.rif:1: bad value for variable 'ZONE'");
    }
    EXPECT_THROW(renderSettings(vars({"ZONE= I 0 1 0 0 0 1"}), 1, false, p), InputError);
}

}  // namespace
}  // namespace rp::rad

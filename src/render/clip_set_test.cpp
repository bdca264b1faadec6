// ClipSet (what antimatter hides from a ray) and AntimatterTable (what each antimatter
// clips, by RADIANCE's lastmod rule) on small scenes.
#include "render/clip_set.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/reader.h"
#include "util/warnings.h"

namespace rp::render {
namespace {

int32_t indexOf(const Scene& s, const std::string& name, size_t from = 0) {
    for (size_t i = from; i < s.prims.size(); ++i)
        if (s.prims[i].name == name) return int32_t(i);
    return -2;
}

TEST(ClipSet, EnteringAddsLeavingRemoves) {
    ClipSet c;
    EXPECT_TRUE(c.empty());
    const std::vector<int32_t> wall{3, 7};
    c.cross(wall, true);
    EXPECT_TRUE(c.contains(3));
    EXPECT_TRUE(c.contains(7));
    EXPECT_FALSE(c.contains(5));
    c.cross(wall, true);  // entering again adds nothing twice
    const std::vector<int32_t> one{3};
    c.cross(one, false);
    EXPECT_FALSE(c.contains(3));
    EXPECT_TRUE(c.contains(7));
    c.cross(one, false);  // leaving what is not there changes nothing
    EXPECT_TRUE(c.contains(7));
    c.cross(wall, false);
    EXPECT_TRUE(c.empty());
}

TEST(ClipSet, ModifiersBeyondTheCapacityAreIgnored) {
    ClipSet c;
    std::vector<int32_t> many;
    for (int32_t i = 0; i < ClipSet::kCapacity + 4; ++i) many.push_back(i);
    c.cross(many, true);
    EXPECT_TRUE(c.contains(ClipSet::kCapacity - 1));
    EXPECT_FALSE(c.contains(ClipSet::kCapacity));
}

TEST(AntimatterTable, NamesAreTheModifiersDefinedLastBefore) {
    // `wall` is defined twice: the antimatter clips the first; surfaces reach the
    // antimatter through a texture; "void" names nothing.
    Scene s = parseScene(R"(
void plastic wall 0 0 5 .5 .5 .5 0 0
void plastic floor 0 0 5 .3 .3 .3 0 0
void antimatter hole 3 void wall floor 0 0
hole texfunc wobble 4 0 0 0 . 0 0
void plastic wall 0 0 5 .9 .9 .9 0 0
wobble sphere s 0 0 4 0 0 0 1
wall sphere t 0 0 4 0 0 3 1
)",
                         "t.rad");
    AntimatterTable t(s);
    EXPECT_FALSE(t.empty());
    const int32_t hole = indexOf(s, "hole"), wobble = indexOf(s, "wobble");
    const int32_t wall1 = indexOf(s, "wall"), wall2 = indexOf(s, "wall", size_t(wall1) + 1);
    ASSERT_NE(t.clips(hole), nullptr);
    ASSERT_NE(t.clips(wobble), nullptr);
    EXPECT_EQ(*t.clips(wobble), (std::vector<int32_t>{wall1, indexOf(s, "floor")}));
    EXPECT_EQ(t.clips(wall1), nullptr);
    EXPECT_EQ(t.clips(wall2), nullptr);
    EXPECT_EQ(t.clips(kVoid), nullptr);
}

TEST(AntimatterTable, UnknownNamesWarnAndAreSkipped) {
    Scene s = parseScene(R"(
void plastic wall 0 0 5 .5 .5 .5 0 0
void antimatter hole 2 wall later 0 0
void plastic later 0 0 5 .5 .5 .5 0 0
)",
                         "t.rad");
    std::vector<std::string> lines;
    setWarningSink([&](const std::string& m) { lines.push_back(m); });
    AntimatterTable quiet(s);
    EXPECT_TRUE(lines.empty());
    AntimatterTable t(s, /*warnUnknown=*/true);
    setWarningSink(nullptr);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("t.rad:3"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("unknown modifier 'later'"), std::string::npos) << lines[0];
    ASSERT_NE(t.clips(indexOf(s, "hole")), nullptr);
    EXPECT_EQ(*t.clips(indexOf(s, "hole")), (std::vector<int32_t>{indexOf(s, "wall")}));
    EXPECT_TRUE(AntimatterTable().empty());
}

}  // namespace
}  // namespace rp::render

#include "pmap/contrib_bins.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace rp::pmap {
namespace {

TEST(ContribBins, BinCountFromDefinitions) {
    // RADIANCE's documented sky binning: rcontrib -e MF:1 -f reinhart.cal -bn Nrbins.
    EXPECT_EQ(evalBinCount({{false, "MF:1"}, {true, "reinhart.cal"}}, "Nrbins"), 146);
    EXPECT_EQ(evalBinCount({{false, "MF:2;"}, {true, "reinhart.cal"}}, "Nrbins"), 578);
    EXPECT_EQ(evalBinCount({{true, "reinhartb.cal"}}, "Nrbins"), 145);
    EXPECT_THROW(evalBinCount({}, "Nrbins"), InputError);
}

TEST(ContribBins, BinCountSeesTheParameters) {
    // RADIANCE 5.4: rcontrib -f reinhartb.cal -p MF=2 -b rbin -bn Nrbins -m sky has 577.
    std::vector<ContribModifier> mods;
    std::vector<CalcDefinition> defs{{true, "reinhartb.cal"}};
    ModifierOptions m(mods, defs, &evalBinCount);
    OptionTable t;
    m.addTo(t, false);
    std::vector<std::string> args{"x", "-p", "MF=2", "-b", "rbin", "-bn", "Nrbins", "-m", "sky"};
    t.parse(args, 1);
    ASSERT_EQ(mods.size(), 1u);
    EXPECT_EQ(mods[0].bins, 577);
    EXPECT_EQ(mods[0].params, "MF=2");
}

TEST(ContribBins, BinsOfReinhartSky) {
    ContribModifier sky;
    sky.name = "skyglow";
    sky.binExpr = "rbin";
    sky.bins = 146;
    sky.params = "MF=1";
    ContribModifier sun;
    sun.name = "solar";
    const ContribBins bins({sky, sun}, {{true, "reinhart.cal"}});
    EXPECT_EQ(bins.size(), 147u);
    EXPECT_EQ(bins.offset(1), 146u);
    ContribBins::Binner b(bins);
    EXPECT_EQ(b.bin(0, {}, {0, 0, 1}), 145);   // zenith: the last patch
    EXPECT_EQ(b.bin(0, {}, {0, 0, -1}), 0);    // ground
    EXPECT_EQ(b.bin(0, {}, {0, 1, 0.01}), 1);  // north at the horizon: the first
    EXPECT_EQ(b.bin(1, {}, {0, 0, 1}), 0);     // a constant bin
}

}  // namespace
}  // namespace rp::pmap

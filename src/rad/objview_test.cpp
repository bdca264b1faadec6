// objview's command line: RADIANCE objview.pl's options and ours (-r, -ap).
#include "rad/objview.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace rp::rad {
namespace {

TEST(ObjviewArgs, OptionsThenInputs) {
    const ObjviewCommand c =
        parseObjviewArgs({"-u", "-Y", "-v", "xZl", "-n", "3", "-s", "-wq", "-b", "-ap", "g.pm",
                          "50", "-ap", "c.pm", "-r", "p.hdr", "a.rad", "-b.rad"});
    EXPECT_EQ(c.up, "-Y");
    EXPECT_EQ(c.view, "xZl");
    EXPECT_EQ(c.radOptions, (std::vector<std::string>{"-N", "3", "-s", "-wq"}));
    EXPECT_EQ(c.renderOptions, " -bv -ap g.pm 50 -ap c.pm");
    EXPECT_EQ(c.picture, "p.hdr");
    EXPECT_EQ(c.inputs, (std::vector<std::string>{"a.rad", "-b.rad"}));
    EXPECT_TRUE(parseObjviewArgs({}).inputs.empty());  // a scene on standard input
    EXPECT_THROW(parseObjviewArgs({"-q", "a.rad"}), InputError);
    EXPECT_THROW(parseObjviewArgs({"-g", "a.rad"}), InputError);
    EXPECT_THROW(parseObjviewArgs({"-u"}), InputError);
}

}  // namespace
}  // namespace rp::rad

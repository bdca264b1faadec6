// pvalue both ways: picture -> values -> picture round trips (ASCII, float, double,
// brightness, no coordinates), value layout and ordering, and one-line input errors.
#include "image/pvalue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "util/error.h"

namespace rp {
namespace {

PvalueOptions opts(std::vector<std::string> args) { return parsePvalueArgs(args); }

// A 3 x 2 picture with distinct pixels, already quantized to RGBE so round trips can be
// compared exactly.
Picture testPicture() {
    Picture pic(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            pic.at(x, y) =
                toPixel(toColr(Pixel{0.1f + x, 0.5f * (y + 1), 0.01f * (x + 3 * y + 1)}));
    pic.header.lines.push_back("test picture");
    return pic;
}

std::string values(const Picture& pic, std::vector<std::string> args) {
    std::ostringstream out;
    writeValues(out, pic, opts(std::move(args)), "pvalue");
    return out.str();
}

Picture picture(const std::string& text, std::vector<std::string> args) {
    std::istringstream in(text);
    return readValues(in, "grid.txt", opts(std::move(args)), "pvalue -r");
}

void expectSamePixels(const Picture& a, const Picture& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        Colr ca = toColr(a.pixels[i]), cb = toColr(b.pixels[i]);
        EXPECT_EQ(0, std::memcmp(&ca, &cb, sizeof ca)) << "pixel " << i;
    }
}

std::string errorOf(const std::string& text, std::vector<std::string> args) {
    try {
        picture(text, std::move(args));
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Pvalue, DefaultOutputIsHeaderResolutionAndCoordinates) {
    std::string s = values(testPicture(), {});
    EXPECT_EQ(0u, s.find("#?RADIANCE\ntest picture\npvalue\nFORMAT=ascii\n\n-Y 2 +X 3\n"));
    // Top-left first; y counts from the bottom as RADIANCE's image coordinates do.
    EXPECT_NE(std::string::npos, s.find("+X 3\n      0       1 "));
    std::string last = s.substr(s.rfind('\n', s.size() - 2) + 1);
    EXPECT_EQ(0u, last.find("      2       0 "));
}

TEST(Pvalue, AsciiRoundTrip) {
    Picture pic = testPicture();
    Picture back = picture(values(pic, {}), {"-r"});
    expectSamePixels(pic, back);
    // The input's header lines come along; FORMAT=ascii does not.
    EXPECT_EQ("test picture", back.header.lines[0]);
    EXPECT_EQ("pvalue -r", back.header.lines.back());
}

TEST(Pvalue, DataOnlyRoundTripWithCommandLineSize) {
    Picture pic = testPicture();
    std::string s = values(pic, {"-h", "-H", "-d"});
    EXPECT_EQ(6, std::count(s.begin(), s.end(), '\n'));
    expectSamePixels(pic, picture(s, {"-r", "-h", "-H", "-d", "-y", "2", "+x", "3"}));
}

TEST(Pvalue, FirstValueIsTopLeft) {
    Picture pic =
        picture("1 1 1\n2 2 2\n3 3 3\n4 4 4\n", {"-r", "-h", "-H", "-d", "-y", "2", "+x", "2"});
    EXPECT_NEAR(1, pic.at(0, 0)[0], 0.01);
    EXPECT_NEAR(2, pic.at(1, 0)[0], 0.01);
    EXPECT_NEAR(3, pic.at(0, 1)[0], 0.01);
    // "+y": bottom scanline first.
    pic = picture("1 1 1\n2 2 2\n3 3 3\n4 4 4\n", {"-r", "-h", "-H", "-d", "+y", "2", "+x", "2"});
    EXPECT_NEAR(3, pic.at(0, 0)[0], 0.01);
}

TEST(Pvalue, Brightness) {
    Picture pic = testPicture();
    std::string s = values(pic, {"-h", "-H", "-d", "-b"});
    std::istringstream in(s);
    double b;
    in >> b;
    EXPECT_NEAR(brightness(pic.at(0, 0)), b, 1e-3 * b);
    Picture grey = picture(s, {"-r", "-h", "-H", "-d", "-b", "-y", "2", "+x", "3"});
    EXPECT_NEAR(grey.at(0, 0)[0], b, 0.01 * b);
    EXPECT_EQ(grey.at(2, 1)[0], grey.at(2, 1)[2]);
}

TEST(Pvalue, BinaryRoundTrips) {
    Picture pic = testPicture();
    for (std::string f : {"-df", "-dd"}) {
        std::string s = values(pic, {"-h", "-H", f});
        EXPECT_EQ(6 * 3 * (f == "-df" ? 4u : 8u), s.size());
        expectSamePixels(pic, picture(s, {"-r", "-h", "-H", f, "-y", "2", "+x", "3"}));
        // With header and resolution, and coordinates kept (+d).
        std::string plus = "+" + f.substr(1);
        expectSamePixels(pic, picture(values(pic, {plus}), {"-r", plus}));
    }
}

TEST(Pvalue, OriginalUndoesExposure) {
    Picture pic = testPicture();
    pic.addExposure(2);
    std::istringstream a(values(pic, {"-h", "-H", "-d"})), b(values(pic, {"-h", "-H", "-d", "-o"}));
    double va, vb;
    a >> va;
    b >> vb;
    EXPECT_NEAR(va / 2, vb, 1e-3 * va);
}

TEST(Pvalue, ExposureOptionInStops) {
    EXPECT_DOUBLE_EQ(4, opts({"-e", "+2"}).exposure);
    EXPECT_DOUBLE_EQ(3, opts({"-e", "3"}).exposure);
}

TEST(Pvalue, BadInputNamesTheFileAndLine) {
    std::vector<std::string> grid = {"-r", "-h", "-H", "-d", "-y", "2", "+x", "2"};
    EXPECT_EQ("grid.txt:2: 'abc' is not a number", errorOf("1 1 1\n1 abc 1\n", grid));
    EXPECT_EQ("grid.txt:3: 2 values on the line, 3 expected", errorOf("1 1 1\n1 1 1\n1 1\n", grid));
    EXPECT_EQ("grid.txt:3: input ends after 3 of 4 pixels for the resolution -Y 2 +X 2",
              errorOf("1 1 1\n1 1 1\n1 1 1\n", grid));
    EXPECT_EQ("grid.txt:5: more pixels than the resolution -Y 2 +X 2 holds (4)",
              errorOf("1 1 1\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n", grid));
    EXPECT_NE(std::string::npos, errorOf("5 0 1 1 1\n", {"-r", "-h", "-H", "-y", "2", "+x", "2"})
                                     .find("grid.txt:1: coordinates"));
    EXPECT_NE(std::string::npos, errorOf("1 1 1\n", {"-r", "-h", "-H"}).find("no resolution"));
    EXPECT_NE(std::string::npos,
              errorOf("#?RADIANCE\n\nnot a size\n", {"-r"}).find("grid.txt:3: bad resolution"));
    std::string floats(4 * 3 * 3, '\0');
    EXPECT_EQ("grid.txt: input ends after 3 of 4 pixels for the resolution -Y 2 +X 2",
              errorOf(floats, {"-r", "-h", "-H", "-df", "-y", "2", "+x", "2"}));
}

TEST(Pvalue, BadOptions) {
    EXPECT_THROW(opts({"-q"}), InputError);
    EXPECT_THROW(opts({"-e"}), InputError);
    EXPECT_THROW(opts({"-r", "-y", "0", "+x", "2"}), InputError);
    EXPECT_THROW(opts({"-r", "-y", "2"}), InputError);
    EXPECT_THROW(opts({"a.hdr", "b.hdr"}), InputError);
}

std::string spectralData(const std::string& name) {
    return std::string(RP_SOURCE_DIR) + "/tests/data/spectral/" + name;
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string run(std::vector<std::string> args) {
    std::istringstream in;
    std::ostringstream out;
    runPvalue(opts(std::move(args)), "pvalue", in, out);
    return out.str();
}

// A RADIANCE 6 spectral picture: each pixel's band averages (scolr2color), as RADIANCE
// 6.1a's pvalue prints them. room.hsr and room12.hsr are spectral_picture_test.cpp's; the
// references were made in tests/data/spectral with RADIANCE 6.1a:
//   pvalue -h -H room.hsr > room_pvalue.txt
//   pvalue -h -H -d -b room.hsr > room_pvalue_b.txt
//   pvalue -h -H -df room.hsr > room_pvalue.df
//   pvalue -h -H room12.hsr > room12_pvalue.txt
//   pvalue room12.hsr > room12_pvalue_full.txt
TEST(Pvalue, SpectralPictureAsRadiance6) {
    const std::string room = spectralData("room.hsr"), room12 = spectralData("room12.hsr");
    EXPECT_EQ(run({"-h", "-H", room}), fileBytes(spectralData("room_pvalue.txt")));
    EXPECT_EQ(run({"-h", "-H", "-d", "-b", room}), fileBytes(spectralData("room_pvalue_b.txt")));
    EXPECT_EQ(run({"-h", "-H", "-df", room}), fileBytes(spectralData("room_pvalue.df")));
    EXPECT_EQ(run({"-h", "-H", room12}), fileBytes(spectralData("room12_pvalue.txt")));
    // No exposure in the header: -o changes nothing.
    EXPECT_EQ(run({"-h", "-H", "-o", room12}), fileBytes(spectralData("room12_pvalue.txt")));
    // The header: the picture's lines without NCOMP=, WAVELENGTH_SPLITS= and FORMAT=, the
    // command line, FORMAT=ascii. (Ours writes the resolution string as "-Y 3 +X 4" and
    // the whole command line; RADIANCE's pads the sizes and stops at the file name.)
    std::string full = fileBytes(spectralData("room12_pvalue_full.txt"));
    std::string ours = run({room12});
    const size_t cmd = full.find("pvalue\nFORMAT=ascii\n\n");
    ASSERT_NE(cmd, std::string::npos);
    EXPECT_EQ(ours.substr(0, cmd), full.substr(0, cmd));
    const std::string values = full.substr(full.find("+X        4\n") + 12);
    EXPECT_EQ(ours.substr(cmd), "pvalue\nFORMAT=ascii\n\n-Y 3 +X 4\n" + values);
}

}  // namespace
}  // namespace rp

// Frozen scene file round trip, corruption handling, RADIANCE octree file lists,
// loadScene() detection by header, and the shared validation scenes.
#include "scene/scene_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "scene/scene_load.h"
#include "util/warnings.h"

namespace rp {
namespace {

namespace fs = std::filesystem;

class TempDir {
public:
    TempDir() {
        path_ = fs::temp_directory_path() / ("rp_scene_test_" + std::to_string(::getpid()));
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    std::string file(const std::string& name, const std::string& contents) const {
        std::string p = (path_ / name).string();
        std::ofstream(p, std::ios::binary) << contents;
        return p;
    }

private:
    fs::path path_;
};

const char* kRoom =
    "void plastic white 0 0 5 .75 .75 .75 0 0\n"
    "void brightfunc pat 4 refl f.cal -rz 90 0 1 2.5\n"
    "pat alias white2 white\n"
    "white2 polygon floor 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n"
    "white sphere ball 0 0 4 0.1 0.2 0.3 0.7\n";

void expectSameScene(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.prims.size(), b.prims.size());
    for (size_t i = 0; i < a.prims.size(); ++i) {
        const Primitive &p = a.prims[i], &q = b.prims[i];
        EXPECT_EQ(p.type, q.type);
        EXPECT_EQ(p.name, q.name);
        EXPECT_EQ(p.modifierName, q.modifierName);
        EXPECT_EQ(p.modifier, q.modifier);
        EXPECT_EQ(p.sargs, q.sargs);
        EXPECT_EQ(p.iargs, q.iargs);
        EXPECT_EQ(p.rargs, q.rargs);  // bit-exact doubles
        EXPECT_EQ(p.loc.file, q.loc.file);
        EXPECT_EQ(p.loc.line, q.loc.line);
    }
    ASSERT_EQ(a.inputs.size(), b.inputs.size());
    for (size_t i = 0; i < a.inputs.size(); ++i) {
        EXPECT_EQ(a.inputs[i].path, b.inputs[i].path);
        EXPECT_EQ(a.inputs[i].mtime, b.inputs[i].mtime);
    }
}

TEST(SceneFile, RoundTrip) {
    Scene s = parseScene(kRoom, "room.rad");
    s.inputs.push_back({"room.rad", 1700000000});
    Scene back = decodeScene(encodeScene(s), "x.oct");
    expectSameScene(s, back);
}

TEST(SceneFile, SavedFileLoadsByHeader) {
    TempDir dir;
    std::string rad = dir.file("room.rad", kRoom);
    Scene s = loadScene({rad});
    std::string oct = (fs::path(rad).parent_path() / "room.oct").string();
    saveSceneFile(oct, s, {"oconv room.rad"});
    std::ifstream in(oct, std::ios::binary);
    std::string head;
    std::getline(in, head);
    EXPECT_EQ(head, "#?RADIANCE");
    Scene back = loadScene({oct});
    ASSERT_EQ(back.inputs.size(), 2u);  // the recorded room.rad, then the scene file
    EXPECT_EQ(back.inputs[0].path, rad);
    EXPECT_EQ(back.inputs[1].path, oct);
    back.inputs.pop_back();
    expectSameScene(s, back);
}

// A scene file whose magic line lost its first byte to a "!" (one flipped bit) has no
// header: it must be refused as binary data, not read as scene text whose first line
// would go to /bin/sh.
TEST(SceneFile, DamagedMagicLineIsNotShellInput) {
    TempDir dir;
    std::string rad = dir.file("room.rad", kRoom);
    std::string marker = (fs::path(rad).parent_path() / "ran").string();
    Scene s = loadScene({rad});
    std::string oct = (fs::path(rad).parent_path() / "room.oct").string();
    saveSceneFile(oct, s, {"oconv room.rad"});
    std::string bytes;
    {
        std::ifstream in(oct, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    bytes.replace(0, std::string("#?RADIANCE").size(), "!touch " + marker + ";#");
    { std::ofstream(oct, std::ios::binary | std::ios::trunc) << bytes; }
    try {
        loadScene({oct});
        ADD_FAILURE() << "a damaged scene file was loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("binary data, not a scene description"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(marker)) << "the damaged file's first line ran as a command";
}

TEST(SceneFile, TruncatedOrCorruptedIsInputError) {
    Scene s = parseScene(kRoom, "room.rad");
    std::string bytes = encodeScene(s);
    // Every truncation, and a flipped byte at many offsets: InputError, never a crash.
    for (size_t n = 0; n < bytes.size(); ++n)
        EXPECT_THROW(decodeScene(std::string_view(bytes).substr(0, n), "t.oct"), InputError) << n;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        std::string bad = bytes;
        bad[i] = static_cast<char>(bad[i] ^ 0x5a);
        EXPECT_THROW(decodeScene(bad, "t.oct"), InputError) << i;
    }
    try {
        decodeScene(std::string_view(bytes).substr(0, bytes.size() - 5), "t.oct");
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("t.oct: corrupted or truncated scene file", 0), 0u);
    }
}

TEST(SceneFile, RadianceOctreeFileList) {
    // writeoct(): magic 283 + sizeof(OBJECT) big-endian, 4 boundary strings, names, "".
    std::string bin = std::string("\x01\x1f", 2) + "0" + '\0' + "0" + '\0' + "0" + '\0' + "5.5" +
                      '\0' + "a.rad" + '\0' + "b.rad" + '\0' + '\0' + "\x00\x00\x00\x07";
    EXPECT_EQ(radianceOctreeFiles(bin, "r.oct"), (std::vector<std::string>{"a.rad", "b.rad"}));
    EXPECT_THROW(radianceOctreeFiles(std::string("\x00\x01", 2), "r.oct"), InputError);
    EXPECT_THROW(radianceOctreeFiles(bin.substr(0, 12), "r.oct"), InputError);
}

TEST(SceneFile, LoadsRadianceOctreeScenes) {
    TempDir dir;
    std::string rad = dir.file("room.rad", kRoom);
    std::string bin = std::string("\x01\x1f", 2) + "0" + '\0' + "0" + '\0' + "0" + '\0' + "5.5" +
                      '\0' + rad + '\0' + '\0' + std::string("\x00\x00\x00\x05\x02", 5);
    std::string oct =
        dir.file("r.oct", "#?RADIANCE\noconv room.rad\nFORMAT=Radiance_octree\n\n" + bin);
    Scene s = loadScene({oct});
    EXPECT_EQ(s.prims.size(), 5u);
    ASSERT_EQ(s.inputs.size(), 2u);
    EXPECT_EQ(s.inputs[0].path, rad);
    EXPECT_EQ(s.inputs[1].path, oct);
    EXPECT_GT(s.inputs[0].mtime, 0);

    std::string frozenBin =
        std::string("\x01\x1f", 2) + "0" + '\0' + "0" + '\0' + "0" + '\0' + "1" + '\0' + '\0';
    std::string frozen =
        dir.file("f.oct", "#?RADIANCE\noconv -f x.rad\nFORMAT=Radiance_octree\n\n" + frozenBin);
    try {
        loadScene({frozen});
        FAIL();
    } catch (const InputError& e) {
        // Frozen: the objects would follow, here nothing does.
        EXPECT_EQ(std::string(e.what()), frozen + ": truncated octree (ends inside object count)");
    }
    std::string pic = dir.file("p.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n");
    EXPECT_THROW(loadScene({pic}), InputError);
}

TEST(SceneFile, OconvAddsToExistingOctree) {
    TempDir dir;
    std::string a = dir.file("a.rad", "void plastic m 0 0 5 1 1 1 0 0\n");
    std::string b = dir.file("b.rad", "m sphere s 0 0 4 0 0 0 1\n");
    OconvRequest r;
    r.files = {a};
    r.commandLine = "oconv a.rad";
    std::string first = oconvOutput(r);
    std::string oct = dir.file("a.oct", first);
    r.files = {b};
    r.addTo = oct;
    r.commandLine = "oconv -i a.oct b.rad";
    std::string second = oconvOutput(r);
    EXPECT_EQ(second.rfind(
                  "#?RADIANCE\noconv a.rad\noconv -i a.oct b.rad\nFORMAT=Radiance_octree\n\n", 0),
              0u);
    Scene s = loadScene({dir.file("b.oct", second)});
    ASSERT_EQ(s.prims.size(), 2u);
    EXPECT_EQ(s.prims[1].modifier, 0);  // b.rad used a.rad's modifier
}

TEST(Validation, DataScenes) {
    std::vector<std::string> w;
    setWarningSink([&](const std::string& m) { w.push_back(m); });
    Scene s = loadScene({RP_SOURCE_DIR "/tests/data/scene/room.rad"});
    setWarningSink(nullptr);
    ASSERT_EQ(s.prims.size(), 5u);
    EXPECT_EQ(s.prims[4].name, "bulb");
    EXPECT_EQ(s.prims[4].loc.line, 14);
    EXPECT_THROW(loadScene({RP_SOURCE_DIR "/tests/data/scene/bad_count.rad"}), InputError);
}

}  // namespace
}  // namespace rp

// rad's executive with a stand-in shell: what runs on a first run, nothing on a second,
// what a changed scene file, an interrupted rendering, -t, -N and a failing command do.
#include "rad/rad_run.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp::rad {
namespace {

namespace fs = std::filesystem;

// Runs in a scratch folder; the shell records commands and writes what they would write
// ("> file", mkpmap's maps), and fails commands that contain `failOn`.
class RadRun : public ::testing::Test {
protected:
    RadRun() : old_(fs::current_path()) {
        fs::current_path(dir_.path());
        write("room.rad", "void light l 0 0 3 1 1 1\nl sphere s 0 0 4 0 0 2 .1\n");
        write("mat.rad", "void plastic p 0 0 5 .5 .5 .5 0 0\n");
        write("t.rif",
              "materials = mat.rad\nscene = room.rad\nZONE = I 0 1 0 1 0 1\n"
              "QUAL = Med\nIND = 1\nAMB = t.amb\nPGMAP = t.gpm 10k 20\n"
              "view = def -vp .5 .5 .5\n");
        age("room.rad", 100);
        age("mat.rad", 100);
        age("t.rif", 100);
    }
    ~RadRun() override { fs::current_path(old_); }

    void write(const std::string& f, const std::string& text) { std::ofstream(f) << text; }
    void age(const std::string& f, int seconds) {
        fs::last_write_time(f, fs::file_time_type::clock::now() - std::chrono::seconds(seconds));
    }

    std::vector<std::string> run(std::vector<std::string> args) {
        commands_.clear();
        std::ostringstream out;
        const Shell shell = [this](const std::string& c) {
            std::lock_guard<std::mutex> lock(m_);
            commands_.push_back(c);
            if (!failOn.empty() && c.find(failOn) != std::string::npos) return 1;
            const std::size_t gt = c.rfind(" > ");
            // An octree's header and bounding cube (all rad reads of it).
            const std::string octree =
                std::string("#?RADIANCE\nFORMAT=Radiance_octree\n\n\x01\x01") + std::string(
                                                                                    "0\0"
                                                                                    "0\0"
                                                                                    "0\0"
                                                                                    "2\0",
                                                                                    8);
            if (gt != std::string::npos && c.find("/dev/null", gt) == std::string::npos)
                write(c.substr(gt + 3), c.rfind("oconv", 0) == 0 ? octree : "made by " + c);
            std::istringstream words(c);
            for (std::string w; words >> w;)
                if (w == "-apg" || w == "-apc") {
                    std::string map;
                    words >> map;
                    write(map, "photons");
                }
            return 0;
        };
        runRad(parseRadArgs(args), out, shell);
        output = out.str();
        return commands_;
    }
    static bool has(const std::vector<std::string>& cmds, const std::string& part) {
        for (const std::string& c : cmds)
            if (c.find(part) != std::string::npos) return true;
        return false;
    }

    TempDir dir_;
    fs::path old_;
    std::mutex m_;
    std::vector<std::string> commands_;
    std::string failOn;
    std::string output;
};

TEST_F(RadRun, FirstRunMakesEverythingSecondRunNothing) {
    const auto first = run({"-s", "t.rif"});
    ASSERT_EQ(first.size(), 5u) << output;
    EXPECT_EQ(first[0], "oconv mat.rad room.rad > t.oct");
    EXPECT_EQ(first[1], "mkpmap -fo+ -apg t.gpm 10k t.oct");
    EXPECT_TRUE(first[2].find("-ap t.gpm 20") != std::string::npos) << first[2];
    EXPECT_TRUE(first[2].find("-x 64 -y 64 -ps 1 t.oct > /dev/null") != std::string::npos);
    EXPECT_TRUE(first[3].find("-x 1024 -y 1024") != std::string::npos) << first[3];
    EXPECT_TRUE(first[3].find("t.oct > t_def.unf") != std::string::npos) << first[3];
    EXPECT_EQ(first[4], "pfilt -r .6 -x /2 -y /2 t_def.unf > t_def.hdr");
    EXPECT_TRUE(fs::exists("t_def.hdr"));
    EXPECT_FALSE(fs::exists("t_def.unf"));  // removed
    EXPECT_TRUE(run({"-s", "t.rif"}).empty());
}

TEST_F(RadRun, ANewerSceneFileRebuildsAndDropsTheAmbientFile) {
    run({"t.rif"});
    write("t.amb", "ambient");
    age("t.amb", 10);
    // What the first run made, a little older: file times are as coarse as the kernel's
    // clock tick, and a busy machine rewrites the scene within one.
    for (const char* f : {"t.oct", "t.gpm", "t_def.hdr"})
        if (fs::exists(f)) age(f, 5);
    write("room.rad", "void light l 0 0 3 2 2 2\nl sphere s 0 0 4 0 0 2 .1\n");
    const auto again = run({"t.rif"});
    EXPECT_TRUE(has(again, "oconv mat.rad room.rad > t.oct"));
    EXPECT_TRUE(has(again, "mkpmap"));
    EXPECT_TRUE(has(again, "> t_def.unf"));
    EXPECT_NE(output.find("\trm -f t.amb\n"), std::string::npos) << output;
    EXPECT_FALSE(fs::exists("t.amb"));
}

TEST_F(RadRun, AMissingPhotonMapIsMadeAlone) {
    run({"t.rif"});
    fs::remove("t.gpm");
    const auto again = run({"t.rif"});
    ASSERT_FALSE(again.empty());
    EXPECT_EQ(again[0], "mkpmap -fo+ -apg t.gpm 10k t.oct");
    EXPECT_FALSE(has(again, "oconv"));
    EXPECT_TRUE(has(again, "> t_def.unf")) << output;  // the picture is older than the new map
}

TEST_F(RadRun, AnInterruptedRenderingIsRecovered) {
    run({"t.rif"});
    fs::remove("t_def.hdr");
    write("t_def.unf", "partial");
    const auto again = run({"t.rif"});
    ASSERT_EQ(again.size(), 2u);
    EXPECT_TRUE(again[0].find(" -ro t_def.unf t.oct") != std::string::npos) << again[0];
    EXPECT_EQ(again[1], "pfilt -r .6 -x /2 -y /2 t_def.unf > t_def.hdr");
}

TEST_F(RadRun, TouchOnlyUpdatesDates) {
    run({"t.rif"});
    age("t.oct", 50);
    age("t.gpm", 50);
    age("t_def.hdr", 50);
    age("room.rad", 10);  // changed since
    EXPECT_TRUE(run({"-t", "t.rif"}).empty());
    EXPECT_NE(output.find("\ttouch t.oct\n"), std::string::npos) << output;
    EXPECT_NE(output.find("\ttouch t.gpm\n"), std::string::npos) << output;
    EXPECT_NE(output.find("\ttouch t_def.hdr\n"), std::string::npos) << output;
    EXPECT_TRUE(run({"t.rif"}).empty());
}

TEST_F(RadRun, ProcessesRenderViewsAtOnceOrOneViewWithThreads) {
    write("t.rif",
          "scene = mat.rad room.rad\nZONE = I 0 1 0 1 0 1\n"
          "view = a -vp .1 .5 .5\nview = b -vp .2 .5 .5\nview = c -vp .3 .5 .5\n");
    const auto cmds = run({"-N", "2", "t.rif"});
    for (const char* p : {"t_a.hdr", "t_b.hdr", "t_c.hdr"}) EXPECT_TRUE(fs::exists(p)) << p;
    EXPECT_EQ(cmds.size(), 1u + 3 * 2);  // oconv, then rpict and pfilt per view
    EXPECT_FALSE(has(cmds, "rpict -n"));
    const auto one = run({"-N", "3", "-v", "b", "t.rif", "RES=64"});
    EXPECT_TRUE(one.empty());  // t_b.hdr is up to date
    fs::remove("t_b.hdr");
    EXPECT_TRUE(has(run({"-N", "3", "-v", "b", "t.rif"}), "rpict -n 3 -vp .2 .5 .5"));
}

TEST_F(RadRun, AFailedCommandStopsWithItsView) {
    failOn = "> t_def.unf";
    try {
        run({"t.rif"});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "error rendering view def");
    }
    failOn = "oconv";
    fs::remove("t.oct");
    EXPECT_THROW(run({"t.rif"}), InputError);
    EXPECT_FALSE(fs::exists("t.oct"));  // removed, as RADIANCE
}

TEST_F(RadRun, PrintOnlyRunsNothing) {
    const auto cmds = run({"-n", "t.rif"});
    EXPECT_TRUE(cmds.empty());
    EXPECT_NE(output.find("\toconv mat.rad room.rad > t.oct\n"), std::string::npos);
    EXPECT_FALSE(fs::exists("t.oct"));
}

TEST(RadArgs, OptionsAndAssignments) {
    const RadCommand c = parseRadArgs({"-silent", "-N", "4", "-e", "-v", "def", "x.rif", "QUAL=H"});
    EXPECT_TRUE(c.silent);
    EXPECT_EQ(c.nprocs, 4);
    EXPECT_TRUE(c.explicate);
    EXPECT_EQ(*c.viewSelect, "def");
    EXPECT_EQ(c.rifFile, "x.rif");
    EXPECT_EQ(c.assignments, std::vector<std::string>{"QUAL=H"});
    EXPECT_EQ(parseRadArgs({"-N", "2", "-n", "x.rif"}).nprocs, 0);
    EXPECT_THROW(parseRadArgs({"-q", "x.rif"}), InputError);
    EXPECT_THROW(parseRadArgs({"-n"}), InputError);
    EXPECT_THROW(parseRadArgs({"-v"}), InputError);
}

}  // namespace
}  // namespace rp::rad

// AtomicFile: the data has no name in the folder until commit, so a process killed while
// writing leaves nothing behind; commit replaces the target whole or, when told not to,
// leaves an existing one alone.
#include "util/file_write.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp {
namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(AtomicFile, NothingInTheFolderUntilCommit) {
    TempDir dir;
    const std::string target = dir.file("out.pm");
    const std::string data(1 << 20, 'x');
    {
        AtomicFile f(target);
        if (!f.unnamed()) GTEST_SKIP() << "no O_TMPFILE on this file system";
        f.write(data.data(), data.size());
        EXPECT_EQ(dir.count(), 0u);  // written, yet nothing named
    }
    EXPECT_EQ(dir.count(), 0u);  // dropped without commit: gone
    {
        AtomicFile f(target);
        f.write(data.data(), data.size());
        f.commit();
    }
    EXPECT_EQ(dir.count(), 1u);
    EXPECT_EQ(slurp(target), data);
}

TEST(AtomicFile, KilledWhileWritingLeavesNothing) {
    TempDir dir;
    const std::string target = dir.file("map.pm");
    for (int k = 0; k < 20; ++k) {
        pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            AtomicFile f(target);
            const std::string chunk(1 << 16, char('a' + k));
            for (int i = 0; i < 16 * (k + 1); ++i) f.write(chunk.data(), chunk.size());
            ::raise(SIGKILL);  // before commit, as a user's kill -9 mid-write
            ::_exit(0);
        }
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFSIGNALED(status));
    }
    // With O_TMPFILE nothing at all; without, at most the hidden names (which the
    // fallback's comment owns up to) - but never anything at the target path.
    AtomicFile probe(target);
    if (probe.unnamed()) {
        EXPECT_EQ(dir.count(), 0u);
    }
    EXPECT_FALSE(std::filesystem::exists(target));
}

TEST(AtomicFile, CommitReplacesOrRefuses) {
    TempDir dir;
    const std::string target = dir.file("pic.hdr");
    writeFileAtomically(target, "old");
    writeFileAtomically(target, "new");
    EXPECT_EQ(slurp(target), "new");
    {
        AtomicFile f(target);
        f.write("newer", 5);
        EXPECT_THROW(f.commit(/*replace=*/false), InputError);
    }
    EXPECT_EQ(slurp(target), "new");
    EXPECT_EQ(dir.count(), 1u);  // the refused data left nothing
}

TEST(AtomicFile, UnwritableFolderNamesTheTarget) {
    try {
        AtomicFile f("/nonexistent-folder/x.pm");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.pm"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rp

// TempFile: data written and read back, nothing named in the folder at any time, and an
// InputError naming the output when the folder cannot hold it.
#include "util/temp_file.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp {
namespace {

TEST(TempFile, RoundTripWithoutANameInTheFolder) {
    TempDir dir;
    std::vector<uint32_t> data(100000);
    std::iota(data.begin(), data.end(), 7u);
    {
        TempFile f(dir.path().string(), "out.pm");
        f.append(data.data(), 1000 * sizeof(uint32_t));
        f.append(data.data() + 1000, (data.size() - 1000) * sizeof(uint32_t));
        EXPECT_EQ(f.size(), data.size() * sizeof(uint32_t));
        EXPECT_EQ(dir.count(), 0u);  // written, yet nothing named
        std::vector<uint32_t> back(500);
        f.readAt(40000 * sizeof(uint32_t), back.data(), back.size() * sizeof(uint32_t));
        EXPECT_TRUE(std::equal(back.begin(), back.end(), data.begin() + 40000));
        // Reading past the end is an error, not a short buffer.
        EXPECT_THROW(f.readAt(f.size() - 4, back.data(), 8), InputError);
        f.clear();
        EXPECT_EQ(f.size(), 0u);
        f.append(data.data(), 8);
        uint32_t two[2];
        f.readAt(0, two, 8);
        EXPECT_EQ(two[0], 7u);
        EXPECT_EQ(two[1], 8u);
        TempFile moved = std::move(f);
        EXPECT_EQ(moved.size(), 8u);
    }
    EXPECT_EQ(dir.count(), 0u);
}

TEST(TempFile, MissingFolderNamesTheOutput) {
    TempDir dir;
    try {
        TempFile f(dir.file("no/such/folder"), "big.pm");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.loc().file, "big.pm");
        EXPECT_NE(std::string(e.what()).find("cannot create a temporary file"), std::string::npos)
            << e.what();
    }
}

TEST(TempFile, FolderOf) {
    EXPECT_EQ(folderOf("g.pm"), ".");
    EXPECT_EQ(folderOf("/g.pm"), "/");
    EXPECT_EQ(folderOf("maps/big/g.pm"), "maps/big");
}

}  // namespace
}  // namespace rp

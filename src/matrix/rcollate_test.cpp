// rcollate: transposes, reshapes and block orders of ASCII and binary records, header
// handling, and one test per kind of bad input.
#include "matrix/rcollate.h"

#include <gtest/gtest.h>

#include <sstream>

#include "util/error.h"

namespace rp::matrix {
namespace {

std::string run(std::vector<const char*> argv, const std::string& input) {
    argv.insert(argv.begin(), "rcollate");
    const RcollateOptions o = parseRcollateArgs(static_cast<int>(argv.size()), argv.data());
    std::ostringstream out;
    runRcollate(o, {"in", input}, out);
    return out.str();
}

std::string errorOf(std::vector<const char*> argv, const std::string& input) {
    try {
        run(std::move(argv), input);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Rcollate, TransposesAsciiWithHeader) {
    EXPECT_EQ(run({"-t"},
                  "#?RADIANCE\nNOTE= x\nNROWS=2\nNCOLS=2\nNCOMP=1\nFORMAT=ascii\n\n"
                  "1 2\n3 4\n"),
              "#?RADIANCE\nNOTE= x\nrcollate -t\nNCOMP=1\nFORMAT=ascii\nNROWS=2\nNCOLS=2\n\n"
              "1\t3\n2\t4\n");
}

TEST(Rcollate, ReshapesHeaderlessRecords) {
    EXPECT_EQ(run({"-h", "-fa2", "-oc", "3"}, "1 2 3 4\n5 6 7 8\n9 10 11 12\n"),
              "1 2\t3 4\t5 6\n7 8\t9 10\t11 12\n");
    EXPECT_EQ(run({"-h", "-ic", "2", "-t"}, "1 1 1 2 2 2\n3 3 3 4 4 4\n"),
              "1 1 1\t3 3 3\n2 2 2\t4 4 4\n");
}

TEST(Rcollate, BlocksAndBinary) {
    EXPECT_EQ(run({"-h", "-fa1", "-o", "2x1X1x2"}, "1 2 3 4\n"), "1\t2\n3\t4\n");
    const std::string bytes = "abcdefgh";  // 2x2 records of 2 bytes
    EXPECT_EQ(run({"-h", "-fb2", "-ic", "2", "-t"}, bytes), "abefcdgh");
}

TEST(Rcollate, BadInputs) {
    EXPECT_EQ(errorOf({"-t"}, "1 2 3\n"),
              "in: bad header (no information header ended by an empty line; -hi reads data "
              "without one)");
    EXPECT_EQ(errorOf({"-t", "-ff"}, "#?RADIANCE\nFORMAT=ascii\n\n1\n"),
              "in: input format 'ascii' != 'float'");
    EXPECT_EQ(errorOf({"-h", "-fa3", "-t"}, "1 2\n3 4 5\n"),
              "in:1: unexpected end of line in record 1 (3 words per record)");
    EXPECT_EQ(errorOf({"-h", "-fa1", "-ic", "2", "-ir", "2", "-t"}, "1 2 3\n"),
              "in: bad dimension(s): 3 records do not make 2x2");
    EXPECT_EQ(errorOf({"-h", "-ff1", "-ic", "2", "-ir", "2", "-t"}, "12345678"),
              "in: input too small for specified size and type (2 records, need 4)");
    EXPECT_EQ(errorOf({"-hi", "-fa1", "-or", "2", "-oc", "2"}, "1 2 3\n"),
              "in:1: incomplete record 4 or unexpected end of data");
    EXPECT_EQ(errorOf({"-q"}, "").rfind("bad option '-q'; Usage: rcollate", 0), 0u);
}

}  // namespace
}  // namespace rp::matrix

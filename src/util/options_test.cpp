// The option table: RADIANCE boolean suffixes, k/m/g counts, range errors, missing values,
// @file/$EVAR expansion, -version and -defaults anywhere among the options, and the
// -defaults text from the table.
#include "util/options.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "util/error.h"
#include "util/temp_dir_for_tests.h"

namespace rp {
namespace {

struct Toy {
    bool back = true;
    bool irr = false;
    double threshold = 0.03;
    int bounces = 0;
    uint64_t photons = 0;
    std::string file;
    Color value;
    std::vector<int> bandwidths;
};

OptionTable toyTable(Toy& t) {
    OptionTable table;
    table.add(flagOption("-bv", t.back),
              [&t] { return formatLine("-bv%c\n", t.back ? '+' : '-'); });
    table.add(flagOption("-i", t.irr, 3));
    table.add(valueOption(
                  "-dt", t.threshold, [](double v) { return v >= 0; }, "must be >= 0"),
              [&t] { return formatLine("-dt %f\t\t\t# direct threshold\n", t.threshold); });
    table.add(valueOption("-ab", t.bounces));
    table.add(countOption("-aC", t.photons));
    table.add(valueOption("-af", t.file));
    table.add(valueOption("-av", t.value));
    table.add(customOption("-ap", [&t](OptionReader& r) {
        r.word();
        while (r.nextIsInteger()) t.bandwidths.push_back(int(r.integer()));
    }));
    return table;
}

Toy parse(std::vector<std::string> args, OptionParse* result = nullptr) {
    Toy t;
    const OptionParse p = toyTable(t).parse(args, 0);
    if (result) *result = p;
    return t;
}

std::string errorOf(std::vector<std::string> args) {
    try {
        parse(std::move(args));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(Options, BooleanSuffixes) {
    EXPECT_FALSE(parse({"-bv"}).back);  // bare toggles
    EXPECT_TRUE(parse({"-bv", "-bv"}).back);
    for (const char* on : {"-bv+", "-bvy", "-bvY", "-bvt", "-bvT", "-bv1"})
        EXPECT_TRUE(parse({"-bv-", on}).back) << on;
    for (const char* off : {"-bv-", "-bvn", "-bvN", "-bvf", "-bvF", "-bv0"})
        EXPECT_FALSE(parse({off}).back) << off;
    EXPECT_EQ(errorOf({"-bvx"}), "unknown option '-bvx'");
    EXPECT_EQ(errorOf({"-bv++"}), "unknown option '-bv++'");
    // A length limit leaves longer words to other options (here: none, so unknown).
    EXPECT_TRUE(parse({"-i+"}).irr);
    EXPECT_EQ(errorOf({"-ix+"}), "unknown option '-ix+'");
}

TEST(Options, Counts) {
    EXPECT_EQ(parse({"-aC", "500k"}).photons, 500000u);
    EXPECT_EQ(parse({"-aC", "2.5M"}).photons, 2500000u);
    EXPECT_EQ(parse({"-aC", "1g"}).photons, 1000000000u);
    EXPECT_EQ(parse({"-aC", "20000"}).photons, 20000u);
    EXPECT_EQ(errorOf({"-aC", "0"}), "bad value '0' for option '-aC'");
    EXPECT_EQ(errorOf({"-aC", "12x"}), "bad value '12x' for option '-aC'");
    EXPECT_FALSE(parseCount("-5"));
    EXPECT_FALSE(parseCount(""));
    EXPECT_FALSE(parseCount("1kk"));
}

TEST(Options, ValuesAndRanges) {
    const Toy t = parse({"-dt", "0.5", "-ab", "-2", "-af", "x.amb", "-av", "1", "2", "3"});
    EXPECT_DOUBLE_EQ(t.threshold, 0.5);
    EXPECT_EQ(t.bounces, -2);
    EXPECT_EQ(t.file, "x.amb");
    EXPECT_EQ(t.value, Color(1, 2, 3));
    EXPECT_EQ(errorOf({"-dt", "-1"}), "option '-dt': must be >= 0");
    EXPECT_EQ(errorOf({"-dt", "abc"}), "bad value 'abc' for option '-dt'");
    EXPECT_EQ(errorOf({"-dt", "inf"}), "bad value 'inf' for option '-dt'");
    EXPECT_EQ(errorOf({"-ab", "1.5"}), "bad value '1.5' for option '-ab'");
    EXPECT_EQ(errorOf({"-ab", "3000000000"}), "bad value '3000000000' for option '-ab'");
    EXPECT_EQ(errorOf({"-zz"}), "unknown option '-zz'");
}

TEST(Options, MissingValues) {
    EXPECT_EQ(errorOf({"-dt"}), "missing value for option '-dt'");
    EXPECT_EQ(errorOf({"-av", "1", "2"}), "missing value for option '-av'");
    EXPECT_EQ(errorOf({"-af"}), "missing value for option '-af'");
}

TEST(Options, TablesKeepTheirMessages) {
    Toy t;
    OptionTable table = toyTable(t);
    table.messages.missing = [](const std::string& o) { return "option " + o + " needs a value"; };
    table.messages.unknown = [](const std::string& o) {
        return "command line error at '" + o + "'";
    };
    auto error = [&table](std::vector<std::string> args) {
        try {
            table.parse(args, 0);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(error({"-dt"}), "option -dt needs a value");
    EXPECT_EQ(error({"-q"}), "command line error at '-q'");
}

TEST(Options, CustomOptionsReadWhatTheyNeed) {
    OptionParse p;
    const Toy t = parse({"-ap", "g.pm", "50", "200", "-ab", "1", "scene.oct"}, &p);
    EXPECT_EQ(t.bandwidths, (std::vector<int>{50, 200}));
    EXPECT_EQ(p.next, 6u);
    EXPECT_EQ(p.stop, OptionStop::kEnd);
}

TEST(Options, VersionAndDefaultsAnywhere) {
    OptionParse p;
    Toy t = parse({"-ab", "2", "-version", "-zz"}, &p);
    EXPECT_EQ(p.stop, OptionStop::kVersion);
    EXPECT_EQ(p.next, 2u);
    EXPECT_EQ(t.bounces, 2);
    parse({"-dt", "0.1", "-defaults", "-zz"}, &p);
    EXPECT_EQ(p.stop, OptionStop::kDefaults);
    // -help is -defaults only where the table says so; after the options it is a file.
    EXPECT_EQ(errorOf({"-help"}), "unknown option '-help'");
    parse({"scene.oct", "-version"}, &p);
    EXPECT_EQ(p.stop, OptionStop::kEnd);
    EXPECT_EQ(p.next, 0u);
}

TEST(Options, DefaultsFromTheTable) {
    Toy t;
    t.threshold = 0.25;
    t.back = false;
    const OptionTable table = toyTable(t);
    EXPECT_EQ(table.formatDefaults(), "-bv-\n-dt 0.250000\t\t\t# direct threshold\n");
    // An option added twice keeps the first (a tool's own before the shared ones).
    OptionTable two;
    bool a = false, b = false;
    two.add(flagOption("-x", a), [] { return std::string("first\n"); });
    two.add(flagOption("-x", b), [] { return std::string("second\n"); });
    std::vector<std::string> args{"-x"};
    two.parse(args, 0);
    EXPECT_TRUE(a);
    EXPECT_FALSE(b);
    EXPECT_EQ(two.formatDefaults(), "first\n");
    two.setDefaultsOrder({"-x", "-x"});
    EXPECT_EQ(two.formatDefaults(), "first\nfirst\n");
}

TEST(Options, ExpandsFilesAndVariablesAtOptionPositions) {
    TempDir dir("options_test");
    const std::string file = dir.file("opts");
    std::ofstream(file) << "-ab 3 '-af' \"my file\"\n";
    ::setenv("RP_OPTIONS_TEST", "-dt 0.5", 1);
    Toy t;
    OptionTable table = toyTable(t);
    table.expandArgs = true;
    std::vector<std::string> args{"@" + file, "$RP_OPTIONS_TEST", "-af", "@x", "scene"};
    const OptionParse p = table.parse(args, 0);
    EXPECT_EQ(t.bounces, 3);
    EXPECT_DOUBLE_EQ(t.threshold, 0.5);
    EXPECT_EQ(t.file, "@x");  // a value is never expanded
    EXPECT_EQ(args[p.next], "scene");
    args = {"@" + dir.file("none")};
    EXPECT_THROW(table.parse(args, 0), InputError);
    ::unsetenv("RP_OPTIONS_TEST_UNSET");
    args = {"$RP_OPTIONS_TEST_UNSET"};
    EXPECT_THROW(table.parse(args, 0), InputError);
}

// RADIANCE's '+' options (gensky +s, pvalue +d) are options only where the table says.
TEST(Options, PlusWordsAreOptionsOnlyWhenAsked) {
    bool plus = false;
    OptionTable table;
    table.add(customOption("+s", [&plus](OptionReader&) { plus = true; }));
    std::vector<std::string> args{"+s", "scene"};
    EXPECT_EQ(table.parse(args, 0).next, 0u);  // "+s" is a word, as a file name would be
    table.plusWords = true;
    EXPECT_EQ(table.parse(args, 0).next, 1u);
    EXPECT_TRUE(plus);
}

// Options after positional arguments (the generators): every remaining word must be one.
TEST(Options, ParseAllRejectsWordsAndVersionAsUnknown) {
    Toy t;
    OptionTable table = toyTable(t);
    table.messages.unknown = [](const std::string& w) { return "unknown option '" + w + "'"; };
    std::vector<std::string> args{"mat", "name", "-ab", "2"};
    table.parseAll(args, 2);
    EXPECT_EQ(t.bounces, 2);
    for (const char* stray : {"x", "-version", "-"}) {
        args = {"mat", "name", "-ab", "2", stray};
        try {
            table.parseAll(args, 2);
            ADD_FAILURE() << stray << " accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), std::string("unknown option '") + stray + "'");
        }
    }
}

}  // namespace
}  // namespace rp

// Input and output channels ($N, in(n), `$N = expr;`) and external variables, the parts
// of the .cal language that rcalc uses (rcalc(1)).
#include <gtest/gtest.h>

#include <vector>

#include "calc/program.h"

namespace rp::calc {
namespace {

// Channels 1..n of one record; channel(n) beyond it is 0, as rcalc's binary input.
class Columns : public ChannelSource {
public:
    explicit Columns(std::vector<double> v) : v_(std::move(v)) {}
    double channel(int n) override {
        if (n < 1) throw InputError("illegal channel number");
        return n <= static_cast<int>(v_.size()) ? v_[n - 1] : 0;
    }
    double channelCount() override { return static_cast<double>(v_.size()); }

private:
    std::vector<double> v_;
};

std::vector<double> outputs(const std::string& defs, std::vector<double> in) {
    Builder b;
    b.enableChannels();
    b.loadString(defs);
    auto prog = b.build();
    Evaluator ev(prog);
    Columns cols(std::move(in));
    ev.setChannels(&cols);
    RayContext none;
    ev.setRay(none);
    std::vector<double> out;
    for (const OutputChannel& c : prog->outputChannels()) out.push_back(ev.eval(c.entry));
    return out;
}

TEST(Channels, OutputsInChannelOrderReadingInputs) {
    // The left $1 is output column 1, the right $1 input column 1.
    Builder b;
    b.enableChannels();
    b.loadString("$3 = $1 + $2; $1 = $1 * 2; x = $2 ^ 2; $2 = x;");
    auto prog = b.build();
    ASSERT_EQ(prog->outputChannels().size(), 3u);
    EXPECT_EQ(prog->outputChannels()[0].channel, 1);
    EXPECT_EQ(prog->outputChannels()[2].channel, 3);
    EXPECT_EQ(outputs("$3 = $1 + $2; $1 = $1 * 2; x = $2 ^ 2; $2 = x;", {3, 4}),
              (std::vector<double>{6, 16, 7}));
}

TEST(Channels, LaterOutputDefinitionReplacesEarlier) {
    EXPECT_EQ(outputs("$1 = 1; $1 = 2;", {}), (std::vector<double>{2}));
}

TEST(Channels, InFunctionCountsAndReads) {
    EXPECT_EQ(outputs("$1 = in(0); $2 = in(1 + 1); $3 = in(5)", {7, 8, 9}),
              (std::vector<double>{3, 8, 0}));
}

TEST(Channels, UserDefinedInWins) {
    EXPECT_EQ(outputs("in(x) = x * 10; $1 = in(2)", {7, 8}), (std::vector<double>{20}));
}

TEST(Channels, IllegalChannelIsAnInputError) { EXPECT_THROW(outputs("$1 = $0", {1}), InputError); }

TEST(Channels, NotAvailableWithoutEnable) {
    Builder b;
    b.loadString("x = $1; y = in(1);", "f.cal");
    auto prog = b.build();
    ASSERT_EQ(prog->problems().size(), 2u);
    EXPECT_NE(prog->problems()[0].find("f.cal:1: input channel '$1' is not available"),
              std::string::npos);
    EXPECT_NE(prog->problems()[1].find("undefined function 'in'"), std::string::npos);
}

TEST(Channels, SyntaxErrors) {
    Builder b;
    EXPECT_THROW(b.loadString("$ = 1"), InputError);
    EXPECT_THROW(b.loadString("$1(x) = 1"), InputError);
    EXPECT_THROW(b.loadString("f($1) = 1"), InputError);
}

TEST(Externals, ValueSetPerEvaluationOverridesDefinition) {
    Builder b;
    b.loadString("recno = 99; y = recno * 2; c : 3;");
    b.addExternal("recno");
    auto prog = b.build();
    EXPECT_TRUE(prog->problems().empty());
    Evaluator ev(prog);
    RayContext none;
    auto recno = prog->variable("recno");
    auto y = prog->variable("y");
    ASSERT_TRUE(recno && y);
    for (int rec = 1; rec <= 3; ++rec) {
        ev.setRay(none);  // a new record forgets y
        ev.set(*recno, rec);
        EXPECT_EQ(ev.eval(*y), 2.0 * rec);
    }
    ev.setRay(none);  // not set for this record: undefined
    EXPECT_THROW(ev.eval(*y), InputError);
}

}  // namespace
}  // namespace rp::calc

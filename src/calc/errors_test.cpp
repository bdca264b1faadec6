// Bad .cal input: syntax errors, undefined names, wrong calls, runaway recursion and
// missing files must all be InputErrors naming file:line.
#include <gtest/gtest.h>

#include <string>

#include "calc/calc_test_util.h"

namespace rp::calc {
namespace {

// The message of the InputError thrown by `fn`, or "" if none.
template <class Fn>
std::string errorOf(Fn fn) {
    try {
        fn();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string loadError(const std::string& text) {
    return errorOf([&] {
        Builder b;
        b.loadString(text, "bad.cal");
    });
}

std::string evalError(const std::string& defs, const std::string& expr) {
    return errorOf([&] { testing::evalWith(defs, expr); });
}

TEST(CalcErrors, SyntaxErrorsNameFileAndLine) {
    EXPECT_EQ(loadError("a = 1;\nb = (2 + 3;\n"),
              "bad.cal:2: syntax error: ')' expected, found ';'");
    EXPECT_EQ(loadError("a = 1;\n\nb = 2 # 3;"),
              "bad.cal:3: syntax error: unexpected character '#'");
    EXPECT_EQ(loadError("a = 1;\n\nb = 2 $ 3;"),
              "bad.cal:3: syntax error: channel number expected after '$'");
    EXPECT_EQ(loadError("a 1;"), "bad.cal:1: syntax error: '=' or ':' expected after 'a'");
    EXPECT_EQ(loadError("a = 1\nb = 2;"), "bad.cal:2: syntax error: ';' expected, found name 'b'");
    EXPECT_EQ(loadError("a = --2;"), "bad.cal:1: syntax error: unexpected '-'");
    EXPECT_EQ(loadError("x = 1;\n{ open\ncomment"),
              "bad.cal:2: syntax error: '}' expected to close comment");
    EXPECT_EQ(loadError("f() = 2;"), "bad.cal:1: syntax error: expected a parameter name");
    EXPECT_EQ(loadError("= 2;"), "bad.cal:1: syntax error: expected a name to define, found '='");
    EXPECT_EQ(loadError("a = f(1,);"), "bad.cal:1: syntax error: unexpected ')'");
    EXPECT_EQ(loadError("a = 2 }"), "bad.cal:1: syntax error: '}' without an opening '{'");
}

TEST(CalcErrors, FinalSemicolonIsOptional) {
    EXPECT_EQ(loadError("a = 1"), "");
    EXPECT_EQ(loadError(";;a = 1;;"), "");
}

TEST(CalcErrors, UndefinedNamesReportTheReference) {
    Builder b;
    b.loadString("a = 1;\nb = a + missing;\nc = 2;\n", "defs.cal");
    auto p = b.build();  // not an error until evaluated
    ASSERT_EQ(p->problems().size(), 1u);
    EXPECT_EQ(p->problems()[0], "defs.cal:2: undefined variable 'missing'");
    Evaluator ev(p);
    EXPECT_EQ(ev.eval(*p->variable("c")), 2);
    EXPECT_EQ(errorOf([&] { ev.eval(*p->variable("b")); }),
              "defs.cal:2: undefined variable 'missing'");
    EXPECT_EQ(evalError("f(x) = x + nothere(x);", "f(1)"),
              "defs.cal:1: undefined function 'nothere'");
}

TEST(CalcErrors, WrongKindsAndCounts) {
    EXPECT_EQ(evalError("a = 2; b = a(3);", "b"), "defs.cal:1: 'a' is a variable, not a function");
    EXPECT_EQ(evalError("b = sqrt + 1;", "b"),
              "defs.cal:1: 'sqrt' is a function; it needs arguments");
    EXPECT_EQ(evalError("b = atan2(1);", "b"),
              "defs.cal:1: function 'atan2' takes 2 argument(s), got 1");
    EXPECT_EQ(evalError("b = if(1, 2);", "b"), "defs.cal:1: if() takes 3 arguments");
    EXPECT_EQ(evalError("f(a, b) = a + b;\ng = f(1);", "g"),
              "defs.cal:1: missing argument 2 to function");
    EXPECT_EQ(evalError("i = Dx + 5;\nb = select(i, 1, 2);", "b"),
              "defs.cal:2: select index 5 out of range 1..2");
    EXPECT_EQ(evalError("b = apply(1);\napply(f) = f(2);", "b"),
              "defs.cal:1: expected a function name as argument");
}

TEST(CalcErrors, ModifierArgumentsMustExist) {
    RayContext ray;
    double args[] = {1, 2};
    ray.args = args;
    EXPECT_EQ(testing::evalWith("", "A2 + AC", true, &ray), 4);
    EXPECT_EQ(errorOf([&] { testing::evalWith("", "A3", true, &ray); }),
              std::string(RP_SOURCE_DIR) +
                  "/lib/rayinit.cal:21: missing real argument 3 (modifier has 2)");
    // Indices beyond int's range saturate instead of overflowing the conversion
    // (undefined behaviour before; found by fuzz_cal): constant and computed.
    EXPECT_NE(errorOf([&] {
                  testing::evalWith("", "arg(7.7e88)", true, &ray);
              }).find("missing real argument 2147483647"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  testing::evalWith("", "arg(Dx * 1e30 + 1e30)", true, &ray);
              }).find("missing real argument 2147483647"),
              std::string::npos);
    EXPECT_NE(evalError("b = select(1e30, 1, 2);", "b").find("out of range"), std::string::npos);
}

TEST(CalcErrors, RecursionWithoutBaseCase) {
    EXPECT_EQ(evalError("f(x) = f(x + 1) + 1;", "f(0)"),
              "defs.cal:1: recursion too deep in function 'f' (missing base case?)");
    EXPECT_NE(evalError("f(x) = 1 + g(x);\ng(x) = 2*f(x);", "f(0)")
                  .find("recursion too deep in function"),
              std::string::npos);
    EXPECT_EQ(evalError("a = b + 1;\nb = a * 2;", "a"),
              "defs.cal:2: recursion too deep in variable 'b' (missing base case?)");
    // A constant function called with constant arguments is folded at build time,
    // so the error comes from build().
    EXPECT_EQ(evalError("f(x) : f(x - 1);\nk = f(3);", "k"),
              "defs.cal:1: recursion too deep in function 'f' (missing base case?)");
}

TEST(CalcErrors, RecursionErrorLeavesEvaluatorUsable) {
    Builder b;
    b.loadString("f(x) = f(x) + 1; ok = 5;", "defs.cal");
    auto p = b.build();
    Evaluator ev(p);
    EXPECT_THROW(ev.call(*p->function("f"), std::vector<double>{1.0}), InputError);
    EXPECT_EQ(ev.eval(*p->variable("ok")), 5);
}

TEST(CalcErrors, MissingFile) {
    Builder b({"/nonexistent"});
    EXPECT_EQ(errorOf([&] { b.loadFile("nosuch.cal"); }),
              "nosuch.cal: cannot find function file (searched /nonexistent)");
}

TEST(CalcErrors, ErrorsInFilesNameTheFile) {
    Builder b({testing::libDir()});
    b.loadFile("rayinit.cal");
    auto p = b.build();
    EXPECT_TRUE(p->problems().empty()) << p->problems()[0];
}

}  // namespace
}  // namespace rp::calc

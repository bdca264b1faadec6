// Table test of the .cal language: expressions with known values covering precedence,
// RADIANCE's unary-minus/'^' rule, numbers, builtins, rayinit.cal functions, if/select,
// constants, recursion, function-valued parameters and contexts.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/calc_test_util.h"

namespace rp::calc {
namespace {

using testing::evalWith;

struct Case {
    const char* defs;
    const char* expr;
    double want;
};

constexpr double kPi = 3.14159265358979323846;

const Case kCases[] = {
    // numbers in all forms
    {"", "42", 42},
    {"", "3.25", 3.25},
    {"", ".5", 0.5},
    {"", "5.", 5},
    {"", "1e3", 1000},
    {"", "2.5E-2", 0.025},
    {"", "1.e2", 100},
    {"", "7E+1", 70},
    // precedence and associativity
    {"", "1+2*3", 7},
    {"", "(1+2)*3", 9},
    {"", "10-4-3", 3},
    {"", "2*3/4", 1.5},
    {"", "8/2/2", 2},
    {"", "1+2^3", 9},
    {"", "2*3^2", 18},
    {"", "2^3^2", 512},  // right-associative
    {"", "(2^3)^2", 64},
    {"", "6/2*3", 9},
    {"", "2-3*4+5", -5},
    // unary minus: binds tighter than '^' (RADIANCE calexpr.c)
    {"", "-2^2", 4},
    {"", "-(2^2)", -4},
    {"", "2^-2", 0.25},
    {"", "-3*-2", 6},
    {"", "+3", 3},
    {"", "4--2", 6},
    {"x = 3;", "-x^2", 9},
    {"x = 3;", "0-x^2", -9},
    {"", "2^-1^2", 2},  // 2^((-1)^2)
    // whitespace and comments
    {"", " 1 +\n 2 { a comment } * 3", 7},
    {"", "1 { outer { nested } still comment } + 1", 2},
    // definitions, constants, overriding
    {"a = 2; b = a*3;", "b", 6},
    {"c : 4*5;", "c", 20},
    {"a = 1; a = 2;", "a", 2},
    {"f(x) = x*x; g(x, y) = f(x) + y;", "g(3, 1)", 10},
    {"f(x) = x + 1; f(x) = x + 2;", "f(1)", 3},
    {"b = a + 1; a = 10;", "b", 11},  // use before definition
    {"k : 2; f(x) : k*x;", "f(21)", 42},
    {"h(a, b, c) = a - b - c;", "h(10, 3, 2)", 5},
    // arg() inside a function
    {"n(a, b, c) = arg(0);", "n(1, 2, 3)", 3},
    {"second(a, b) = arg(2);", "second(7, 8)", 8},
    {"f(a) = arg(0);", "f(1, 2, 3, 4)", 4},  // extra arguments are allowed
    // if and select
    {"", "if(1, 2, 3)", 2},
    {"", "if(0, 2, 3)", 3},
    {"", "if(-1, 2, 3)", 3},
    {"", "if(1e-300, 2, 3)", 2},
    {"", "select(2, 10, 20, 30)", 20},
    // RADIANCE 5.4 calfunc.c's min and max, any number of arguments
    {"", "max(3)", 3},
    {"", "max(1, 7, -2)", 7},
    {"", "min(4, 2, 9, -1.5)", -1.5},
    {"", "min(.25, 1)", .25},
    {"", "select(0, 10, 20, 30)", 3},
    {"", "select(1.4, 10, 20)", 10},
    {"", "select(1.6, 10, 20)", 20},
    {"i = 3;", "select(i, 1, 2, 3)", 3},
    {"", "if(1, 5, 1/0)", 5},  // lazy: the other branch is not evaluated
    // builtins
    {"", "sqrt(16)", 4},
    {"", "sin(0)", 0},
    {"", "cos(0)", 1},
    {"", "tan(0)", 0},
    {"", "asin(1)", kPi / 2},
    {"", "acos(-1)", kPi},
    {"", "atan(1)", kPi / 4},
    {"", "atan2(1, -1)", 3 * kPi / 4},
    {"", "exp(1)", std::exp(1.0)},
    {"", "log(exp(2))", 2},
    {"", "log10(1000)", 3},
    {"", "floor(-1.5)", -2},
    {"", "ceil(-1.5)", -1},
    {"", "floor(2.7)", 2},
    {"", "erf(0)", 0},
    {"", "erfc(0)", 1},
    {"", "hermite(1, 2, 0, 0, 0)", 1},
    {"", "hermite(1, 2, 0, 0, 1)", 2},
    {"", "hermite(0, 1, 0, 0, .5)", 0.5},
    {"", "rand(3) - rand(3)", 0},
    {"", "noise3(1, 2, 3)", 0},  // gradient noise vanishes on lattice points
    // RADIANCE compat: math errors give 0
    {"", "1/0", 0},
    {"", "sqrt(-1)", 0},
    {"", "log(0)", 0},
    {"", "(-8)^(1/3)", 0},
    // rayinit.cal
    {"", "PI", kPi},
    {"", "DEGREE*180", kPi},
    {"", "abs(-3)", 3},
    {"", "sgn(-2) + sgn(0) + 10*sgn(5)", 9},
    {"", "sq(7)", 49},
    {"", "max(2, 9)", 9},
    {"", "min(2, 9)", 2},
    {"", "bound(0, 5, 1)", 1},
    {"", "bound(0, -5, 1)", 0},
    {"", "bound(0, .3, 1)", 0.3},
    {"", "and(1, -1)", -1},
    {"", "or(-1, 1)", 1},
    {"", "not(1)", -1},
    {"", "inside(0, .5, 1)", 0.5},
    {"", "inside(0, 2, 1)", -1},
    {"", "frac(3.25)", 0.25},
    {"", "mod(7, 3)", 1},
    {"", "mod(-1, 3)", 2},
    {"", "tri(1, 2)", 1},
    {"", "linterp(.25, 4, 8)", 5},
    {"", "Acos(1.0000001)", 0},
    {"", "Sqrt(-4)", 0},
    {"", "Exp(-200)", 0},
    {"", "Atan2(0, 0)", 0},
    {"", "clip(2)", 1},
    {"", "noneg(-2)", 0},
    {"", "grey(1, 1, 1)", 1},
    {"", "bezier(0, 0, 1, 1, .5)", 0.5},
    {"", "bspline(1, 1, 1, 1, .3)", 1},
    {"", "if(1e-6 - abs(unif2norm(.5)), 1, 0)", 1},
    {"", "if(1e-3 - abs(unif2norm(.975) - 1.95996), 1, 0)", 1},
    // function-valued parameters (rayinit's dot and cross)
    {"u(i) = select(i, 1, 2, 3); v(i) = select(i, 4, 5, 6);", "dot(u, v)", 32},
    {"u(i) = select(i, 1, 0, 0); v(i) = select(i, 0, 1, 0);", "cross(3, u, v)", 1},
    {"apply(f, x) = f(x);", "apply(sqrt, 9)", 3},
    {"apply(f, x) = f(x); twice(f, x) = apply(f, apply(f, x));", "twice(sqrt, 16)", 2},
    // recursion
    {"fact(n) = if(n - 1.5, n*fact(n - 1), 1);", "fact(10)", 3628800},
    {"fib(n) = if(n - 1.5, fib(n - 1) + fib(n - 2), n);", "fib(15)", 610},
    {"cfact(n) : if(n - 1.5, n*cfact(n - 1), 1);", "cfact(5)", 120},
    {"ev(n) = if(n - .5, od(n - 1), 1); od(n) = if(n - .5, ev(n - 1), 0);", "ev(10)", 1},
    // contexts
    {"x`a = 5;", "x`a", 5},
    {"x = 1; x`a = 2;", "x", 1},
    {"g` = 7;", "g", 7},
    // names with dots and underscores
    {"my.var = 3; my_var = 4;", "my.var*my_var", 12},
};

TEST(CalcExprTable, KnownValues) {
    EXPECT_GE(std::size(kCases), 80u);
    for (const Case& c : kCases) {
        SCOPED_TRACE(std::string("defs: ") + c.defs + "  expr: " + c.expr);
        double got = evalWith(c.defs, c.expr);
        EXPECT_NEAR(got, c.want, 1e-12 * std::max(1.0, std::fabs(c.want)));
    }
}

TEST(CalcExpr, ContextLookupSearchesOutward) {
    Builder b({testing::libDir()});
    b.loadString("shared = 10; x = 1;");
    b.setContext("sky");
    b.loadString("x = 2; y = x + shared;");
    b.setContext("");
    auto p = b.build();
    Evaluator ev(p);
    EXPECT_EQ(ev.eval(*p->variable("y", "sky")), 12);
    EXPECT_EQ(ev.eval(*p->variable("x", "sky")), 2);
    EXPECT_EQ(ev.eval(*p->variable("x")), 1);
    EXPECT_EQ(ev.eval(*p->variable("x`sky")), 2);
    EXPECT_FALSE(p->variable("y").has_value());
    EXPECT_FALSE(p->variable("`shared", "sky").has_value());  // local only
}

TEST(CalcExpr, InlineExpressionsOverrideFiles) {
    Builder b({testing::libDir()});
    b.loadFile("rayinit.cal");
    b.loadString("PI : 3;");  // like rtrace -e after -f
    auto p = b.build();
    Evaluator ev(p);
    EXPECT_EQ(ev.eval(*p->variable("PI")), 3);
    EXPECT_NEAR(ev.eval(*p->variable("DEGREE")), 3.0 / 180, 1e-15);
}

TEST(CalcExpr, CallFunctionByHandle) {
    Builder b;
    b.loadString("hyp(a, b) = sqrt(a*a + b*b);");
    auto p = b.build();
    Evaluator ev(p);
    auto f = p->function("hyp");
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->nparams, 2);
    double args[] = {3, 4};
    EXPECT_EQ(ev.call(*f, args), 5);
    auto sq = p->function("sqrt");
    ASSERT_TRUE(sq.has_value());
    double nine[] = {9};
    EXPECT_EQ(ev.call(*sq, nine), 3);
}

TEST(CalcExpr, MathErrorsAreCounted) {
    Builder b;
    b.loadString("z = Dx; r = 1/z + sqrt(z - 1);");
    auto p = b.build();
    Evaluator ev(p);
    RayContext ray;
    ray.D = {0, 0, 1};
    ev.setRay(ray);
    EXPECT_EQ(ev.eval(*p->variable("r")), 0);
    EXPECT_EQ(ev.mathErrors(), 2);
}

TEST(CalcExpr, ConstantsAreFolded) {
    Builder b;
    b.loadString("k : 2*3; f(x) : x*k; g = f(7) + 1;");
    auto p = b.build();
    // A folded definition is a constant node: no cache slot, no call.
    auto g = p->variable("g");
    ASSERT_TRUE(g.has_value());
    EXPECT_EQ(g->node->fn, &evConst);
    EXPECT_EQ(g->node->num, 43);
}

TEST(CalcExpr, VariablesAreCachedPerRay) {
    Builder b;
    b.loadString("v = Dx*2;");
    auto p = b.build();
    Evaluator ev(p);
    RayContext r1, r2;
    r1.D = {1, 0, 0};
    r2.D = {3, 0, 0};
    ev.setRay(r1);
    EXPECT_EQ(ev.eval(*p->variable("v")), 2);
    ev.setRay(r2);
    EXPECT_EQ(ev.eval(*p->variable("v")), 6);
}

}  // namespace
}  // namespace rp::calc

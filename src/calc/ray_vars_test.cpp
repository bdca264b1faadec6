// Every predefined ray variable and modifier argument reaches a .cal function, and the
// evaluator can be shared by threads each with their own Evaluator.
#include <gtest/gtest.h>

#include <thread>

#include "calc/calc_test_util.h"

namespace rp::calc {
namespace {

RayContext distinctRay(std::span<const double> args) {
    RayContext r;
    r.D = {1, 2, 3};
    r.N = {4, 5, 6};
    r.P = {7, 8, 9};
    r.Lu = 10;
    r.Lv = 11;
    r.T = 12;
    r.Ts = 13;
    r.Rdot = 14;
    r.S = 15;
    r.Tvec = {16, 17, 18};
    r.I = {19, 20, 21};
    r.J = {22, 23, 24};
    r.K = {25, 26, 27};
    r.NP = {28, 29, 30};
    r.RdotP = 31;
    r.CP = {32, 33, 34};
    r.DA = {35, 36, 37};
    r.args = args;
    return r;
}

TEST(CalcRayVars, EachVariableReachesAFunction) {
    const char* names[] = {"Dx",    "Dy",  "Dz",  "Nx",   "Ny",  "Nz",  "Px", "Py",  "Pz",  "Lu",
                           "Lv",    "T",   "Ts",  "Rdot", "S",   "Tx",  "Ty", "Tz",  "Ix",  "Iy",
                           "Iz",    "Jx",  "Jy",  "Jz",   "Kx",  "Ky",  "Kz", "NxP", "NyP", "NzP",
                           "RdotP", "CrP", "CgP", "CbP",  "DxA", "DyA", "DzA"};
    ASSERT_EQ(rayVariables().size(), std::size(names));
    double args[] = {101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111};
    RayContext ray = distinctRay(args);
    Builder b({testing::libDir()});
    b.loadFile("rayinit.cal");
    b.loadString("pass(x) = x*1;");
    std::vector<int> ids;
    for (const char* n : names)
        ids.push_back(b.addExpression(std::string("pass(") + n + ")", SourceLoc{"t", 1}));
    std::vector<int> argIds;
    for (int i = 1; i <= 10; ++i)
        argIds.push_back(b.addExpression("pass(A" + std::to_string(i) + ")", SourceLoc{"t", 1}));
    int ac = b.addExpression("pass(AC) + arg(0)", SourceLoc{"t", 1});
    int dyn = b.addExpression("arg(Dx + 10)", SourceLoc{"t", 1});
    int vec = b.addExpression("dot(D, N) + P(3)", SourceLoc{"t", 1});
    auto p = b.build();
    Evaluator ev(p);
    ev.setRay(ray);
    for (std::size_t i = 0; i < ids.size(); ++i)
        EXPECT_EQ(ev.eval(p->expression(ids[i])), static_cast<double>(i + 1)) << names[i];
    for (int i = 0; i < 10; ++i) EXPECT_EQ(ev.eval(p->expression(argIds[i])), 101 + i);
    EXPECT_EQ(ev.eval(p->expression(ac)), 22);
    EXPECT_EQ(ev.eval(p->expression(dyn)), 111);
    EXPECT_EQ(ev.eval(p->expression(vec)), 1 * 4 + 2 * 5 + 3 * 6 + 9);
}

TEST(CalcRayVars, LocalUVOnPlane) {
    RayContext ray;
    ray.N = {0, 0, 1};  // horizontal plane: U = Px, V = Py
    ray.P = {2, 3, 0};
    EXPECT_EQ(testing::evalWith("", "U*10 + V", true, &ray), 23);
}

TEST(CalcRayVars, ThreadsShareOneProgram) {
    Builder b({testing::libDir()});
    b.loadFile("rayinit.cal");
    b.loadString("g = sq(Dx) + A1; h(n) = if(n - .5, h(n - 1) + g, 0);");
    int id = b.addExpression("h(20)", SourceLoc{"t", 1});
    auto p = b.build();
    std::vector<double> results(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            Evaluator ev(p);
            double args[] = {static_cast<double>(t)};
            double sum = 0;
            for (int i = 0; i < 2000; ++i) {
                RayContext ray;
                ray.D = {static_cast<double>(t), 0, 0};
                ray.args = args;
                ev.setRay(ray);
                sum += ev.eval(p->expression(id));
            }
            results[t] = sum;
        });
    }
    for (auto& th : threads) th.join();
    for (int t = 0; t < 4; ++t) EXPECT_EQ(results[t], 2000.0 * 20 * (t * t + t));
}

}  // namespace
}  // namespace rp::calc

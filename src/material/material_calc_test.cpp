// Function-driven materials: plastic2's u orientation through the record's transform,
// plasfunc/metfunc/transfunc/plasdata specular functions and BRTDfunc's colours and
// directional-diffuse functions weighted as m_brdf.c does, prism1/prism2 redirections
// (DxA DyA DzA, the transform), and errors at the record.
#include "material/material_calc.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <optional>

#include "material/material.h"
#include "scene/reader.h"
#include "util/temp_dir_for_tests.h"

namespace rp::material {

namespace {

constexpr double kEps = 1e-12;

int32_t indexOf(const Scene& s, const std::string& name) {
    for (size_t i = s.prims.size(); i-- > 0;)
        if (s.prims[i].name == name) return int32_t(i);
    return -2;
}

struct Fixture {
    TempDir dir;
    std::unique_ptr<Scene> scene;
    std::unique_ptr<MaterialCalc> calc;
    std::unique_ptr<MaterialCalcEvaluator> eval;
    BoundHit bound;  // the hit set last (hit())

    void write(const std::string& name, const std::string& text) {
        std::ofstream((dir.path() / name).string()) << text;
    }
    void load(const std::string& text) {
        scene = std::make_unique<Scene>(parseScene(text, "c.rad"));
        calc = std::make_unique<MaterialCalc>(
            *scene,
            std::vector<std::string>{dir.path().string(), std::string(RP_SOURCE_DIR) + "/lib"});
        eval = std::make_unique<MaterialCalcEvaluator>(*calc);
    }
    // A hit on the plane z = 0 (normal +z); `shading` is the perturbed normal on the
    // ray's side (the plain one when not given).
    int32_t hit(const std::string& name, const Vec3& dir = {0, 0, -1},
                std::optional<Vec3> shading = std::nullopt, Color pattern = {1, 1, 1},
                const TransformPair* object = nullptr) {
        int32_t m = indexOf(*scene, name);
        PatternPoint at;
        at.object = object;
        at.dir = dir;
        at.point = {0.5, 0.25, 0};
        at.normal = {0, 0, 1};
        at.distance = 2;
        at.rdot = -dot(dir, at.normal);
        Vec3 n = shading ? *shading : at.rdot < 0 ? -at.normal : at.normal;
        eval->setHit(m, at, n, pattern);
        bound = eval->bound();
        return m;
    }
    MaterialParams params(int32_t m) { return makeMaterial(scene->prims[m]); }
    SurfacePoint point(const Vec3& dir = {0, 0, -1}) {
        SurfacePoint sp = makeSurfacePoint(dir, {0, 0, 1}, true);
        sp.directional = &bound;
        return sp;
    }
};

void expectColor(const Color& got, const Color& want, double tol = kEps) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tol) << "channel " << c;
}

Vec3 lightAt(double thetaDeg) {
    double t = thetaDeg * kPi / 180;
    return {0, std::sin(t), std::cos(t)};
}

}  // namespace

TEST(MaterialCalcFunc, PlasfuncConstantAddsWhiteSpecularTimesCosine) {
    Fixture f;
    f.write("f.cal", "refl(lx, ly, lz, om) = 0.3;\n");
    f.load("void plasfunc pf\n2 refl f.cal\n0\n4 .5 .4 .3 .2\n");
    int32_t m = f.hit("pf");
    EXPECT_TRUE(f.calc->uses(m));
    MaterialParams p = f.params(m);
    Vec3 l = lightAt(40);
    double ldot = l.z;
    SurfacePoint plain = makeSurfacePoint({0, 0, -1}, {0, 0, 1}, true);
    Color lambert = Color{.5, .4, .3} * (0.8 * ldot / kPi);
    expectColor(evaluate(p, plain, l), lambert);  // unchanged without the function
    // m_brdf.c: + white * f * cos * specularity for plasfunc.
    expectColor(evaluate(p, f.point(), l), lambert + Color::grey(0.3 * ldot * 0.2));
}

TEST(MaterialCalcFunc, MetfuncSpecularIsColouredAndVariableNamesWork) {
    Fixture f;
    f.write("f.cal", "refl = 0.5;\n");  // RADIANCE's funvalue accepts a variable
    f.load("void metfunc mf\n2 refl f.cal\n0\n4 .5 .4 .3 .6\n");
    int32_t m = f.hit("mf");
    Vec3 l = lightAt(20);
    Color lambert = Color{.5, .4, .3} * (0.4 * l.z / kPi);
    expectColor(evaluate(f.params(m), f.point(), l),
                lambert + Color{.5, .4, .3} * (0.5 * l.z * 0.6));
}

TEST(MaterialCalcFunc, FunctionSeesLightDirectionInFunctionSpace) {
    Fixture f;
    f.write("f.cal", "refl(lx, ly, lz, om) = lx;\n");
    // -rz 90: world +y is function-space +x.
    f.load("void plasfunc pf\n4 refl f.cal -rz 90\n0\n4 .5 .5 .5 .1\n");
    int32_t m = f.hit("pf");
    Vec3 l = lightAt(30);
    Color v = f.eval->directional(l);
    EXPECT_NEAR(v.r, std::sin(30 * kPi / 180), 1e-9);
    Color lambert = Color::grey(.5 * 0.9 * l.z / kPi);
    expectColor(evaluate(f.params(m), f.point(), l), lambert + Color::grey(v.r * l.z * 0.1), 1e-9);
    // A light on the other side of the function's x axis gives a negative value: no specular.
    expectColor(evaluate(f.params(m), f.point(), {0, -l.y, l.z}), lambert, 1e-9);
}

TEST(MaterialCalcFunc, MathErrorDropsTheSpecularPart) {
    Fixture f;
    f.write("f.cal", "refl(lx, ly, lz, om) = 1 / (lx - lx) + 1;\n");
    f.load(
        "void plasfunc pf\n2 refl f.cal\n0\n4 .5 .5 .5 .2\n"
        "void plastic2 a\n4 1/(Px-Px) 0 1 .\n0\n6 .5 .5 .5 .05 .1 .2\n");
    int32_t m = f.hit("pf");
    Vec3 l = lightAt(40);
    expectColor(f.eval->directional(l), {});  // m_brdf.c: "compute error", no specular
    expectColor(evaluate(f.params(m), f.point(), l), Color::grey(.5 * .8 * l.z / kPi));
    f.hit("a");
    Vec3 u = f.eval->anisoU();  // aniso.c punts to an isotropic frame
    EXPECT_EQ(length(u), 0);
}

TEST(MaterialCalcFunc, TransfuncTransmitsColouredSpecular) {
    Fixture f;
    f.write("f.cal", "brdf(lx, ly, lz, om) = 2;\n");
    f.load("void transfunc tf\n2 brdf f.cal\n0\n6 .5 .4 .3 .1 .5 .4\n");
    int32_t m = f.hit("tf");
    Vec3 l = {0, 0.6, -0.8};  // light behind the surface
    // trans = .5*.9 = .45, tspec = .18, tdiff = .27
    Color c = Color{.5, .4, .3};
    expectColor(evaluate(f.params(m), f.point(), l), c * (0.27 * 0.8 / kPi) + c * (2 * 0.8 * 0.18));
}

TEST(MaterialCalcFunc, PlasdataLooksUpTheDataFile) {
    Fixture f;
    f.write("d.dat", "1\n0 1 3\n0 0.5 1\n");
    f.write("f.cal", "cz(lx, ly, lz, om) = lz;\nd(v, lx, ly, lz, om) = 2 * v;\n");
    f.load("void plasdata pd\n4 d d.dat f.cal cz\n0\n4 .5 .5 .5 .2\n");
    int32_t m = f.hit("pd");
    Vec3 l = lightAt(60);
    EXPECT_NEAR(f.eval->directional(l).g, 2 * l.z, 1e-9);
    expectColor(evaluate(f.params(m), f.point(), l),
                Color::grey(.5 * .8 * l.z / kPi + 2 * l.z * l.z * .2), 1e-9);
}

TEST(MaterialCalcBrtd, SpecularColoursFromConstantsAndExpressions) {
    Fixture f;
    f.write("f.cal", "rr = 0.25;\ntt = 0.1 + 0 * Dz;\n");
    f.load(
        "void BRTDfunc b\n10 0.5 rr 0.5 0 0 tt 0 0 0 f.cal\n0\n9 .1 .1 .1 .2 .2 .2 0 0 0\n"
        "void BRTDfunc k\n10 0.5 0.5 0.5 0 0 0 0 0 0 .\n0\n9 .1 .1 .1 .2 .2 .2 0 0 0\n");
    int32_t m = f.hit("b");
    EXPECT_TRUE(f.calc->uses(m));
    EXPECT_FALSE(f.calc->uses(indexOf(*f.scene, "k")));  // constants only: params.cpp has them
    Color refl, trans;
    f.eval->brtdSpecular(refl, trans);
    expectColor(refl, {0.5, 0.25, 0.5});
    expectColor(trans, {0, 0, 0.1});
}

// m_brdf.c setbrdfunc: NxP NyP NzP the perturbed normal on the ray's side (through the
// function transform), RdotP its cosine with the ray (clamped), CrP CgP CbP the material
// colour times the pattern (*func) or the pattern alone (BRTDfunc); on the back, m_brdf2
// also turns N and Rdot to the ray, BRTDfunc does not.
struct PerturbedValues {
    double nx, ny, nz, rdotp, cr, cg, cb, n, r;
};

PerturbedValues perturbedValues(Fixture& f, const std::string& type, const std::string& transform,
                                const Vec3& dir, const Vec3& shading, const Color& pattern) {
    const char* vars[] = {"NxP", "NyP", "NzP", "RdotP", "CrP", "CgP", "CbP", "Nz", "Rdot"};
    std::string cal, rad;
    for (int k = 0; k < 9; ++k) {
        std::string fn = "f" + std::to_string(k);
        cal += fn + "(lx, ly, lz, om) = " + vars[k] + ";\n";
        if (type == "plasfunc")
            rad += "void plasfunc m" + std::to_string(k) + "\n" +
                   std::to_string(2 + (transform.empty() ? 0 : 2)) + " " + fn + " p.cal " +
                   transform + "\n0\n4 .5 .4 .3 .2\n";
        else
            rad += "void BRTDfunc m" + std::to_string(k) + "\n" +
                   std::to_string(10 + (transform.empty() ? 0 : 2)) + " 0 0 0 0 0 0 " + fn + " " +
                   fn + " " + fn + " p.cal " + transform + "\n0\n9 .1 .1 .1 .1 .1 .1 0 0 0\n";
    }
    f.write("p.cal", cal);
    f.load(rad);
    double v[9];
    for (int k = 0; k < 9; ++k) {
        f.hit("m" + std::to_string(k), dir, shading, pattern);
        v[k] = f.eval->directional({0, 0, 1}).r;
    }
    return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]};
}

TEST(MaterialCalcFunc, PerturbedVariablesOfFuncMaterials) {
    Fixture f;
    Vec3 pert = normalize(Vec3{0.6, 0, 0.8});
    Vec3 d = normalize(Vec3{0, 0.6, -0.8});
    // -rz 90 takes world x to function-space -y... through the inverse: (x,y) -> (y,-x).
    PerturbedValues v = perturbedValues(f, "plasfunc", "-rz 90", d, pert, {2, 1, 0.5});
    EXPECT_NEAR(v.nx, 0, kEps);
    EXPECT_NEAR(v.ny, -0.6, kEps);
    EXPECT_NEAR(v.nz, 0.8, kEps);
    EXPECT_NEAR(v.rdotp, -dot(d, pert), kEps);
    EXPECT_NEAR(v.cr, 0.5 * 2, kEps);  // material colour .5 .4 .3 times the pattern
    EXPECT_NEAR(v.cg, 0.4 * 1, kEps);
    EXPECT_NEAR(v.cb, 0.3 * 0.5, kEps);
    // From the back: the shading normal faces the ray; m_brdf2 reverses N and Rdot too.
    Vec3 up = normalize(Vec3{0, 0.6, 0.8});
    PerturbedValues b = perturbedValues(f, "plasfunc", "", up, {0, 0, -1}, {1, 1, 1});
    EXPECT_NEAR(b.nz, -1, kEps);
    EXPECT_NEAR(b.rdotp, 0.8, kEps);
    EXPECT_NEAR(b.n, -1, kEps);
    EXPECT_NEAR(b.r, 0.8, kEps);
}

TEST(MaterialCalcBrtd, PerturbedVariablesOfBrtdfunc) {
    Fixture f;
    Vec3 up = normalize(Vec3{0, 0.6, 0.8});
    PerturbedValues b = perturbedValues(f, "BRTDfunc", "", up, {0, 0, -1}, {0.5, 0.25, 2});
    EXPECT_NEAR(b.nz, -1, kEps);  // flipped to the ray's side
    EXPECT_NEAR(b.rdotp, 0.8, kEps);
    EXPECT_NEAR(b.n, 1, kEps);  // but N and Rdot stay as the surface has them
    EXPECT_NEAR(b.r, -0.8, kEps);
    EXPECT_NEAR(b.cr, 0.5, kEps);  // the pattern alone
    EXPECT_NEAR(b.cg, 0.25, kEps);
    EXPECT_NEAR(b.cb, 2, kEps);
}

// RADIANCE's rayinit.cal frame functions on top of them (Idz is RdotP; Ldz projects on NP).
TEST(MaterialCalcFunc, RayinitFrameFunctions) {
    Fixture f;
    f.write("p.cal",
            "fz(lx, ly, lz, om) = Idz;\nfl(lx, ly, lz, om) = Ldz(lx, ly, lz) + 10*Ldx(1, 0, 0);\n");
    f.load(
        "void plasfunc a\n2 fz p.cal\n0\n7 .5 .5 .5 .1 0 1 0\n"
        "void plasfunc b\n2 fl p.cal\n0\n7 .5 .5 .5 .1 0 1 0\n");
    Vec3 d = normalize(Vec3{0.3, 0, -1});
    f.hit("a", d);
    EXPECT_NEAR(f.eval->directional({0, 0, 1}).r, -d.z, kEps);
    f.hit("b", d);
    // up (0,1,0): Vn = up x N = (1,0,0), Un = Vn x N... = N x Vn ordering of rayinit:
    // Un = (Ny*Vnz - Nz*Vny, Nz*Vnx - Nx*Vnz, Nx*Vny - Ny*Vnx) = (0, 1, 0); Ldx(1,0,0) = 0.
    EXPECT_NEAR(f.eval->directional({0, 0, 1}).r, 1, kEps);
}

TEST(MaterialCalcBrtd, DirectionalDiffuseFunctionOfLightDirection) {
    Fixture f;
    f.write("f.cal", "br(lx, ly, lz, om) = lz * lz;\nbb(lx, ly, lz, om) = 0.5 * A10;\n");
    f.load("void BRTDfunc b\n10 0 0 0 0 0 0 br br bb f.cal\n0\n10 .2 .2 .2 0 0 0 .1 .1 .1 3\n");
    int32_t m = f.hit("b");
    MaterialParams p = f.params(m);
    Vec3 l = lightAt(50);
    double c = l.z;
    // m_brdf.c: brtd colour times |cos|, not patterned, plus the front diffuse.
    SurfacePoint sp = f.point();
    sp.pattern = {1, 0.5, 1};
    Color diffuse = Color{.2, .1, .2} * (c / kPi);
    expectColor(evaluate(p, sp, l), diffuse + Color{c * c, c * c, 1.5} * c, 1e-9);
    // Transmission side: the transmitted diffuse plus the function's value at the light.
    Vec3 lb = {0, l.y, -l.z};
    expectColor(evaluate(p, sp, lb), Color{.1, .05, .1} * (c / kPi) + Color{c * c, c * c, 1.5} * c,
                1e-9);
    // RADIANCE compat: a brtd colour of brightness <= FTINY adds nothing at all.
    f.write("g.cal", "n(lx, ly, lz, om) = -1;\np(lx, ly, lz, om) = 1;\n");
    f.load("void BRTDfunc b\n10 0 0 0 0 0 0 n n p g.cal\n0\n9 .2 .2 .2 0 0 0 0 0 0\n");
    p = f.params(f.hit("b"));
    expectColor(evaluate(p, f.point(), l), Color::grey(.2 * c / kPi), 1e-9);
}

TEST(MaterialCalcAniso, UOrientationRotatesWithTheTransform) {
    Fixture f;
    f.load(
        "void plastic2 a\n4 1 0 0 .\n0\n6 .5 .5 .5 .05 .1 .2\n"
        "void plastic2 r\n6 1 0 0 . -rz 90\n0\n6 .5 .5 .5 .05 .1 .2\n"
        "void metal2 e\n4 Px 0 1 .\n0\n6 .5 .5 .5 .05 .1 .2\n");
    f.hit("a");
    Vec3 u = f.eval->anisoU();
    EXPECT_NEAR(u.x, 1, kEps);
    EXPECT_NEAR(u.y, 0, kEps);
    f.hit("r");
    u = f.eval->anisoU();
    EXPECT_NEAR(u.x, 0, 1e-12);
    EXPECT_NEAR(u.y, 1, 1e-12);
    EXPECT_NEAR(u.z, 0, 1e-12);
    f.hit("e");  // the hit point is (0.5, 0.25, 0): u = (0.5, 0, 1) normalised
    u = f.eval->anisoU();
    EXPECT_NEAR(u.x, 0.5 / std::sqrt(1.25), 1e-12);
    EXPECT_NEAR(u.z, 1 / std::sqrt(1.25), 1e-12);
}

TEST(MaterialCalcErrors, NameTheRecordsFileAndLine) {
    auto expectError = [](const std::string& scene, int line, const std::string& what,
                          const std::string& cal = "") {
        Fixture f;
        if (!cal.empty()) f.write("f.cal", cal);
        try {
            f.load(scene);
            ADD_FAILURE() << "no error for " << what;
        } catch (const InputError& e) {
            EXPECT_EQ(e.loc().line, line) << e.what();
            EXPECT_EQ(e.loc().file, "c.rad") << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    std::string lead = "void plastic p\n0\n0\n5 .5 .5 .5 0 0\n";  // lines 1-4
    expectError(lead + "void plasfunc pf\n2 refl nosuch.cal\n0\n4 .5 .5 .5 .2\n", 5, "nosuch.cal");
    expectError(lead + "void plasfunc pf\n2 nofunc f.cal\n0\n4 .5 .5 .5 .2\n", 5,
                "unknown function 'nofunc'", "refl(a, b, c, d) = 1;\n");
    expectError(lead + "void BRTDfunc b\n10 0 0 0 0 0 0 br br nob f.cal\n0\n9 0 0 0 0 0 0 0 0 0\n",
                5, "unknown function 'nob'", "br(a, b, c, d) = 1;\n");
    expectError(lead + "void plasdata pd\n4 d none.dat . cz\n0\n4 .5 .5 .5 .2\n", 5, "none.dat");
    expectError(lead + "void plastic2 a\n5 1 0 0 . -rz\n0\n6 .5 .5 .5 .05 .1 .2\n", 5, "");
}

TEST(MaterialCalc, PrismRedirectionsSeeDxAAndTheTransform) {
    Fixture f;
    // Function space is world turned by -rz 90: world +y is function +x. Redirection 1
    // is the ray direction itself; redirection 2 turns it to function +x (world +y),
    // with the coefficient telling DxA (world +x is function -y) from none.
    f.write("p.cal",
            "c1 = A1; x1 = Dx; y1 = Dy; z1 = Dz;\n"
            "c2 = if(DyA*DyA - .5, -DyA, A2); x2 = 2; y2 = 0; z2 = 0;\n");
    f.load("void prism2 p 11 c1 x1 y1 z1 c2 x2 y2 z2 p.cal -rz 90 0 2 .7 .3\n");
    const Vec3 d = normalize(Vec3{0.3, 0.4, -1});
    f.hit("p", d);
    Redirection r1 = f.eval->redirect(0, {});
    ASSERT_TRUE(r1.ok);
    EXPECT_NEAR(r1.coef, 0.7, kEps);
    EXPECT_NEAR(length(r1.dir - d), 0, 1e-9);
    Redirection r2 = f.eval->redirect(1, {});
    ASSERT_TRUE(r2.ok);
    EXPECT_NEAR(r2.coef, 0.3, kEps);
    EXPECT_NEAR(length(r2.dir - Vec3{0, 1, 0}), 0, 1e-9);       // made unit, back in world
    EXPECT_NEAR(f.eval->redirect(1, {1, 0, 0}).coef, 1, kEps);  // DyA = -1
}

// Inside an instance (object space turned by +90 degrees about z: object +x is world +y)
// the prism's functions see DxA in object space and their directions come back through
// the object's rotation (m_direct.c, RADIANCE ray.rox).
TEST(MaterialCalc, PrismRedirectionsInsideAnInstance) {
    Fixture f;
    f.write("p.cal", "c1 = if(DyA*DyA - .5, -DyA, A1); x1 = 2; y1 = 0; z1 = 0;\n");
    f.load("void prism1 p 5 c1 x1 y1 z1 p.cal 0 1 .3\n");
    const TransformPair object = TransformPair::of(Transform::rotateZ(90));
    f.hit("p", normalize(Vec3{0.3, 0.4, -1}), std::nullopt, {1, 1, 1}, &object);
    Redirection r = f.eval->redirect(0, {1, 0, 0});  // world +x is object -y: DyA = -1
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.coef, 1, kEps);
    EXPECT_NEAR(length(r.dir - Vec3{0, 1, 0}), 0, 1e-9);  // object +x, world +y
    f.hit("p", normalize(Vec3{0.3, 0.4, -1}));            // world space: DyA = 0
    EXPECT_NEAR(f.eval->redirect(0, {1, 0, 0}).coef, 0.3, kEps);
    EXPECT_NEAR(length(f.eval->redirect(0, {1, 0, 0}).dir - Vec3{1, 0, 0}), 0, 1e-9);
}

TEST(MaterialCalc, PrismErrorsAtTheRecord) {
    Fixture f;
    try {
        f.load("\nvoid prism1 p 5 coef dx dy dz nofile.cal 0 0\n");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("c.rad:2: prism1 'p'"), std::string::npos) << e.what();
    }
    // An undefined name is reported when first evaluated, at the record's line, as the
    // calc module does for every material (RADIANCE reports it at evaluation too).
    f.load("void prism1 p 5 nocoef dx dy dz . 0 0\n");
    f.hit("p");
    try {
        f.eval->redirect(0, {});
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("c.rad:1: undefined variable 'nocoef'"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace rp::material

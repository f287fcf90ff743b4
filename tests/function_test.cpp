// User-defined functions (scene/function.h, lang/function_syntax.cpp): their
// values against closed forms and against POV-Ray 3.7's own values of the
// internal functions (printed by `povray` with #debug), calls at parse time,
// function patterns, the isosurface against the analytic sphere, function
// height fields, and the located errors.
#include "accel/isosurface_shape.h"
#include "accel/shapes.h"
#include "lang/load.h"
#include "pov/load.h"
#include "render/pigment.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drt {
namespace {

std::unique_ptr<test::SceneRun> run(const std::string& text, bool pov = true) {
    return test::readSceneText(text, pov);
}

// The value of a float expression after `declarations`, printed with 9 decimals.
double value(const std::string& declarations, const std::string& expression, bool pov = true) {
    auto r = run(declarations + "\n#warning str(" + expression + ", 0, 9)\n", pov);
    EXPECT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    return r->messages.empty() ? NAN : std::stod(r->messages[0]);
}

// The first error of a scene: "line:column: message".
std::string firstError(const std::string& text, bool pov = false) {
    auto r = run(text, pov);
    EXPECT_FALSE(r->scene);
    for (const Diagnostic& d : r->diags.all())
        if (d.severity == Severity::Error)
            return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message;
    return "<no error>";
}

TEST(Function, ExpressionsOfTheParametersAgreeWithClosedForms) {
    const std::string f = "#declare F = function { x * x + 2 * y - z / 4 }\n"
                          "#declare G = function(a, b) { pow(a, b) + select(a - 2, -1, 0, 1) + (a > b ? 10 : 20) }\n"
                          "#declare H = function { min(x, y, z) * max(x, 3) + mod(x, 2) + abs(-z) + sqrt(y) }\n";
    EXPECT_DOUBLE_EQ(value(f, "F(1, 2, 3)"), 1 + 4 - 0.75);
    EXPECT_DOUBLE_EQ(value(f, "F(-2, 0.5, -8)"), 4 + 1 + 2);
    EXPECT_DOUBLE_EQ(value(f, "G(2, 3)"), 8 + 0 + 20);
    EXPECT_DOUBLE_EQ(value(f, "G(3, 2)"), 9 + 1 + 10);
    EXPECT_DOUBLE_EQ(value(f, "G(1, 2)"), 1 - 1 + 20);
    EXPECT_DOUBLE_EQ(value(f, "H(5, 4, 1)"), 1 * 5 + 1 + 1 + 2);
    // Both dialects read the same functions.
    EXPECT_DOUBLE_EQ(value(f, "F(1, 2, 3)", false), 1 + 4 - 0.75);
}

TEST(Function, CallsOtherFunctionsAndReadsDeclaredNumbersAsConstants) {
    const std::string f = "#declare R = 2;\n"
                          "#declare V = <1, 5, 9>;\n"
                          "#declare Sq = function(t) { t * t }\n"
                          "#declare Len = function { sqrt(Sq(x) + Sq(y) + Sq(z)) - R + V.y }\n"
                          "#declare R = 100;\n"; // a later value does not change Len
    EXPECT_DOUBLE_EQ(value(f, "Len(3, 4, 12)"), 13 - 2 + 5);
    EXPECT_DOUBLE_EQ(value(f, "Len(0, 0, 0) * 2"), 6);
}

TEST(Function, MathIncFunctionsAndMacrosWork) {
    const std::string inc = "#include \"math.inc\"\n";
    EXPECT_DOUBLE_EQ(value(inc, "f_sqr(7)"), 49);
    EXPECT_DOUBLE_EQ(value(inc, "sgn(-3) + 10 * sgn(4)"), 9);
    EXPECT_DOUBLE_EQ(value(inc, "max3(1, 7, 3)"), 7);
    EXPECT_NEAR(value(inc, "sind(30)"), 0.5, 1e-9);
    EXPECT_DOUBLE_EQ(value(inc, "adj_range2(5, 0, 10, 100, 200)"), 150);
    EXPECT_DOUBLE_EQ(value(inc, "even(4) + 2 * odd(3)"), 3);
    // vGradient: a macro that calls a function passed as its argument.
    EXPECT_NEAR(value(inc + "#declare P = function { x * x + 3 * y }\n", "vlength(vGradient(P, <2, 0, 0>) - <4, 3, 0>)"),
                0, 1e-4);
}

// POV-Ray 3.7's values, printed by `povray` with #debug str(f(...), 0, 9).
TEST(Function, InternalFunctionsAgreeWithPovRay) {
    const std::string inc = "#include \"functions.inc\"\n";
    EXPECT_NEAR(value(inc, "f_r(1, 2, 3)"), 3.741657387, 1e-9);
    EXPECT_NEAR(value(inc, "f_th(1, 2, 3)"), 0.321750554, 1e-9);
    EXPECT_NEAR(value(inc, "f_th(-1, 2, -3)"), -2.819842099, 1e-9);
    EXPECT_NEAR(value(inc, "f_ph(1, 2, 3)"), 1.006853685, 1e-9);
    EXPECT_NEAR(value(inc, "f_ph(1, -2, 3)"), 2.134738968, 1e-9);
    EXPECT_NEAR(value(inc, "f_sphere(1, 2, 3, 0.5)"), 3.241657387, 1e-9);
    EXPECT_NEAR(value(inc, "f_rounded_box(1.2, 0.3, 0.1, 0.1, 1, 0.5, 0.5)"), 0.199999, 1e-9);
    EXPECT_NEAR(value(inc, "f_rounded_box(1.05, 0.48, 0.1, 0.1, 1, 0.5, 0.5)"), 0.069999, 1e-9);
    EXPECT_NEAR(value(inc, "f_rounded_box(0.2, 0.1, 0.1, 0.1, 1, 0.5, 0.5)"), -0.100001, 1e-9);
    EXPECT_NEAR(value(inc, "f_torus(1, 2, 3, 1.5, 0.3)"), 2.300608971, 1e-9);
    EXPECT_NEAR(value(inc, "f_superellipsoid(0.3, 0.4, 0.5, 0.5, 0.8)"), 0.384728261, 1e-9);
    // Without functions.inc the internal functions are known by name too.
    EXPECT_NEAR(value("", "f_sphere(1, 2, 3, 0.5)"), 3.241657387, 1e-9);
    EXPECT_NEAR(value("#declare F = function { f_torus(x, y, z, 1.5, 0.3) }", "F(1, 2, 3)", false), 2.300608971,
                1e-9);
    // Noise is drt's own: in [0, 1], 0.5 on the lattice, f_snoise3d = 2 f_noise3d - 1.
    EXPECT_DOUBLE_EQ(value(inc, "f_noise3d(1, 2, 3)"), 0.5);
    const double n = value(inc, "f_noise3d(0.3, 0.4, 0.5)");
    EXPECT_GT(n, 0);
    EXPECT_LT(n, 1);
    EXPECT_NEAR(value(inc, "f_snoise3d(0.3, 0.4, 0.5)"), 2 * n - 1, 1e-9);
}

TEST(Function, PatternAndPigmentFunctionsGiveThePatternsValues) {
    const std::string f = "#declare G = function { pattern { gradient x } }\n"
                          "#declare P = function { pigment { gradient x color_map { [0 rgb <0, 1, 0>] [1 rgb <1, 0, 0.5>] } } }\n"
                          "#declare C = function { pattern { checker } }\n";
    EXPECT_NEAR(value(f, "G(0.25, 7, 7)"), 0.25, 1e-9);
    EXPECT_NEAR(value(f, "P(0.25, 0, 0).red"), 0.25, 1e-9);
    EXPECT_NEAR(value(f, "P(0.25, 0, 0).green"), 0.75, 1e-9);
    EXPECT_NEAR(value(f, "C(0.5, 0.5, 0.5) + C(1.5, 0.5, 0.5)"), 1, 1e-9);
    // In a function: a channel of a colour function, and drt's inline pattern call.
    EXPECT_NEAR(value(f + "#declare Q = function { P(x, y, z).blue * 2 + pattern { gradient y }(y, x, z) }\n",
                      "Q(0.5, 0.1, 0)"),
                0.5 + 0.5, 1e-9);
}

TEST(Function, NeverGivesNaN) {
    const std::string f = "#declare F = function { sqrt(x) + ln(y) }\n";
    auto r = run(f + "#declare G = function { F(x, y, z) / z }\n");
    ASSERT_FALSE(r->diags.hasErrors()) << r->diags.formatAll();
    auto scene = run(f + "sphere { 0, 1 pigment { function { F(x, y, z) / z } } }\n");
    ASSERT_TRUE(scene->scene) << scene->diags.formatAll();
    const Pigment& p = scene->scene->objects[0].texture->pigment;
    ASSERT_EQ(p.pattern, PatternKind::Function);
    const double bad[][3] = {{-1, 1, 1}, {1, -1, 1}, {1, 1, 0}, {0, 0, 0}};
    for (const auto& a : bad) {
        const double v = (*p.function)(a);
        EXPECT_TRUE(std::isfinite(v)) << a[0] << " " << a[1] << " " << a[2];
    }
}

TEST(Function, FunctionPatternsColourPigmentsTexturesAndNormals) {
    auto r = run("sphere { 0, 1 pigment { function { abs(x) } color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } } }\n"
                 "sphere { 0, 1 texture { function { y } texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }\n"
                 "sphere { 0, 1 normal { function { sin(x * 10) } 0.5 } }\n",
                 false);
    ASSERT_TRUE(r->scene) << r->diags.formatAll();
    const ColorFT c = evaluatePigment(r->scene->objects[0].texture->pigment, Vec3(-0.4, 0, 0));
    EXPECT_NEAR(c.rgb.r, 0.4, 1e-9);
    EXPECT_NEAR(c.rgb.g, 0.2, 1e-9);
    const Texture& t = r->scene->objects[1].texture;
    ASSERT_EQ(t.map.size(), 2u);
    EXPECT_EQ(t.pigment.pattern, PatternKind::Function);
    EXPECT_NEAR(samplePattern(t.pigment, Vec3(0, 0.3, 0)).value, 0.3, 1e-9);
    ASSERT_TRUE(r->scene->objects[2].texture->normal);
    EXPECT_EQ(r->scene->objects[2].texture->normal->pattern, PatternKind::Function);
}

TEST(Function, HeightFieldSamplesTheFunctionAsPovRayDoes) {
    // POV-Ray: height_field { function 11, 11 { y } } is 1 at z = 0 and 0 at z = 1;
    // { x } rises along x (measured with trace() in POV-Ray 3.7).
    auto r = run("height_field { function 3, 5 { y * 0.5 + x * 0.25 } }\n");
    ASSERT_TRUE(r->scene) << r->diags.formatAll();
    const Mesh* m = std::get_if<Mesh>(&r->scene->objects[0].shape);
    ASSERT_TRUE(m);
    ASSERT_EQ(m->vertices.size(), 15u);
    for (const Vec3& v : m->vertices) EXPECT_NEAR(v.y, (1 - v.z) * 0.5 + v.x * 0.25, 1e-12);
    EXPECT_EQ(m->triangles.size(), 2u * 2 * 4);
}

// The isosurface of x^2 + y^2 + z^2 - 1 is the unit sphere.
TEST(Isosurface, CrossingsOfTheUnitSphereFunctionMatchTheAnalyticSphere) {
    auto r = run("isosurface { function { x * x + y * y + z * z - 1 } contained_by { box { -2, 2 } } max_gradient 4 }\n",
                 false);
    ASSERT_TRUE(r->scene) << r->diags.formatAll();
    const accel::AnalyticShape iso = *accel::prepareShape(r->scene->objects[0].shape);
    const accel::AnalyticShape sphere = *accel::prepareShape(Sphere{Vec3(0), 1});
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.9, 0.9);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 o = Vec3(u(rng), u(rng), -5);
        const Vec3 d = normalize(Vec3(u(rng) * 0.1, u(rng) * 0.1, 1));
        accel::Crossing a[accel::kMaxCrossings], b[accel::kMaxCrossings];
        const int na = accel::intersectShape(iso, o, d, a), nb = accel::intersectShape(sphere, o, d, b);
        ASSERT_EQ(na, nb) << i;
        for (int k = 0; k < na; ++k) {
            EXPECT_NEAR(a[k].t, b[k].t, 1e-6);
            EXPECT_GT(dot(normalize(a[k].normal), normalize(b[k].normal)), 1 - 1e-6);
            ++hits;
        }
        accel::Crossing first;
        if (nb > 0) {
            ASSERT_TRUE(accel::firstCrossing(iso, o, d, 0, INFINITY, first));
            EXPECT_NEAR(first.t, b[0].t, 1e-6);
        }
    }
    EXPECT_GT(hits, 100);
    EXPECT_TRUE(accel::insideShape(iso, Vec3(0.5, 0, 0)));
    EXPECT_FALSE(accel::insideShape(iso, Vec3(1.5, 0, 0)));
}

TEST(Isosurface, TheContainerClosesTheSolidUnlessOpen) {
    // f = y: the inside is y < 0, cut by the box: a slab whose top is the surface
    // and whose sides and bottom are the box's.
    for (const bool open : {false, true}) {
        auto r = run(std::string("isosurface { function { y } contained_by { box { -1, 1 } }") +
                         (open ? " open" : "") + " }\n",
                     false);
        ASSERT_TRUE(r->scene) << r->diags.formatAll();
        const accel::AnalyticShape iso = *accel::prepareShape(r->scene->objects[0].shape);
        accel::Crossing c[accel::kMaxCrossings];
        const int n = accel::intersectShape(iso, Vec3(0, -5, 0.2), Vec3(0, 1, 0), c);
        ASSERT_EQ(n, open ? 1 : 2);
        if (!open) {
            EXPECT_NEAR(c[0].t, 4, 1e-12); // the box's bottom
        }
        EXPECT_NEAR(c[n - 1].t, 5, 1e-6); // the surface y = 0
    }
}

TEST(Isosurface, RendersLikeTheAnalyticSphereAndTheSameForAnyThreadCount) {
    const std::string head = "camera { location <0, 0, -4> look_at 0 angle 40 }\n"
                             "light_source { <3, 4, -5>, rgb 1 }\n"
                             "render { width 48 height 36 samples 4 seed 3 }\n";
    auto iso = run(head + "isosurface { function { x * x + y * y + z * z - 1 } contained_by { sphere { 0, 1.5 } }"
                          " max_gradient 3 pigment { rgb <1, 0.5, 0.2> } }\n",
                   false);
    auto sphere = run(head + "sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }\n", false);
    ASSERT_TRUE(iso->scene && sphere->scene) << iso->diags.formatAll() << sphere->diags.formatAll();
    RenderOptions options = resolveRenderOptions(iso->scene->render);
    options.threads = 1;
    const Image a = render(*iso->scene, options).color;
    const Image b = render(*sphere->scene, options).color;
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    double sum = 0, worst = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        ASSERT_TRUE(std::isfinite(a.pixels[i]));
        const double diff = std::fabs(double(a.pixels[i]) - double(b.pixels[i]));
        sum += diff;
        worst = std::max(worst, diff);
    }
    // Stated tolerance: mean absolute difference below 1e-4 (edge pixels may
    // differ by a sample), no pixel more than 0.35 off.
    EXPECT_LT(sum / double(a.pixels.size()), 1e-4);
    EXPECT_LT(worst, 0.35);
    options.threads = 3;
    const Image c = render(*iso->scene, options).color;
    EXPECT_TRUE(c.pixels == a.pixels);
}

TEST(Isosurface, WorksInCsgAndWithPovRaysDefaults) {
    auto r = run("#include \"functions.inc\"\n"
                 "difference { box { -1, 1 } isosurface { function { f_sphere(x, y, z, 0.8) } } }\n");
    ASSERT_TRUE(r->scene) << r->diags.formatAll();
    const Csg* csg = std::get_if<Csg>(&r->scene->objects[0].shape);
    ASSERT_TRUE(csg);
    const Isosurface* iso = std::get_if<Isosurface>(&csg->children[1].shape);
    ASSERT_TRUE(iso);
    EXPECT_EQ(iso->threshold, 0);
    EXPECT_EQ(iso->accuracy, 0.001);
    EXPECT_EQ(iso->maxGradient, 1.1);
    EXPECT_EQ(iso->corner1, Vec3(-1));
    const accel::AnalyticShape shape = *accel::prepareShape(csg->children[1].shape);
    EXPECT_TRUE(accel::insideShape(shape, Vec3(0.7, 0, 0)));
    EXPECT_FALSE(accel::insideShape(shape, Vec3(0.9, 0, 0)));
    test::buildAccelerator(*r->scene);
}

TEST(Isosurface, TraceAndInsideSeeItWhileTheSceneIsRead) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/iso.pov", R"(#declare Iso = isosurface { function { x * x + y * y + z * z - 1 } max_gradient 4 }
#declare N = <0, 0, 0>;
#declare Q = trace(Iso, <0.6, 0, -5>, <0, 0, 1>, N);
#declare J = inside(Iso, <0, 0.5, 0>) + 2 * inside(Iso, <0, 1.5, 0>);
#warning concat("Q=", vstr(3, Q, ",", 0, 4), " N=", vstr(3, N, ",", 0, 3), " J=", str(J, 0, 0))
)");
    const test::CommandResult r = test::runDrt("check '" + scene + "'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("Q=0.6000,0.0000,-0.8000 N=0.600,0.000,-0.800 J=1"), std::string::npos) << r.err;
}

// ------------------------------------------------------------ errors

TEST(FunctionErrors, AreLocatedAndClear) {
    EXPECT_EQ(firstError("#declare F = function { x + qqq }"), "1:29: unknown function or parameter 'qqq'");
    EXPECT_EQ(firstError("#declare F = function { x + sin(1, 2) }"), "1:29: 'sin' takes 1 argument, got 2");
    EXPECT_EQ(firstError("#declare G = function(a) { a }\n#declare F = function { G(x, y) }"),
              "2:25: 'G' takes 1 argument, got 2");
    EXPECT_EQ(firstError("#declare G = function(a) { a }\n#declare V = G(1, 2);"), "2:14: 'G' takes 1 argument, got 2");
    EXPECT_EQ(firstError("#declare F = function { F(x, y, z) + 1 }"),
              "1:25: function 'F' calls itself: a function can only call functions declared before it");
    EXPECT_EQ(firstError("#declare F = function(a, b) { a + z }"),
              "1:35: 'z' is not a parameter of this function (its parameters are a, b)");
    EXPECT_EQ(firstError("#declare F = function(a, a) { a }"), "1:26: parameter 'a' is named twice");
    EXPECT_EQ(firstError("#declare S = \"s\";\n#declare F = function { x + S }"),
              "2:29: 'S' is a string; a function takes numbers and functions only");
    EXPECT_EQ(firstError("#declare F = function { pattern { agate }(y, x, z) + 1 }"),
              "1:42: a body that starts with 'pattern { }' is that pattern; to call it at a point, write "
              "(pattern { ... }(a, b, c))");
    EXPECT_EQ(firstError("sphere { 0, 1 pigment { function(a, b) { a * b } } }"),
              "1:25: a function pattern needs a function of 3 parameters (x, y, z), this one has 2");
    EXPECT_EQ(firstError("isosurface { contained_by { box { -1, 1 } } }"),
              "1:1: an isosurface needs a 'function { ... }'");
    EXPECT_EQ(firstError("isosurface { function { x } contained_by { cone { 0, 1, y, 0 } } }"),
              "1:44: an isosurface is contained by a 'box' or a 'sphere', not 'cone'");
    EXPECT_EQ(firstError("isosurface { function { x } max_gradient 0 }"),
              "1:42: isosurface max_gradient must be positive, got 0");
    EXPECT_EQ(firstError("height_field { function 1, 5 { x } }"),
              "1:25: the height_field function's width 1 is out of range (2 to 8192)");
    // POV-Ray's dialect: the same messages.
    EXPECT_EQ(firstError("#declare F = function { x + qqq }", true), "1:29: unknown function or parameter 'qqq'");
}

TEST(FunctionErrors, TheCommandLineShowsTheLocationWithACaretAndFails) {
    const std::string dir = test::tempDir();
    const std::string scene = test::writeFile(dir + "/bad.pov", "#declare F = function { x * y }\n"
                                                                "#declare V = F(1, 2);\n");
    const test::CommandResult r = test::runDrt("check " + scene);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("bad.pov:2:14: error: 'F' takes 3 arguments, got 2"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("^"), std::string::npos) << r.err;
}

} // namespace
} // namespace drt

namespace drt {
namespace {

// vturbulence(lambda, omega, octaves, p) is the displacement a pattern's
// `turbulence 1` with the same lambda, omega and octaves gives p: a gradient x
// pattern so warped reads fract(p.x + V.x) at p. And octaves add up:
// V(n + 1 octaves at p) = V(1 at p) + omega V(n at lambda p).
TEST(Function, TransformFunctionIsTheTransformedPoint) {
    // transforms.inc's vtransform(V, T) is function { transform { T } }(V.x, V.y, V.z): the point moved by T.
    for (bool pov : {true, false}) {
        const std::string f = "#declare F = function { transform { scale <2, 3, 4> rotate <0, 0, 90> translate <1, 0, 0> } }\n"
                              "#declare V = F(1, 1, 1);\n";
        // scale: <2, 3, 4>; rotating 90 degrees about z takes x to y and y to -x: <-3, 2, 4>; then + x.
        EXPECT_NEAR(value(f, "V.x", pov), -2, 1e-9);
        EXPECT_NEAR(value(f, "V.y", pov), 2, 1e-9);
        EXPECT_NEAR(value(f, "V.z", pov), 4, 1e-9);
        EXPECT_NEAR(value(f + "#declare H = function { F(x, y, z).y + F(x, y, z).x }", "H(1, 1, 1)", pov), 0, 1e-9);
        EXPECT_NEAR(value("#declare G = function { transform { translate <1, 2, 3> inverse } }", "G(0, 0, 0).y", pov), -2,
                    1e-12);
    }
    EXPECT_EQ(firstError("#declare F = function(a, b) { transform { scale 2 } }\n"),
              "1:31: a transform function has three parameters (x, y, z)");
}

TEST(Function, VturbulenceIsThePatternWarpsDisplacement) {
    const Vec3 p(0.3, 0.7, 1.1);
    for (bool pov : {true, false}) {
        const std::string at = "<0.3, 0.7, 1.1>";
        const double vx = value("#declare V = vturbulence(2.5, 0.4, 3, " + at + ");", "V.x", pov);
        const double vy = value("#declare V = vturbulence(2.5, 0.4, 3, " + at + ");", "V.y", pov);
        EXPECT_GT(std::abs(vx) + std::abs(vy), 1e-3) << "a zero vector would pass the identities below";
        Pigment gradient;
        gradient.pattern = PatternKind::Gradient;
        gradient.gradientAxis = Vec3(1, 0, 0);
        gradient.turbulence.amount = Vec3(1.0);
        gradient.turbulence.lambda = 2.5;
        gradient.turbulence.omega = 0.4;
        gradient.turbulence.octaves = 3;
        const double warped = samplePattern(gradient, p).value;
        const double expected = p.x + vx - std::floor(p.x + vx);
        EXPECT_NEAR(warped, expected, 2e-9) << (pov ? "POV-Ray dialect" : ".drt dialect");
        // Octaves: 3 at p = 1 at p + 0.4 x (2 at 2.5 p).
        const double one = value("", "vturbulence(2.5, 0.4, 1, " + at + ").x", pov);
        const double two = value("", "vturbulence(2.5, 0.4, 2, <0.75, 1.75, 2.75>).x", pov);
        EXPECT_NEAR(vx, one + 0.4 * two, 3e-9);
        EXPECT_NEAR(vy, value("", "vturbulence(2.5, 0.4, 1, " + at + ").y", pov) +
                            0.4 * value("", "vturbulence(2.5, 0.4, 2, <0.75, 1.75, 2.75>).y", pov),
                    3e-9);
    }
    // Octaves past POV-Ray's 10 are clipped to 10; a non-number is a located error.
    EXPECT_DOUBLE_EQ(value("", "vturbulence(2, 0.5, 50, <0.1, 0.2, 0.3>).z"),
                     value("", "vturbulence(2, 0.5, 10, <0.1, 0.2, 0.3>).z"));
    EXPECT_EQ(firstError("#declare V = vturbulence(2, 0.5, \"a\", <0, 0, 0>);\n"),
              "1:34: argument of 'vturbulence' must be a number, not a string");
}

} // namespace
} // namespace drt

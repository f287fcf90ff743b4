// POV-Ray's julia_fractal: closed forms (c = 0 makes the quaternion set the
// unit ball, for sqr and cube; a slice at w = d cuts it to the ball of radius
// sqrt(1 - d^2); a hypercomplex orbit on the x axis stays real, so the axis
// crosses the set at |x| = 1), every crossing for CSG, the scene through the
// accelerator with a transform, both front ends and the .drt writer, and
// located errors (the .drt ones also in parser_errors_test.cpp). The render
// against POV-Ray's is pov_crosscheck/fidelity/julia_fractal.pov.
#include "accel/accel.h"
#include "accel/julia_fractal_shape.h"
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace drt {
namespace {

using accel::Crossing;
using accel::JuliaFractalGeometry;
using test::makeObject;
using test::sceneOf;

JuliaFractal fractal(std::array<double, 4> c, JuliaFractal::Algebra algebra = JuliaFractal::Algebra::Quaternion,
                     JuliaFractal::Function function = JuliaFractal::Function::Sqr) {
    JuliaFractal f;
    f.parameter = c;
    f.algebra = algebra;
    f.function = function;
    return f;
}

Vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        if (length(v) > 1e-6) return normalize(v);
    }
}

// The first crossing of a ray from outside against the sphere of radius r about the origin.
void expectBall(const JuliaFractal& f, double r, double normalAgreement = 0.999) {
    const JuliaFractalGeometry g(f);
    std::mt19937 rng(7);
    std::vector<Crossing> out;
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 origin = randomUnit(rng) * 3;
        const Vec3 target = randomUnit(rng) * (0.9 * r);
        const Vec3 d = (target - origin) * 0.5; // not unit length: t in units of d
        g.intersect(origin, d, 0, INFINITY, 1, out);
        ASSERT_EQ(out.size(), 1u) << i;
        // |o + t d| = r, the nearer root.
        const double a = dot(d, d), b = dot(origin, d), c = dot(origin, origin) - r * r;
        const double t = (-b - std::sqrt(b * b - a * c)) / a;
        EXPECT_NEAR(out[0].t, t, 2e-6 / std::sqrt(a)) << i;
        const Vec3 p = origin + out[0].t * d;
        EXPECT_GT(dot(normalize(out[0].normal), normalize(p)), normalAgreement) << i;
        ++hits;
    }
    EXPECT_EQ(hits, 300);
}

TEST(JuliaFractal, QuaternionSqrWithZeroParameterIsTheUnitBall) {
    expectBall(fractal({0, 0, 0, 0}), 1);
}

TEST(JuliaFractal, QuaternionCubeWithZeroParameterIsTheUnitBall) {
    // |q_20| = |q|^(3^20) underflows to 0 a little inside the surface, so the
    // orbit's normal vanishes at some hits; the ray's direction stands in.
    expectBall(fractal({0, 0, 0, 0}, JuliaFractal::Algebra::Quaternion, JuliaFractal::Function::Cube), 1, 0.95);
}

TEST(JuliaFractal, SliceAtWCutsTheBallToItsSection) {
    JuliaFractal f = fractal({0, 0, 0, 0});
    f.slice = {0, 0, 0, 2}; // normalised to <0, 0, 0, 1>
    f.sliceDistance = 0.6;  // w = 0.6 everywhere: |p|^2 + 0.36 <= 1
    expectBall(f, 0.8);
}

TEST(JuliaFractal, HypercomplexOrbitOnTheXAxisStaysReal) {
    // x -> x^2 with exit value 16: inside while |x|^(2^20) <= 16, |x| <= 1 + 2.6e-6.
    const JuliaFractalGeometry g(fractal({0, 0, 0, 0}, JuliaFractal::Algebra::Hypercomplex));
    std::vector<Crossing> out;
    g.intersect({-5, 0, 0}, {1, 0, 0}, -INFINITY, INFINITY, SIZE_MAX, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_NEAR(out[0].t, 4, 1e-5);
    EXPECT_NEAR(out[1].t, 6, 1e-5);
    EXPECT_LT(out[0].normal.x, 0);
    EXPECT_GT(out[1].normal.x, 0);
    EXPECT_TRUE(g.inside({0.5, 0, 0}));
    EXPECT_FALSE(g.inside({1.01, 0, 0}));
}

TEST(JuliaFractal, EveryCrossingOfTheLineAlternatesAndIsSorted) {
    // A connected quaternion set, crossed along random lines: entries and
    // exits alternate, the inside test agrees between them.
    const JuliaFractalGeometry g(fractal({-0.083, 0.0, -0.83, -0.025}));
    std::mt19937 rng(3);
    std::vector<Crossing> out;
    int lines = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 origin = randomUnit(rng) * 3, d = randomUnit(rng) * 0.3 - origin * 0.3;
        g.intersect(origin, d, -INFINITY, INFINITY, SIZE_MAX, out);
        if (out.empty()) continue;
        ++lines;
        EXPECT_EQ(out.size() % 2, 0u) << i;
        for (size_t k = 0; k < out.size(); ++k) {
            if (k > 0) {
                EXPECT_GT(out[k].t, out[k - 1].t) << i;
            }
            // entering crossings face the ray, leaving ones face along it
            EXPECT_EQ(dot(out[k].normal, d) < 0, k % 2 == 0) << i << " " << k;
            // The crossing is the inside end of the bisected step; just outside it, the other side.
            const double eps = 1e-6 / length(d);
            EXPECT_TRUE(g.inside(origin + out[k].t * d)) << i << " " << k;
            EXPECT_FALSE(g.inside(origin + (out[k].t + (k % 2 == 0 ? -eps : eps)) * d)) << i << " " << k;
        }
    }
    EXPECT_GT(lines, 20);
}

TEST(JuliaFractal, AcceleratorPlacesTheTransformedBall) {
    Object o = makeObject(fractal({0, 0, 0, 0}), Transform::scale(Vec3(2)).then(Transform::translate({1, 2, 3})));
    const Scene scene = sceneOf({o});
    const Accelerator accel(scene);
    Ray ray;
    ray.origin = {1, 2, -10};
    ray.direction = {0, 0, 1};
    Hit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.t, 11, 1e-5);
    EXPECT_LT(normalize(hit.geometricNormal).z, -0.999);
}

TEST(JuliaFractal, BadFractalsAreRejected) {
    JuliaFractal f = fractal({0, 0, 0, 0}, JuliaFractal::Algebra::Quaternion, JuliaFractal::Function::Exp);
    EXPECT_THROW(JuliaFractalGeometry{f}, std::invalid_argument);
    f = fractal({0, 0, 0, 0});
    f.maxIteration = 0;
    EXPECT_THROW(JuliaFractalGeometry{f}, std::invalid_argument);
    f = fractal({0, 0, NAN, 0});
    EXPECT_THROW(JuliaFractalGeometry{f}, std::invalid_argument);
    f = fractal({0, 0, 0, 0});
    f.slice = {1, 0, 0, 0};
    EXPECT_THROW(JuliaFractalGeometry{f}, std::invalid_argument);
}

// ------------------------------------------------------------ front ends

TEST(DrtJuliaFractal, ParsesAndRoundTrips) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 0, 0> }
light_source { <5, 10, -10>, rgb 1 }
julia_fractal { <0.2, 0.1, 0.59, -0.2> sqr hypercomplex max_iteration 7 precision 20 slice <0, 0, 1, 1>, 0.5
  pigment { rgb 1 } }
julia_fractal { <1, 2, 3> pwr(2, 0.5) hypercomplex }
julia_fractal { 0.25 }
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadSceneText(text, "a.drt", diags, ".");
    ASSERT_TRUE(scene) << diags.formatAll();
    ASSERT_EQ(scene->objects.size(), 3u);
    const JuliaFractal& a = std::get<JuliaFractal>(scene->objects[0].shape);
    EXPECT_EQ(a.algebra, JuliaFractal::Algebra::Hypercomplex);
    EXPECT_EQ(a.function, JuliaFractal::Function::Sqr);
    EXPECT_EQ(a.maxIteration, 7);
    EXPECT_EQ(a.precision, 20);
    EXPECT_EQ(a.slice, (std::array<double, 4>{0, 0, 1, 1})); // as written: the geometry normalises it
    EXPECT_EQ(a.sliceDistance, 0.5);
    const JuliaFractal& b = std::get<JuliaFractal>(scene->objects[1].shape);
    EXPECT_EQ(b.parameter, (std::array<double, 4>{1, 2, 3, 0}));
    EXPECT_EQ(b.function, JuliaFractal::Function::Pwr);
    EXPECT_EQ(b.exponent, (std::array<double, 2>{2, 0.5}));
    const JuliaFractal& c = std::get<JuliaFractal>(scene->objects[2].shape);
    EXPECT_EQ(c.parameter, (std::array<double, 4>{0.25, 0.25, 0.25, 0.25}));
    EXPECT_EQ(c.algebra, JuliaFractal::Algebra::Quaternion); // POV-Ray's defaults
    EXPECT_EQ(c.maxIteration, 20);
    EXPECT_EQ(c.precision, 20);
    const std::string written = writeDrtScene(*scene);
    Diagnostics again;
    const std::optional<Scene> reread = loadSceneText(written, "b.drt", again, ".");
    ASSERT_TRUE(reread) << again.formatAll() << written;
    EXPECT_EQ(writeDrtScene(*reread), written);
    for (size_t i = 0; i < scene->objects.size(); ++i)
        EXPECT_EQ(std::get<JuliaFractal>(scene->objects[i].shape), std::get<JuliaFractal>(reread->objects[i].shape))
            << written;
}

TEST(PovJuliaFractal, ReadsPovRaysFormAndClampsPrecision) {
    const std::string text = R"(
camera { location <0, 2, -8> look_at <0, 0, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> max_iteration 9.7 precision 0.5 cube
  pigment { rgb 1 } scale <1, 2, 1> }
)";
    Diagnostics diags;
    const std::optional<Scene> scene = loadPovSceneText(text, "s.pov", diags);
    ASSERT_TRUE(scene) << diags.formatAll();
    EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
    const JuliaFractal& f = std::get<JuliaFractal>(scene->objects[0].shape);
    EXPECT_EQ(f.function, JuliaFractal::Function::Cube);
    EXPECT_EQ(f.maxIteration, 9);  // truncated
    EXPECT_EQ(f.precision, 1);     // POV-Ray takes at least 1
}

TEST(PovJuliaFractal, BadFractalsAreErrorsWithLocations) {
    const struct { const char* source; const char* message; int line, column; } cases[] = {
        {"julia_fractal { <0, 0, 0, 0>\n  exp }",
         "a quaternion julia_fractal iterates 'sqr' or 'cube', not 'exp' (add 'hypercomplex' for the other functions)",
         2, 3},
        {"julia_fractal { <0, 0, 0, 0> slice <1, 0, 0, 0>, 0 }",
         "the slice normal needs a non-zero fourth (w) component", 1, 36},
        {"julia_fractal { <0, 0, 0, 0> slice 0, 0 }", "the slice normal must not be zero", 1, 36},
        {"julia_fractal { <0, 0, 0, 0, 0> }", "expected the julia parameter (a 4-D vector <x, y, z, w>)", 1, 17},
    };
    for (const auto& c : cases) {
        Diagnostics diags;
        EXPECT_FALSE(loadPovSceneText(c.source, "e.pov", diags)) << c.source;
        ASSERT_GE(diags.errorCount(), 1) << c.source;
        EXPECT_EQ(diags.all()[0].message, c.message) << c.source;
        EXPECT_EQ(diags.all()[0].loc.line, c.line) << c.source;
        EXPECT_EQ(diags.all()[0].loc.column, c.column) << c.source;
    }
}

} // namespace
} // namespace drt

// Render-level closed-form tests of time: a disc spinning about its own
// centre, a sphere on a circular path (keyed, and from a POV-Ray scene's
// clock), a camera panning against a scene panning the other way: emissive
// objects on black seen by an orthographic camera along +z, so a pixel's value
// is exactly the fraction of its area and of the shutter the object covers.
// Moving point and area lights over a diffuse floor: the pixel is the time
// average of the irradiance. Fixed seeds; every tolerance is stated where it
// is asserted.
#include "closed_form_scenes.h"

#include "animation/animation.h"
#include "pov/load.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <functional>
#include <memory>

namespace drt {
namespace {

using namespace closedform;

constexpr int kSize = 64;
constexpr double kView = 2.4;            // world units across the image
const Vec3 kCentre{0.7, -0.3, 0};        // the spin's centre, off the origin
constexpr double kDiscRadius = 1.0;

// An orthographic camera looking along +z at kCentre, kView across: pixel
// (px, py) sees world x = c.x + (px/W - 0.5) kView, y = c.y + (0.5 - py/H) kView.
void viewCentre(Scene& scene) {
    scene.camera.orthographic = true;
    scene.camera.location = kCentre + Vec3{0, 0, -5};
    scene.camera.direction = {0, 0, 1};
    scene.camera.right = Vec3(kView, 0, 0);
    scene.camera.up = {0, kView, 0};
    scene.camera.shutterOpen = 0;
    scene.camera.shutterClose = 1;
}

Vec3 worldOf(double px, double py) {
    return kCentre + Vec3{(px / kSize - 0.5) * kView, (0.5 - py / kSize) * kView, 0};
}

// The mean of f over pixel (x, y), by the midpoint rule on 16 x 16 points
// (f is smooth in the pixels it is used on: error far below the noise).
double pixelMean(int x, int y, const std::function<double(const Vec3&)>& f) {
    double sum = 0;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) sum += f(worldOf(x + (i + 0.5) / 16, y + (j + 0.5) / 16));
    return sum / 256;
}

struct Agreement {
    double zMean = 0; // summed error / sqrt(summed variance-image values): ~N(0, 1) if unbiased
    double meanSquaredOverVariance = 0;
    int pixels = 0;
};

Agreement agreement(const RenderResult& r, const std::function<bool(int, int)>& use,
                    const std::function<double(int, int)>& exact) {
    Agreement a;
    double sum = 0, squared = 0, variance = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!use(x, y)) continue;
            const double d = red(r.color, x, y) - exact(x, y);
            sum += d;
            squared += d * d;
            variance += red(r.variance, x, y);
            ++a.pixels;
        }
    a.zMean = sum / std::sqrt(variance);
    a.meanSquaredOverVariance = squared / variance;
    return a;
}

// ---------------------------------------------------------------- spinning disc

constexpr double kSpinDegrees = 90;

// The right half of a disc about kCentre (a disc clipped by a box; the clip
// moves with it), spinning by kSpinDegrees about its own centre over the
// shutter: translate -c, motion { rotate z*90 }, translate c.
Scene spinningHalfDisc(bool moving) {
    Scene scene;
    Object disc;
    disc.shape = Disc{kCentre, {0, 0, -1}, kDiscRadius, 0};
    disc.texture = emissive();
    Object clip;
    clip.shape = Box{kCentre + Vec3{0, -2, -1}, kCentre + Vec3{2, 2, 1}};
    disc.clippedBy.push_back(clip);
    if (moving) { // the clip is in the rest pose's world, which the motion moves
        disc.transform = Transform::translate(-kCentre);
        disc.motion = {MotionStage{motionTo({}, {0, 0, kSpinDegrees}), Transform::translate(kCentre)}};
    }
    scene.objects.push_back(disc);
    viewCentre(scene);
    return scene;
}

// Time-averaged coverage of a point at polar angle phi (degrees, about the
// centre, from +x toward +y) inside the disc: white while phi - 90 t lies in
// [-90, 90], so over t in [0, 1] the arc fraction
//   (phi + 90) / 90 on [-90, 0], 1 on [0, 90], (180 - phi) / 90 on [90, 180], 0 else.
double spinCoverage(const Vec3& p) {
    const Vec3 d = p - kCentre;
    if (length(Vec3{d.x, d.y, 0}) > kDiscRadius) return 0;
    const double phi = std::atan2(d.y, d.x) * 180 / kPi;
    if (phi < -90) return 0;
    if (phi < 0) return (phi + 90) / 90;
    if (phi < 90) return 1;
    return (180 - phi) / 90;
}

TEST(ClosedFormTime, SpinningDiscCoversTheArcFraction) {
    // Pixels wholly inside the radii 0.15 .. 0.9 (away from the disc's rim and
    // its centre, where the pixel mean of the arc fraction needs no care).
    const auto inside = [](int x, int y) {
        for (int c = 0; c < 4; ++c) {
            const Vec3 d = worldOf(x + (c & 1), y + (c >> 1)) - kCentre;
            const double r = std::hypot(d.x, d.y);
            if (r < 0.15 || r > 0.9) return false;
        }
        return true;
    };
    const auto exact = [](int x, int y) { return pixelMean(x, y, spinCoverage); };
    // Independent samples: each pixel's mean is unbiased with the variance
    // the variance image estimates. Tolerance: |z| < 3 over ~1500 pixels.
    const RenderResult r = render(spinningHalfDisc(true), options(kSize, kSize, 64, "independent", 31));
    const Agreement a = agreement(r, inside, exact);
    std::printf("  spinning disc: %d pixels, z %.2f, mean squared error / variance %.3f\n", a.pixels, a.zMean,
                a.meanSquaredOverVariance);
    EXPECT_GT(a.pixels, 1200);
    EXPECT_LT(std::fabs(a.zMean), 3.0);
    EXPECT_LT(a.meanSquaredOverVariance, 1.5);
    // The blur is real: the still half disc is far from the time average.
    const RenderResult still = render(spinningHalfDisc(false), options(kSize, kSize, 64, "independent", 31));
    EXPECT_GT(agreement(still, inside, exact).meanSquaredOverVariance, 10.0);
}

// ---------------------------------------------------------------- circular path

constexpr double kOrbit = 0.8, kBall = 0.12, kSweepDegrees = 180;

// A sphere at kOrbit from kCentre, sent half way round it over the shutter.
Scene orbitingBall() {
    Scene scene;
    Object ball;
    ball.shape = Sphere{kCentre + Vec3{kOrbit, 0, 0}, kBall};
    ball.texture = emissive();
    ball.transform = Transform::translate(-kCentre);
    ball.motion = {MotionStage{motionTo({}, {0, 0, kSweepDegrees}), Transform::translate(kCentre)}};
    scene.objects.push_back(ball);
    viewCentre(scene);
    return scene;
}

// The time a point at radius r and angle phi from the centre spends inside
// the ball's disc (orthographic image), for a sweep over angles [0, S]: the
// ball at angle psi covers it when r^2 + R^2 - 2 r R cos(phi - psi) < rho^2,
// i.e. |phi - psi| < acos((r^2 + R^2 - rho^2) / (2 r R)); the fraction of the
// sweep with psi in that window (clipped to [0, S]).
double arcCoverage(const Vec3& p) {
    const Vec3 d = p - kCentre;
    const double r = std::hypot(d.x, d.y);
    const double k = (r * r + kOrbit * kOrbit - kBall * kBall) / (2 * r * kOrbit);
    if (!(k < 1)) return 0;
    const double half = std::acos(std::max(-1.0, k)), phi = std::atan2(d.y, d.x);
    const double sweep = kSweepDegrees * kPi / 180;
    const double lo = std::max(0.0, phi - half), hi = std::min(sweep, phi + half);
    return std::max(0.0, hi - lo) / sweep;
}

TEST(ClosedFormTime, BallOnACircularPathBlursAlongTheArc) {
    const auto ring = [](int x, int y) { // pixels over the swept ring, away from its ends
        const Vec3 d = worldOf(x + 0.5, y + 0.5) - kCentre;
        const double r = std::hypot(d.x, d.y), phi = std::atan2(d.y, d.x) * 180 / kPi;
        return r > kOrbit - kBall + 0.02 && r < kOrbit + kBall - 0.02 && phi > 20 && phi < 160;
    };
    const auto exact = [](int x, int y) { return pixelMean(x, y, arcCoverage); };
    const RenderResult r = render(orbitingBall(), options(kSize, kSize, 128, "independent", 32));
    const Agreement a = agreement(r, ring, exact);
    std::printf("  ball on an arc: %d pixels, z %.2f, mean squared error / variance %.3f\n", a.pixels, a.zMean,
                a.meanSquaredOverVariance);
    EXPECT_GT(a.pixels, 60);
    EXPECT_LT(std::fabs(a.zMean), 3.0); // |z| < 3
    EXPECT_LT(a.meanSquaredOverVariance, 1.5);
    // The arc, not its chord: the streak reaches the top of the circle
    // (centre + (0, R)), and nothing lies on the chord's middle (the centre),
    // which a straight-line path from start to end would cross.
    const int topX = int(std::floor((0.5) * kSize)), topY = int(std::floor((0.5 - kOrbit / kView) * kSize));
    EXPECT_GT(red(r.color, topX, topY), 0.05);
    const int midX = kSize / 2, midY = kSize / 2;
    EXPECT_EQ(red(r.color, midX, midY), 0.0);
    EXPECT_EQ(red(r.color, midX - 1, midY - 1), 0.0);
}

// ---------------------------------------------------------------- panning camera

// Emissive objects around a pinhole camera at the origin; `cameraPans`: the
// camera turns by 20 degrees about y over the shutter, else the objects turn
// by -20 degrees about the camera.
Scene panScene(bool cameraPans) {
    Scene scene;
    const Vec3 places[] = {{-1, 0.3, 5}, {0.5, -0.4, 6}, {1.6, 0.2, 4}, {2.8, -0.1, 5}};
    int k = 0;
    for (const Vec3& p : places) {
        Object o;
        o.shape = k % 2 ? Shape{Sphere{p, 0.5}} : Shape{Box{p - Vec3(0.4), p + Vec3(0.4)}};
        o.texture = emissive(Color(0.2 + 0.2 * k, 0.9 - 0.2 * k, 0.5));
        if (!cameraPans) o.motion = {MotionStage{motionTo({}, {0, -20, 0}), {}}};
        scene.objects.push_back(o);
        ++k;
    }
    scene.camera.location = {0, 0, 0};
    scene.camera.direction = {0, 0, 1};
    scene.camera.right = Vec3(1, 0, 0);
    scene.camera.up = {0, 1, 0};
    scene.camera.shutterOpen = 0;
    scene.camera.shutterClose = 1;
    if (cameraPans) scene.camera.motion = {MotionStage{motionTo({}, {0, 20, 0}), {}}};
    return scene;
}

TEST(ClosedFormTime, PanningCameraEqualsTheScenePanningTheOtherWay) {
    // The same samples (pixel, time) see the same points: the camera turned by
    // a(t) about its own location, or the world turned by -a(t) about it. The
    // two differ only by rounding, which may flip a sample on an edge.
    // Tolerance: at most 1% of the pixels differ by more than 1e-4, and the
    // images agree to an RMSE below 0.2 / spp (a few flipped samples).
    constexpr int spp = 32;
    const RenderResult a = render(panScene(true), options(kSize, kSize, spp, "sobol", 33));
    const RenderResult b = render(panScene(false), options(kSize, kSize, spp, "sobol", 33));
    int differing = 0;
    double squared = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = a.color.at(x, y, c) - b.color.at(x, y, c);
                squared += d * d;
                differing += std::fabs(d) > 1e-4;
            }
    const double rmse = std::sqrt(squared / (3.0 * kSize * kSize));
    std::printf("  panning camera against panning scene: %d channel values differ, RMSE %.2e\n", differing, rmse);
    EXPECT_LE(differing, 3 * kSize * kSize / 100);
    EXPECT_LT(rmse, 0.2 / spp);
    // The pan is real: a still camera sees another image.
    Scene still = panScene(true);
    still.camera.motion.clear();
    const RenderResult c = render(still, options(kSize, kSize, spp, "sobol", 33));
    double stillSquared = 0;
    for (size_t i = 0; i < c.color.pixels.size(); ++i)
        stillSquared += std::pow(double(c.color.pixels[i]) - a.color.pixels[i], 2);
    EXPECT_GT(std::sqrt(stillSquared / c.color.pixels.size()), 10 * rmse + 0.01);
}

// ---------------------------------------------------------------- motion from the clock

// The orbiting ball of BallOnACircularPathBlursAlongTheArc written as a
// POV-Ray animation: no motion block, only `rotate z*180*clock` about the
// centre. With the shutter open over the frame (clock 0 .. 1) drt evaluates the
// scene over the shutter and moves the ball along the path the evaluations
// trace, which must be the arc.
TEST(ClosedFormTime, BallMovedByTheClockBlursAlongTheArc) {
    const std::string text = fmt::format(
        "camera {{ orthographic location <{0}, {1}, -5> direction <0, 0, 1> right <{2}, 0, 0> up <0, {2}, 0> }}\n"
        "sphere {{ <{3}, {1}, 0>, {4} pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 0 emission 1 }}\n"
        "  translate <{5}, {6}, 0> rotate z * {7} * clock translate <{0}, {1}, 0> }}\n",
        kCentre.x, kCentre.y, kView, kCentre.x + kOrbit, kBall, -kCentre.x, -kCentre.y, kSweepDegrees);
    const SceneEvaluator evaluate = [&](const FrameClock& frame, Diagnostics& diagnostics) {
        PovOptions o;
        o.frame = frame;
        o.imageWidth = o.imageHeight = kSize;
        return loadPovSceneText(text, "orbit.pov", diagnostics, o);
    };
    FrameClock frame; // clock 0, clock_delta 1: scene time t is clock t
    FrameOptions shutter;
    shutter.shutter = 1.0;
    Diagnostics diagnostics;
    FrameReport report;
    const std::optional<Scene> scene = evaluateFrame(evaluate, frame, shutter, diagnostics, &report);
    ASSERT_TRUE(scene && !diagnostics.hasErrors()) << diagnostics.formatAll();
    EXPECT_EQ(report.objectsFromClock, 1);
    EXPECT_GE(report.evaluations, 3);
    const RenderResult r = render(*scene, options(kSize, kSize, 128, "independent", 34));
    const auto ring = [](int x, int y) {
        const Vec3 d = worldOf(x + 0.5, y + 0.5) - kCentre;
        const double radius = std::hypot(d.x, d.y), phi = std::atan2(d.y, d.x) * 180 / kPi;
        return radius > kOrbit - kBall + 0.02 && radius < kOrbit + kBall - 0.02 && phi > 20 && phi < 160;
    };
    const Agreement a = agreement(r, ring, [](int x, int y) { return pixelMean(x, y, arcCoverage); });
    std::printf("  ball moved by the clock (%d evaluations): %d pixels, z %.2f, mean squared error / variance %.3f\n",
                report.evaluations, a.pixels, a.zMean, a.meanSquaredOverVariance);
    // The same tolerances as the keyed path: |z| < 3, mean squared error
    // within 1.5 variances (the evaluations' path is within 1e-3 of the
    // ball's size of the arc).
    EXPECT_GT(a.pixels, 60);
    EXPECT_LT(std::fabs(a.zMean), 3.0);
    EXPECT_LT(a.meanSquaredOverVariance, 1.5);
    // The arc, not its chord: nothing at the centre.
    EXPECT_EQ(red(r.color, kSize / 2, kSize / 2), 0.0);
}

// ---------------------------------------------------------------- moving lights

// A white point light at height h above the floor, moving along x from s0 to
// s1 over the shutter. Without falloff the floor at p = (px, 0, pz) shows
// cos(theta) = h / sqrt((s - px)^2 + h^2 + pz^2); averaged over s uniform in
// [s0, s1] (constant speed): h (asinh((s1 - px) / q) - asinh((s0 - px) / q)) / (s1 - s0),
// q = sqrt(h^2 + pz^2).
TEST(ClosedFormTime, MovingPointLightGivesTheTimeAverageOfItsLambertTerm) {
    constexpr double h = 2, s0 = -1.5, s1 = 1.5;
    Scene scene;
    scene.objects.push_back(floorPlane());
    Light light;
    light.position = {s0, h, 0};
    auto path = std::make_shared<LightMotion>();
    path->chain = {MotionStage{motionTo({s1 - s0, 0, 0}), {}}};
    light.motion = path;
    scene.lights.push_back(light);
    scene.camera.shutterOpen = 0;
    scene.camera.shutterClose = 1;
    for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{0.7, 0, 0.4}, Vec3{-2, 0, 1}}) {
        const double q = std::hypot(h, p.z);
        const double exact = h * (std::asinh((s1 - p.x) / q) - std::asinh((s0 - p.x) / q)) / (s1 - s0);
        // Independent samples: the variance image is the variance of the mean; |z| < 3.
        const Measure m = measureAt(scene, p, 256, "independent", 35);
        const double z = (m.mean - exact) / std::sqrt(m.variance);
        std::printf("  point light moving by (%.1f, %.1f): E %.5f, rendered %.5f, z %.2f\n", p.x, p.z, exact, m.mean,
                    z);
        EXPECT_LT(std::fabs(z), 3.0);
        // The motion is real: the light held at its opening place gives another value.
        const double opening = h / std::sqrt(std::pow(s0 - p.x, 2) + q * q);
        EXPECT_GT(std::fabs(opening - exact) / std::sqrt(m.variance), 8.0);
    }
}

// A tilted rectangle light (inverse_square, radiance C / area on both faces)
// turning 40 degrees about z and moving 2 along x over the shutter. The floor
// shows the time average of Lambert's polygon irradiance, integrated here by
// the midpoint rule over 2000 times (error far below the noise). Sampled with
// the default sobol sampler, whose pixel samples stratify the light jointly
// with time (Cook's association): the variance image overstates a stratified
// mean's variance, so |z| < 3 is conservative.
TEST(ClosedFormTime, MovingAreaLightGivesTheTimeAverageOfLambertsFormula) {
    const Vec3 center{0.3, 2, -0.2}, axis1{1.5, 0, 0}, axis2{0, 0.6, 0.8};
    constexpr double turnDegrees = 40, radiance = 3.0 / 1.5;
    const auto cornersAt = [&](double t) { // rotate about z by 40 t degrees, then move 2 t along x
        const double a = turnDegrees * t * kPi / 180, c = std::cos(a), s = std::sin(a);
        std::vector<Vec3> corners;
        for (const Vec3& k : {center - 0.5 * axis1 - 0.5 * axis2, center + 0.5 * axis1 - 0.5 * axis2,
                              center + 0.5 * axis1 + 0.5 * axis2, center - 0.5 * axis1 + 0.5 * axis2})
            corners.push_back({c * k.x - s * k.y + 2 * t, s * k.x + c * k.y, k.z});
        return corners;
    };
    for (AreaSampling sampling : {AreaSampling::Stratified, AreaSampling::SolidAngle}) {
        Scene scene;
        scene.objects.push_back(floorPlane());
        Light light = rectangleLight(center, axis1, axis2, Color(3), sampling, true);
        auto path = std::make_shared<LightMotion>();
        path->chain = {MotionStage{motionTo({2, 0, 0}, {0, 0, turnDegrees}), {}}};
        light.motion = path;
        scene.lights.push_back(light);
        scene.camera.shutterOpen = 0;
        scene.camera.shutterClose = 1;
        for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{-1, 0, 0.5}, Vec3{1.2, 0, -1}}) {
            double exact = 0;
            constexpr int steps = 2000;
            for (int k = 0; k < steps; ++k)
                exact += lambertIrradiance(p, {0, 1, 0}, cornersAt((k + 0.5) / steps), radiance) / steps;
            const Measure m = measureAt(scene, p, 256, "sobol", 36);
            const double z = (m.mean - exact) / std::sqrt(m.variance);
            std::printf("  %s area light moving, at (%.1f, %.1f): E %.5f, rendered %.5f, z %.2f\n",
                        sampling == AreaSampling::SolidAngle ? "solid angle" : "stratified ", p.x, p.z, exact, m.mean,
                        z);
            EXPECT_LT(std::fabs(z), 3.0);
            EXPECT_GT(m.variance, 0.0);
            // The motion is real: the still light's irradiance is far off
            // (by 15% to 65% of E at these points, over 5 standard deviations).
            const double still = lambertIrradiance(p, {0, 1, 0}, cornersAt(0), radiance);
            EXPECT_GT(std::fabs(still - exact), 0.1 * exact);
            EXPECT_GT(std::fabs(still - exact) / std::sqrt(m.variance), 5.0);
        }
    }
}

} // namespace
} // namespace drt

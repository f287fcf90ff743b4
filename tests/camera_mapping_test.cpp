// POV-Ray's non-planar cameras (fisheye, ultra_wide_angle, panoramic,
// cylinder 1-4, spherical): rays against the closed forms of render/camera.h
// (POV-Ray 3.7's tracepixel.cpp), the .drt language and writer, and the POV
// front end.
#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"
#include "render/camera.h"
#include "render/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace drt {
namespace {

constexpr double kDeg = kPi / 180;

double degreesBetween(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(a, b) / (length(a) * length(b)), -1.0, 1.0)) / kDeg;
}

// Unit vectors right = x, up = y, direction = z on a square image.
ResolvedCamera axisCamera(CameraMapping m, std::optional<double> angle, int width = 100, int height = 100,
                          std::optional<double> vertical = std::nullopt) {
    CameraSpec spec;
    spec.mapping = m;
    spec.angle = angle;
    spec.verticalAngle = vertical;
    spec.right = Vec3(1, 0, 0);
    return resolveCamera(spec, width, height);
}

const CameraMapping kAllMappings[] = {CameraMapping::Fisheye,   CameraMapping::UltraWideAngle, CameraMapping::Panoramic,
                                      CameraMapping::Cylinder1, CameraMapping::Cylinder2,      CameraMapping::Cylinder3,
                                      CameraMapping::Cylinder4, CameraMapping::Spherical};

TEST(CameraMapping, CentreRayIsTheViewDirection) {
    for (CameraMapping m : kAllMappings) {
        CameraSpec spec;
        spec.mapping = m;
        spec.location = {1, 2, -3};
        spec.lookAt = Vec3(3, 1, 2);
        const ResolvedCamera cam = resolveCamera(spec, 64, 48);
        const Ray ray = cam.generateRay(32, 24, {0.5, 0.5}, 0);
        EXPECT_LT(degreesBetween(ray.direction, *spec.lookAt - spec.location), 1e-9) << int(m);
        EXPECT_LT(length(ray.origin - spec.location), 1e-12) << int(m);
        EXPECT_TRUE(cam.covers(32, 24));
    }
}

TEST(CameraMapping, FisheyeAngleIsTheFullFieldAcrossTheCircle) {
    const ResolvedCamera cam = axisCamera(CameraMapping::Fisheye, 180);
    // Edge midpoints: rho = 1, theta = angle / 2 = 90 degrees off axis.
    EXPECT_LT(degreesBetween(cam.generateRay(100, 50, {}, 0).direction, {1, 0, 0}), 1e-9);
    EXPECT_LT(degreesBetween(cam.generateRay(0, 50, {}, 0).direction, {-1, 0, 0}), 1e-9);
    EXPECT_LT(degreesBetween(cam.generateRay(50, 0, {}, 0).direction, {0, 1, 0}), 1e-9);
    EXPECT_LT(degreesBetween(cam.generateRay(50, 100, {}, 0).direction, {0, -1, 0}), 1e-9);
    // Off axis in proportion to rho: (75, 25) has rho = sqrt(0.5), 45 sqrt(2) degrees, azimuth 45.
    const Vec3 d = cam.generateRay(75, 25, {}, 0).direction;
    EXPECT_NEAR(degreesBetween(d, {0, 0, 1}), 90 * std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(d.x, d.y, 1e-12);
    // Corners lie outside the circle: no ray there.
    EXPECT_FALSE(cam.covers(0, 0));
    EXPECT_FALSE(cam.covers(99, 1));
    EXPECT_TRUE(cam.covers(50, 1));
    // Angle 90: the edge midpoints are 45 degrees off axis.
    const ResolvedCamera narrow = axisCamera(CameraMapping::Fisheye, 90);
    EXPECT_NEAR(degreesBetween(narrow.generateRay(100, 50, {}, 0).direction, {0, 0, 1}), 45, 1e-9);
}

TEST(CameraMapping, UltraWideAngleScalesTheVerticalAngleByTheAspect) {
    CameraSpec spec;
    spec.mapping = CameraMapping::UltraWideAngle;
    spec.angle = 120;
    spec.right = Vec3(2, 0, 0); // |u| / |r| = 1/2
    const ResolvedCamera cam = resolveCamera(spec, 200, 100);
    // Right edge: x0 = 0.5, 60 degrees towards right.
    const Vec3 r = cam.generateRay(200, 50, {}, 0).direction;
    EXPECT_NEAR(degreesBetween(r, {0, 0, 1}), 60, 1e-9);
    EXPECT_NEAR(r.y, 0, 1e-15);
    // Top edge: y0 = 0.5, 0.5 * 120 * 1/2 = 30 degrees up.
    const Vec3 t = cam.generateRay(100, 0, {}, 0).direction;
    EXPECT_NEAR(std::atan2(t.y, t.z) / kDeg, 30, 1e-9);
    EXPECT_NEAR(t.x, 0, 1e-15);
    // A corner: D = sin(h) r + sin(v) u + cos(h) cos(v) d exactly.
    const Vec3 c = cam.generateRay(0, 0, {}, 0).direction;
    EXPECT_NEAR(c.x, -std::sin(60 * kDeg), 1e-15);
    EXPECT_NEAR(c.y, std::sin(30 * kDeg), 1e-15);
    EXPECT_NEAR(c.z, std::cos(60 * kDeg) * std::cos(30 * kDeg), 1e-15);
}

TEST(CameraMapping, PanoramicHorizontalAngleIsProportionalToX) {
    const ResolvedCamera cam = axisCamera(CameraMapping::Panoramic, std::nullopt, 360, 100);
    // 180 degrees across the image: the longitude is (px / width - 1/2) 180.
    for (double px : {0.0, 30.0, 90.0, 180.0, 275.0, 360.0}) {
        const Vec3 d = cam.generateRay(px, 50, {}, 0).direction;
        EXPECT_NEAR(std::atan2(d.x, d.z) / kDeg, (px / 360 - 0.5) * 180, 1e-9) << px;
        EXPECT_NEAR(d.y, 0, 1e-15);
    }
    // Vertically tan(q), q = 2 y0 90 degrees: y0 = 1/4 is 45 degrees up.
    EXPECT_NEAR(degreesBetween(cam.generateRay(180, 25, {}, 0).direction, {0, 1, 1}), 0, 1e-9);
    // The poles: POV-Ray's tan(90 degrees) stand-in, finite.
    const Vec3 pole = cam.generateRay(180, 0, {}, 0).direction;
    EXPECT_TRUE(isFinite(pole));
    EXPECT_GT(pole.y, 1e9);
}

TEST(CameraMapping, CylindersBendOneAxis) {
    CameraSpec spec;
    spec.angle = 90;
    spec.right = Vec3(2, 0, 0);
    spec.up = {0, 3, 0};
    spec.direction = {0, 0, 5}; // only its direction counts
    const auto camera = [&](CameraMapping m) {
        spec.mapping = m;
        return resolveCamera(spec, 100, 100);
    };
    // Cylinder 1 (axis up): longitude x0 angle, height y0 |up| per unit of distance from the axis.
    const ResolvedCamera c1 = camera(CameraMapping::Cylinder1);
    for (double px : {0.0, 20.0, 100.0}) {
        const Vec3 d = c1.generateRay(px, 25, {}, 0).direction;
        EXPECT_NEAR(std::atan2(d.x, d.z) / kDeg, (px / 100 - 0.5) * 90, 1e-9) << px;
        EXPECT_NEAR(d.y / std::hypot(d.x, d.z), 0.25 * 3, 1e-12) << px;
    }
    // Cylinder 2 (axis right): latitude y0 angle, x0 |right| sideways.
    const ResolvedCamera c2 = camera(CameraMapping::Cylinder2);
    const Vec3 d2 = c2.generateRay(75, 0, {}, 0).direction;
    EXPECT_NEAR(std::atan2(d2.y, d2.z) / kDeg, 45, 1e-9);
    EXPECT_NEAR(d2.x / std::hypot(d2.y, d2.z), 0.25 * 2, 1e-12);
    // Cylinder 3: horizontal rays (longitude x0 angle) from heights y0 |up|.
    const Ray r3 = camera(CameraMapping::Cylinder3).generateRay(100, 0, {}, 0);
    EXPECT_NEAR(r3.origin.y, 1.5, 1e-12);
    EXPECT_NEAR(r3.direction.y, 0, 1e-15);
    EXPECT_NEAR(std::atan2(r3.direction.x, r3.direction.z) / kDeg, 45, 1e-9);
    // Cylinder 4: rays in the up-direction plane (latitude y0 angle) from x0 |right| along right.
    const Ray r4 = camera(CameraMapping::Cylinder4).generateRay(0, 100, {}, 0);
    EXPECT_NEAR(r4.origin.x, -1, 1e-12);
    EXPECT_NEAR(r4.direction.x, 0, 1e-15);
    EXPECT_NEAR(std::atan2(r4.direction.y, r4.direction.z) / kDeg, -45, 1e-9);
}

TEST(CameraMapping, SphericalIsLongitudeAndLatitude) {
    // Defaults 360 x 180: the whole sphere.
    const ResolvedCamera all = axisCamera(CameraMapping::Spherical, std::nullopt, 200, 100);
    EXPECT_LT(degreesBetween(all.generateRay(150, 50, {}, 0).direction, {1, 0, 0}), 1e-9);
    EXPECT_LT(degreesBetween(all.generateRay(50, 50, {}, 0).direction, {-1, 0, 0}), 1e-9);
    EXPECT_LT(degreesBetween(all.generateRay(0, 50, {}, 0).direction, {0, 0, -1}), 1e-9);
    EXPECT_LT(degreesBetween(all.generateRay(100, 0, {}, 0).direction, {0, 1, 0}), 1e-9);
    EXPECT_LT(degreesBetween(all.generateRay(100, 100, {}, 0).direction, {0, -1, 0}), 1e-9);
    // angle 120, 60: (px, py) at x0 = 0.25, y0 = 0.25 is longitude 30, latitude 15.
    const ResolvedCamera part = axisCamera(CameraMapping::Spherical, 120, 200, 100, 60);
    const Vec3 d = part.generateRay(150, 25, {}, 0).direction;
    EXPECT_NEAR(std::atan2(d.x, d.z) / kDeg, 30, 1e-9);
    EXPECT_NEAR(std::asin(d.y / length(d)) / kDeg, 15, 1e-9);
    // One angle: the vertical is half of it.
    const ResolvedCamera half = axisCamera(CameraMapping::Spherical, 120, 200, 100);
    EXPECT_NEAR(half.verticalAngle, 60 * kDeg, 1e-15);
}

TEST(CameraMapping, NoLensAndNoOrthographic) {
    CameraSpec spec;
    spec.mapping = CameraMapping::Fisheye;
    spec.aperture = 0.5;
    EXPECT_THROW(resolveCamera(spec, 10, 10), RenderError);
    spec.aperture = 0;
    spec.orthographic = true;
    EXPECT_THROW(resolveCamera(spec, 10, 10), RenderError);
}

TEST(CameraMapping, FisheyeRendersBlackOutsideItsCircle) {
    Scene scene;
    scene.camera.mapping = CameraMapping::Fisheye;
    scene.camera.angle = 180;
    scene.camera.right = Vec3(1, 0, 0);
    scene.background = Color(0.5);
    scene.render.filter = "box";
    RenderOptions o;
    o.width = o.height = 20;
    o.samplesPerPixel = 4;
    o.threads = 1;
    const RenderResult r = render(scene, o);
    EXPECT_FLOAT_EQ(r.color.at(10, 10, 0), 0.5f);
    EXPECT_FLOAT_EQ(r.color.at(0, 0, 0), 0.0f);
    EXPECT_FLOAT_EQ(r.color.at(19, 19, 1), 0.0f);
}

std::optional<Scene> loadPov(const std::string& text, Diagnostics& diags);

// POV-Ray's omnimax (render/camera.h): theta(rho) = 1.411269 rho - 0.09439 rho^3 + 0.25674 rho^5.
double omnimaxTheta(double rho) { return 1.411269 * rho - 0.09439 * std::pow(rho, 3) + 0.25674 * std::pow(rho, 5); }

// An omnimax camera along z with right = x * width / height (the aspect it fits to its dome) and up = y.
ResolvedCamera omnimaxCamera(int width, int height) {
    CameraSpec spec;
    spec.mapping = CameraMapping::Omnimax;
    spec.right = Vec3(double(width) / height, 0, 0);
    return resolveCamera(spec, width, height);
}

TEST(CameraMapping, OmnimaxOnASquareImage) {
    const ResolvedCamera cam = omnimaxCamera(100, 100);
    // The centre looks along the axis.
    EXPECT_LT(degreesBetween(cam.generateRay(50, 50, {}, 0).direction, Vec3(0, 0, 1)), 1e-9);
    // Halfway to the right edge: rho = 0.5, towards +x.
    const Vec3 half = cam.generateRay(75, 50, {}, 0).direction;
    EXPECT_NEAR(degreesBetween(half, Vec3(0, 0, 1)), omnimaxTheta(0.5) / kDeg, 1e-9);
    EXPECT_NEAR(half.y, 0, 1e-12);
    EXPECT_GT(half.x, 0);
    // Up and left: the polar angle of (X, Y) = (-0.4, 0.3).
    const Vec3 d = normalize(cam.generateRay(30, 35, {}, 0).direction);
    const double theta = omnimaxTheta(0.5), phi = kPi - std::asin(0.6);
    EXPECT_NEAR(d.x, std::sin(theta) * std::cos(phi), 1e-12);
    EXPECT_NEAR(d.y, std::sin(theta) * std::sin(phi), 1e-12);
    EXPECT_NEAR(d.z, std::cos(theta), 1e-12);
    // No ray outside the circle (the corners), nor more than 45 degrees below the axis: straight down at
    // rho = 0.9 theta is 77 degrees; at rho = 0.5 (40 degrees) there is one.
    EXPECT_FALSE(cam.covers(2, 2));
    EXPECT_FALSE(cam.covers(50, 95));
    EXPECT_TRUE(cam.covers(50, 75));
    EXPECT_TRUE(cam.covers(50, 5)); // the same distance up
}

TEST(CameraMapping, OmnimaxFitsAWideImageToItsDome) {
    // 4:3, wider than the dome's 1.283458: X is stretched by (4/3) / 1.283458 and the centre row moves down
    // the dome, so the image centre looks up by theta(1 - 1 / 1.283458).
    const ResolvedCamera wide = omnimaxCamera(120, 90);
    const Vec3 centre = normalize(wide.generateRay(60, 45, {}, 0).direction);
    const double theta = omnimaxTheta(1 - 1 / 1.283458);
    EXPECT_NEAR(centre.x, 0, 1e-12);
    EXPECT_NEAR(centre.y, std::sin(theta), 1e-12);
    EXPECT_NEAR(centre.z, std::cos(theta), 1e-12);
    // 1.2:1, narrower than the dome: Y = (Y - 1) / 1.2 + 1.
    const ResolvedCamera mid = omnimaxCamera(120, 100);
    const Vec3 c2 = normalize(mid.generateRay(60, 50, {}, 0).direction);
    EXPECT_NEAR(std::asin(c2.y), omnimaxTheta(1 - 1 / 1.2), 1e-12);
    // Tall (1:2): Y / A = 2 Y0 * 2: the top edge's midpoint is off the circle.
    const ResolvedCamera tall = omnimaxCamera(50, 100);
    EXPECT_FALSE(tall.covers(25, 10));
    EXPECT_TRUE(tall.covers(25, 30));
}

TEST(CameraMapping, OmnimaxInBothDialectsAndTheWriter) {
    for (const bool pov : {true, false}) {
        Diagnostics diags;
        const std::string text = "camera { omnimax location <0, 1, -5> look_at <0, 1, 0> }\n"
                                 "sphere { 0, 1 pigment { rgb 1 } }";
        const auto scene = pov ? loadPov(text, diags) : loadSceneText(text, "o.drt", diags);
        ASSERT_TRUE(scene) << diags.formatAll();
        EXPECT_EQ(diags.warningCount(), 0) << diags.formatAll();
        EXPECT_EQ(scene->camera.mapping, CameraMapping::Omnimax);
        const std::string written = writeDrtScene(*scene);
        EXPECT_NE(written.find("omnimax"), std::string::npos) << written;
        Diagnostics again;
        const auto back = loadSceneText(written, "back.drt", again);
        ASSERT_TRUE(back) << again.formatAll() << written;
        EXPECT_EQ(back->camera.mapping, CameraMapping::Omnimax);
    }
}

struct KeywordCase {
    const char* text;
    CameraMapping mapping;
};

const KeywordCase kKeywords[] = {
    {"fisheye", CameraMapping::Fisheye},       {"ultra_wide_angle", CameraMapping::UltraWideAngle},
    {"panoramic", CameraMapping::Panoramic},   {"cylinder 1", CameraMapping::Cylinder1},
    {"cylinder 2", CameraMapping::Cylinder2}, {"cylinder 3", CameraMapping::Cylinder3},
    {"cylinder 4", CameraMapping::Cylinder4}, {"spherical", CameraMapping::Spherical}};

TEST(CameraMapping, DrtLanguageAndWriterRoundTrip) {
    for (const KeywordCase& k : kKeywords) {
        const bool spherical = k.mapping == CameraMapping::Spherical;
        const std::string text = std::string("camera { ") + k.text + " location <0, 1, -5> look_at 0 angle 200" +
                                 (spherical ? ", 70" : "") + " }";
        Diagnostics diags;
        const auto scene = loadSceneText(text, "m.drt", diags);
        ASSERT_TRUE(scene) << diags.formatAll();
        EXPECT_EQ(scene->camera.mapping, k.mapping) << k.text;
        EXPECT_EQ(scene->camera.angle, 200.0);
        EXPECT_EQ(scene->camera.verticalAngle.has_value(), spherical);
        const std::string written = writeDrtScene(*scene);
        EXPECT_NE(written.find(k.text), std::string::npos) << written;
        Diagnostics again;
        const auto back = loadSceneText(written, "back.drt", again);
        ASSERT_TRUE(back) << again.formatAll() << written;
        EXPECT_EQ(back->camera.mapping, k.mapping);
        EXPECT_EQ(back->camera.angle, scene->camera.angle);
        EXPECT_EQ(back->camera.verticalAngle, scene->camera.verticalAngle);
    }
    // The angle's range follows the camera type, written before or after it.
    Diagnostics d;
    const auto late = loadSceneText("camera { angle 250 fisheye }", "late.drt", d);
    ASSERT_TRUE(late) << d.formatAll();
    EXPECT_EQ(late->camera.mapping, CameraMapping::Fisheye);
    // perspective / orthographic switch back to the planar camera.
    const auto back = loadSceneText("camera { fisheye orthographic }", "o.drt", d);
    ASSERT_TRUE(back) << d.formatAll();
    EXPECT_EQ(back->camera.mapping, CameraMapping::Planar);
    EXPECT_TRUE(back->camera.orthographic);
}

std::optional<Scene> loadPov(const std::string& text, Diagnostics& diags) {
    return loadPovSceneText(text, "m.pov", diags, PovOptions{});
}

TEST(CameraMapping, PovFrontEndLoadsEachCameraWithoutWarnings) {
    for (const KeywordCase& k : kKeywords) {
        const bool spherical = k.mapping == CameraMapping::Spherical;
        Diagnostics diags;
        const auto s = loadPov(std::string("camera { ") + k.text + " location <0, 1, -5> look_at 0 angle 200" +
                                   (spherical ? ", 70" : "") + " }\nsphere { 0, 1 pigment { rgb 1 } }",
                               diags);
        ASSERT_TRUE(s) << diags.formatAll();
        EXPECT_EQ(diags.warningCount(), 0) << k.text << "\n" << diags.formatAll();
        EXPECT_EQ(s->camera.mapping, k.mapping) << k.text;
        // The angle is the mapping's, not a rescaled direction.
        EXPECT_EQ(s->camera.angle, 200.0) << k.text;
        EXPECT_NEAR(length(s->camera.direction), 1, 1e-12) << k.text;
        if (spherical) {
            EXPECT_EQ(s->camera.verticalAngle, 70.0);
        }
        const ResolvedCamera cam = resolveCamera(s->camera, 40, 30);
        EXPECT_LT(degreesBetween(cam.generateRay(20, 15, {}, 0).direction, Vec3(0, -1, 5)), 1e-9) << k.text;
    }
}

TEST(CameraMapping, PovFrontEndErrorsAndIgnoredBlur) {
    Diagnostics bad;
    EXPECT_FALSE(loadPov("camera { cylinder 5 }", bad));
    EXPECT_NE(bad.formatAll().find("m.pov:1:19"), std::string::npos) << bad.formatAll();
    EXPECT_NE(bad.formatAll().find("invalid cylinder camera type: valid are types 1 to 4, got 5"), std::string::npos) << bad.formatAll();
    Diagnostics negative;
    EXPECT_FALSE(loadPov("camera { fisheye angle -10 }", negative));
    EXPECT_NE(negative.formatAll().find("m.pov:1:24"), std::string::npos) << negative.formatAll();
    // Focal blur with a non-planar camera: a warning, and no lens.
    Diagnostics blur;
    const auto s = loadPov("camera { panoramic aperture 0.4 blur_samples 10 focal_point <0, 0, 5> }", blur);
    ASSERT_TRUE(s) << blur.formatAll();
    EXPECT_EQ(blur.warningCount(), 1) << blur.formatAll();
    EXPECT_EQ(s->camera.aperture, 0.0);
    // mesh_camera stays unsupported: a warning, and a perspective camera.
    Diagnostics meshCamera;
    const auto m = loadPov("camera { mesh_camera { 1, 0 } }", meshCamera);
    ASSERT_TRUE(m) << meshCamera.formatAll();
    EXPECT_EQ(meshCamera.warningCount(), 1);
    EXPECT_EQ(m->camera.mapping, CameraMapping::Planar);
}

} // namespace
} // namespace drt

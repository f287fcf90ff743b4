// POV-Ray camera conventions (docs/pov.md) and the thin lens.
#include "render/camera.h"
#include "render/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace drt {
namespace {

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(a, b) / (length(a) * length(b)), -1.0, 1.0)) * 180 / kPi;
}

void expectParallel(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
    EXPECT_NEAR(length(cross(normalize(a), normalize(b))), 0.0, tolerance);
    EXPECT_GT(dot(a, b), 0.0);
}

TEST(Camera, CentreRayFollowsDirection) {
    CameraSpec spec;
    spec.direction = {0, 0, 2.5};
    const ResolvedCamera cam = resolveCamera(spec, 64, 48);
    const Ray ray = cam.generateRay(32, 24, {0.5, 0.5}, 0);
    EXPECT_EQ(ray.origin, spec.location);
    EXPECT_EQ(ray.direction, spec.direction);
}

TEST(Camera, RightDefaultsToImageAspect) {
    const ResolvedCamera cam = resolveCamera(CameraSpec{}, 320, 240);
    EXPECT_DOUBLE_EQ(cam.right.x, 320.0 / 240.0);
    // The top-left corner of the image: direction - right/2 + up/2.
    const Ray corner = cam.generateRay(0, 0, {}, 0);
    EXPECT_DOUBLE_EQ(corner.direction.x, -320.0 / 240.0 / 2);
    EXPECT_DOUBLE_EQ(corner.direction.y, 0.5);
    EXPECT_DOUBLE_EQ(corner.direction.z, 1.0);
}

TEST(Camera, ExplicitRightIsKept) {
    CameraSpec spec;
    spec.right = Vec3(1.33, 0, 0); // what the POV-Ray front end sets
    const ResolvedCamera cam = resolveCamera(spec, 100, 100);
    EXPECT_EQ(cam.right, Vec3(1.33, 0, 0));
}

TEST(Camera, AngleIsTheHorizontalFieldOfView) {
    for (double angle : {30.0, 67.38, 90.0, 150.0}) {
        CameraSpec spec;
        spec.angle = angle;
        const ResolvedCamera cam = resolveCamera(spec, 200, 100);
        const Ray left = cam.generateRay(0, 50, {}, 0);
        const Ray right = cam.generateRay(200, 50, {}, 0);
        EXPECT_NEAR(angleBetween(left.direction, right.direction), angle, 1e-9) << angle;
        EXPECT_NEAR(length(cam.direction), 0.5 * length(cam.right) / std::tan(angle * kPi / 360), 1e-12);
    }
}

TEST(Camera, LookAtAimsTheCentreRayAndKeepsLengths) {
    CameraSpec spec;
    spec.location = {1, 2, 3};
    spec.direction = {0, 0, 1.5};
    spec.up = {0, 2, 0};
    spec.lookAt = Vec3(4, 2, 7);
    const ResolvedCamera cam = resolveCamera(spec, 40, 20);
    expectParallel(cam.generateRay(20, 10, {}, 0).direction, Vec3(3, 0, 4));
    EXPECT_NEAR(length(cam.direction), 1.5, 1e-12);
    EXPECT_NEAR(length(cam.up), 2.0, 1e-12);
    EXPECT_NEAR(length(cam.right), 2.0, 1e-12);
    EXPECT_NEAR(dot(cam.up, cam.direction), 0.0, 1e-12);
    EXPECT_NEAR(dot(cam.right, cam.direction), 0.0, 1e-12);
    EXPECT_GT(cam.up.y, 0.0); // sky = y stays up
}

TEST(Camera, LeftHandedPlusXAppearsOnTheRight) {
    // Looking along +z: the right half of the image sees +x.
    const ResolvedCamera cam = resolveCamera(CameraSpec{}, 10, 10);
    EXPECT_GT(cam.generateRay(9.5, 5, {}, 0).direction.x, 0.0);
    EXPECT_LT(cam.generateRay(0.5, 5, {}, 0).direction.x, 0.0);
    // The top of the image sees +y.
    EXPECT_GT(cam.generateRay(5, 0.5, {}, 0).direction.y, 0.0);

    // Looking back along -z from z = 10, left-handed: +x is now on the left.
    CameraSpec back;
    back.location = {0, 0, 10};
    back.lookAt = Vec3(0, 0, 0);
    const ResolvedCamera turned = resolveCamera(back, 10, 10);
    EXPECT_LT(turned.generateRay(9.5, 5, {}, 0).direction.x, 0.0);
    EXPECT_NEAR(turned.right.x, -1.0, 1e-12);
}

TEST(Camera, NegativeRightIsRightHanded) {
    CameraSpec spec;
    spec.right = Vec3(-1, 0, 0);
    spec.lookAt = Vec3(0, 0, 5);
    const ResolvedCamera cam = resolveCamera(spec, 10, 10);
    EXPECT_NEAR(cam.right.x, -1.0, 1e-12);
    EXPECT_LT(cam.generateRay(9.5, 5, {}, 0).direction.x, 0.0);
}

TEST(Camera, ThinLensRaysConvergeOnTheFocalPlane) {
    CameraSpec spec;
    spec.location = {0, 1, -3};
    spec.lookAt = Vec3(0, 1, 10);
    spec.aperture = 0.5;
    spec.focalDistance = 7.0;
    const ResolvedCamera cam = resolveCamera(spec, 32, 24);
    ASSERT_TRUE(cam.hasLens());
    EXPECT_DOUBLE_EQ(cam.lensRadius, 0.25);
    const Ray pinhole = cam.generateRay(5.3, 17.9, {0.5, 0.5}, 0);
    // Where the pinhole ray crosses the plane z = -3 + 7.
    const Vec3 focus = pinhole.origin + pinhole.direction * (7.0 / pinhole.direction.z);
    for (Vec2 lens : {Vec2{0.1, 0.9}, Vec2{0.99, 0.01}, Vec2{0.3, 0.3}, Vec2{0.0, 0.5}}) {
        const Ray ray = cam.generateRay(5.3, 17.9, lens, 0);
        EXPECT_NEAR(ray.origin.z, -3.0, 1e-12); // the lens lies in the plane of the camera
        EXPECT_LE(length(ray.origin - spec.location), 0.25 + 1e-12);
        const Vec3 hit = ray.origin + ray.direction * ((4.0 - ray.origin.z) / ray.direction.z);
        EXPECT_NEAR(length(hit - focus), 0.0, 1e-12);
    }
    // Lens samples spread over the disc: the corner sample lands on the rim.
    const Ray rim = cam.generateRay(16, 12, {1.0, 0.5}, 0);
    EXPECT_NEAR(length(rim.origin - spec.location), 0.25, 1e-12);
}

TEST(Camera, FocalPointSetsTheFocalDepthByDistance) {
    CameraSpec spec;
    spec.aperture = 1;
    spec.focalPoint = Vec3(3, 0, 4);
    EXPECT_DOUBLE_EQ(resolveCamera(spec, 8, 8).focalDistance, 5.0);
    CameraSpec plain;
    plain.aperture = 1;
    plain.direction = {0, 0, 2};
    EXPECT_DOUBLE_EQ(resolveCamera(plain, 8, 8).focalDistance, 2.0);
}

TEST(Camera, ApertureZeroIsThePinholeBitForBit) {
    CameraSpec pinhole;
    pinhole.location = {0.3, 0.2, -4};
    pinhole.lookAt = Vec3(1, 0, 0);
    pinhole.angle = 50;
    CameraSpec zero = pinhole;
    zero.aperture = 0;
    zero.focalDistance = 3;
    const ResolvedCamera a = resolveCamera(pinhole, 17, 13), b = resolveCamera(zero, 17, 13);
    EXPECT_FALSE(b.hasLens());
    for (Vec2 lens : {Vec2{0.1, 0.7}, Vec2{0.9, 0.2}}) {
        const Ray ra = a.generateRay(3.25, 9.5, {0.5, 0.5}, 0), rb = b.generateRay(3.25, 9.5, lens, 0);
        EXPECT_EQ(ra.origin, rb.origin);
        EXPECT_EQ(ra.direction, rb.direction);
    }
}

TEST(Camera, ShutterTimes) {
    CameraSpec spec;
    spec.shutterOpen = spec.shutterClose = 0.25;
    const ResolvedCamera still = resolveCamera(spec, 4, 4);
    EXPECT_FALSE(still.hasShutter());
    spec.shutterOpen = 0.2;
    spec.shutterClose = 0.6;
    const ResolvedCamera moving = resolveCamera(spec, 4, 4);
    EXPECT_TRUE(moving.hasShutter());
    EXPECT_DOUBLE_EQ(moving.timeAt(0.5), 0.4);
    EXPECT_DOUBLE_EQ(moving.generateRay(2, 2, {}, 0.4).time, 0.4);
}

TEST(Camera, DegenerateInputThrowsInsteadOfNaN) {
    CameraSpec zeroDirection;
    zeroDirection.direction = {0, 0, 0};
    EXPECT_THROW(resolveCamera(zeroDirection, 8, 8), RenderError);

    CameraSpec lookAtSelf;
    lookAtSelf.location = {1, 1, 1};
    lookAtSelf.lookAt = Vec3(1, 1, 1);
    EXPECT_THROW(resolveCamera(lookAtSelf, 8, 8), RenderError);

    CameraSpec skyParallel;
    skyParallel.location = {0, 5, 0};
    skyParallel.lookAt = Vec3(0, 0, 0);
    EXPECT_THROW(resolveCamera(skyParallel, 8, 8), RenderError);

    CameraSpec nanLocation;
    nanLocation.location = {std::nan(""), 0, 0};
    EXPECT_THROW(resolveCamera(nanLocation, 8, 8), RenderError);

    CameraSpec badAngle;
    badAngle.angle = 180;
    EXPECT_THROW(resolveCamera(badAngle, 8, 8), RenderError);

    CameraSpec negativeAperture;
    negativeAperture.aperture = -1;
    EXPECT_THROW(resolveCamera(negativeAperture, 8, 8), RenderError);

    EXPECT_THROW(resolveCamera(CameraSpec{}, 0, 8), RenderError);
}

} // namespace
} // namespace drt

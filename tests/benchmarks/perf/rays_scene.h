// The geometry of the ray-rate benchmark (drt_perf rays), written once and
// handed both to raw Embree (rays_embree.cpp) and to drt (as scene files), so
// that both trace the same rays through the same shapes:
//   spheres: a ground plane and 10 spheres (two rows of five);
//   mesh:    the ground plane and a bumpy sphere of ~1M triangles.
// A pinhole camera with POV-Ray's conventions, one point light, matte
// surfaces (no reflection or refraction: no secondary rays).
#pragma once

#include "core/vec.h"

#include <array>
#include <string>
#include <vector>

namespace drt::perf {

struct RaysSphere {
    Vec3 center;
    double radius = 1;
};

struct RaysScene {
    std::string name;
    Vec3 cameraLocation, cameraLookAt;
    double cameraAngle = 60; // horizontal field of view, degrees
    Vec3 light;
    std::vector<RaysSphere> spheres;
    // Triangle mesh (the "mesh" scene): shared vertices, index triples.
    std::vector<std::array<float, 3>> vertices;
    std::vector<std::array<unsigned, 3>> triangles;
};

RaysScene spheresScene();
// About `triangles` triangles (rounded to a longitude x latitude grid).
RaysScene meshScene(int triangles);

// The scene as drt reads it: `.drt` text for the spheres, POV-Ray `mesh2` text
// for the mesh (compact: shared vertices). `withLight` false: no light source,
// so drt traces camera rays only.
std::string drtSceneText(const RaysScene& scene, bool withLight);
std::string drtSceneExtension(const RaysScene& scene); // ".drt" or ".pov"

// The camera ray through image point (x, y) in pixels (top left 0, 0) of a
// width x height image: POV-Ray's perspective camera, `right` of length
// width/height, `up` of length 1, direction length 0.5 / tan(angle / 2) times |right|.
struct CameraFrame {
    Vec3 origin, forward, right, up;
};
CameraFrame cameraFrame(const RaysScene& scene, int width, int height);
inline Vec3 cameraDirection(const CameraFrame& c, double x, double y, int width, int height) {
    return c.forward + c.right * (x / width - 0.5) + c.up * (0.5 - y / height);
}

} // namespace drt::perf

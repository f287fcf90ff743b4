#include "rays_scene.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::perf {

RaysScene spheresScene() {
    RaysScene s;
    s.name = "spheres";
    s.cameraLocation = {0, 3, -9};
    s.cameraLookAt = {0, 0.6, 2};
    s.cameraAngle = 60;
    s.light = {-6, 10, -6};
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i < 5; ++i)
            s.spheres.push_back({{-4.0 + 2.0 * i + row, 0.8, 4.0 * row}, 0.8});
    return s;
}

RaysScene meshScene(int triangles) {
    RaysScene s = spheresScene();
    s.name = "mesh";
    s.spheres.clear();
    // A sphere of radius 2.5 with bumps, on a longitude x latitude grid of
    // 2 n x n quads (two triangles each; the poles' quads are kept, degenerate
    // halves and all, as a scanned mesh has them).
    const int n = std::max(4, int(std::lround(std::sqrt(triangles / 4.0))));
    const int longitudes = 2 * n, latitudes = n;
    const Vec3 centre{0, 2.5, 2};
    for (int j = 0; j <= latitudes; ++j) {
        const double theta = kPi * j / latitudes;
        for (int i = 0; i < longitudes; ++i) {
            const double phi = 2 * kPi * i / longitudes;
            const double r = 2.5 * (1 + 0.04 * std::sin(12 * theta) * std::sin(12 * phi));
            const Vec3 p = centre + r * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                             std::sin(theta) * std::sin(phi));
            s.vertices.push_back({float(p.x), float(p.y), float(p.z)});
        }
    }
    const auto index = [&](int i, int j) { return unsigned(j * longitudes + (i % longitudes)); };
    for (int j = 0; j < latitudes; ++j)
        for (int i = 0; i < longitudes; ++i) {
            s.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
            s.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return s;
}

std::string drtSceneExtension(const RaysScene& scene) {
    return scene.triangles.empty() ? ".drt" : ".pov";
}

std::string drtSceneText(const RaysScene& scene, bool withLight) {
    const auto vec = [](const Vec3& v) { return fmt::format("<{}, {}, {}>", v.x, v.y, v.z); };
    std::string text;
    const bool pov = !scene.triangles.empty();
    if (pov)
        text += "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n";
    text += fmt::format("camera {{ location {} look_at {} angle {} {}}}\n", vec(scene.cameraLocation),
                        vec(scene.cameraLookAt), scene.cameraAngle,
                        pov ? "right x*image_width/image_height " : "");
    if (withLight)
        text += fmt::format("light_source {{ {}, color rgb 1 }}\n", vec(scene.light));
    text += "background { color rgb <0.3, 0.4, 0.6> }\n";
    const std::string matte = "finish { ambient 0.1 diffuse 0.8 }";
    text += fmt::format("plane {{ y, 0 pigment {{ color rgb 0.7 }} {} }}\n", matte);
    for (const RaysSphere& sphere : scene.spheres)
        text += fmt::format("sphere {{ {}, {} pigment {{ color rgb <0.8, 0.3, 0.2> }} {} }}\n",
                            vec(sphere.center), sphere.radius, matte);
    if (pov) {
        text += fmt::format("mesh2 {{\n  vertex_vectors {{ {}", scene.vertices.size());
        for (const auto& v : scene.vertices)
            text += fmt::format(",\n    <{}, {}, {}>", v[0], v[1], v[2]);
        text += fmt::format("\n  }}\n  face_indices {{ {}", scene.triangles.size());
        for (const auto& t : scene.triangles)
            text += fmt::format(",\n    <{}, {}, {}>", t[0], t[1], t[2]);
        text += fmt::format("\n  }}\n  pigment {{ color rgb <0.3, 0.6, 0.8> }} {}\n}}\n", matte);
    }
    return text;
}

CameraFrame cameraFrame(const RaysScene& scene, int width, int height) {
    CameraFrame c;
    c.origin = scene.cameraLocation;
    const Vec3 forward = normalize(scene.cameraLookAt - scene.cameraLocation);
    // Left-handed, y up: right = up x forward, then up = forward x right.
    const Vec3 right = normalize(cross(Vec3(0, 1, 0), forward));
    const Vec3 up = cross(forward, right);
    const double aspect = double(width) / height;
    c.right = right * aspect;
    c.up = up;
    c.forward = forward * (0.5 * aspect / std::tan(scene.cameraAngle * kPi / 360));
    return c;
}

} // namespace drt::perf

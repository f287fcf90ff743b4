// Scene-building and measuring helpers for the render-level closed-form tests
// (closed_form_test.cpp, closed_form_lights_test.cpp, closed_form_time_test.cpp).
#pragma once

#include "render/render.h"
#include "scene/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace drt::closedform {

// A texture that shows exactly its pigment (no ambient, no diffuse): with
// emission 1 a white object on a black background renders its coverage.
inline Texture emissive(Color color = Color(1)) {
    Texture t;
    t.pigment.color = ColorFT{color, 0, 0};
    t.finish.ambient = Color(0);
    t.finish.diffuse = 0;
    t.finish.emission = Color(1);
    return t;
}

inline RenderOptions options(int width, int height, int spp, const std::string& sampler, uint64_t seed) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.samplesPerPixel = spp;
    o.sampler = sampler;
    o.seed = seed;
    o.threads = 0;
    return o;
}

inline double red(const Image& image, int x, int y) { return image.at(x, y, 0); }

// Area of {(u, v) in [0,1]^2 : a.(u, v) < c}: the unit square clipped by one
// half-plane (Sutherland-Hodgman), then the shoelace formula.
inline double halfPlaneArea(double ax, double ay, double c) {
    const double square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<std::array<double, 2>> out;
    for (int i = 0; i < 4; ++i) {
        const double* p = square[i];
        const double* q = square[(i + 1) % 4];
        const double fp = ax * p[0] + ay * p[1] - c, fq = ax * q[0] + ay * q[1] - c;
        if (fp < 0) out.push_back({p[0], p[1]});
        if ((fp < 0) != (fq < 0)) {
            const double t = fp / (fp - fq);
            out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
        }
    }
    double twice = 0;
    for (size_t i = 0; i < out.size(); ++i) {
        const auto& a = out[i];
        const auto& b = out[(i + 1) % out.size()];
        twice += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * std::fabs(twice);
}

// Least-squares slope of log(y) against log(x).
inline double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// A white diffuse floor y = 0 (diffuse 1, no ambient): with brilliance 1 its
// pixel value is exactly the irradiance sum_lights I cos(theta) the lights
// deliver (POV-Ray's diffuse term has no 1/pi).
inline Object floorPlane() {
    Object o;
    o.shape = Plane{{0, 1, 0}, 0};
    o.texture.edit().pigment.color = ColorFT{Color(1), 0, 0};
    o.texture.edit().finish.ambient = Color(0);
    o.texture.edit().finish.diffuse = 1;
    return o;
}

// A camera whose every ray goes straight down onto `point`, so a 1x1 render
// measures the floor at one point.
inline CameraSpec needleAt(const Vec3& point) {
    CameraSpec c;
    c.location = point + Vec3(0, 1e-3, 0);
    c.direction = {0, -1, 0};
    c.up = Vec3(0, 0, 1) * 1e-9;
    c.right = Vec3(1, 0, 0) * 1e-9;
    return c;
}

inline Light rectangleLight(const Vec3& center, const Vec3& axis1, const Vec3& axis2, Color color, AreaSampling sampling,
                            bool inverseSquare) {
    Light l;
    l.position = center;
    l.color = color;
    l.area = AreaLight{axis1, axis2, 4, 4};
    l.area->sampling = sampling;
    l.areaIllumination = true;
    l.inverseSquare = inverseSquare;
    return l;
}

// Lambert (1760): the irradiance at p (unit normal n) from a polygon of
// uniform radiance L is E = L/2 |sum_i beta_i n.Gamma_i|, where beta_i is the
// angle edge i subtends at p and Gamma_i the unit normal of the plane through
// p and that edge: Gamma_i = normalize(v_i x v_i+1), v_i = corner_i - p.
inline double lambertIrradiance(const Vec3& p, const Vec3& n, const std::vector<Vec3>& corners, double radiance) {
    double sum = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const Vec3 a = normalize(corners[i] - p), b = normalize(corners[(i + 1) % corners.size()] - p);
        const double beta = std::acos(std::clamp(dot(a, b), -1.0, 1.0));
        sum += beta * dot(n, normalize(cross(a, b)));
    }
    return 0.5 * radiance * std::fabs(sum);
}

struct Measure {
    double mean, variance; // of the pixel mean
};

// `lightSamples`: RenderOptions::lightSamples.
inline Measure measureAt(const Scene& base, const Vec3& point, int spp, const std::string& sampler, uint64_t seed,
                         int lightSamples = 1) {
    Scene scene = base;
    scene.camera = needleAt(point);
    scene.camera.shutterOpen = base.camera.shutterOpen; // the base scene's shutter (moving lights)
    scene.camera.shutterClose = base.camera.shutterClose;
    RenderOptions o = options(1, 1, spp, sampler, seed);
    o.lightSamples = lightSamples;
    const RenderResult r = render(scene, o);
    return {red(r.color, 0, 0), red(r.variance, 0, 0)};
}

} // namespace drt::closedform

// Scene-building and measuring helpers for the render-level closed-form tests
// (closed_form_test.cpp, closed_form_lights_test.cpp).
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

} // namespace drt::closedform

#include "render/image_pattern.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

// POV-Ray nudges image coordinates by this, so that x = 0 falls in the first column.
constexpr double kImageEpsilon = 1e-10;

double wrap(double v, double n) {
    const double r = std::fmod(v, n);
    return r < 0 ? (r + n < n ? r + n : 0.0) : r;
}

// Angle around the y axis from +x towards +z, as a fraction of a turn in [0, 1).
double turnAroundY(double x, double z) {
    const double len = std::sqrt(x * x + z * z);
    if (z == 0) return x > 0 ? 0.0 : 0.5;
    const double theta = std::acos(std::clamp(x / len, -1.0, 1.0));
    return (z < 0 ? 2 * kPi - theta : theta) / (2 * kPi);
}

// Image coordinates (u along the width, v up the height, in pixels) of a
// pattern-space point; false when the point is off the map.
bool project(const ImageMap& m, const Vec3& p, double& u, double& v) {
    const double w = m.width, h = m.height;
    switch (m.projection) {
    case ImageMap::Projection::Planar:
        if (m.once && (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1)) return false;
        u = std::fmod(p.x * w, w);
        v = std::fmod(p.y * h, h);
        return true;
    case ImageMap::Projection::Spherical: {
        const double len = length(p);
        if (len == 0) return false;
        const double y = std::clamp(p.y / len, -1.0, 1.0);
        const bool pole = p.x == 0 && p.z == 0;
        u = (pole ? 0.0 : turnAroundY(p.x, p.z)) * w;
        v = (0.5 + std::asin(y) / kPi) * h;
        return true;
    }
    case ImageMap::Projection::Cylindrical:
        if (m.once && (p.y < 0 || p.y > 1)) return false;
        if (p.x == 0 && p.z == 0) return false;
        v = std::fmod(p.y * h, h);
        u = turnAroundY(p.x, p.z) * w;
        return true;
    case ImageMap::Projection::Torus: {
        // Major radius 1: u runs around the y axis, v around the tube.
        const double ring = std::sqrt(p.x * p.x + p.z * p.z);
        if (ring == 0) return false;
        const double dx = ring - 1.0, tube = std::sqrt(dx * dx + p.y * p.y);
        if (tube == 0) return false;
        double phi = std::acos(std::clamp(-dx / tube, -1.0, 1.0));
        if (p.y > 0) phi = 2 * kPi - phi;
        u = turnAroundY(p.x, p.z) * w;
        v = phi / (2 * kPi) * h;
        return true;
    }
    }
    return false;
}

// One texel by (possibly out-of-range) pixel coordinates: repeated, or
// clamped to the edge when the map is shown once.
size_t texelIndex(const ImageMap& m, double x, double y) {
    int ix, iy;
    if (m.once) {
        ix = x < 0 ? 0 : x >= m.width ? m.width - 1 : int(x);
        iy = y < 0 ? 0 : y >= m.height ? m.height - 1 : int(y);
    } else {
        ix = std::min(int(wrap(x, m.width)), m.width - 1);
        iy = std::min(int(wrap(y, m.height)), m.height - 1);
    }
    return size_t(iy) * size_t(m.width) + size_t(ix);
}

ColorFT texel(const ImageMap& m, double x, double y) {
    const size_t i = texelIndex(m, x, y);
    const float* t = &m.rgbt[i * 4];
    const double filter = m.filter.empty() ? m.filterAll : m.filterAll + m.filter[i];
    return ColorFT{Color(t[0], t[1], t[2]), filter, t[3] + m.transmitAll};
}

ColorFT weighted(const ColorFT& c, double k) { return ColorFT{c.rgb * k, c.filter * k, c.transmit * k}; }

ColorFT add(const ColorFT& a, const ColorFT& b) {
    return ColorFT{a.rgb + b.rgb, a.filter + b.filter, a.transmit + b.transmit};
}

// POV-Ray's four-corner interpolation: pixel centres at integer + 0.5.
ColorFT interpolated(const ImageMap& m, double x, double y) {
    x += 0.5, y += 0.5;
    const double ix = std::floor(x), iy = std::floor(y);
    const double p = x - ix, q = y - iy;
    double f[4];
    if (m.interpolation == ImageMap::Interpolation::Bilinear) {
        f[0] = p * q, f[1] = (1 - p) * q, f[2] = p * (1 - q), f[3] = (1 - p) * (1 - q);
    } else { // normalised distance: weights 1 / squared distance to each corner
        const double d[4] = {(1 - p) * (1 - p) + (1 - q) * (1 - q), p * p + (1 - q) * (1 - q),
                             (1 - p) * (1 - p) + q * q, p * p + q * q};
        double sum = 0;
        for (int i = 0; i < 4; ++i) {
            if (d[i] == 0) { // exactly on a corner
                for (int k = 0; k < 4; ++k) f[k] = k == i ? 1 : 0;
                sum = -1;
                break;
            }
            f[i] = 1 / d[i];
            sum += f[i];
        }
        if (sum > 0)
            for (double& k : f) k /= sum;
    }
    ColorFT c = weighted(texel(m, ix, iy), f[0]);
    c = add(c, weighted(texel(m, ix - 1, iy), f[1]));
    c = add(c, weighted(texel(m, ix, iy - 1), f[2]));
    return add(c, weighted(texel(m, ix - 1, iy - 1), f[3]));
}

// POV-Ray's bicubic: Catmull-Rom weights for the four texels around x (in
// texel units, centres at integer + 0.5), in each direction.
void cubicWeights(double p, double f[4]) {
    const double q = 1 - p;
    f[0] = -0.5 * p * q * q;
    f[1] = 0.5 * q * (q * (3 * p + 1) + 1);
    f[2] = 0.5 * p * (p * (3 * q + 1) + 1);
    f[3] = -0.5 * q * p * p;
}

ColorFT bicubic(const ImageMap& m, double x, double y) {
    x += 0.5, y += 0.5;
    const double ix = std::floor(x), iy = std::floor(y);
    double fx[4], fy[4];
    cubicWeights(x - ix, fx);
    cubicWeights(y - iy, fy);
    ColorFT c{Color(0), 0, 0};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) c = add(c, weighted(texel(m, ix + i - 2, iy + j - 2), fx[i] * fy[j]));
    return c;
}

// The texel coordinates of a pattern-space point; false off the map.
bool imageCoordinates(const ImageMap& m, const Vec3& p, double& x, double& y) {
    if (m.width < 1 || m.height < 1) return false;
    double u = 0, v = 0;
    if (!project(m, p, u, v)) return false;
    u += kImageEpsilon, v += kImageEpsilon;
    if (m.once && (u >= m.width || v >= m.height || u < 0 || v < 0)) return false;
    // Image rows run top down: v up the image is row height - v.
    x = wrap(u, m.width), y = wrap(-v, m.height);
    return true;
}

} // namespace

int imageMapIndex(const ImageMap& m, const Vec3& p) {
    double x = 0, y = 0;
    if (m.indices.empty() || !imageCoordinates(m, p, x, y)) return 0;
    return m.indices[texelIndex(m, x, y)];
}

ColorFT imageMapColor(const ImageMap& m, const Vec3& p) {
    const ColorFT clear{Color(1), 0, 1};
    double x = 0, y = 0;
    if (!imageCoordinates(m, p, x, y)) return clear;
    ColorFT c = m.interpolation == ImageMap::Interpolation::None      ? texel(m, x, y)
                : m.interpolation == ImageMap::Interpolation::Bicubic ? bicubic(m, x, y)
                                                                       : interpolated(m, x, y);
    if (m.workingGamma != 1) {
        const double inv = 1.0 / m.workingGamma;
        c.rgb = Color(std::pow(std::max(0.0, c.rgb.r), inv), std::pow(std::max(0.0, c.rgb.g), inv),
                      std::pow(std::max(0.0, c.rgb.b), inv));
    }
    return c;
}

double imagePatternValue(const ImageMap& map, const Vec3& p) {
    const ColorFT c = imageMapColor(map, p);
    if (c.transmit == 1 && c.rgb.r == 1 && c.rgb.g == 1 && c.rgb.b == 1) return 0; // off the map
    return 0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b;
}

} // namespace drt

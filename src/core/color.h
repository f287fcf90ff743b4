// Linear RGB colour, and POV-Ray's five-component colour (rgb + filter + transmit).
#pragma once

#include <algorithm>
#include <cmath>

namespace drt {

struct Color {
    double r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr Color(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Color(double s) : r(s), g(s), b(s) {}

    constexpr Color& operator+=(const Color& o) { r += o.r; g += o.g; b += o.b; return *this; }
    constexpr Color& operator*=(const Color& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    constexpr Color& operator*=(double s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Color&) const = default;
    constexpr double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
};

constexpr Color operator+(Color a, const Color& b) { return a += b; }
constexpr Color operator-(const Color& a, const Color& b) { return {a.r - b.r, a.g - b.g, a.b - b.b}; }
constexpr Color operator*(Color a, const Color& b) { return a *= b; }
constexpr Color operator*(Color a, double s) { return a *= s; }
constexpr Color operator*(double s, Color a) { return a *= s; }
constexpr Color operator/(const Color& a, double s) { return {a.r / s, a.g / s, a.b / s}; }

inline bool isFinite(const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }
constexpr double luminance(const Color& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }
constexpr bool isBlack(const Color& c) { return c.r == 0 && c.g == 0 && c.b == 0; }
inline double maxComponent(const Color& c) { return std::max(c.r, std::max(c.g, c.b)); }

// POV-Ray's colour with filter (light passes tinted by the colour) and transmit
// (light passes untinted). alpha = 1 - filter - transmit weighs the surface's own shading.
struct ColorFT {
    Color rgb;
    double filter = 0;
    double transmit = 0;

    constexpr double opacity() const { return 1.0 - filter - transmit; }
    constexpr bool operator==(const ColorFT&) const = default;
};

} // namespace drt

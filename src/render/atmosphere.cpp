#include "render/atmosphere.h"

#include "render/noise.h"
#include "render/pigment.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

// Antiderivative of the ground-fog density over the height h above the offset.
double groundFogIntegral(double h, double altitude) { return h <= 0 ? h : altitude * std::atan(h / altitude); }

// The fog's turbulence: octaves of |noise| in [-1, 1], weight omega^i at frequency lambda^i.
double fogTurbulence(const Turbulence& t, const Vec3& p) {
    double sum = 0, weight = 1, frequency = 1;
    for (int i = 0; i < std::clamp(t.octaves, 1, 10); ++i) {
        sum += weight * std::abs(2 * noise01(p * frequency) - 1);
        weight *= t.omega;
        frequency *= t.lambda;
    }
    return sum;
}

double plainFogDepth(const Fog& fog, const Vec3& origin, const Vec3& direction, double length);

} // namespace

double fogDepth(const Fog& fog, const Vec3& origin, const Vec3& direction, double length) {
    const double depth = plainFogDepth(fog, origin, direction, length);
    if (!fog.turbulence) return depth;
    const Vec3 mid = (origin + direction * (length / 2)) * fog.turbulence->amount;
    const double k = std::exp(-length / (fog.distance > 0 ? fog.distance : 1e-9)); // by the path length (POV-Ray)
    return depth * (1 - k * std::min(1.0, fogTurbulence(*fog.turbulence, mid) * fog.turbDepth));
}

namespace {

double plainFogDepth(const Fog& fog, const Vec3& origin, const Vec3& direction, double length) {
    if (fog.type == Fog::Type::Constant) return length;
    const double altitude = fog.altitude > 0 ? fog.altitude : 1e-9;
    const Vec3 up = normalize(fog.up);
    const double h0 = dot(origin, up) - fog.offset;
    const double dh = dot(direction, up) * length;
    if (std::abs(dh) < 1e-9 * std::max(1.0, length)) { // level ray: the density at its height
        const double u = h0 / altitude;
        return length * (h0 <= 0 ? 1.0 : 1.0 / (1.0 + u * u));
    }
    return length * (groundFogIntegral(h0 + dh, altitude) - groundFogIntegral(h0, altitude)) / dh;
}

} // namespace

FogEffect fogEffect(const std::vector<Fog>& fogs, const Vec3& origin, const Vec3& direction, double length) {
    FogEffect total;
    // POV-Ray (trace.cpp ComputeFog): every fog acts on the whole segment on its
    // own; their colours add, (1 - T_i) C_i, and what they let through
    // multiplies, T_i ((1 - f_i) + f_i C_i). So the order of fogs does not matter.
    for (const Fog& fog : fogs) {
        const double distance = fog.distance > 0 ? fog.distance : 1e-9;
        const double t = std::clamp(std::max(std::exp(-fogDepth(fog, origin, direction, length) / distance),
                                             fog.color.transmit),
                                    0.0, 1.0);
        const double f = fog.color.filter;
        total.add += (1 - t) * fog.color.rgb;
        total.scale *= t * (Color(1 - f) + f * fog.color.rgb);
    }
    return total;
}

Color skyColor(const Scene& scene, const Vec3& unitDirection) {
    Color result(0);
    Color through(1); // what the layers above let through
    for (auto it = scene.sky.rbegin(); it != scene.sky.rend(); ++it) {
        const ColorFT c = evaluatePigment(*it, unitDirection);
        result += through * (std::max(0.0, c.opacity()) * c.rgb);
        through *= c.rgb * c.filter + Color(c.transmit);
    }
    return result + through * scene.background;
}

} // namespace drt

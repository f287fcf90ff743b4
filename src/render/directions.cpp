#include "render/directions.h"

#include <algorithm>
#include <cmath>

namespace drt {

double lobeExponent(double blur) {
    const double s = std::clamp(blur, 1e-6, 1.0);
    return std::max(0.0, 2.0 / (s * s) - 2.0);
}

bool refract(const Vec3& i, const Vec3& n, double eta, Vec3& transmitted) {
    const double cosI = -dot(i, n);
    const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k < 0) return false;
    transmitted = normalize(eta * i + (eta * cosI - std::sqrt(k)) * n);
    return true;
}

double fresnelDielectric(double cosIncident, double eta) {
    const double cosI = std::clamp(cosIncident, 0.0, 1.0);
    const double sin2T = eta * eta * (1.0 - cosI * cosI);
    if (sin2T >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sin2T);
    // rs = (n1 cosI - n2 cosT)/(n1 cosI + n2 cosT), rp = (n2 cosI - n1 cosT)/(n2 cosI + n1 cosT), divided by n2.
    const double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    const double rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

} // namespace drt

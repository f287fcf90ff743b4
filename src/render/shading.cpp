#include "render/shading.h"

#include "render/directions.h"
#include "sampling/warp.h"

#include <algorithm>
#include <cmath>

namespace drt {

// POV-Ray's empirical Fresnel term for metallic highlights, with x the angle
// between N and L over pi/2: F = 0.014567225 / (x - 1.12)^2 - 0.011612903, in [0, 1].
double metallicFresnel(double cosNL) {
    const double x = std::fabs(std::acos(std::clamp(cosNL, -1.0, 1.0))) / (kPi / 2);
    const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    return std::clamp(f, 0.0, 1.0);
}

Color highlightTerm(const Finish& finish, const ColorFT& pigment, const Vec3& normal, const Vec3& incoming,
                    const Vec3& toLight) {
    const double cosNL = dot(normal, toLight);
    if (!(cosNL > 0)) return Color(0);
    const double highlight = highlightFactor(finish, normal, incoming, toLight);
    if (!(highlight > 0)) return Color(0);
    return highlight * metallicTint(finish.metallic, pigment, cosNL);
}

namespace {

// The mixture's share of Phong's lobe (the rest is Blinn's).
double phongShare(const Finish& finish) {
    const bool phong = finish.phong > 0 && finish.phongSize >= 0;
    const bool blinn = finish.specular > 0 && finish.roughness > 0;
    if (!blinn) return phong ? 1.0 : 0.0;
    if (!phong) return 0.0;
    return finish.phong / (finish.phong + finish.specular);
}

// Blinn's density per steradian of the direction to the light l.
double blinnPdf(const Finish& finish, const Vec3& normal, const Vec3& view, const Vec3& l) {
    const Vec3 sum = view + l;
    const double len = length(sum);
    if (!(len > 0)) return 0;
    const Vec3 h = sum / len;
    const double cosVH = dot(view, h);
    if (!(cosVH > 0)) return 0;
    return lobeAroundPdf(normal, 1.0 / finish.roughness, h) / (4 * cosVH);
}

} // namespace

bool sampleHighlightLobe(const Finish& finish, const Vec3& normal, const Vec3& incoming, Vec2 u, Vec3& direction) {
    const double share = phongShare(finish);
    // One value picks the lobe and, stretched back to [0, 1), places the direction.
    if (u.x < share) {
        u.x = std::min(u.x / share, std::nextafter(1.0, 0.0));
        direction = sampleLobeAround(reflect(incoming, normal), finish.phongSize, u);
        return true;
    }
    if (!(finish.specular > 0 && finish.roughness > 0)) return false;
    u.x = std::min((u.x - share) / (1 - share), std::nextafter(1.0, 0.0));
    const Vec3 h = sampleLobeAround(normal, 1.0 / finish.roughness, u);
    const Vec3 view = -incoming;
    const double cosVH = dot(view, h);
    if (!(cosVH > 0)) return false;
    direction = normalize(2 * cosVH * h - view);
    return true;
}

double highlightLobePdf(const Finish& finish, const Vec3& normal, const Vec3& incoming, const Vec3& direction) {
    const double share = phongShare(finish);
    double pdf = 0;
    if (share > 0) pdf += share * lobeAroundPdf(reflect(incoming, normal), finish.phongSize, direction);
    if (share < 1) pdf += (1 - share) * blinnPdf(finish, normal, -incoming, direction);
    return pdf;
}

Color reflectivity(const Finish& finish, double cosIncident, double eta) {
    // (reflection metallic, which needs the pigment, is applied by the integrator)
    const Color& lo = finish.reflectionMin;
    const Color& hi = finish.reflectionMax;
    if (lo == hi) return lo;
    double blend;
    if (finish.reflectionFresnel)
        blend = fresnelDielectric(cosIncident, eta);
    else
        blend = std::pow(std::clamp(1.0 - cosIncident, 0.0, 1.0), finish.reflectionFalloff);
    return lo + blend * (hi - lo);
}

SpotCones spotCones(const Light& light) {
    SpotCones cones;
    cones.cosFalloff = std::cos(light.falloff * kPi / 180);
    cones.cosRadius = std::cos(light.radius * kPi / 180);
    cones.centreAxis = light.pointAt - light.position;
    cones.centreAxisLength = length(cones.centreAxis);
    return cones;
}

double spotlightAttenuation(const Light& light, const Vec3& lightPosition, const Vec3& point) {
    if (!light.spotlight) return 1;
    return spotlightAttenuation(light, spotCones(light), lightPosition, point);
}

double spotlightAttenuation(const Light& light, const SpotCones& cones, const Vec3& lightPosition,
                            const Vec3& point, bool atCentre) {
    if (!light.spotlight) return 1;
    const Vec3 axis = atCentre ? cones.centreAxis : light.pointAt - lightPosition;
    const Vec3 toPoint = point - lightPosition;
    const double axisLength = atCentre ? cones.centreAxisLength : length(axis), pointDistance = length(toPoint);
    if (!(axisLength > 0) || !(pointDistance > 0)) return 0;
    const double cosAngle = dot(axis, toPoint) / (axisLength * pointDistance);
    if (!(cosAngle > 0)) return 0;
    const double cosFalloff = cones.cosFalloff, cosRadius = cones.cosRadius;
    if (cosAngle < cosFalloff) return 0; // outside the cone: no tightness power needed
    double attenuation = light.tightness > 0 ? std::pow(cosAngle, light.tightness) : 1.0;
    if (cosAngle < cosRadius && cosRadius > cosFalloff) {
        const double t = (cosAngle - cosFalloff) / (cosRadius - cosFalloff);
        attenuation *= t * t * (3 - 2 * t); // smoothstep from the falloff cone to the radius cone
    }
    return attenuation;
}

// spotlightAttenuation at the centre is 0 where d = axis . toPoint is not
// positive (cosAngle has its sign, or is NaN) and where cosAngle < cosFalloff.
// The latter is certain when d^2 < (1 - 1e-9) c^2 |axis|^2 |toPoint|^2 with c =
// cosFalloff > 0, all finite: the computed cosAngle is within a few ulps of
// d / (|axis| |toPoint|) < c sqrt(1 - 1e-9).
bool outsideSpotCone(const Light& light, const SpotCones& cones, const Vec3& point) {
    if (!light.spotlight) return false;
    const Vec3 toPoint = point - light.position;
    const double d = dot(cones.centreAxis, toPoint);
    if (!(d > 0)) return true;
    const double c = cones.cosFalloff;
    if (!(c > 0)) return false;
    const double axis2 = cones.centreAxisLength * cones.centreAxisLength;
    const double bound = (1 - 1e-9) * (c * c) * axis2 * dot(toPoint, toPoint);
    return std::isfinite(bound) && d * d < bound;
}

double fadeAttenuation(const Light& light, double distance) {
    if (!(light.fadeDistance > 0) || !(light.fadePower > 0)) return 1;
    return 2.0 / (1.0 + std::pow(distance / light.fadeDistance, light.fadePower));
}

Color interiorAttenuation(const Interior& interior, double distance) {
    if (!(interior.fadeDistance > 0) || !std::isfinite(interior.fadePower) || !(distance >= 0)) return Color(1);
    const double x = distance / interior.fadeDistance;
    const Color& c = interior.fadeColor;
    if (interior.fadePower >= 1000)
        return Color(std::exp(-(1 - c.r) * x), std::exp(-(1 - c.g) * x), std::exp(-(1 - c.b) * x));
    const double a = 1.0 / (1.0 + std::pow(x, interior.fadePower));
    return c + a * (Color(1) - c);
}

} // namespace drt

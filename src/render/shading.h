// POV-Ray 3.7's classic finish model and light attenuation, as pure functions
// (docs/language.md, finishes; docs/pov.md). With P the pigment colour,
// alpha = 1 - filter - transmit, N the normal facing the viewer, I the unit
// incoming ray direction, L the unit direction to the light and I_L the light's
// colour x visibility x attenuation:
//   ambient + emission  P (ambient ambient_light + emission) alpha
//   diffuse             diffuse (N.L)^brilliance alpha P I_L
//   Phong               phong max(R.L, 0)^phong_size I_L, R = I - 2 (I.N) N
//   Blinn specular      specular max(N.H, 0)^(1/roughness) I_L, H = normalize(L - I)
//   metallic m          highlights tinted: I_L (1 + m (1 - F) (P - 1)), F POV-Ray's empirical Fresnel
#pragma once

#include "core/color.h"
#include "core/vec.h"
#include "render/directions.h"
#include "scene/scene.h"

#include <cmath>

namespace drt {

// ambientTerm and lightTerm are inline (below): every shaded point calls them.
Color ambientTerm(const Finish& finish, const ColorFT& pigment, const Color& ambientLight);

// Diffuse + Phong + specular from one light, or black when N.L <= 0.
// `crandU` in [0, 1): POV-Ray's crand noise, the diffuse factor becomes
// (diffuse (N.L)^brilliance - crandU crand) alpha (it may go negative, as in POV-Ray).
// `highlightScale` multiplies the highlights alone (an area light's
// multiple importance weight, lighting.cpp).
Color lightTerm(const Finish& finish, const ColorFT& pigment, const Vec3& normal, const Vec3& incoming,
                const Vec3& toLight, const Color& lightIntensity, double crandU = 0, double highlightScale = 1);

// ---------------------------------------------------------------- highlights as a lobe
// For multiple importance sampling of area lights' highlights (lighting.h):
// the highlight factor of lightTerm alone, and a density of directions that
// follows it. With both highlights the density is their mixture, weighted by
// phong and specular: Phong's lobe cos^phong_size about the mirror direction
// R, and Blinn's about the normal, (e + 1)/(2 pi) (N.H)^e per steradian of
// the half vector H, e = 1/roughness, which is (e + 1)/(2 pi) (N.H)^e / (4 V.H)
// per steradian of L = 2 (V.H) H - V, V = -I (zero where V.H <= 0).

// Whether the finish has a highlight (phong, or specular with a roughness).
inline bool hasHighlight(const Finish& finish) {
    return (finish.phong > 0 && finish.phongSize >= 0) || (finish.specular > 0 && finish.roughness > 0);
}

// lightTerm's highlights for a light of intensity 1 in unit direction
// toLight: (Phong + specular) times the metallic tint, black when N.L <= 0.
Color highlightTerm(const Finish& finish, const ColorFT& pigment, const Vec3& normal, const Vec3& incoming,
                    const Vec3& toLight);

// A unit direction drawn from the finish's highlight lobe with u in
// [0,1)^2, and its density per steradian (highlightLobePdf). False where the
// draw gives no direction (Blinn's half vector facing away from the viewer).
bool sampleHighlightLobe(const Finish& finish, const Vec3& normal, const Vec3& incoming, Vec2 u, Vec3& direction);
double highlightLobePdf(const Finish& finish, const Vec3& normal, const Vec3& incoming, const Vec3& direction);

// How much of a ray is reflected: reflection min..max blended by Fresnel
// (reflection_fresnel, with eta = n_incident / n_transmitted) or by
// (1 - cos)^falloff. cosIncident = -I.N.
Color reflectivity(const Finish& finish, double cosIncident, double eta);

// POV-Ray's metallic tint 1 + m (1 - F) (P - 1), with F its empirical
// Fresnel term of the angle whose cosine is given (N.L for highlights, the
// incidence angle for `reflection { metallic m }`).
// Inline: a call returning a Color through memory, read back at once, costs
// a highlight more than the tint's arithmetic (the plain finish's 1).
double metallicFresnel(double cosAngle);
inline Color metallicTint(double metallic, const ColorFT& pigment, double cosAngle) {
    if (!(metallic > 0)) return Color(1);
    const double k = metallic * (1.0 - metallicFresnel(cosAngle));
    return Color(1) + k * (pigment.rgb - Color(1));
}

// Spotlight factor at `point` for a light at `lightPosition`: tightness power
// of cos, times smoothstep from the falloff cone (0) to the radius cone (1).
// 1 for non-spotlights.
double spotlightAttenuation(const Light& light, const Vec3& lightPosition, const Vec3& point);

// What spotlightAttenuation computes from the light alone at each call: the
// cosines of the falloff and radius angles and the axis from the light's own
// position. A caller that shades many points with one light computes them
// once (the same values to the bit); `atCentre` says lightPosition is the
// light's position, whose axis is then taken from here.
struct SpotCones {
    double cosFalloff = 1, cosRadius = 1;
    Vec3 centreAxis{0, 0, 0};
    double centreAxisLength = 0;
};
SpotCones spotCones(const Light& light);
// Whether spotlightAttenuation(light, cones, light.position, point, true) is
// surely 0 (the point lies outside the falloff cone about the centre's axis):
// found without a square root or a division, and false wherever that is not
// certain (then the attenuation itself decides).
bool outsideSpotCone(const Light& light, const SpotCones& cones, const Vec3& point);
double spotlightAttenuation(const Light& light, const SpotCones& cones, const Vec3& lightPosition, const Vec3& point,
                            bool atCentre = false);

// POV-Ray's fade: 2 / (1 + (distance/fade_distance)^fade_power); 1 without fade.
double fadeAttenuation(const Light& light, double distance);

// Interior fade over a path of `distance` inside an object (POV-Ray 3.7), per
// channel, with x = distance / fade_distance (no fade when fade_distance <= 0):
//   fade_power >= 1000:  exp(-(1 - fade_colour) x)
//   otherwise:           fade_colour + (1 - fade_colour) / (1 + x^fade_power)
// (so fade_power 0 halves what is not fade_colour, as in POV-Ray).
Color interiorAttenuation(const Interior& interior, double distance);

inline Color ambientTerm(const Finish& finish, const ColorFT& pigment, const Color& ambientLight) {
    return pigment.rgb * (finish.ambient * ambientLight + finish.emission) * pigment.opacity();
}

// Phong + specular for unit toLight, before the tint and the light's colour.
inline double highlightFactor(const Finish& finish, const Vec3& normal, const Vec3& incoming, const Vec3& toLight) {
    double highlight = 0;
    if (finish.phong > 0) {
        const double cosRL = dot(reflect(incoming, normal), toLight);
        if (cosRL > 0) highlight += finish.phong * std::pow(cosRL, finish.phongSize);
    }
    if (finish.specular > 0 && finish.roughness > 0) {
        const Vec3 h = toLight - incoming;
        const double len = length(h);
        if (len > 0) {
            const double cosNH = dot(normal, h / len);
            if (cosNH > 0) highlight += finish.specular * std::pow(cosNH, 1.0 / finish.roughness);
        }
    }
    return highlight;
}

inline Color lightTerm(const Finish& finish, const ColorFT& pigment, const Vec3& normal, const Vec3& incoming,
                       const Vec3& toLight, const Color& lightIntensity, double crandU, double highlightScale) {
    const double cosNL = dot(normal, toLight);
    if (!(cosNL > 0)) return Color(0);
    Color result(0);
    if (finish.diffuse != 0) {
        // pow(x, 1) is x exactly: brilliance 1, the default, needs no pow.
        const double shaped = finish.brilliance == 1 ? cosNL : std::pow(cosNL, finish.brilliance);
        const double d = (finish.diffuse * shaped - crandU * finish.crand) * pigment.opacity();
        result += d * pigment.rgb * lightIntensity;
    }
    const double highlight = highlightFactor(finish, normal, incoming, toLight);
    // (x * 1 is x: a scale of 1 leaves the bits as they were)
    if (highlight > 0)
        result += (highlight * highlightScale) * metallicTint(finish.metallic, pigment, cosNL) * lightIntensity;
    return result;
}

} // namespace drt

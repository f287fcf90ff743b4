// Geometric optics used by the integrator: mirror and Snell directions, the
// dielectric Fresnel term, and drt's blur-to-lobe-exponent rule. The sampling
// maps themselves (discs, lobes) are in sampling/warp.h.
#pragma once

#include "core/vec.h"

namespace drt {

// The exponent n of the lobe cos^n(theta) around an ideal direction for a drt
// blur s in (0, 1]: n = 2/s^2 - 2 (s = 1 is the uniform hemisphere, n = 0).
double lobeExponent(double blur);

// Mirror of incoming direction i about unit normal n: i - 2 (i.n) n.
inline Vec3 reflect(const Vec3& i, const Vec3& n) { return i - 2.0 * dot(i, n) * n; }

// Snell refraction of unit incoming i through unit normal n facing against i,
// with eta = n_incident / n_transmitted. Returns false on total internal reflection.
bool refract(const Vec3& i, const Vec3& n, double eta, Vec3& transmitted);

// Unpolarised Fresnel reflectance of a dielectric interface for the cosine of
// the incidence angle and eta = n_incident / n_transmitted (1 on total internal reflection).
double fresnelDielectric(double cosIncident, double eta);

} // namespace drt

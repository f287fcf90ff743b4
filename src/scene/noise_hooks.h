// The renderer's noise for the front end, which evaluates POV-Ray's
// vturbulence(lambda, omega, octaves, point) while parsing: render/noise.h's
// turbulence (of amount 1), set by
// src/render when it is linked (render/function_hooks.cpp), as the function
// hooks of scene/function.h are. Without them the front end cannot evaluate
// the call and says so.
#pragma once

#include "core/vec.h"

namespace drt {

struct NoiseHooks {
    Vec3 (*turbulence)(double lambda, double omega, int octaves, const Vec3& p) = nullptr;
};
void setNoiseHooks(const NoiseHooks& hooks);
NoiseHooks noiseHooks(); // null members until set

} // namespace drt

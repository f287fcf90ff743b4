// The renderer's side of user-defined functions (scene/function.h): noise,
// and the value of a function's pattern or pigment body, given to the
// function evaluator when this library is linked.
#include "render/function_hooks.h"

#include "render/noise.h"
#include "render/pigment.h"
#include "scene/noise_hooks.h"

namespace drt {

namespace {

double functionNoise(const Vec3& p) { return noise01(p); }

// A pattern's value in [0, 1]; a block pattern's is its index (checker 0 or 1).
double functionPattern(const Pigment& pattern, const Vec3& p) {
    const PatternSample s = samplePattern(pattern, p);
    return s.block ? double(s.index) : s.value;
}

double functionColour(const Pigment& pigment, const Vec3& p, int channel) {
    const ColorFT c = evaluatePigment(pigment, p);
    switch (channel) {
    case 0: return c.rgb.r;
    case 1: return c.rgb.g;
    case 2: return c.rgb.b;
    case 3: return c.filter;
    case 4: return c.transmit;
    default: return 0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b; // POV-Ray's gray
    }
}

// vturbulence(lambda, omega, octaves, p): the turbulence that warps patterns, of amount 1.
Vec3 functionTurbulence(double lambda, double omega, int octaves, const Vec3& p) {
    Turbulence t;
    t.amount = Vec3(1.0);
    t.lambda = lambda;
    t.omega = omega;
    t.octaves = octaves;
    return turbulenceOffset(t, p);
}

} // namespace

bool installFunctionHooks() {
    static const bool installed = [] {
        setFunctionHooks({functionNoise, functionPattern, functionColour});
        setNoiseHooks({functionTurbulence});
        return true;
    }();
    return installed;
}

namespace {
const bool kInstalled = installFunctionHooks();
}

} // namespace drt

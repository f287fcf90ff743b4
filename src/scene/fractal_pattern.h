// POV-Ray's fractal patterns (mandel, julia, magnet 1|2 mandel|julia) as the
// scene model holds them; their value is render/pattern_fractal.h's. The
// pattern lives in the x-y plane of pattern space (z is ignored).
#pragma once

namespace drt {

enum class FractalKind {
    Mandel,        // z <- z^exponent + p, from z = p
    Julia,         // z <- z^exponent + c, from z = p
    Magnet1Mandel, // z <- ((z^2 + p - 1) / (2z + p - 2))^2, from z = 0
    Magnet1Julia,  // the same with c for p, from z = p
    Magnet2Mandel, // z <- ((z^3 + 3(p-1)z + (p-1)(p-2)) / (3z^2 + 3(p-2)z + (p-1)(p-2) + 1))^2, from z = 0
    Magnet2Julia,  // the same with c for p, from z = p
};

struct FractalPattern {
    FractalKind kind = FractalKind::Mandel;
    long long iterations = 0; // POV-Ray's ITERATIONS (>= 0)
    int exponent = 2;         // mandel and julia: 2 to 33
    double cx = 0, cy = 0;    // julia's complex constant
    // POV-Ray's colouring of points that escape (exterior, types 0-8) and of
    // points that do not (interior, types 0-6), each with its factor.
    int exteriorType = 1;
    double exteriorFactor = 1;
    int interiorType = 0;
    double interiorFactor = 1;
};

inline bool isMagnet(FractalKind k) { return k != FractalKind::Mandel && k != FractalKind::Julia; }
inline bool isJuliaForm(FractalKind k) {
    return k == FractalKind::Julia || k == FractalKind::Magnet1Julia || k == FractalKind::Magnet2Julia;
}

} // namespace drt

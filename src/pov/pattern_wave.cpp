// POV-Ray's pattern value modifiers: frequency, phase and the wave types.
#include "pov/parser.h"

namespace drt::pov {

// frequency float, phase float, ramp_wave, triangle_wave, sine_wave,
// scallop_wave, cubic_wave, poly_wave [float]: consumed with their value when
// the peeked token `t` is one of them.
bool PovParser::waveModifier(const Tok& t, PatternWave& wave) {
    if (t.kind != TokKind::Word) return false;
    const std::string& w = t.text;
    if (w == "frequency" || w == "phase") {
        next();
        (w == "frequency" ? wave.frequency : wave.phase) = floatExpr();
        return true;
    }
    if (const std::optional<WaveKind> named = waveKindNamed(w)) {
        const WaveKind kind = *named;
        next();
        wave.kind = kind;
        if (kind == WaveKind::Poly) {
            wave.exponent = 1; // POV-Ray's default exponent
            const Tok e = peek();
            if (e.kind == TokKind::Number || e.is("(") || e.is("-")) {
                const double exponent = floatExpr();
                if (exponent > 0) {
                    wave.exponent = exponent;
                } else {
                    warnOnce("poly_wave-exponent", e.loc,
                             "a 'poly_wave' exponent that is not positive is not supported; 1 is used");
                }
            }
        }
        return true;
    }
    return false;
}

} // namespace drt::pov

namespace drt::pov {

// After 'warp' (the peeked token `t`): `warp { turbulence ... }` before any
// transform of the pattern is the pattern's turbulence (both warp the
// untransformed pattern point first); other warps are warnings.
void PovParser::warpBlock(const Tok& t, Pigment& p) {
    next();
    expectSymbol("{", "after 'warp'");
    if (!peek().isWord("turbulence")) {
        warnOnce("warp", t.loc, "'warp' is not supported and is ignored");
        skipBlock();
        return;
    }
    Turbulence turbulence;
    while (patternModifier(peek(), turbulence)) {
    }
    expectSymbol("}", "to end 'warp { turbulence ... }'");
    if (p.toWorld.isIdentity() && p.turbulence.amount == Vec3(0, 0, 0)) {
        p.turbulence = turbulence;
    } else {
        warnOnce("warp-turbulence", t.loc,
                 "'warp { turbulence }' after a transform or beside 'turbulence' is not supported and is ignored");
    }
}

} // namespace drt::pov

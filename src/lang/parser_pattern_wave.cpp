// Pattern value modifiers: frequency, phase and the wave types.
#include "lang/parser.h"

namespace drt {

const std::vector<std::string>& Parser::waveWords() {
    static const std::vector<std::string> words{"frequency",    "phase",       "ramp_wave", "triangle_wave",
                                                "sine_wave",    "scallop_wave", "cubic_wave", "poly_wave"};
    return words;
}

// wave-item = "frequency" float | "phase" float | "ramp_wave" | "triangle_wave" | "sine_wave"
//           | "scallop_wave" | "cubic_wave" | "poly_wave" [ float ]
// Returns false, consuming nothing, at any other token.
bool Parser::waveItem(PatternWave& wave) {
    if (!check(TokenKind::Identifier)) return false;
    const std::string w = current_.text;
    if (w == "frequency" || w == "phase") {
        advance();
        (w == "frequency" ? wave.frequency : wave.phase) = floatExpr();
        return true;
    }
    if (const std::optional<WaveKind> named = waveKindNamed(w)) {
        const WaveKind kind = *named;
        advance();
        wave.kind = kind;
        if (kind == WaveKind::Poly) {
            wave.exponent = 1; // POV-Ray's default exponent
            if (check(TokenKind::Number) || check(TokenKind::LeftParen) || check(TokenKind::Minus)) {
                const SourceLoc loc = current_.loc;
                wave.exponent = floatExpr("the poly_wave exponent");
                if (!(wave.exponent > 0)) error(loc, "the 'poly_wave' exponent must be positive");
            }
        }
        return true;
    }
    return false;
}

} // namespace drt

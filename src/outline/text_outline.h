// TrueType text -> closed polylines (scene/extrusion.h contours), laid out
// like POV-Ray 3.7's text object (truetype.cpp ProcessNewTTF):
//   - 1 unit is the font's em (font units / unitsPerEm); baseline at y = 0;
//   - the first glyph is shifted so its outline starts at x = 0; each next
//     glyph's origin follows at the previous one's origin plus its advance
//     width plus the pair's kerning (the font's 'kern' table), and after every
//     glyph the pen also moves by the text's offset (x and y);
//   - outlines use FreeType's unhinted font-unit outlines, quadratic and cubic
//     Bezier segments cut into n equal steps with n = ceil(sqrt(max|P''| /
//     (8 tol))), so no chord strays more than tol = kGlyphTolerance em.
#pragma once

#include "scene/extrusion.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace drt {

inline constexpr double kGlyphTolerance = 1e-4;

// POV-Ray's include folder (Debian's povray-includes), where its fonts are.
inline constexpr const char* kPovFontDir = "/usr/share/povray-3.7/include";

// A font that cannot be read, or a string that is not UTF-8.
struct FontError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The first of dir/name for dir in `dirs` that is a regular file (name itself
// when absolute), trying name.ttf too when the name has no extension (as
// POV-Ray does); empty when there is none.
std::string findFontFile(const std::string& name, const std::vector<std::string>& dirs);

// The outline of `text` set in the font at `fontPath`, and if asked the
// glyphs' box (TextSource::boxLower/boxUpper). Throws FontError.
std::vector<std::vector<Vec2>> textContours(const std::string& fontPath, const std::string& text, Vec2 offset,
                                            Vec2* boxLower = nullptr, Vec2* boxUpper = nullptr);

// A text object: the outline extruded along z from 0 to `thickness` (no
// contours for a text of spaces). Throws FontError.
Extrusion makeTextExtrusion(const TextSource& source, double thickness);

} // namespace drt

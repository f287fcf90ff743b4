// POV-Ray's fractal patterns in pigments, normals and patterned textures:
//   mandel ITERATIONS | julia COMPLEX [,] ITERATIONS | magnet 1|2 mandel|julia ...
// and their modifiers exponent, exterior, interior and max_iteration (the
// values: render/pattern_fractal.h).
#include "lang/evaluator.h"

#include <algorithm>
#include <cmath>

namespace drt::lang {

namespace {

constexpr double kMostIterations = 4294967295.0; // POV-Ray's limit, 2^32 - 1

} // namespace

bool Evaluator::isFractalWord(const std::string& word) { return word == "mandel" || word == "julia" || word == "magnet"; }

std::shared_ptr<const FractalPattern> Evaluator::fractalPattern(const Token& keyword) {
    FractalPattern f;
    bool julia = keyword.text == "julia";
    if (keyword.text == "magnet") {
        const SourceLoc typeLoc = peek().loc;
        const double type = floatExpr("the magnet type");
        if (type != 1 && type != 2) fail(typeLoc, "the magnet type must be 1 or 2" + got(type));
        const Token form = next();
        if (!form.isWord("mandel") && !form.isWord("julia")) failExpected(form, "'mandel' or 'julia' after 'magnet " +
                                                                                     std::to_string(int(type)) + "'");
        julia = form.text == "julia";
        f.kind = type == 1 ? (julia ? FractalKind::Magnet1Julia : FractalKind::Magnet1Mandel)
                           : (julia ? FractalKind::Magnet2Julia : FractalKind::Magnet2Mandel);
    } else {
        f.kind = julia ? FractalKind::Julia : FractalKind::Mandel;
    }
    if (julia) {
        const Vec3 c = vectorExpr("the julia constant");
        f.cx = c.x, f.cy = c.y;
        acceptSymbol(",");
    }
    const SourceLoc countLoc = peek().loc;
    const double n = floatExpr("the iteration count");
    if (!(n >= 0 && n <= kMostIterations))
        fail(countLoc, "the iteration count must be between 0 and 4294967295" + got(n));
    f.iterations = static_cast<long long>(n);
    return std::make_shared<const FractalPattern>(f);
}

bool Evaluator::fractalModifier(const Token& t, std::shared_ptr<const FractalPattern>& fractal) {
    if (!fractal || t.kind != TokenKind::Word) return false;
    const std::string& w = t.text;
    if (w != "exponent" && w != "exterior" && w != "interior" && w != "max_iteration") return false;
    next();
    FractalPattern f = *fractal;
    const SourceLoc loc = peek().loc;
    if (w == "exponent") {
        if (isMagnet(f.kind)) fail(t.loc, "'exponent' is only for 'mandel' and 'julia', not for 'magnet'");
        const double e = floatExpr("the exponent");
        // POV-Ray documents 2 to 33 and reads others without a word.
        if (!(e >= 2 && e <= 33 && e == std::floor(e)))
            refuse(loc, "the fractal exponent must be a whole number from 2 to 33" + got(e));
        f.exponent = static_cast<int>(std::clamp(std::isfinite(e) ? e : 2.0, 1.0, 33.0));
    } else if (w == "max_iteration") {
        const double n = floatExpr("the iteration count");
        if (!(n >= 0 && n <= kMostIterations))
            fail(loc, "the iteration count must be between 0 and 4294967295" + got(n));
        f.iterations = static_cast<long long>(n);
    } else {
        const bool exterior = w == "exterior";
        const double type = floatExpr(exterior ? "the exterior type" : "the interior type");
        const int highest = exterior ? 8 : 6;
        if (!(type >= 0 && type <= highest) || type != std::floor(type))
            fail(loc, "the " + w + " type must be a whole number from 0 to " + std::to_string(highest) + got(type));
        expectSymbol(",", "between the ", w, " type and its factor");
        const double factor = floatExpr("the factor");
        (exterior ? f.exteriorType : f.interiorType) = static_cast<int>(type);
        (exterior ? f.exteriorFactor : f.interiorFactor) = factor;
    }
    fractal = std::make_shared<const FractalPattern>(f);
    return true;
}

} // namespace drt::lang

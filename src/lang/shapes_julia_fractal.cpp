// The julia_fractal (scene/julia_fractal.h), in both dialects:
//   julia_fractal { <c_x, c_y, c_z, c_w>
//                   [quaternion | hypercomplex]
//                   [sqr | cube | reciprocal | exp | ln | sin | asin | cos | acos | tan | atan
//                    | sinh | asinh | cosh | acosh | tanh | atanh | pwr(e_x, e_y)]
//                   [max_iteration n] [precision p] [slice <n_x, n_y, n_z, n_w>, distance]
//                   ... object modifiers }
// Defaults are POV-Ray's: c <1, 0, 0, 0>, quaternion sqr, max_iteration 20,
// precision 20, slice <0, 0, 0, 1>, 0. The parameter and the slice normal are
// 4-D vectors (a number stands for all four components). Quaternions iterate
// sqr or cube only; the functions after reciprocal apply to hypercomplex
// numbers.
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

#include <cmath>
#include <utility>

namespace drt::lang {

using writer::number;

namespace {

using Function = JuliaFractal::Function;

const std::vector<std::pair<std::string, Function>>& functionWords() {
    static const std::vector<std::pair<std::string, Function>> words{
        {"sqr", Function::Sqr},     {"cube", Function::Cube},   {"reciprocal", Function::Reciprocal},
        {"exp", Function::Exp},     {"ln", Function::Ln},       {"sin", Function::Sin},
        {"asin", Function::Asin},   {"cos", Function::Cos},     {"acos", Function::Acos},
        {"tan", Function::Tan},     {"atan", Function::Atan},   {"sinh", Function::Sinh},
        {"asinh", Function::Asinh}, {"cosh", Function::Cosh},   {"acosh", Function::Acosh},
        {"tanh", Function::Tanh},   {"atanh", Function::Atanh}, {"pwr", Function::Pwr}};
    return words;
}

// A 4-D vector: a number (all four components) or a vector of up to four
// components, the missing ones 0.
std::array<double, 4> vector4(Evaluator& e, const char* what) {
    const SourceLoc loc = e.peek().loc;
    const Value v = e.expression();
    std::array<double, 4> out{};
    if (v.kind == Value::Kind::Float) {
        out.fill(v.number);
    } else if (v.kind == Value::Kind::Vector && v.size <= 4) {
        for (int i = 0; i < v.size; ++i) out[size_t(i)] = v.v[size_t(i)];
    } else {
        e.fail(loc, std::string("expected ") + what + " (a 4-D vector <x, y, z, w>)");
    }
    for (double c : out)
        if (!std::isfinite(c)) e.fail(loc, std::string(what) + " must be finite");
    return out;
}

std::string vector4Text(const std::array<double, 4>& v) {
    // Appended piece by piece: gcc 12 warns (-Wrestrict, a false positive) on "literal" + a temporary string.
    std::string text = "<";
    for (size_t i = 0; i < 4; ++i) {
        if (i) text += ", ";
        text += number(v[i]);
    }
    return text + ">";
}

} // namespace

template <>
const std::vector<std::string>& ShapeSyntax<JuliaFractal>::keywords() {
    static const std::vector<std::string> w{"julia_fractal"};
    return w;
}

template <>
void ShapeSyntax<JuliaFractal>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    (void)keyword;
    JuliaFractal f;
    f.parameter = vector4(e, "the julia parameter");
    SourceLoc functionLoc = keyword.loc;
    for (;;) {
        const Token item = e.peek();
        if (item.isWord("quaternion") || item.isWord("hypercomplex")) {
            e.next();
            f.algebra = item.text == "quaternion" ? JuliaFractal::Algebra::Quaternion
                                                  : JuliaFractal::Algebra::Hypercomplex;
            continue;
        }
        bool isFunction = false;
        for (const auto& [word, function] : functionWords())
            if (item.isWord(word.c_str())) {
                e.next();
                f.function = function;
                functionLoc = item.loc;
                isFunction = true;
                if (function == Function::Pwr) {
                    e.expectSymbol("(", "after 'pwr'");
                    f.exponent[0] = e.floatExpr("pwr's real exponent");
                    e.expectSymbol(",", "between pwr's two exponents");
                    f.exponent[1] = e.floatExpr("pwr's imaginary exponent");
                    e.expectSymbol(")", "to close 'pwr('");
                }
                break;
            }
        if (isFunction) continue;
        if (item.isWord("max_iteration")) {
            e.next();
            // POV-Ray takes the floor, and 1 for less.
            const SourceLoc loc = e.peek().loc;
            const double n = std::floor(e.floatExpr("max_iteration"));
            if (!(n <= 1e6)) e.fail(loc, "the julia max_iteration must be at most 1000000" + e.got(n));
            if (n < 1) e.refuse(loc, "the julia max_iteration must be at least 1 (POV-Ray takes 1)" + e.got(n));
            f.maxIteration = int(std::fmax(n, 1.0));
        } else if (item.isWord("precision")) {
            e.next();
            const SourceLoc loc = e.peek().loc;
            const double p = e.floatExpr("the julia precision");
            if (!std::isfinite(p)) e.fail(loc, "the julia precision must be finite" + e.got(p));
            if (p < 1) e.refuse(loc, "the julia precision must be at least 1 (POV-Ray takes 1)" + e.got(p));
            f.precision = std::fmax(p, 1.0);
        } else if (item.isWord("slice")) {
            e.next();
            const SourceLoc loc = e.peek().loc;
            std::array<double, 4> n = vector4(e, "the slice normal");
            e.comma("slice normal");
            f.sliceDistance = e.floatExpr("the slice distance");
            const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
            if (!(len > 1e-10)) e.fail(loc, "the slice normal must not be zero");
            if (!(std::fabs(n[3]) > 1e-10))
                e.fail(loc, "the slice normal needs a non-zero fourth (w) component");
            f.slice = n; // as written; the geometry normalises it (accel/julia_fractal_shape.cpp)
        } else {
            break;
        }
    }
    if (f.algebra == JuliaFractal::Algebra::Quaternion && f.function != Function::Sqr &&
        f.function != Function::Cube) {
        std::string name;
        for (const auto& [word, function] : functionWords())
            if (function == f.function) name = word;
        e.fail(functionLoc, "a quaternion julia_fractal iterates 'sqr' or 'cube', not '" + name +
                                "' (add 'hypercomplex' for the other functions)");
    }
    o.object.shape = std::move(f);
}

template <>
std::string ShapeSyntax<JuliaFractal>::head(const JuliaFractal& f, ShapeText& out) {
    (void)out;
    std::string text = "julia_fractal { " + vector4Text(f.parameter);
    text += f.algebra == JuliaFractal::Algebra::Quaternion ? " quaternion " : " hypercomplex ";
    for (const auto& [word, function] : functionWords())
        if (function == f.function) text += word;
    if (f.function == Function::Pwr) {
        text += "(";
        text += number(f.exponent[0]);
        text += ", ";
        text += number(f.exponent[1]);
        text += ")";
    }
    text += " max_iteration " + std::to_string(f.maxIteration) + " precision " + number(f.precision);
    if (f.slice != std::array<double, 4>{0, 0, 0, 1} || f.sliceDistance != 0)
        text += " slice " + vector4Text(f.slice) + ", " + number(f.sliceDistance);
    return text;
}

} // namespace drt::lang

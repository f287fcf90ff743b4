// Expressions: floats, vectors, colours and strings, with POV-Ray's
// precedence (lowest first): ?:, |, &, comparisons, + -, * /, unary, postfix.
#include "pov/parser.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::pov {

using Kind = PovValue::Kind;

const char* kindName(Kind kind) {
    switch (kind) {
    case Kind::Float: return "float";
    case Kind::Vector: return "vector";
    case Kind::Color: return "color";
    case Kind::String: return "string";
    case Kind::Array: return "array";
    case Kind::Object: return "object";
    case Kind::Texture: return "texture";
    case Kind::Pigment: return "pigment";
    case Kind::Finish: return "finish";
    case Kind::Interior: return "interior";
    case Kind::Material: return "material";
    case Kind::Normal: return "normal";
    case Kind::Camera: return "camera";
    case Kind::Light: return "light_source";
    case Kind::Transform: return "transform";
    case Kind::ColorMap: return "color_map";
    case Kind::Macro: return "macro";
    case Kind::Opaque: return "unsupported item";
    case Kind::SkySphere: return "sky_sphere";
    case Kind::Media: return "media";
    }
    return "value";
}

namespace {

int componentsOf(const PovValue& v) { return v.kind == Kind::Float ? 1 : v.size; }

// Float op vector promotes the float to every component (POV-Ray).
PovValue widen(const PovValue& v, int size, Kind kind) {
    PovValue out;
    out.kind = kind;
    out.size = size;
    if (v.kind == Kind::Float) out.v.fill(v.number);
    else out.v = v.v;
    for (int i = componentsOf(v) == 1 ? size : v.size; i < 5; ++i) out.v[i] = 0;
    return out;
}

} // namespace

double PovParser::toFloat(const PovValue& v, SourceLoc loc) {
    if (v.kind == Kind::Float) return v.number;
    fail(loc, std::string("expected a float, found a ") + kindName(v.kind));
}

Vec3 PovParser::toVector(const PovValue& v, SourceLoc loc) {
    if (v.kind == Kind::Float) return Vec3(v.number);
    if (v.kind == Kind::Vector || v.kind == Kind::Color) return {v.v[0], v.v[1], v.v[2]};
    fail(loc, std::string("expected a vector, found a ") + kindName(v.kind));
}

std::array<double, 5> PovParser::toColor(const PovValue& v, SourceLoc loc) {
    if (v.kind == Kind::Float) return {v.number, v.number, v.number, 0, 0};
    if (v.kind == Kind::Vector || v.kind == Kind::Color) {
        std::array<double, 5> c = v.v;
        for (int i = v.size; i < 5; ++i) c[i] = 0;
        return c;
    }
    fail(loc, std::string("expected a color, found a ") + kindName(v.kind));
}

double PovParser::floatExpr() {
    const SourceLoc loc = peek().loc;
    return toFloat(expression(), loc);
}

int PovParser::countExpr(const char* what, double lowest, double highest) {
    const SourceLoc loc = peek().loc;
    return countValue(floatExpr(), loc, what, lowest, highest);
}

int PovParser::countValue(double value, SourceLoc loc, const char* what, double lowest, double highest) {
    if (std::string problem = checkCount(what, value, lowest, highest); !problem.empty()) fail(loc, problem);
    return static_cast<int>(std::trunc(value));
}

Vec3 PovParser::vectorExpr() {
    const SourceLoc loc = peek().loc;
    return toVector(expression(), loc);
}

std::string PovParser::stringExpr() {
    const SourceLoc loc = peek().loc;
    const PovValue v = expression();
    if (v.kind != Kind::String) fail(loc, std::string("expected a string, found a ") + kindName(v.kind));
    return v.text;
}

// color = { colour-expression | ("red"|"green"|"blue"|"filter"|"transmit"|"gray") float }
std::array<double, 5> PovParser::colorExpr() {
    std::array<double, 5> c{};
    bool any = false;
    for (;;) {
        const Tok t = peek();
        static const char* parts[] = {"red", "green", "blue", "filter", "transmit"};
        int part = -1;
        for (int i = 0; i < 5; ++i)
            if (t.isWord(parts[i])) part = i;
        if (part >= 0) {
            next();
            c[size_t(part)] = floatExpr();
            any = true;
            continue;
        }
        if (t.isWord("gray") || t.isWord("grey")) {
            next();
            const double g = floatExpr();
            c[0] = c[1] = c[2] = g;
            any = true;
            continue;
        }
        if (any) return c;
        c = toColor(expression(), t.loc);
        any = true;
    }
}

namespace {

PovValue arithmetic(PovParser& p, const Tok& op, const PovValue& left, const PovValue& right) {
    const std::string& s = op.text;
    if (left.kind == Kind::String || right.kind == Kind::String)
        p.fail(op.loc, "strings are joined with concat(), not '" + s + "'");
    if (!left.isNumeric() || !right.isNumeric())
        p.fail(op.loc, "'" + s + "' needs numbers, found a " + kindName(left.isNumeric() ? right.kind : left.kind));
    auto apply = [&](double a, double b) {
        if (s == "+") return a + b;
        if (s == "-") return a - b;
        if (s == "*") return a * b;
        return a / b; // POV-Ray: division by zero gives a huge value, not an error
    };
    const int size = std::max(componentsOf(left), componentsOf(right));
    if (size == 1 && left.kind == Kind::Float && right.kind == Kind::Float) {
        if (s == "/" && right.number == 0) p.fail(op.loc, "division by zero");
        return PovValue::makeFloat(apply(left.number, right.number));
    }
    const Kind kind = (left.kind == Kind::Color || right.kind == Kind::Color) ? Kind::Color : Kind::Vector;
    const int n = kind == Kind::Color ? 5 : size;
    PovValue a = widen(left, n, kind), b = widen(right, n, kind);
    for (int i = 0; i < n; ++i) {
        if (s == "/" && b.v[size_t(i)] == 0) {
            // <1,2,3>/<1,0,1>: POV-Ray leaves such components huge; drt refuses.
            p.fail(op.loc, "division by zero in a vector component");
        }
        a.v[size_t(i)] = apply(a.v[size_t(i)], b.v[size_t(i)]);
    }
    return a;
}

} // namespace

// Binary operators by level: 1 |, 2 &, 3 comparisons, 4 + -, 5 * /.
static bool isLevelOperator(int level, const Tok& t, bool inVector) {
    if (t.kind != TokKind::Symbol) return false;
    const std::string& s = t.text;
    switch (level) {
    case 1: return s == "|";
    case 2: return s == "&";
    case 3: return s == "<" || s == "<=" || s == "=" || s == "!=" || s == ">=" || (s == ">" && !inVector);
    case 4: return s == "+" || s == "-";
    case 5: return s == "*" || s == "/";
    default: return false;
    }
}

static PovValue binaryLevel(PovParser& p, int level) {
    if (level == 6) {
        const Tok t = p.peek();
        if (t.is("-") || t.is("+") || t.is("!")) {
            p.next();
            PovValue v = binaryLevel(p, 6);
            if (t.is("-")) {
                if (v.kind == Kind::Float) v.number = -v.number;
                else if (v.kind == Kind::Vector || v.kind == Kind::Color) for (double& c : v.v) c = -c;
                else p.fail(t.loc, std::string("cannot negate a ") + kindName(v.kind));
            } else if (t.is("!")) {
                v = PovValue::makeFloat(p.toFloat(v, t.loc) == 0 ? 1 : 0);
            } else if (!v.isNumeric()) {
                p.fail(t.loc, std::string("unary '+' on a ") + kindName(v.kind));
            }
            return v;
        }
        return p.primary();
    }
    PovValue left = binaryLevel(p, level + 1);
    for (;;) {
        const Tok op = p.peekOperator();
        if (!isLevelOperator(level, op, p.inVector_)) return left;
        // POV-Ray's commas are optional: `<a, b, c> <d, e, f>` is two vectors,
        // and a comparison needs floats, so '<' after a vector starts the next one.
        if (level == 3 && op.text == "<" &&
            (left.kind == Kind::Vector || left.kind == Kind::Color || p.countBeforeVector_))
            return left;
        p.next();
        const PovValue right = binaryLevel(p, level + 1);
        if (level >= 4) {
            left = arithmetic(p, op, left, right);
            continue;
        }
        if (level == 3 && left.kind == Kind::String && right.kind == Kind::String) {
            // POV-Ray compares strings only through strcmp(); allow = and != for convenience.
            if (op.text == "=" || op.text == "!=") {
                left = PovValue::makeFloat((left.text == right.text) == (op.text == "="));
                continue;
            }
        }
        const double a = p.toFloat(left, op.loc), b = p.toFloat(right, op.loc);
        const std::string& s = op.text;
        double r = 0;
        // = and != compare with POV-Ray's tolerance EPSILON = 1e-10.
        if (s == "|") r = (a != 0 || b != 0);
        else if (s == "&") r = (a != 0 && b != 0);
        else if (s == "<") r = a < b;
        else if (s == "<=") r = a <= b;
        else if (s == "=") r = std::fabs(a - b) <= 1e-10;
        else if (s == "!=") r = std::fabs(a - b) > 1e-10;
        else if (s == ">=") r = a >= b;
        else r = a > b;
        left = PovValue::makeFloat(r);
    }
}

PovValue PovParser::expression() {
    DepthGuard guard(*this, peek().loc);
    PovValue condition = binaryLevel(*this, 1);
    const Tok q = peekOperator();
    if (!q.is("?")) return condition;
    next();
    const double c = toFloat(condition, q.loc);
    const bool savedInVector = inVector_;
    inVector_ = false;
    PovValue a = expression();
    expectSymbol(":", "in a ?: expression");
    PovValue b = expression();
    inVector_ = savedInVector;
    return c != 0 ? a : b;
}

} // namespace drt::pov

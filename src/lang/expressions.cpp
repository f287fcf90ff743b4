// Expressions: numbers, vectors, colours and strings, with POV-Ray's
// precedence (lowest first): ?:, |, &, comparisons, + -, * /, unary, postfix.
// A number is promoted to a vector wherever a vector is expected (`scale 2`).
#include "lang/evaluator.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

std::string kindName(Value::Kind kind) {
    switch (kind) {
    case Kind::Float: return "a number";
    case Kind::Vector: return "a vector";
    case Kind::Color: return "a colour";
    case Kind::String: return "a string";
    case Kind::Array: return "an array";
    case Kind::Object: return "an object";
    case Kind::Texture: return "a texture";
    case Kind::Pigment: return "a pigment";
    case Kind::Finish: return "a finish";
    case Kind::Interior: return "an interior";
    case Kind::Material: return "a material";
    case Kind::Normal: return "a normal";
    case Kind::Camera: return "a camera";
    case Kind::Light: return "a light_source";
    case Kind::Transform: return "a transform";
    case Kind::ColorMap: return "a color_map";
    case Kind::Macro: return "a macro";
    case Kind::Opaque: return "an unsupported item";
    case Kind::SkySphere: return "a sky_sphere";
    case Kind::Media: return "a media";
    case Kind::Function: return "a function";
    case Kind::Spline: return "a spline";
    }
    return "a value";
}

std::string kindName(const Value& v) {
    if (v.kind == Kind::Object && v.object && v.object->lightOnly && !v.object->lights.empty()) return "a light_source";
    if (v.kind == Kind::Opaque && !v.text.empty()) return "a " + v.text + " (unsupported)";
    return kindName(v.kind);
}

namespace {

int componentsOf(const Value& v) { return v.kind == Kind::Float ? 1 : v.size; }

// A float op vector promotes the float to every component; a shorter vector
// is padded with `pad` (1 for * and /, so the extra components stay as they are).
Value widen(const Value& v, int size, Kind kind, double pad) {
    Value out;
    out.kind = kind;
    out.size = size;
    if (v.kind == Kind::Float) out.v.fill(v.number);
    else out.v = v.v;
    if (v.kind != Kind::Float)
        for (int i = v.size; i < 5; ++i) out.v[size_t(i)] = i < size ? pad : 0;
    return out;
}

} // namespace

double Evaluator::toFloat(const Value& v, SourceLoc loc, const char* what) {
    if (v.kind == Kind::Float) return v.number;
    fail(loc, std::string("expected ") + what + ", found " + kindName(v));
}

Vec3 Evaluator::toVector(const Value& v, SourceLoc loc, const char* what) {
    if (v.kind == Kind::Float) return Vec3(v.number);
    if (v.kind == Kind::Vector || v.kind == Kind::Color) return {v.v[0], v.v[1], v.size > 2 ? v.v[2] : 0.0};
    fail(loc, std::string("expected ") + what + ", found " + kindName(v));
}

std::array<double, 5> Evaluator::toColor(const Value& v, SourceLoc loc) {
    if (v.kind == Kind::Float) return {v.number, v.number, v.number, 0, 0};
    if (v.kind == Kind::Vector || v.kind == Kind::Color) {
        std::array<double, 5> c = v.v;
        for (int i = v.size; i < 5; ++i) c[size_t(i)] = 0;
        return c;
    }
    fail(loc, "expected a colour, found " + kindName(v));
}

double Evaluator::floatExpr(const char* what) {
    const SourceLoc loc = peek().loc;
    const Value v = expression();
    lastOrigin_ = v.origin;
    lastExpressionLoc_ = loc;
    return toFloat(v, loc, what);
}

Vec3 Evaluator::vectorExpr(const char* what) {
    const SourceLoc loc = peek().loc;
    const Value v = expression();
    lastOrigin_ = v.origin;
    lastExpressionLoc_ = loc;
    return toVector(v, loc, what);
}

int Evaluator::intExpr(const char* what) {
    const SourceLoc loc = peek().loc;
    const double d = floatExpr(what);
    if (d != std::floor(d) || std::fabs(d) > 2e9) {
        if (syntax().strictValues) {
            error(loc, std::string(what) + " must be a whole number");
            return 1;
        }
        if (!(std::fabs(d) <= 2e9)) fail(loc, std::string(what) + " is out of range" + got(d));
    }
    return static_cast<int>(d); // POV-Ray truncates
}

int Evaluator::countExpr(const char* what, double lowest, double highest) {
    const SourceLoc loc = peek().loc;
    return countValue(floatExpr(what), loc, what, lowest, highest);
}

int Evaluator::countValue(double value, SourceLoc loc, const char* what, double lowest, double highest) {
    if (std::string problem = checkCount(what, value, lowest, highest); !problem.empty()) fail(loc, problem);
    return static_cast<int>(std::trunc(value));
}

std::string Evaluator::stringExpr() {
    const SourceLoc loc = peek().loc;
    const Value v = expression();
    if (v.kind != Kind::String) fail(loc, "expected a string, found " + kindName(v));
    return v.text;
}

bool Evaluator::optionalBool(bool fallback) {
    const Token n = peekOperator();
    static const char* const words[] = {"on", "off", "true", "false", "yes", "no"};
    bool word = false;
    for (const char* w : words) word = word || n.isWord(w);
    if (word || n.kind == TokenKind::Number || n.is("(")) return floatExpr() != 0;
    if (n.kind == TokenKind::Word) {
        const Cell c = lookup(n.text);
        if (c && c->kind == Kind::Float) return floatExpr() != 0;
    }
    return fallback;
}

// colour = { colour-expression | ("red"|"green"|"blue"|"filter"|"transmit"|"gray") float }
std::array<double, 5> Evaluator::colorExpr() {
    std::array<double, 5> c{};
    bool any = false;
    for (;;) {
        const Token t = peek();
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
        if (any) {
            // `rgb 1 rgbt <0, 0, 0, 0.5>`: in .drt files a colour keyword may follow
            // another one (POV-Ray reads two colours, as in `checker rgb 1 rgb 0`).
            if (syntax().requireCommas && (t.isWord("rgb") || t.isWord("rgbf") || t.isWord("rgbt") || t.isWord("rgbft") || t.isWord("srgb") ||
                t.isWord("srgbf") || t.isWord("srgbt") || t.isWord("srgbft"))) {
                const std::array<double, 5> more = toColor(expression(), t.loc);
                const std::string& w = t.text;
                const std::string form = w[0] == 's' ? w.substr(1) : w;
                const int count = form == "rgb" ? 3 : form == "rgbft" ? 5 : 4;
                const int slots[5] = {0, 1, 2, form == "rgbt" ? 4 : 3, 4};
                for (int i = 0; i < count; ++i) c[size_t(slots[i])] = more[size_t(slots[i])];
                continue;
            }
            return c;
        }
        c = toColor(expression(), t.loc);
        any = true;
    }
}

bool Evaluator::startsColor(const Token& t) const {
    if (t.is("<") || t.kind == TokenKind::Number || t.is("(") || t.is("-")) return true;
    if (t.kind != TokenKind::Word) return false;
    static const std::set<std::string> words = {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf",
                                                "srgbt", "srgbft", "red", "green", "blue", "filter", "transmit",
                                                "gray", "grey"};
    if (words.count(t.text)) return true;
    const Cell c = lookup(t.text);
    if (c && c->kind == Kind::Array) return arrayOfNumbers(*c); // an element of an array of colours (`Colors[2]`)
    return c && c->isNumeric();
}

bool arrayOfNumbers(const Value& array) {
    if (array.kind != Kind::Array || !array.array) return false;
    bool any = false;
    for (const Cell& item : array.array->items) {
        if (!item) continue;
        if (item->kind == Kind::Array ? !arrayOfNumbers(*item) : !item->isNumeric()) return false;
        any = true;
    }
    return any;
}

const Value* arrayItemSample(const Value& array) {
    const Value* v = &array;
    while (v && v->kind == Kind::Array && v->array) {
        const Value* next = nullptr;
        for (const Cell& item : v->array->items)
            if (item) {
                next = item.get();
                break;
            }
        v = next;
    }
    return v;
}

namespace {

Value arithmetic(Evaluator& e, const Token& op, const Value& left, const Value& right) {
    const std::string& s = op.text;
    if (left.kind == Kind::String || right.kind == Kind::String)
        e.fail(op.loc, "strings are joined with concat(), not '" + s + "'");
    if (!left.isNumeric() || !right.isNumeric())
        e.fail(op.loc, "cannot apply '" + s + "' to " + kindName(left.isNumeric() ? right : left));
    // The operator, told once (Token::is: no strlen or memcmp per component).
    const bool plus = op.is("+"), minus = op.is("-"), times = op.is("*"), divide = op.is("/");
    const bool multiplicative = times || divide;
    bool bad = false, divisionByZero = false;
    auto apply = [&](double a, double b) {
        if (divide && b == 0) {
            divisionByZero = true;
            return 1.0;
        }
        const double r = plus ? a + b : minus ? a - b : times ? a * b : a / b;
        if (!std::isfinite(r)) {
            bad = true;
            return 1.0;
        }
        return r;
    };
    Value out;
    if (left.kind == Kind::Float && right.kind == Kind::Float) {
        out = Value::makeFloat(apply(left.number, right.number));
    } else {
        const Kind kind = (left.kind == Kind::Color || right.kind == Kind::Color) ? Kind::Color : Kind::Vector;
        const int n = kind == Kind::Color ? 5 : std::max(componentsOf(left), componentsOf(right));
        Value a = widen(left, n, kind, multiplicative ? 1 : 0), b = widen(right, n, kind, multiplicative ? 1 : 0);
        for (int i = 0; i < n; ++i) a.v[size_t(i)] = apply(a.v[size_t(i)], b.v[size_t(i)]);
        out = std::move(a);
    }
    if (divisionByZero) e.error(op.loc, "division by zero");
    else if (bad) e.error(op.loc, "result of '" + s + "' is not a finite number");
    return out;
}

// Binary operators by level: 1 |, 2 &, 3 comparisons, 4 + -, 5 * /.
bool isLevelOperator(int level, const Token& t, bool inVector) {
    if (t.kind != TokenKind::Symbol) return false;
    // Token::is: literal lengths known at compile time, characters compared in line
    switch (level) {
    case 1: return t.is("|");
    case 2: return t.is("&");
    case 3: return t.is("<") || t.is("<=") || t.is("=") || t.is("!=") || t.is(">=") || (t.is(">") && !inVector);
    case 4: return t.is("+") || t.is("-");
    case 5: return t.is("*") || t.is("/");
    default: return false;
    }
}

// Level 6: unary operators, then a primary.
Value unary(Evaluator& e) {
    const Token& peeked = e.peek();
    if (!(peeked.is("-") || peeked.is("+") || peeked.is("!"))) return e.primary();
    const Token t = e.next();
    Evaluator::DepthGuard guard(e, t.loc);
    Value v = unary(e);
    v.origin = nullptr;
    if (t.is("!")) return Value::makeFloat(e.toFloat(v, t.loc) == 0 ? 1 : 0);
    if (!v.isNumeric()) e.fail(t.loc, "cannot apply unary '" + t.text + "' to " + kindName(v));
    if (t.is("-")) {
        if (v.kind == Kind::Float) v.number = -v.number;
        else
            for (double& c : v.v) c = -c;
    }
    return v;
}

// Levels 1 to 5. Every return is of `left`, so it is made in the caller's
// result (no move of a Value per level a primary passes through).
Value binaryLevel(Evaluator& e, int level) {
    Value left = level == 5 ? unary(e) : binaryLevel(e, level + 1);
    for (;;) {
        const Token& peeked = e.peekOperator();
        if (!isLevelOperator(level, peeked, e.inVector_)) return left;
        const Token op = peeked;
        // POV-Ray's commas are optional: `<a, b, c> <d, e, f>` is two vectors,
        // and a comparison needs floats, so '<' after a vector starts the next one.
        if (level == 3 && op.is("<") &&
            (left.kind == Kind::Vector || left.kind == Kind::Color || e.countBeforeVector_))
            return left;
        e.next();
        const Value right = level == 5 ? unary(e) : binaryLevel(e, level + 1);
        if (level >= 4) {
            left = arithmetic(e, op, left, right);
            continue;
        }
        if (level == 3 && left.kind == Kind::String && right.kind == Kind::String) {
            // POV-Ray compares strings only through strcmp(); allow = and != for convenience.
            if (op.text == "=" || op.text == "!=") {
                left = Value::makeFloat((left.text == right.text) == (op.text == "="));
                continue;
            }
        }
        const double a = e.toFloat(left, op.loc), b = e.toFloat(right, op.loc);
        const std::string_view s = op.text;
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
        left = Value::makeFloat(r);
    }
}

} // namespace

Value Evaluator::expression() {
    DepthGuard guard(*this, peek().loc);
    Value condition = binaryLevel(*this, 1);
    if (!peekOperator().is("?")) return condition;
    const Token q = next();
    const double c = toFloat(condition, q.loc);
    const bool savedInVector = inVector_;
    inVector_ = false;
    Value a = expression();
    expectSymbol(":", "in a ?: expression");
    Value b = expression();
    inVector_ = savedInVector;
    condition = std::move(c != 0 ? a : b);
    return condition;
}

} // namespace drt::lang

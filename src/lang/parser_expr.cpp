// Expressions: numbers, vectors and colours, with POV-Ray's promotion of a
// number to a vector wherever a vector is expected (`scale 2` = `scale <2,2,2>`).
#include "lang/parser.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace drt {

namespace {

struct Function {
    const char* name;
    int arity; // -1: two or more (min, max)
};

const std::vector<Function>& functions() {
    static const std::vector<Function> table{
        {"sqrt", 1},  {"sin", 1},    {"cos", 1},     {"tan", 1},     {"asin", 1},       {"acos", 1},
        {"atan", 1},  {"atan2", 2},  {"radians", 1}, {"degrees", 1}, {"pow", 2},        {"abs", 1},
        {"min", -1},  {"max", -1},   {"exp", 1},     {"log", 1},     {"floor", 1},      {"ceil", 1},
        {"mod", 2},   {"int", 1},    {"vlength", 1}, {"vnormalize", 1}, {"vdot", 2},   {"vcross", 2},
    };
    return table;
}

const Function* findFunction(const std::string& name) {
    for (const auto& f : functions())
        if (name == f.name) return &f;
    return nullptr;
}

VectorValue makeVector(const Vec3& v) {
    VectorValue r;
    r.c = {v.x, v.y, v.z, 0, 0};
    r.size = 3;
    return r;
}

VectorValue promote(const Value& v, int size) {
    if (const double* d = std::get_if<double>(&v)) {
        VectorValue r;
        r.size = size;
        for (int i = 0; i < size; ++i) r.c[i] = *d;
        return r;
    }
    return std::get<VectorValue>(v);
}

bool isNumeric(const Value& v) { return std::holds_alternative<double>(v) || std::holds_alternative<VectorValue>(v); }

// sRGB transfer function, decoding (IEC 61966-2-1).
double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

const char* const kColorWords[] = {"rgb",  "rgbf",  "rgbt",  "rgbft", "srgb",   "srgbf",    "srgbt",
                                   "srgbft", "red", "green", "blue",  "filter", "transmit"};

} // namespace

bool Parser::atColorWord() const {
    if (current_.kind != TokenKind::Identifier) return false;
    for (const char* w : kColorWords)
        if (current_.text == w) return true;
    return false;
}

bool Parser::atBoolean() const {
    static const char* const words[] = {"on", "off", "true", "false", "yes", "no"};
    if (current_.kind != TokenKind::Identifier) return false;
    for (const char* w : words)
        if (current_.text == w) return true;
    return false;
}

// expression = term { ("+" | "-") term }
Value Parser::expression() {
    DepthGuard guard(*this, current_.loc);
    Value left = term();
    while (check(TokenKind::Plus) || check(TokenKind::Minus)) {
        const Token op = current_;
        advance();
        Value right = term();
        if (!isNumeric(left) || !isNumeric(right))
            fail(op.loc, "cannot apply '" + op.text + "' to " + kindName(isNumeric(left) ? right : left));
        const double sign = op.kind == TokenKind::Plus ? 1 : -1;
        if (std::holds_alternative<double>(left) && std::holds_alternative<double>(right)) {
            left = std::get<double>(left) + sign * std::get<double>(right);
        } else {
            const int n = std::max(std::holds_alternative<VectorValue>(left) ? std::get<VectorValue>(left).size : 0,
                                   std::holds_alternative<VectorValue>(right) ? std::get<VectorValue>(right).size : 0);
            VectorValue a = promote(left, n), b = promote(right, n);
            a.size = n;
            for (int i = 0; i < n; ++i) a.c[i] += sign * b.c[i];
            left = a;
        }
        if (std::holds_alternative<double>(left) ? !std::isfinite(std::get<double>(left)) : false) {
            error(op.loc, "result of '" + op.text + "' is not a finite number");
            left = 1.0;
        }
    }
    return left;
}

// term = unary { ("*" | "/") unary }; vector * vector is component-wise.
Value Parser::term() {
    Value left = unary();
    while (check(TokenKind::Star) || check(TokenKind::Slash)) {
        const Token op = current_;
        advance();
        Value right = unary();
        if (!isNumeric(left) || !isNumeric(right))
            fail(op.loc, "cannot apply '" + op.text + "' to " + kindName(isNumeric(left) ? right : left));
        const bool divide = op.kind == TokenKind::Slash;
        auto apply = [&](double a, double b, bool& bad) {
            if (divide && b == 0) {
                bad = true;
                return 1.0;
            }
            const double r = divide ? a / b : a * b;
            if (!std::isfinite(r)) {
                bad = true;
                return 1.0;
            }
            return r;
        };
        bool divisionByZero = false;
        if (std::holds_alternative<double>(left) && std::holds_alternative<double>(right)) {
            left = apply(std::get<double>(left), std::get<double>(right), divisionByZero);
        } else {
            const int n = std::max(std::holds_alternative<VectorValue>(left) ? std::get<VectorValue>(left).size : 0,
                                   std::holds_alternative<VectorValue>(right) ? std::get<VectorValue>(right).size : 0);
            VectorValue a = promote(left, n), b = promote(right, n);
            // A shorter right operand is padded with 1 so the extra components stay as they are.
            for (int i = b.size; i < n; ++i) b.c[i] = 1;
            a.size = n;
            for (int i = 0; i < n; ++i) a.c[i] = apply(a.c[i], b.c[i], divisionByZero);
            left = a;
        }
        if (divisionByZero) error(op.loc, divide ? "division by zero" : "result of '*' is not a finite number");
    }
    return left;
}

// unary = ("-" | "+") unary | primary
Value Parser::unary() {
    if (check(TokenKind::Minus) || check(TokenKind::Plus)) {
        const Token op = current_;
        advance();
        DepthGuard guard(*this, op.loc);
        Value v = unary();
        if (!isNumeric(v)) fail(op.loc, "cannot apply unary '" + op.text + "' to " + kindName(v));
        if (op.kind == TokenKind::Plus) return v;
        if (double* d = std::get_if<double>(&v)) return -*d;
        VectorValue r = std::get<VectorValue>(v);
        for (int i = 0; i < r.size; ++i) r.c[i] = -r.c[i];
        return r;
    }
    return primary();
}

// primary = number | "(" expression ")" | vector | colour | "x" | "y" | "z" | "pi"
//         | boolean | function "(" arguments ")" | declared-name
Value Parser::primary() {
    const Token t = current_;
    switch (t.kind) {
    case TokenKind::Number: advance(); return t.number;
    case TokenKind::LeftParen: {
        advance();
        DepthGuard guard(*this, t.loc);
        Value v = expression();
        expect(TokenKind::RightParen, "')' to close '('");
        return v;
    }
    case TokenKind::LeftAngle: return vectorLiteral();
    case TokenKind::Identifier: break;
    default: failExpected("a value (a number, a vector <x, y, z> or a name)");
    }
    const std::string& w = t.text;
    if (w == "x") return advance(), makeVector({1, 0, 0});
    if (w == "y") return advance(), makeVector({0, 1, 0});
    if (w == "z") return advance(), makeVector({0, 0, 1});
    if (w == "pi") return advance(), kPi;
    if (w == "on" || w == "true" || w == "yes") return advance(), 1.0;
    if (w == "off" || w == "false" || w == "no") return advance(), 0.0;
    if (w == "color" || w == "colour") {
        advance();
        return colorBody();
    }
    if (atColorWord()) return colorBody();
    if (findFunction(w)) {
        advance();
        return call(t);
    }
    if (const Value* v = lookup(w)) {
        advance();
        return *v;
    }
    if (const std::optional<double> v = clockIdentifier(w)) {
        advance();
        return *v;
    }
    std::vector<std::string> known{"x", "y", "z", "pi", "color", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "clock",
                                   "clock_delta", "clock_on", "frame_number", "initial_frame", "final_frame",
                                   "initial_clock", "final_clock"};
    for (const auto& f : functions()) known.push_back(f.name);
    for (const auto& [name, value] : symbols_) known.push_back(name);
    failUnknown(t, known, "identifier");
}

// The animation's identifiers (scene/frame_clock.h), unless #declare'd: the
// scene records that it read `clock`, so that motion blur can find how it moves.
std::optional<double> Parser::clockIdentifier(const std::string& name) {
    const std::optional<double> v = frameClockValue(frame_, name);
    if (v && name == "clock") scene_.readsClock = true;
    return v;
}

// function "(" expression { "," expression } ")"
Value Parser::call(const Token& name) {
    const Function& f = *findFunction(name.text);
    expect(TokenKind::LeftParen, ("'(' after '" + name.text + "'").c_str());
    std::vector<Value> args;
    std::vector<SourceLoc> locs;
    if (!check(TokenKind::RightParen)) {
        do {
            locs.push_back(current_.loc);
            args.push_back(expression());
        } while (match(TokenKind::Comma));
    }
    expect(TokenKind::RightParen, "')' after the arguments");
    const int n = static_cast<int>(args.size());
    if (f.arity >= 0 ? n != f.arity : n < 2) {
        const std::string want = f.arity < 0 ? "at least 2 arguments" : f.arity == 1 ? "1 argument"
                                                                                      : std::to_string(f.arity) + " arguments";
        fail(name.loc, "'" + name.text + "' takes " + want + ", got " + std::to_string(n));
    }
    const bool vectorFunction = name.text[0] == 'v';
    for (int i = 0; i < n; ++i) {
        if (!isNumeric(args[i])) fail(locs[i], "argument of '" + name.text + "' must be a number, not " + kindName(args[i]));
        if (!vectorFunction && !std::holds_alternative<double>(args[i]))
            fail(locs[i], "argument of '" + name.text + "' must be a number, not " + kindName(args[i]));
    }
    auto num = [&](int i) { return std::get<double>(args[i]); };
    auto vec = [&](int i) {
        const VectorValue v = promote(args[i], 3);
        return Vec3(v.c[0], v.c[1], v.c[2]);
    };
    Value result;
    const std::string& w = name.text;
    if (w == "sqrt") result = std::sqrt(num(0));
    else if (w == "sin") result = std::sin(num(0));
    else if (w == "cos") result = std::cos(num(0));
    else if (w == "tan") result = std::tan(num(0));
    else if (w == "asin") result = std::asin(num(0));
    else if (w == "acos") result = std::acos(num(0));
    else if (w == "atan") result = std::atan(num(0));
    else if (w == "atan2") result = std::atan2(num(0), num(1));
    else if (w == "radians") result = num(0) * kPi / 180;
    else if (w == "degrees") result = num(0) * 180 / kPi;
    else if (w == "pow") result = std::pow(num(0), num(1));
    else if (w == "abs") result = std::fabs(num(0));
    else if (w == "exp") result = std::exp(num(0));
    else if (w == "log") result = num(0) > 0 ? std::log(num(0)) : NAN;
    else if (w == "floor") result = std::floor(num(0));
    else if (w == "ceil") result = std::ceil(num(0));
    else if (w == "int") result = std::trunc(num(0));
    else if (w == "mod") result = num(1) == 0 ? NAN : std::fmod(num(0), num(1));
    else if (w == "min" || w == "max") {
        double r = num(0);
        for (int i = 1; i < n; ++i) r = w == "min" ? std::min(r, num(i)) : std::max(r, num(i));
        result = r;
    } else if (w == "vlength") result = length(vec(0));
    else if (w == "vnormalize") {
        const double len = length(vec(0));
        if (len == 0) {
            error(name.loc, "'vnormalize' of a zero-length vector");
            return makeVector({1, 0, 0});
        }
        result = makeVector(vec(0) / len);
    } else if (w == "vdot") result = dot(vec(0), vec(1));
    else result = makeVector(cross(vec(0), vec(1))); // vcross
    const bool finite = std::holds_alternative<double>(result)
                            ? std::isfinite(std::get<double>(result))
                            : isFinite(Vec3(std::get<VectorValue>(result).c[0], std::get<VectorValue>(result).c[1],
                                            std::get<VectorValue>(result).c[2]));
    if (!finite) {
        error(name.loc, "result of '" + w + "' is not a finite number (argument out of its domain)");
        return std::holds_alternative<double>(result) ? Value(1.0) : Value(makeVector({1, 0, 0}));
    }
    return result;
}

// vector = "<" expression { "," expression } ">", with 2 to 5 components.
VectorValue Parser::vectorLiteral() {
    const Token open = current_;
    advance();
    DepthGuard guard(*this, open.loc);
    VectorValue v;
    v.size = 0;
    do {
        const SourceLoc loc = current_.loc;
        Value c = expression();
        if (!std::holds_alternative<double>(c)) fail(loc, "a vector component must be a number, not " + kindName(c));
        if (v.size == 5) fail(loc, "a vector has at most 5 components");
        v.c[v.size++] = std::get<double>(c);
    } while (match(TokenKind::Comma));
    expect(TokenKind::RightAngle, "',' or '>' in the vector");
    if (v.size < 2) fail(open.loc, "a vector needs 2 to 5 components, got 1");
    return v;
}

// colour-body = ( colour-item | expression ) { colour-item }
// colour-item = ("rgb" | "rgbf" | "rgbt" | "rgbft" | "srgb" | ...) expression
//             | ("red" | "green" | "blue" | "filter" | "transmit") expression
// The result is the 5-vector <r, g, b, filter, transmit>.
VectorValue Parser::colorBody() {
    VectorValue color;
    color.size = 5;
    if (!atColorWord()) {
        const SourceLoc loc = current_.loc;
        Value v = expression();
        if (!isNumeric(v)) fail(loc, "expected a colour, found " + kindName(v));
        if (const double* d = std::get_if<double>(&v)) {
            color.c[0] = color.c[1] = color.c[2] = *d;
        } else {
            const VectorValue& given = std::get<VectorValue>(v);
            for (int i = 0; i < given.size; ++i) color.c[i] = given.c[i];
        }
    }
    while (atColorWord()) {
        const Token word = current_;
        advance();
        const SourceLoc loc = current_.loc;
        const std::string& w = word.text;
        if (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit") {
            const int index = w == "red" ? 0 : w == "green" ? 1 : w == "blue" ? 2 : w == "filter" ? 3 : 4;
            color.c[index] = floatExpr();
            continue;
        }
        const bool srgb = w[0] == 's';
        const std::string kind = srgb ? w.substr(1) : w; // rgb, rgbf, rgbt, rgbft
        const int count = kind == "rgb" ? 3 : kind == "rgbft" ? 5 : 4;
        Value v = expression();
        if (!isNumeric(v)) fail(loc, "'" + w + "' needs a number or a vector, not " + kindName(v));
        const VectorValue given = promote(v, count);
        if (given.size < count)
            fail(loc, "'" + w + "' needs " + std::to_string(count) + " components, got " + std::to_string(given.size));
        // Target slots: rgbt skips filter.
        const int slots[5] = {0, 1, 2, kind == "rgbt" ? 4 : 3, 4};
        for (int i = 0; i < count; ++i) color.c[slots[i]] = given.c[i];
        if (srgb)
            for (int i = 0; i < 3; ++i) color.c[i] = srgbToLinear(color.c[i]);
    }
    return color;
}

double Parser::floatExpr(const char* what) {
    const SourceLoc loc = current_.loc;
    Value v = expression();
    if (const double* d = std::get_if<double>(&v)) return *d;
    fail(loc, std::string("expected ") + what + ", found " + kindName(v));
}

int Parser::intExpr(const char* what) {
    const SourceLoc loc = current_.loc;
    const double d = floatExpr(what);
    if (d != std::floor(d) || std::fabs(d) > 2e9) {
        error(loc, std::string(what) + " must be a whole number");
        return 1;
    }
    return static_cast<int>(d);
}

Vec3 Parser::vectorExpr(const char* what) {
    const SourceLoc loc = current_.loc;
    Value v = expression();
    if (!isNumeric(v)) fail(loc, std::string("expected ") + what + ", found " + kindName(v));
    const VectorValue r = promote(v, 3);
    return {r.c[0], r.c[1], r.size > 2 ? r.c[2] : 0.0};
}

ColorFT Parser::colorExpr() {
    const SourceLoc loc = current_.loc;
    Value v = expression();
    if (!isNumeric(v)) fail(loc, "expected a colour, found " + kindName(v));
    ColorFT c;
    if (const double* d = std::get_if<double>(&v)) {
        c.rgb = Color(*d);
        return c;
    }
    const VectorValue& given = std::get<VectorValue>(v);
    c.rgb = {given.c[0], given.c[1], given.size > 2 ? given.c[2] : 0.0};
    if (given.size > 3) c.filter = given.c[3];
    if (given.size > 4) c.transmit = given.c[4];
    return c;
}

bool Parser::booleanOr(bool fallback) {
    if (atBoolean()) {
        const bool on = current_.text == "on" || current_.text == "true" || current_.text == "yes";
        advance();
        return on;
    }
    if (check(TokenKind::Number) || check(TokenKind::LeftParen) || check(TokenKind::Minus)) return floatExpr() != 0;
    return fallback;
}

} // namespace drt

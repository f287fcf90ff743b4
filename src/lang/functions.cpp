// Built-in constants and functions of the scene language (POV-Ray's, with
// POV-Ray's meanings: log is base 10, ln the natural logarithm).
#include "lang/evaluator.h"
#include "scene/noise_hooks.h"
#include "scene/bounds.h"

#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <unordered_map>

namespace drt::lang {

using Kind = Value::Kind;

namespace {

double radians(double d) { return d * kPi / 180.0; }

// POV-Ray's rand(): a 32-bit linear congruential stream, stream = stream *
// 1812433253 + 12345, returned as (stream & 0xFFFFFFFF) / 0xFFFFFFFF.
double nextRandom(uint32_t& stream) {
    stream = stream * 1812433253u + 12345u;
    return double(stream) / 4294967295.0;
}

// Rotates v by `degrees` about x, then y, then z (POV-Ray's rotate, left-handed).
Vec3 rotateXyz(Vec3 v, const Vec3& degrees) { return Transform::rotate(degrees).vector(v); }

// POV-Ray's str(): L is the minimum width (negative pads with zeros), P the
// digits after the point (negative: as many as needed, up to 6).
std::string formatNumber(double value, int width, int precision) {
    std::string s = precision < 0 ? fmt::format("{:g}", value) : fmt::format("{:.{}f}", value, precision);
    const size_t w = size_t(std::abs(width));
    if (s.size() >= w) return s;
    const std::string pad(w - s.size(), width < 0 ? '0' : ' ');
    if (width < 0 && s[0] == '-') return "-" + pad + s.substr(1);
    return pad + s;
}

} // namespace

bool Evaluator::startsFloat(const Token& t) const {
    if (t.kind == TokenKind::Number || t.is("(") || t.is("-") || t.is("+") || t.is("!")) return true;
    if (t.kind != TokenKind::Word) return false;
    if (const Cell c = lookup(t.text))
        return c->kind == Kind::Float || c->kind == Kind::Macro || (c->kind == Kind::Function && !c->function->colour && !c->function->vector);
    static const std::set<std::string> words = {
        "pi", "tau", "true", "false", "yes", "no", "on", "off", "clock", "image_width", "image_height", "version",
        "abs", "acos", "asin", "atan", "atan2", "ceil", "cos", "cosh", "degrees", "div", "exp", "floor", "int", "ln",
        "log", "max", "min", "mod", "pow", "radians", "rand", "sin", "sinh", "sqrt", "tan", "tanh", "vdot",
        "vlength", "strlen", "val", "select", "dimension_size", "defined", "frame_number", "clock_delta",
        "clock_on", "initial_frame", "final_frame", "initial_clock", "final_clock"};
    return words.count(t.text) > 0;
}

namespace {

// What builtin() knows a name as: one lookup per name instead of one per table.
struct BuiltinName {
    std::optional<double> constant;    // pi, true, on, ...
    bool function = false;             // called with a parenthesised argument list
    double (*unary)(double) = nullptr; // a one-argument float function
};

const BuiltinName* builtinName(const std::string& w) {
    static const std::unordered_map<std::string, BuiltinName> names = [] {
        std::unordered_map<std::string, BuiltinName> m;
        const std::pair<const char*, double> constants[] = {
            {"pi", kPi}, {"tau", 2 * kPi}, {"true", 1}, {"yes", 1}, {"on", 1}, {"false", 0}, {"no", 0}, {"off", 0},
            {"max_intersections", 64}};
        for (const auto& [name, value] : constants) m[name].constant = value;
        for (const char* name :
             {"abs", "acos", "acosh", "asin", "asinh", "atan", "atanh", "atan2", "ceil", "cos", "cosh", "degrees",
              "div", "exp", "floor", "int", "ln", "log", "max", "min", "mod", "pow", "radians", "rand", "seed", "sin",
              "sinh", "sqrt", "tan", "tanh", "select", "bitwise_and", "bitwise_or", "bitwise_xor", "vaxis_rotate",
              "vcross", "vdot", "vlength", "vnormalize", "vrotate", "vturbulence", "concat", "str", "chr", "substr",
              "strlen", "val", "asc", "strupr", "strlwr", "vstr", "dimension_size", "dimensions", "defined",
              "file_exists", "inside", "trace", "min_extent", "max_extent", "noise3d", "strcmp", "sqr", "prod", "sum",
              "datetime"})
            m[name].function = true;
        const std::pair<const char*, double (*)(double)> unary[] = {
            {"acos", [](double a) { return std::acos(a); }},    {"acosh", [](double a) { return std::acosh(a); }},
            {"asin", [](double a) { return std::asin(a); }},    {"asinh", [](double a) { return std::asinh(a); }},
            {"atanh", [](double a) { return std::atanh(a); }},  {"ceil", [](double a) { return std::ceil(a); }},
            {"cos", [](double a) { return std::cos(a); }},      {"cosh", [](double a) { return std::cosh(a); }},
            {"degrees", [](double a) { return a * 180.0 / kPi; }}, {"exp", [](double a) { return std::exp(a); }},
            {"floor", [](double a) { return std::floor(a); }},  {"int", [](double a) { return std::trunc(a); }},
            {"ln", [](double a) { return std::log(a); }},       {"log", [](double a) { return std::log10(a); }},
            {"radians", [](double a) { return radians(a); }},   {"sin", [](double a) { return std::sin(a); }},
            {"sinh", [](double a) { return std::sinh(a); }},    {"sqrt", [](double a) { return std::sqrt(a); }},
            {"tan", [](double a) { return std::tan(a); }},      {"tanh", [](double a) { return std::tanh(a); }},
            {"sqr", [](double a) { return a * a; }}};
        for (const auto& [name, f] : unary) m[name].unary = f;
        return m;
    }();
    const auto it = names.find(w);
    return it == names.end() ? nullptr : &it->second;
}

} // namespace

bool Evaluator::builtin(const Token& name, Value& out) {
    const std::string& w = name.text;
    // Compared with literals as a string_view: a literal of another length costs no call of memcmp.
    const std::string_view n = w;
    // ---- constants
    const BuiltinName* known = builtinName(w);
    if (known && known->constant) {
        out = Value::makeFloat(*known->constant);
        return true;
    }
    // The clock's names (scene/frame_clock.h): clock, clock_delta, clock_on, frame_number, initial_frame,
    // final_frame, initial_clock, final_clock.
    const bool clockName = n.starts_with("clock") || n == "frame_number" || n.starts_with("initial_") ||
                           n.starts_with("final_");
    if (const std::optional<double> v = clockName ? frameClockValue(options_.frame, w) : std::nullopt) {
        if (n == "clock") scene_.readsClock = true; // motion blur may evaluate the scene again over the shutter
        return out = Value::makeFloat(*v), true;
    }
    if (n == "image_width") return out = Value::makeFloat(options_.imageWidth), true;
    if (n == "image_height") return out = Value::makeFloat(options_.imageHeight), true;
    if (n == "version") return out = Value::makeFloat(version_), true;
    if (n == "x" || n == "y" || n == "z") {
        out = Value::makeVector({n == "x" ? 1.0 : 0.0, n == "y" ? 1.0 : 0.0, n == "z" ? 1.0 : 0.0});
        return true;
    }
    if (n == "t") {
        out.kind = Kind::Vector;
        out.size = 4;
        out.v = {0, 0, 0, 1, 0};
        return true;
    }
    if (n == "u" || n == "v") {
        out.kind = Kind::Vector;
        out.size = 2;
        out.v = {n == "u" ? 1.0 : 0.0, n == "v" ? 1.0 : 0.0, 0, 0, 0};
        return true;
    }
    if (n == "input_file_name") return out = Value::makeString(diags_.files().path(name.loc.file)), true;

    // ---- functions with a parenthesised argument list
    if (!known || !known->function) return false;

    if (n == "defined") {
        expectSymbol("(", "after 'defined'");
        noExpand_ = true;
        const Token id = next();
        noExpand_ = false;
        if (id.kind != TokenKind::Word) failExpected(id, "an identifier");
        expectSymbol(")", "after the identifier");
        out = Value::makeFloat(lookup(id.text) ? 1 : 0);
        return true;
    }
    if (n == "min_extent" || n == "max_extent") {
        expectSymbol("(", "after the function name");
        const SourceLoc at = peek().loc;
        const Value v = rvalue();
        expectSymbol(")", "after the object");
        if (v.kind != Kind::Object || (v.object->lightOnly && !v.object->lights.empty()))
            fail(at, "'" + w + "' needs an object, not " + kindName(v));
        Vec3 lo(-kUnboundedExtent), hi(kUnboundedExtent); // a shape left out (warned about): unbounded
        if (!v.object->lightOnly) objectBounds(*v.object, lo, hi);
        out = Value::makeVector(n == "min_extent" ? lo : hi);
        return true;
    }
    if (n == "trace" || n == "inside") {
        out = traceOrInside(name);
        return true;
    }

    expectSymbol("(", "after '", w, "'");
    std::vector<Value> args;
    std::vector<SourceLoc> locs;
    args.reserve(4); // most functions take 1 to 4: no copies as the lists grow
    locs.reserve(4);
    if (!peek().is(")")) {
        const bool saved = inVector_;
        inVector_ = false;
        do {
            locs.push_back(peek().loc);
            args.push_back(expression());
        } while (acceptSymbol(","));
        inVector_ = saved;
    }
    expectSymbol(")", "to close the arguments of '", w, "'");
    auto need = [&](size_t lo, size_t hi) {
        if (args.size() >= lo && args.size() <= hi) return;
        std::string want;
        if (hi > 100) want = fmt::format("at least {} arguments", lo);
        else if (lo == hi) want = fmt::format("{} argument{}", lo, lo == 1 ? "" : "s");
        else want = fmt::format("{} to {} arguments", lo, hi);
        fail(name.loc, fmt::format("'{}' takes {}, got {}", w, want, args.size()));
    };
    auto numeric = [&](size_t i) {
        if (!args[i].isNumeric()) fail(locs[i], "argument of '" + w + "' must be a number, not " + kindName(args[i]));
    };
    auto f = [&](size_t i) {
        numeric(i);
        if (args[i].kind != Kind::Float)
            fail(locs[i], "argument of '" + w + "' must be a number, not " + kindName(args[i]));
        return args[i].number;
    };
    auto vec = [&](size_t i) {
        numeric(i);
        return toVector(args[i], locs[i]);
    };
    // An argument that becomes an int (a count, a width, a code, an index).
    auto count = [&](size_t i, const char* what, double lowest, double highest) {
        return countValue(f(i), locs[i], what, lowest, highest);
    };
    const double maxLength = double(diags_.limits().stringLength);
    auto checkLength = [&](const std::string& s) {
        if (double(s.size()) > maxLength)
            failLimit(name.loc, limitExceeded(diags_.limits(), &Limits::stringLength, "the string's length",
                                         double(s.size())));
    };
    auto str = [&](size_t i) -> const std::string& {
        if (args[i].kind != Kind::String) fail(locs[i], "expected a string, found " + kindName(args[i]));
        return args[i].text;
    };
    // A result out of the function's domain (sqrt(-1), log(0)) is an error: NaN never reaches an image.
    auto setFloat = [&](double value) {
        if (!std::isfinite(value)) {
            error(name.loc, "result of '" + w + "' is not a finite number (argument out of its domain)");
            value = 1;
        }
        out = Value::makeFloat(value);
    };

    // One-argument float functions.
    if (known->unary) {
        need(1, 1);
        setFloat(known->unary(f(0)));
        return true;
    }
    if (n == "abs") {
        need(1, 1);
        if (args[0].kind == Kind::Float) setFloat(std::fabs(args[0].number));
        else {
            out = args[0];
            for (double& c : out.v) c = std::fabs(c);
            if (!out.isNumeric()) fail(locs[0], "argument of 'abs' must be a number, not " + kindName(args[0]));
        }
        return true;
    }
    if (n == "atan") {
        need(1, 2);
        setFloat(args.size() == 2 ? std::atan2(f(0), f(1)) : std::atan(f(0)));
        return true;
    }
    if (n == "atan2" || n == "pow" || n == "mod" || n == "div") {
        need(2, 2);
        const double a = f(0), b = f(1);
        if (n == "atan2") setFloat(std::atan2(a, b));
        else if (n == "pow") setFloat(std::pow(a, b));
        else if (n == "mod") setFloat(b == 0 ? NAN : std::fmod(a, b));
        else setFloat(b == 0 ? NAN : std::trunc(a / b));
        return true;
    }
    if (n == "max" || n == "min") {
        need(2, 1000);
        double r = f(0);
        for (size_t i = 1; i < args.size(); ++i) r = n == "max" ? std::max(r, f(i)) : std::min(r, f(i));
        setFloat(r);
        return true;
    }
    if (n == "select") {
        need(3, 4);
        const double s = f(0);
        out = s < 0 ? args[1] : (args.size() == 3 || s == 0 ? args[2] : args[3]);
        return true;
    }
    if (n == "bitwise_and" || n == "bitwise_or" || n == "bitwise_xor") {
        if (args.size() < 2) need(2, 2);
        const auto operand = [&](size_t i) {
            const double v = f(i);
            if (std::string problem = checkCount("bitwise operand", v, -9.2e18, 9.2e18); !problem.empty())
                fail(locs[i], problem);
            return long(v);
        };
        long r = operand(0);
        for (size_t i = 1; i < args.size(); ++i) {
            const long b = operand(i);
            r = n == "bitwise_and" ? (r & b) : n == "bitwise_or" ? (r | b) : (r ^ b);
        }
        setFloat(double(r));
        return true;
    }
    if (n == "seed") {
        need(1, 1);
        // POV-Ray takes the seed modulo 2^32.
        const double seed = f(0);
        if (std::string problem = checkCount("seed", seed, -9.2e18, 9.2e18); !problem.empty()) fail(locs[0], problem);
        randomStreams_.push_back(static_cast<uint32_t>(static_cast<int64_t>(seed)));
        setFloat(double(randomStreams_.size() - 1));
        return true;
    }
    if (n == "rand") {
        need(1, 1);
        const double s = f(0);
        if (!(s >= 0) || s >= double(randomStreams_.size()) || s != std::floor(s))
            fail(locs[0], "rand() needs a stream made by seed()");
        setFloat(nextRandom(randomStreams_[size_t(s)]));
        return true;
    }
    // ---- vectors
    if (n == "vdot") {
        need(2, 2);
        setFloat(dot(vec(0), vec(1)));
        return true;
    }
    if (n == "vlength") {
        need(1, 1);
        setFloat(length(vec(0)));
        return true;
    }
    if (n == "vcross" || n == "vnormalize" || n == "vrotate" || n == "vaxis_rotate" || n == "vturbulence") {
        Vec3 r;
        if (n == "vcross") need(2, 2), r = cross(vec(0), vec(1));
        else if (n == "vnormalize") {
            need(1, 1);
            const Vec3 a = vec(0);
            // POV-Ray gives <0,0,0> for a zero vector; drt's rules call it an error.
            if (length(a) == 0) refuse(name.loc, "'vnormalize' of a zero-length vector");
            r = length(a) == 0 ? Vec3(0) : normalize(a);
        } else if (n == "vrotate") need(2, 2), r = rotateXyz(vec(0), vec(1));
        else if (n == "vaxis_rotate") {
            need(3, 3);
            if (length(vec(1)) == 0) fail(locs[1], "vaxis_rotate about a zero axis");
            r = Transform::rotateAxis(vec(1), f(2)).vector(vec(0));
        } else { // vturbulence(lambda, omega, octaves, point): the renderer's turbulence (scene/noise_hooks.h)
            need(4, 4);
            // Octaves beyond POV-Ray's 1 to 10 are clipped, as in a pattern's turbulence.
            const int octaves = std::clamp(count(2, "vturbulence() octaves", -1e9, 1e9), 1, 10);
            const NoiseHooks hooks = noiseHooks();
            if (!hooks.turbulence) fail(name.loc, "vturbulence() needs drt's renderer, which this program does not link");
            r = hooks.turbulence(f(0), f(1), octaves, vec(3));
        }
        out = Value::makeVector(r);
        return true;
    }
    if (n == "noise3d") {
        warnOnce("noise", name.loc, "noise functions are not supported; '" + w + "' returns 0.5");
        setFloat(0.5);
        return true;
    }
    // ---- strings
    if (n == "concat") {
        std::string s;
        for (size_t i = 0; i < args.size(); ++i) {
            s += str(i);
            checkLength(s);
        }
        out = Value::makeString(s);
        return true;
    }
    if (n == "str") {
        need(3, 3);
        out = Value::makeString(formatNumber(f(0), count(1, "str() width", -maxLength, maxLength),
                                                count(2, "str() precision", -1e9, 100)));
        return true;
    }
    if (n == "vstr") {
        need(5, 5);
        const int n = count(0, "vstr() component count", -1e9, 1e9);
        const auto c = args[1].isNumeric() ? toColor(args[1], locs[1]) : std::array<double, 5>{};
        if (!args[1].isNumeric()) fail(locs[1], "vstr() needs a vector");
        std::string s;
        for (int i = 0; i < std::clamp(n, 1, 5); ++i) {
            if (i) s += str(2);
            s += formatNumber(c[size_t(i)], count(3, "vstr() width", -maxLength, maxLength),
                              count(4, "vstr() precision", -1e9, 100));
            checkLength(s);
        }
        out = Value::makeString(s);
        return true;
    }
    if (n == "chr") {
        need(1, 1);
        const int c = count(0, "chr() code", 0, 255);
        out = Value::makeString(std::string(1, char(c)));
        return true;
    }
    if (n == "asc") {
        need(1, 1);
        setFloat(str(0).empty() ? 0 : double(static_cast<unsigned char>(str(0)[0])));
        return true;
    }
    if (n == "strlen") {
        need(1, 1);
        setFloat(double(str(0).size()));
        return true;
    }
    if (n == "strcmp") {
        need(2, 2);
        const int c = str(0).compare(str(1));
        setFloat(c < 0 ? -1 : c > 0 ? 1 : 0);
        return true;
    }
    if (n == "substr") {
        need(3, 3);
        const std::string& s = str(0);
        const int start = count(1, "substr() start", 1, double(s.size()) + 1); // 1-based
        const int length = count(2, "substr() length", 0, double(s.size()));
        if (size_t(start - 1 + length) > s.size())
            fail(name.loc, fmt::format("substr({}, {}) is outside the {}-character string", start, length, s.size()));
        out = Value::makeString(s.substr(size_t(start - 1), size_t(length)));
        return true;
    }
    if (n == "strupr" || n == "strlwr") {
        need(1, 1);
        std::string s = str(0);
        for (char& c : s) c = char(n == "strupr" ? std::toupper((unsigned char)c) : std::tolower((unsigned char)c));
        out = Value::makeString(s);
        return true;
    }
    if (n == "val") {
        need(1, 1);
        setFloat(std::strtod(str(0).c_str(), nullptr));
        return true;
    }
    if (n == "file_exists") {
        need(1, 1);
        setFloat(findInclude(str(0), ".").empty() ? 0 : 1);
        return true;
    }
    if (n == "datetime") {
        out = Value::makeString("");
        return true;
    }
    // ---- arrays
    if (n == "dimensions" || n == "dimension_size") {
        need(n == "dimensions" ? 1 : 2, n == "dimensions" ? 1 : 2);
        if (args[0].kind != Kind::Array) fail(locs[0], "'" + w + "' needs an array");
        const auto& sizes = args[0].array->sizes;
        if (n == "dimensions") {
            setFloat(double(sizes.size()));
        } else {
            const int d = count(1, "dimension", 1, double(sizes.size()));
            setFloat(double(sizes[size_t(d - 1)]));
        }
        return true;
    }
    fail(name.loc, "'" + w + "' is not supported");
}

// trace(OBJECT, A, B [, NORMAL]): the first point of the object along the ray
// from A in direction B, and its normal into the identifier NORMAL; <0, 0, 0>
// for both when the ray misses. inside(OBJECT, P): 1 if P is inside. Both ask
// the geometry the loader passed in (scene/geometry_query.h).
Value Evaluator::traceOrInside(const Token& name) {
    const std::string& w = name.text;
    expectSymbol("(", "after '", w, "'");
    const SourceLoc at = peek().loc;
    const Value object = rvalue();
    if (object.kind != Kind::Object)
        fail(at, "'" + w + "' needs an object, not " + kindName(object));
    // A light has no surface to meet; a shape drt leaves out (warned about
    // where it was made) is not in the scene, so the ray misses it.
    const bool leftOut = object.object->lightOnly && object.object->lights.empty();
    if (object.object->lightOnly && !leftOut)
        fail(at, "'" + w + "' needs an object with a surface, not a light_source");
    acceptSymbol(",");
    const Vec3 a = vectorExpr(w == "trace" ? "the ray's start" : "the point");
    Vec3 direction;
    Cell normalOut;
    if (w == "trace") {
        acceptSymbol(",");
        direction = vectorExpr("the ray's direction");
        if (acceptSymbol(",")) {
            noExpand_ = true;
            const Token id = next();
            noExpand_ = false;
            if (id.kind != TokenKind::Word) failExpected(id, "an identifier for the normal");
            if (!lookup(id.text)) declare(id.text, Value::makeVector(Vec3(0)), false);
            normalOut = lookup(id.text);
        }
    }
    expectSymbol(")", "to close the arguments of '", w, "'");
    if (!options_.geometry)
        fail(name.loc, "'" + w + "' needs the scene's geometry while the scene is read; this loader gives none");
    if (leftOut) {
        warn(at, "'" + w + "' is given an object drt leaves out (see the warning where it was made): " +
                     (w == "trace" ? "the ray misses, <0, 0, 0>" : "no point is inside, 0"));
        if (normalOut) *normalOut = Value::makeVector(Vec3(0));
        return w == "inside" ? Value::makeFloat(0) : Value::makeVector(Vec3(0));
    }
    // The declared value does not change while it lives: the query may keep
    // what it builds for it (a 500 x 500 height_field traced in a loop).
    const QueriedObject model{object.object, [this, &object] { return placed(*object.object); }};
    if (w == "inside") return Value::makeFloat(options_.geometry->inside(model, a) ? 1 : 0);
    if (!(length(direction) > 0)) fail(name.loc, "'trace' needs a direction that is not zero");
    const std::optional<SurfaceHit> hit = options_.geometry->trace(model, a, direction);
    if (normalOut) *normalOut = Value::makeVector(hit ? hit->normal : Vec3(0));
    return Value::makeVector(hit ? hit->point : Vec3(0));
}

} // namespace drt::lang

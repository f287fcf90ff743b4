// Primary expressions (literals, identifiers, colour keywords, parentheses),
// postfix swizzles and indexing, array literals, and the right-hand side of
// #declare, which may also be a scene item.
#include "lang/evaluator.h"

#include <cmath>
#include <fmt/format.h>
#include <unordered_set>

namespace drt::lang {

using Kind = Value::Kind;

namespace {

double srgbToLinear(double c) {
    // IEC 61966-2-1 decoding.
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

bool isColorKeyword(std::string_view w) {
    return w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" || w == "srgb" || w == "srgbf" || w == "srgbt" ||
           w == "srgbft";
}

} // namespace

double Evaluator::workingGamma() const {
    if (!scene().versionGammaRules) return 1.0;
    return assumedGamma_ ? *assumedGamma_ : (version_ < 3.7 ? 2.2 : 1.0);
}

Value Evaluator::postfix(Value v, SourceLoc) {
    while (peekOperator().is(".")) {
        const Token dot = next();
        const Token member = expectWord("a component name after '.'");
        const std::string& m = member.text;
        int index = -1;
        if (m == "x" || m == "u" || m == "red") index = 0;
        else if (m == "y" || m == "v" || m == "green") index = 1;
        else if (m == "z" || m == "blue") index = 2;
        else if (m == "t" || m == "filter") index = 3;
        else if (m == "transmit") index = 4;
        else if (m == "gray" || m == "grey") {
            const auto c = toColor(v, dot.loc);
            // POV-Ray's gray: 0.297 R + 0.589 G + 0.114 B.
            v = Value::makeFloat(0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]);
            continue;
        } else {
            fail(member.loc,
                 "unknown component '." + m + "' (use .x .y .z .t .u .v .red .green .blue .filter .transmit .gray)");
        }
        if (v.kind == Kind::Float) {
            if (index > 0) fail(dot.loc, "'." + m + "' of a number");
            continue;
        }
        if (v.kind != Kind::Vector && v.kind != Kind::Color) fail(dot.loc, "'." + m + "' of " + kindName(v));
        if (index >= v.size) fail(member.loc, fmt::format("'.{}' of a {}-component vector", m, v.size));
        v = Value::makeFloat(v.v[size_t(index)]);
    }
    return v;
}

Value Evaluator::primary() {
    const Token t = next();
    // Without a '.' after it, a number or an identifier's value is made in the
    // result itself: postfix() would take it and give it back, a Value's copy and move.
    if (t.kind == TokenKind::Number)
        return peekOperator().is(".") ? postfix(Value::makeFloat(t.number), t.loc) : Value::makeFloat(t.number);
    if (t.kind == TokenKind::String) return Value::makeString(t.text);
    if (t.is("(")) {
        const bool saved = inVector_, savedCount = countBeforeVector_;
        inVector_ = countBeforeVector_ = false;
        Value v = expression();
        expectSymbol(")", "to close '('");
        inVector_ = saved;
        countBeforeVector_ = savedCount;
        v.origin = nullptr;
        return postfix(std::move(v), t.loc);
    }
    if (t.is("<")) {
        DepthGuard guard(*this, t.loc);
        const bool saved = inVector_, savedCount = countBeforeVector_;
        inVector_ = true;
        countBeforeVector_ = false;
        Value v;
        v.kind = Kind::Vector;
        int n = 0;
        for (;;) {
            const SourceLoc loc = peek().loc;
            const Value c = expression();
            if (c.kind != Kind::Float) fail(loc, "a vector component must be a number, not " + kindName(c));
            if (n == 5) fail(loc, "a vector has at most 5 components");
            v.v[size_t(n++)] = c.number;
            if (syntax().requireCommas) {
                if (acceptSymbol(",")) continue;
                if (!peek().is(">")) failExpected(peek(), "',' or '>' in the vector");
                break;
            }
            // POV-Ray accepts components separated by blanks only: <4 0 0>,
            // and a trailing comma: <0.2, 0.1, 0.5,>.
            if (acceptSymbol(",")) {
                if (peek().is(">")) break;
                continue;
            }
            if (peek().is(">") || n >= 5) break;
        }
        expectSymbol(">", "to close the vector");
        inVector_ = saved;
        countBeforeVector_ = savedCount;
        if (n < 2) fail(t.loc, "a vector needs 2 to 5 components, got 1");
        v.size = n;
        return postfix(std::move(v), t.loc);
    }
    if (t.kind != TokenKind::Word) failExpected(t, "a value (a number, a vector <x, y, z> or a name)");

    if (const Cell c = useIndexed(t)) {
        if (c->kind == Kind::Function) return postfix(callFunction(t, *c->function), t.loc);
        if (c->kind == Kind::Spline && peek().is("(")) return postfix(callSpline(t, *c->spline), t.loc);
        if (!peekOperator().is(".")) return *c;
        return postfix(*c, t.loc);
    }

    const std::string& w = t.text;
    if (isColorKeyword(w)) {
        const SourceLoc loc = peek().loc;
        const Value v = expression();
        const bool srgb = w[0] == 's';
        const std::string form = srgb ? w.substr(1) : w;
        const int need = form == "rgb" ? 3 : form == "rgbft" ? 5 : 4;
        std::array<double, 5> c{};
        if (v.kind == Kind::Float) {
            for (int i = 0; i < need; ++i) c[size_t(i)] = v.number;
        } else if (v.kind == Kind::Vector || v.kind == Kind::Color) {
            if (v.size < need) fail(loc, fmt::format("'{}' needs {} components, got {}", w, need, v.size));
            for (int i = 0; i < need; ++i) c[size_t(i)] = v.v[size_t(i)];
        } else {
            fail(loc, "'" + w + "' needs a number or a vector, not " + kindName(v));
        }
        if (form == "rgbt") c[4] = c[3], c[3] = 0;
        if (srgb) { // sRGB-encoded: to linear, then into the working space (gamma g: c^(1/g))
            const double g = workingGamma();
            for (int i = 0; i < 3; ++i) {
                const double linear = srgbToLinear(c[size_t(i)]);
                c[size_t(i)] = g == 1.0 || linear <= 0 ? linear : std::pow(linear, 1 / g);
            }
        }
        return Value::makeColor(c);
    }
    if (t.isWord("color") || t.isWord("colour")) return Value::makeColor(colorExpr());
    // builtin() first: its names are asked for far more often, and no internal
    // function (f_...) is one of them, so the order changes no meaning.
    Value out;
    if (builtin(t, out)) return postfix(std::move(out), t.loc);
    if (const int internal = internalNamed(w); internal >= 0) // f_sphere, f_r, ... without functions.inc
        return postfix(callFunction(t, *internalFunction(internal)), t.loc);
    std::vector<std::string> known{"x",           "y",           "z",           "pi",           "color",
                                   "rgb",         "rgbf",        "rgbt",        "rgbft",        "srgb",
                                   "clock",       "clock_delta", "clock_on",    "frame_number", "initial_frame",
                                   "final_frame", "initial_clock", "final_clock"};
    const std::vector<std::string> names = declaredNames();
    known.insert(known.end(), names.begin(), names.end());
    for (const char* f : {"sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "radians", "degrees", "pow",
                          "abs", "min", "max", "exp", "log", "ln", "floor", "ceil", "mod", "int", "vlength",
                          "vnormalize", "vdot", "vcross"})
        known.push_back(f);
    failUnknownIn(t, known, "identifier");
}

size_t Evaluator::arrayIndex(const lang::Array& a, const Token& name) {
    size_t index = 0;
    for (size_t d = 0; d < a.sizes.size(); ++d) {
        expectSymbol("[", "for an index into '", name.text, "'");
        const int i = countExpr("array index", 0, a.sizes[d] - 1);
        expectSymbol("]", "after an array index");
        index = index * size_t(a.sizes[d]) + size_t(i);
    }
    return index;
}

Cell Evaluator::indexArray(Cell cell, const Token& t) {
    while (cell->kind == Kind::Array && peekOperator().is("[")) {
        const lang::Array& a = *cell->array;
        const size_t index = arrayIndex(a, t);
        if (!a.items[index]) fail(t.loc, "array element of '" + t.text + "' used before it was given a value");
        cell = a.items[index];
    }
    return cell;
}

Cell Evaluator::useIndexed(const Token& t) {
    Cell c = use(t);
    if (c && c->kind == Kind::Array) c = indexArray(c, t);
    return c;
}

Value Evaluator::arrayLiteral(SourceLoc loc) {
    auto a = std::make_shared<lang::Array>();
    size_t total = 1;
    while (peekOperator().is("[")) {
        next();
        const SourceLoc at = peek().loc;
        const Limits& limits = diags_.limits();
        const int n = countExpr("array size", 1, double(limits.arrayElements));
        expectSymbol("]", "after the array size");
        a->sizes.push_back(n);
        total *= size_t(n);
        if (total > size_t(limits.arrayElements))
            failLimit(at, limitExceeded(limits, &Limits::arrayElements, "the array's element count", double(total)));
    }
    if (a->sizes.empty()) fail(loc, "array needs a size: array[n]");
    a->items.resize(total);
    if (peekOperator().is("{")) {
        // Nested braces, one level per dimension.
        size_t index = 0;
        auto fill = [&](auto&& self, size_t dim) -> void {
            expectSymbol("{", "to start an array initialiser");
            for (int i = 0; i < a->sizes[dim]; ++i) {
                if (dim + 1 < a->sizes.size()) self(self, dim + 1);
                else a->items[index++] = std::make_shared<Value>(rvalue());
                if (i + 1 < a->sizes[dim]) acceptSymbol(","); // POV-Ray tolerates a missing comma
            }
            acceptSymbol(",");
            expectSymbol("}", "after the array items (too many items?)");
        };
        fill(fill, 0);
    }
    Value v;
    v.kind = Kind::Array;
    v.array = a;
    return v;
}

Value Evaluator::rvalue() {
    const Token& peeked = peek();
    if (peeked.kind == TokenKind::Word && !lookup(peeked)) {
        const Token t = peeked;
        Value v;
        const std::string& w = t.text;
        const std::string_view n = w; // compared with literals without strlen or memcmp calls
        if (isObjectWord(t) || n == "light_source") {
            next();
            v.kind = Kind::Object;
            v.object = std::make_shared<ObjectValue>(object(t));
            return v;
        }
        if (n == "texture") {
            next();
            v.kind = Kind::Texture;
            Texture layered = texture(Texture{});
            // `texture {A} texture {B}`: a layered texture, B on top of A.
            while (peekOperator().isWord("texture")) {
                const Token keyword = next();
                layerOnTop(layered, texture(Texture{}), keyword.loc);
            }
            v.texture = std::make_shared<Texture>(std::move(layered));
            return v;
        }
        if (n == "pigment") {
            next();
            v.kind = Kind::Pigment;
            v.pigment = std::make_shared<Pigment>(pigment(Pigment{}));
            return v;
        }
        if (n == "finish") {
            next();
            v.kind = Kind::Finish;
            v.finish = std::make_shared<Finish>(finish(Finish{}));
            return v;
        }
        if (n == "interior") {
            next();
            v.kind = Kind::Interior;
            v.interior = std::make_shared<Interior>(interior(Interior{}));
            return v;
        }
        if (n == "media") {
            next();
            v.kind = Kind::Media;
            v.media = std::make_shared<Media>(media(Media{}));
            return v;
        }
        if (n == "density") { // kept as the pigment it is evaluated as
            next();
            v.kind = Kind::Pigment;
            Pigment unit;
            unit.color = ColorFT{Color(1), 0, 0};
            v.pigment = std::make_shared<Pigment>(density(unit));
            return v;
        }
        if (n == "material") {
            next();
            v.kind = Kind::Material;
            v.material = std::make_shared<lang::Material>(material(lang::Material{}));
            return v;
        }
        if (n == "normal") {
            next();
            const std::optional<Normal> n = normalBlock(t.loc, std::nullopt);
            v.kind = Kind::Normal;
            if (n) v.normal = std::make_shared<Normal>(*n);
            return v;
        }
        if (n == "camera") {
            next();
            v.kind = Kind::Camera;
            v.camera = std::make_shared<CameraSpec>(camera(CameraSpec{}, t.loc));
            return v;
        }
        if (n == "color_map" || n == "colour_map") {
            next();
            v.kind = Kind::ColorMap;
            v.colorMap = std::make_shared<std::vector<ColorMapEntry>>(colorMap());
            return v;
        }
        if (n == "transform") {
            next();
            v.kind = Kind::Transform;
            v.transform = std::make_shared<Transform>(transformBlock());
            return v;
        }
        if (n == "sky_sphere") {
            next();
            v.kind = Kind::SkySphere;
            v.sky = std::make_shared<const std::vector<Pigment>>(skySphere());
            return v;
        }
        if (n == "array") {
            next();
            return arrayLiteral(t.loc);
        }
        if (n == "spline") {
            next();
            v.kind = Kind::Spline;
            v.spline = splineBlock(t.loc);
            return v;
        }
        if (n == "function") {
            next();
            v.kind = Kind::Function;
            v.function = functionBody(t);
            return v;
        }
        static const std::unordered_set<std::string> opaque = {
            "pigment_map", "normal_map", "texture_map", "slope_map", "density_map",
            "material_map", "interior_texture", "rainbow", "fog", "photons", "radiosity"};
        if (opaque.count(w)) {
            next();
            unsupported("declare-" + w, t.loc, "'" + w + "' is not supported; the declared value cannot be used");
            if (peek().is("(")) {
                next();
                int depth = 1;
                while (depth > 0) {
                    const Token s = next();
                    if (s.kind == TokenKind::EndOfFile) fail(t.loc, "unbalanced '('");
                    depth += s.is("(") ? 1 : s.is(")") ? -1 : 0;
                }
            }
            if (peek().is("{")) {
                next();
                skipBlock();
            }
            v.kind = Kind::Opaque;
            v.text = w;
            return v;
        }
    }
    return expression();
}

} // namespace drt::lang

// Values of the scene language: what identifiers hold. Numbers, vectors (2 to
// 5 components), colours (5 components: r g b filter transmit), strings,
// arrays, and the scene items that can be declared (objects, textures, ...).
#pragma once

#include "lang/dialect.h"
#include "scene/scene.h"
#include "scene/spline.h"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace drt::lang {

struct Token;
class TokenStream;

// An object while it is evaluated: CSG stays a tree, and the flags the
// inheritance rules need (a union's texture goes to members without one) are
// kept beside it. A member's pigments are in its CSG's own space; the root's
// are in the space its transform maps to (world space once it is placed).
struct ObjectValue {
    Object object; // shape, transform, texture, ...; for CSG the members are below
    std::vector<ObjectValue> children;
    bool textured = false;
    bool interiorSet = false;
    std::vector<Light> lights; // light_source inside a union
    bool lightOnly = false;    // a declared light_source or a left-out shape: no shape of its own
    bool isCsg() const { return std::holds_alternative<Csg>(object.shape); }
};

struct Material {
    std::optional<Texture> texture;
    std::optional<Interior> interior;
};

struct Macro {
    std::string name;
    std::vector<std::string> params;
    std::shared_ptr<TokenStream> tokens; // the file holding the body
    size_t bodyStart = 0;                               // index of the first body token
    DialectKind dialect = DialectKind::Drt;             // of the file it was defined in
    SourceLoc loc;
};

// A warning raised while a #declare was evaluated. It is reported when the
// identifier is used, so that the unused declarations of include files
// (POV-Ray's textures.inc, ...) do not warn.
struct PendingWarning {
    std::string kind;
    Severity severity = Severity::Warning;
    SourceLoc loc;
    std::string message;
    std::vector<SourceLoc> includedFrom;
};

struct Value;
using Cell = std::shared_ptr<Value>;

struct Array {
    std::vector<int> sizes;  // one entry per dimension
    std::vector<Cell> items; // row-major; null: not initialised yet
};

// Where a number came from, for messages: the identifier and the text of its
// declaration ("R = 0.5 - 1").
struct Origin {
    std::string name;
    std::string text;
};

struct Value {
    enum class Kind {
        Float, Vector, Color, String, Array, Object, Texture, Pigment, Finish, Interior, Material,
        Normal, Camera, Light, Transform, ColorMap, Macro, Opaque, SkySphere, Media, Function, Spline,
    };
    Kind kind = Kind::Float;
    double number = 0;
    std::array<double, 5> v{};
    int size = 0;     // components of a Vector (2..5); Colors have 5
    std::string text; // String; for Opaque, what it was (e.g. "function")
    std::shared_ptr<lang::Array> array;
    std::shared_ptr<const ObjectValue> object;
    std::shared_ptr<const drt::Texture> texture;
    std::shared_ptr<const drt::Pigment> pigment;
    std::shared_ptr<const std::vector<drt::Pigment>> sky; // SkySphere: its pigments, transformed
    std::shared_ptr<const drt::Finish> finish;
    std::shared_ptr<const drt::Interior> interior;
    std::shared_ptr<const drt::Normal> normal;
    std::shared_ptr<const drt::Media> media;
    std::shared_ptr<const lang::Material> material;
    std::shared_ptr<const CameraSpec> camera;
    std::shared_ptr<const drt::Transform> transform;
    std::shared_ptr<const std::vector<ColorMapEntry>> colorMap;
    std::shared_ptr<const lang::Macro> macro;
    std::shared_ptr<const drt::Function> function;
    std::shared_ptr<const drt::Spline> spline;
    std::shared_ptr<const std::vector<PendingWarning>> warnings; // see PendingWarning
    std::shared_ptr<const Origin> origin;                         // numbers read from an identifier

    bool isNumeric() const { return kind == Kind::Float || kind == Kind::Vector || kind == Kind::Color; }

    static Value makeFloat(double f) {
        Value v;
        v.number = f;
        return v;
    }
    static Value makeVector(const Vec3& a) {
        Value v;
        v.kind = Kind::Vector;
        v.size = 3;
        v.v = {a.x, a.y, a.z, 0, 0};
        return v;
    }
    static Value makeColor(const std::array<double, 5>& c) {
        Value v;
        v.kind = Kind::Color;
        v.size = 5;
        v.v = c;
        return v;
    }
    static Value makeString(std::string s) {
        Value v;
        v.kind = Kind::String;
        v.text = std::move(s);
        return v;
    }
};

// "a number", "a vector", "a colour", "an object", ...: for messages.
std::string kindName(const Value& v);
std::string kindName(Value::Kind kind);

} // namespace drt::lang

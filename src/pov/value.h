// Values of POV-Ray's language: what identifiers hold. Floats, vectors (2 to 5
// components), colours (5 components: r g b filter transmit), strings, arrays,
// and the scene items that can be #declared (objects, textures, ...).
#pragma once

#include "scene/scene.h"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace drt::pov {

struct Tok;

// An object while it is parsed: CSG stays a tree, and the flags POV-Ray's
// inheritance rules need (a union's texture goes to children without one) are
// kept beside it. Every pigment in the tree is in the space the root's
// transform maps to (world space once the root is in the scene).
struct PovObject {
    Object object; // shape, transform, texture, ...; for CSG the children are below
    std::vector<PovObject> children;
    bool textured = false;
    bool interiorSet = false;
    std::vector<Light> lights; // light_source inside a union
    bool lightOnly = false;    // a declared light_source: no shape of its own
    bool isCsg() const { return std::holds_alternative<Csg>(object.shape); }
};

struct PovMaterial {
    std::optional<Texture> texture;
    std::optional<Interior> interior;
};

struct PovMacro {
    std::string name;
    std::vector<std::string> params;
    std::shared_ptr<const std::vector<Tok>> tokens; // the file holding the body
    size_t bodyStart = 0;                           // index of the first body token
    SourceLoc loc;
};

// A warning raised while a #declare was evaluated. It is reported when the
// identifier is used, so that the unused declarations of the standard include
// files do not warn.
struct PendingWarning {
    std::string kind;
    SourceLoc loc;
    std::string message;
    std::vector<SourceLoc> includedFrom;
};

struct PovValue;
using Cell = std::shared_ptr<PovValue>;

struct PovArray {
    std::vector<int> sizes;   // one entry per dimension
    std::vector<Cell> items; // row-major; null: not initialised yet
};

struct PovValue {
    enum class Kind {
        Float, Vector, Color, String, Array, Object, Texture, Pigment, Finish, Interior, Material,
        Normal, Camera, Light, Transform, ColorMap, Macro, Opaque, SkySphere, Media,
    };
    Kind kind = Kind::Float;
    double number = 0;
    std::array<double, 5> v{};
    int size = 0; // components of a Vector (2..5); Colors have 5
    std::string text; // String; for Opaque, what it was (e.g. "function")
    std::shared_ptr<PovArray> array;
    std::shared_ptr<const PovObject> object;
    std::shared_ptr<const Texture> texture;
    std::shared_ptr<const Pigment> pigment;
    std::shared_ptr<const std::vector<Pigment>> sky; // SkySphere: its pigments, transformed
    std::shared_ptr<const Finish> finish;
    std::shared_ptr<const Interior> interior;
    std::shared_ptr<const Media> media;
    std::shared_ptr<const PovMaterial> material;
    std::shared_ptr<const CameraSpec> camera;
    std::shared_ptr<const Transform> transform;
    std::shared_ptr<const std::vector<ColorMapEntry>> colorMap;
    std::shared_ptr<const PovMacro> macro;
    std::shared_ptr<const std::vector<PendingWarning>> warnings; // see PendingWarning

    bool isNumeric() const { return kind == Kind::Float || kind == Kind::Vector || kind == Kind::Color; }

    static PovValue makeFloat(double f) {
        PovValue v;
        v.number = f;
        return v;
    }
    static PovValue makeVector(const Vec3& a) {
        PovValue v;
        v.kind = Kind::Vector;
        v.size = 3;
        v.v = {a.x, a.y, a.z, 0, 0};
        return v;
    }
    static PovValue makeColor(const std::array<double, 5>& c) {
        PovValue v;
        v.kind = Kind::Color;
        v.size = 5;
        v.v = c;
        return v;
    }
    static PovValue makeString(std::string s) {
        PovValue v;
        v.kind = Kind::String;
        v.text = std::move(s);
        return v;
    }
};

// "float", "vector", "object", ...: for messages.
const char* kindName(PovValue::Kind kind);

} // namespace drt::pov

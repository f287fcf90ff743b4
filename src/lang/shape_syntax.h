// Every shape of the scene model (scene.h, Shape) is declared once, in one
// front-end entry: its keywords, its reader (arguments, defaults, validation,
// model construction) and its .drt writer entry. The entries live beside each
// other in shapes_*.cpp. The reader table (shapeReaders) and the writer both
// go through every alternative of Shape, so a shape without an entry does not
// build: adding a shape means its model type (scene/scene.h), its intersection
// code (accel/shapes.h and .cpp) and its ShapeSyntax in one shapes_*.cpp.
#pragma once

#include "scene/scene.h"

#include <set>
#include <string>
#include <vector>

namespace drt::lang {

class Evaluator;
struct ObjectValue;
struct Token;

// What a writer entry needs beside the shape.
struct ShapeText {
    int indent = 0;                    // of the shape's line, for entries written over several lines
    std::set<std::string>& problems;   // what .drt cannot express, one line per kind
    const Object* object = nullptr;    // the object the shape belongs to (a mesh's textures are placed by it)
};

// ShapeSyntax<T> for each T in Shape, defined (as `template <>` members) in the
// shape's own lang/shapes_*.cpp (CSG: objects.cpp):
//   keywords()                      the words that start it (`sphere`; `lathe`, `sor`; ...)
//   read(evaluator, keyword, object) after the shape's '{': reads its arguments into object
//   head(shape, text)               the .drt text from the keyword through its arguments
// The reader table and the writer use all three for every alternative of
// Shape, so a shape without an entry does not link.
template <class T> struct ShapeSyntax {
    static const std::vector<std::string>& keywords();
    static void read(Evaluator& e, const Token& keyword, ObjectValue& object);
    static std::string head(const T& shape, ShapeText& text);
};

// The reader of each shape keyword, from every ShapeSyntax.
using ShapeReader = void (*)(Evaluator& e, const Token& keyword, ObjectValue& object);
const std::vector<std::pair<std::string, ShapeReader>>& shapeReaders();
ShapeReader shapeReader(const std::string& keyword); // nullptr for a word that is no shape

// POV-Ray shapes drt does not have: left out with a warning, or refused in .drt.
bool isUnsupportedShape(const std::string& keyword);

// The .drt text of a shape, from the keyword through its arguments ("" when .drt cannot write it).
std::string shapeHead(const Shape& shape, ShapeText& text);

} // namespace drt::lang

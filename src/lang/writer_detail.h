// Private to the .drt writer (writer.cpp, writer_transform.cpp,
// writer_texture.cpp): number
// formatting and the search for a readable transform sequence.
#pragma once

#include "core/transform.h"
#include "core/vec.h"
#include "scene/density_file.h"
#include "scene/image_map.h"
#include "scene/scene.h"

#include <array>
#include <set>
#include <string>
#include <vector>

namespace drt::writer {

// The shortest decimal text that reads back (strtod) as exactly `v`.
std::string number(double v);
std::string vector(const Vec3& v); // "<x, y, z>"
std::string quoted(const std::string& s); // a string literal: "..." with \" \\ \n \t escaped

// One transform item as the .drt parser reads it.
struct Step {
    enum class Kind { Translate, Rotate, Scale, Matrix };
    Kind kind = Kind::Translate;
    Vec3 v;                      // translate / rotate (degrees) / scale
    std::array<double, 12> m{};  // matrix, POV-Ray order
    Transform transform() const; // what the parser builds for this item
};

// `start` followed by the steps, composed one at a time as the parser does.
Transform compose(const std::vector<Step>& steps, const Transform& start = {});

// Matrix and inverse both bit-identical: the renderer uses both.
bool sameTransform(const Transform& a, const Transform& b);

// Steps that compose to `t`: the readable translate/rotate/scale form when it
// reproduces the matrix exactly (preferring one that also reproduces the
// inverse), else one `matrix` step. Identity gives no steps.
std::vector<Step> decompose(const Transform& t);

// " translate <...> rotate <...>": each step preceded by a space.
std::string formatSteps(const std::vector<Step>& steps);

// The short direction the author most likely wrote for a unit normal (the
// reader normalises plane, disc and smooth-triangle normals).
Vec3 unnormalised(const Vec3& n);

// ------------------------------------------------------------ writer_image_map.cpp

// " image_map { \"/abs/file.png\" ... }" (" image_pattern {" for a pattern's image: ImageMap::fileValues);
// a material_map's image as " material_map { \"/abs/file.png\" ... TEXTURES }".
std::string imageMapText(const ImageMap& m, const std::string& textures = "");
std::string densityFileText(const DensityFile& d); // " density_file df3 \"/abs/file.df3\" [interpolate n]"

// ------------------------------------------------------------ writer_texture.cpp

std::string colorText(const Color& c);   // "rgb 0.5" or "rgb <r, g, b>"
std::string colorText(const ColorFT& c); // rgb / rgbf / rgbt / rgbft as needed
bool isDefaultPigment(const Pigment& p); // solid black, whatever its transform
bool isDefaultFinish(const Finish& f);
bool isDefaultInterior(const Interior& i);
// The inside of `pigment { ... }`, given the transform items the enclosing
// text applies after it; clears `exact` if the pattern transform cannot be
// rebuilt to the last bit, and adds to `problems` what .drt cannot express.
std::string pigmentBody(const Pigment& p, const std::vector<Step>& suffix, bool& exact,
                        std::set<std::string>& problems);
// The inside of `normal { ... }`, placed like pigmentBody.
std::string normalBody(const Normal& n, const std::vector<Step>& suffix, bool& exact);
// The inside of `texture { ... }` for one layer or a patterned texture (its
// layersAbove left out), placed like pigmentBody.
std::string textureBody(const Texture& t, const std::vector<Step>& suffix, bool& exact,
                        std::set<std::string>& problems);
// A whole texture as `texture { ... }` blocks, bottom layer first.
std::vector<std::string> textureBlocks(const Texture& t, const std::vector<Step>& suffix, bool& exact,
                                       std::set<std::string>& problems);
std::string finishBody(const Finish& f);     // the non-default items, each after a space
std::string interiorBody(const Interior& i, std::set<std::string>& problems); // the same, media included
std::string mediaBody(const Media& m, std::set<std::string>& problems);       // the inside of `media { }`

} // namespace drt::writer

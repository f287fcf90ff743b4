// Keyword tables of the scene language, one per concept, shared by the
// evaluator (reading) and the .drt writer (writing), and the keywords each
// block accepts (for "did you mean" and "'ior' goes in 'interior', not
// 'finish'").
#pragma once

#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace drt::lang {

enum class Block {
    Statement, Object, Camera, LightSource, Texture, Pigment, Normal, Finish, Reflection, Interior, Media,
    Scattering, GlobalSettings, Render, Adaptive, Fog, Motion, ImageMap, SkySphere, TexturePattern, Transform,
};

const char* blockName(Block block);
// The keywords `block` accepts (its items; not values such as colours).
const std::vector<std::string>& blockKeywords(Block block);
// The blocks other than `in` whose own keyword `word` is (their home), for
// "'ior' goes in 'interior', not 'finish'". Words every block shares are left out.
std::vector<Block> homesOf(const std::string& word, Block in);

// A pattern's keyword.
struct PatternWord {
    const char* word;
    PatternKind kind;
};

// ---- noise patterns (render/noise.h): read in pigments, normals, textures
// and densities, written back by the .drt writer.
using NoisePatternWord = PatternWord;
// Every word, the canonical one of each kind first (POV-Ray's `spotted` is `bozo`).
const std::vector<NoisePatternWord>& noisePatternWords();
std::optional<PatternKind> noisePatternNamed(const std::string& word);
const char* noisePatternWord(PatternKind kind); // nullptr for a kind that is not a noise pattern
// The canonical words (for suggestions).
std::vector<std::string> noisePatternNames();

// Patterns of the point's place alone, with no parameters and a colour map
// (radial, onion, spherical, planar, cylindrical, boxed): read and written by this one table.
using PlacePatternWord = PatternWord;
const std::vector<PlacePatternWord>& placePatternWords();
std::optional<PatternKind> placePatternNamed(const std::string& word);
const char* placePatternWord(PatternKind kind); // nullptr for a kind that is not in the table

// POV-Ray patterns drt does not have: read and approximated (pigments,
// textures) or refused (.drt dialect).
bool isApproximatedPattern(const std::string& word);

// ---- CSG operations
struct CsgWord {
    const char* word;
    Csg::Op op;
};
const std::vector<CsgWord>& csgWords();
std::optional<Csg::Op> csgOpNamed(const std::string& word);
const char* csgWord(Csg::Op op);

// ---- camera types (`cylinder` takes its type number 1 to 4 after the word)
struct CameraWord {
    const char* word;
    CameraMapping mapping;
    bool orthographic;
};
const std::vector<CameraWord>& cameraWords();
std::optional<CameraWord> cameraWordNamed(const std::string& word);
std::string cameraKeyword(const CameraSpec& camera); // "perspective", "cylinder 2", ...

// ---- area_sampling names
struct AreaSamplingWord {
    const char* word;
    AreaSampling sampling;
};
const std::vector<AreaSamplingWord>& areaSamplingWords();
const char* areaSamplingWord(AreaSampling sampling);

} // namespace drt::lang

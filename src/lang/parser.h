// The .drt parser (private to src/lang): recursive descent, one function per
// grammar rule of grammar/drt.ebnf, one token of look-ahead. Split by seams:
//   parser.cpp          token stream, #include, errors, recovery, top level
//   parser_expr.cpp     expressions, vectors, colours
//   parser_scene.cpp    camera, light_source, background, global_settings, render
//   parser_objects.cpp  shapes and object modifiers
//   parser_textures.cpp texture, pigment, finish, interior
#pragma once

#include "lang/lexer.h"
#include "scene/frame_clock.h"
#include "scene/scene.h"
#include "scene/weight.h"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace drt {

// A vector of 2 to 5 components. Colours are 5-vectors <r, g, b, filter, transmit>.
struct VectorValue {
    std::array<double, 5> c{};
    int size = 3;
};

// An object under construction: `textured` is true once the object itself
// was given a texture (CSG children without one inherit the parent's).
// A union's children stay ParsedObjects (in the union's space) until the union
// reaches the scene, where it is flattened into its leaves.
struct ParsedObject {
    Object object;
    bool textured = false;
    std::vector<ParsedObject> children;
};

using Value = std::variant<double, VectorValue, Pigment, Finish, Texture, Interior, ParsedObject>;
std::string kindName(const Value& v);

// Thrown after a syntax error has been reported: unwinds to the statement
// loop, which skips to the next statement.
struct ParseAbort {};

class Parser {
public:
    Parser(Diagnostics& diags, Scene& scene, const FrameClock& frame = {})
        : diags_(diags), scene_(scene), frame_(frame) {}

    // Parses the file with id `fileId` in diags.files(); `path` identifies it
    // for include-cycle detection and `dir` is where its #includes resolve.
    void parseFile(int fileId, const std::string& path, const std::string& dir);

private:
    // ------------------------------------------------------------ parser.cpp
    struct Source {
        std::unique_ptr<Lexer> lexer;
        std::string canonicalPath;
        std::string dir;
        int fileId = -1;
    };
    void advance();
    void include(const Token& directive);
    bool check(TokenKind kind) const { return current_.kind == kind; }
    bool checkWord(const char* word) const { return current_.kind == TokenKind::Identifier && current_.text == word; }
    bool match(TokenKind kind);
    bool matchWord(const char* word);
    const Token& expect(TokenKind kind, const char* what);
    std::vector<SourceLoc> includeChain(const SourceLoc& loc) const;
    // A syntax error: reported, then ParseAbort.
    [[noreturn]] void fail(const SourceLoc& loc, const std::string& message);
    [[noreturn]] void failExpected(const char* what);
    [[noreturn]] void failUnknown(const Token& word, const std::vector<std::string>& known,
                                  const char* kind = "keyword");
    // A value error: reported, parsing carries on.
    void error(const SourceLoc& loc, const std::string& message);
    void warning(const SourceLoc& loc, const std::string& message);
    void synchronize();
    void statement();
    void declare();
    bool isTopLevelWord(const std::string& word) const;

    // Guards recursion depth (nested parentheses, blocks).
    struct DepthGuard {
        Parser& parser;
        DepthGuard(Parser& p, const SourceLoc& loc);
        ~DepthGuard() { --parser.depth_; }
    };

    // ------------------------------------------------------- parser_expr.cpp
    Value expression();
    Value term();
    Value unary();
    Value primary();
    Value call(const Token& name);
    VectorValue vectorLiteral();
    VectorValue colorBody(); // after `color`: rgb/rgbf/.../red/green/... items
    bool atColorWord() const;
    double floatExpr(const char* what = "a number");
    Vec3 vectorExpr(const char* what = "a vector");
    ColorFT colorExpr();
    Color rgbExpr() { return colorExpr().rgb; }
    bool booleanOr(bool fallback); // optional `on off true false yes no` or a number
    bool atBoolean() const;
    int intExpr(const char* what);
    const Value* lookup(const std::string& name) const;
    std::optional<double> clockIdentifier(const std::string& name);

    // ------------------------------------------------------ parser_scene.cpp
    void camera();
    void lightSource();
    void areaLight(Light& light);
    void background();
    void skySphere();
    void fog();
    void globalSettings();
    void renderBlock();
    void adaptiveBlock(const SourceLoc& keyword);
    void requireNonZero(const Vec3& v, const SourceLoc& loc, const char* what);
    // translate/rotate/scale/matrix at the current token, or nothing.
    std::optional<Transform> transformItem();

    // ---------------------------------------------------- parser_objects.cpp
    bool atObjectWord() const;
    ParsedObject object();
    void shapeBody(const Token& keyword, ParsedObject& po);
    void objectModifiers(ParsedObject& po, const Token& keyword);
    bool objectModifier(ParsedObject& po);
    void motion(Object& object);
    Motion motionBlock(); // at 'motion': the block, as scene/motion.h Motion
    void meshTriangle(Mesh& mesh, bool smooth);
    void setTexture(ParsedObject& po, const Texture& texture);
    void addChild(ParsedObject& parent, ParsedObject child);
    void applyTransform(ParsedObject& po, const Transform& t, const SourceLoc& loc);
    void addObjectToScene(ParsedObject po);
    void flatten(ParsedObject& po, const Transform& parentBefore, const MotionChain& parentChain, bool noShadow,
                 bool hollow, const std::vector<Object>& parentClips = {});
    void clippedBy(Object& clipped);
    std::vector<Object> csgChildren(ParsedObject& po, const Transform& csgToWorld);
    double positiveRadius(const char* what);
    // parser_algebraic.cpp
    static bool isAlgebraicWord(const std::string& word);
    void algebraicBody(const Token& keyword, ParsedObject& po);
    std::vector<double> coefficientList(const std::string& what, int expected);
    // parser_extrusion.cpp
    void prismBody(const Token& keyword, ParsedObject& po);
    void textBody(ParsedObject& po);
    // parser_revolution.cpp
    static bool isRevolutionWord(const std::string& word);
    void revolutionBody(const Token& keyword, ParsedObject& po);
    // parser_blob.cpp
    void blobBody(const Token& keyword, ParsedObject& po);
    BlobComponent blobComponent();

    // --------------------------------------------------- parser_textures.cpp
    Texture texture();
    Pigment pigment();
    // The items of a texture / pigment up to `closer` (`}`, or `]` in a map entry).
    Texture textureBody(TokenKind closer, const char* where);
    Pigment pigmentBody(TokenKind closer, const char* where);
    bool pigmentItem(Pigment& p);
    // parser_texture_maps.cpp: texture patterns, texture_map, pigment_map.
    bool atTexturePattern() const;
    Texture patternedTexture(TokenKind closer, const char* where);
    std::vector<Texture::MapEntry> textureMap(bool average);
    void pigmentMap(Pigment& p);
    // After a `texture` keyword at `loc`: parses it and layers it on top of `below`.
    void layerTexture(Texture& below, SourceLoc loc);
    Pigment pigmentOrColor();
    void colorMap(Pigment& p);
    void imageMap(Pigment& p); // parser_image_map.cpp, at 'image_map'
    Finish finish();
    Normal normal();
    bool turbulenceItem(Turbulence& turbulence);
    bool waveItem(PatternWave& wave); // parser_pattern_wave.cpp
    static const std::vector<std::string>& waveWords();
    void reflectionBlock(Finish& f);
    Interior interior();
    // parser_media.cpp
    Media media();              // at 'media'
    void scattering(Media& m);  // after 'scattering'
    Pigment density();          // at 'density'

    Diagnostics& diags_;
    Scene& scene_;
    FrameClock frame_; // what `clock`, `frame_number`, ... read
    std::vector<Source> sources_;
    std::map<int, std::vector<SourceLoc>> includeChains_; // file id -> #include locations, innermost first
    Token current_;
    Token previous_;
    int braceDepth_ = 0;
    long tokensRead_ = 0;
    int depth_ = 0;
    std::map<std::string, Value> symbols_;
    // Limits::objects: nodes built and copied so far, and each declared
    // name's weight (what a use copies).
    static constexpr int64_t kMemoryCheckWeight = 4096; // nodes between looks at the memory in use
    static int64_t valueWeight(const Value& value, int64_t cap);
    void countBuilt(const SourceLoc& loc, int64_t weight);
    int64_t built_ = 0;
    int abandonedFile_ = -1; // an included file that is no scene, read no further after its first error
    std::map<std::string, int64_t> symbolWeights_;
};


} // namespace drt

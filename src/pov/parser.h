// The POV-Ray evaluator. POV-Ray's language is a macro language evaluated
// while it is read, so parsing and evaluation are one pass, as in POV-Ray: the
// token stream (reader.cpp) runs directives, includes, loops and macro calls as
// the parser pulls tokens; expressions (expr.cpp), textures (textures.cpp),
// objects (objects.cpp) and the scene statements (scene_items.cpp) consume it.
#pragma once

#include "pov/lexer.h"
#include "pov/load.h"
#include "pov/value.h"
#include "scene/weight.h"

#include <map>
#include <set>

namespace drt::pov {

// Loop passes and macro calls between two looks at the memory in use
// (Limits::memoryMB).
inline constexpr long kMemoryCheckInterval = 1024;

// Thrown after an error has been reported: POV-Ray stops at the first error.
struct PovAbort {};

class PovParser {
public:
    PovParser(Diagnostics& diags, const PovOptions& options);

    // Evaluates a file (already added to SourceFiles as `fileId`) into scene_.
    std::optional<Scene> run(int fileId, const std::string& baseDir);

    // ------------------------------------------------------------ tokens (reader.cpp)
    Tok next();          // directives run, macros expanded
    Tok peek();          // the same token next() will return
    Tok peekOperator();  // stops at a directive or a macro name (returned unconsumed, unexpanded)
    void pushBack(Tok t) { pushed_.push_back(std::move(t)); }
    bool acceptSymbol(const char* s);
    Tok expectSymbol(const char* s, const char* context);
    bool acceptWord(const char* w);
    Tok expectWord(const char* context); // any word
    // After '{' was consumed: skips to its matching '}', directives included.
    void skipBlock();

    // ------------------------------------------------------------ diagnostics
    [[noreturn]] void fail(SourceLoc loc, const std::string& message);
    [[noreturn]] void failExpected(const Tok& got, const std::string& what);
    void warn(SourceLoc loc, const std::string& message);
    // One warning per `kind` for the whole scene.
    void warnOnce(const std::string& kind, SourceLoc loc, const std::string& message);
    void note(SourceLoc loc, const std::string& message);

    // ------------------------------------------------------------ symbols
    Cell lookup(const std::string& name) const;
    // lookup() for a use of the identifier: reports the warnings its declaration deferred.
    Cell use(const std::string& name);
    // use() for an identifier just read, following `[i]...` indices into an array.
    Cell useIndexed(const Tok& name);
    // The element of array `cell` named by the `[i]...` that follow.
    Cell indexArray(Cell cell, const Tok& name);
    void declare(const std::string& name, const PovValue& value, bool local);
    bool isMacro(const std::string& name) const;

    // ------------------------------------------------------------ expressions (expr.cpp)
    PovValue expression();
    double floatExpr();
    // A float that becomes a count or an index: it must be finite and in
    // [lowest, highest] (a located error names `what` otherwise); truncated
    // toward zero as POV-Ray does.
    int countExpr(const char* what, double lowest, double highest);
    int countValue(double value, SourceLoc loc, const char* what, double lowest, double highest);
    Vec3 vectorExpr(); // a float promotes to <f,f,f>
    std::array<double, 5> colorExpr(); // colour keywords and expressions
    std::string stringExpr();
    bool boolExpr() { return floatExpr() != 0; }
    // Whether `t` starts a float expression (a number, '(', a sign, a float identifier, a function).
    bool startsFloat(const Tok& t) const;
    // The right-hand side of #declare and of a macro argument: an expression or a scene item.
    PovValue rvalue();
    // Built-in functions and constants (functions.cpp); false if `name` is none.
    bool builtin(const Tok& name, PovValue& out);
    PovValue primary();
    PovValue postfix(PovValue v, SourceLoc loc);
    PovValue arrayLiteral(SourceLoc loc); // after 'array'
    bool inVector_ = false;               // '>' closes a vector literal, not a comparison
    bool countBeforeVector_ = false;      // '<' after a count or thickness starts a vector, not a comparison
    // Scalar conversions with a clear error.
    double toFloat(const PovValue& v, SourceLoc loc);
    Vec3 toVector(const PovValue& v, SourceLoc loc);
    std::array<double, 5> toColor(const PovValue& v, SourceLoc loc);

    // ------------------------------------------------------------ textures (textures.cpp)
    Texture texture(const Texture& base);  // after 'texture'
    Pigment pigment(const Pigment& base);  // after 'pigment'
    // The items of a texture / pigment up to `closer` ("}", or "]" in a map entry).
    Texture textureBody(const Texture& base, const char* closer);
    Pigment pigmentBody(const Pigment& base, const char* closer);
    // Texture patterns and maps (texture_maps.cpp).
    static bool isTexturePatternWord(const std::string& w);
    Texture patternedTexture(const Tok& patternWord, const char* closer); // pattern word consumed
    std::vector<Texture::MapEntry> textureMap();                          // after 'texture_map'
    double mapEntryValue(); // after '[' in a map
    std::vector<Pigment::MapEntry> pigmentMap();                          // after 'pigment_map'
    // addLayerOnTop, with POV-Ray's errors for layers over or of patterned textures.
    void layerOnTop(Texture& below, Texture top, SourceLoc loc);
    Finish finish(const Finish& base);     // after 'finish'
    Interior interior(const Interior& base);
    // media.cpp
    Media media(const Media& base); // after 'media'
    void scattering(Media& m);      // after 'scattering'
    Pigment density();              // after 'density': POV-Ray's default density is 1
    Pigment density(const Pigment& base);
    PovMaterial material(const PovMaterial& base);
    // After 'normal': the bump pattern, or none (then a warning says why).
    std::optional<Normal> normalBlock(SourceLoc keyword);
    bool patternModifier(const Tok& t, Turbulence& turbulence); // turbulence/octaves/omega/lambda
    bool waveModifier(const Tok& t, PatternWave& wave); // frequency/phase/wave types (pattern_wave.cpp)
    void warpBlock(const Tok& t, Pigment& p);           // at 'warp' (pattern_wave.cpp)
    void noiseNote(const std::string& kind, SourceLoc loc);
    std::vector<ColorMapEntry> colorMap(); // after 'color_map'
    // A transform keyword (translate rotate scale matrix transform) at the current token, or nothing.
    std::optional<Transform> transformItem();
    Transform transformBlock(); // after 'transform'

    // ------------------------------------------------------------ objects (objects.cpp)
    bool isObjectWord(const Tok& t) const;
    PovObject object(const Tok& keyword); // keyword consumed
    // extrusion.cpp: the bodies of prism and text, after '{'.
    Extrusion prismShape(SourceLoc keyword);
    std::optional<Extrusion> textShape();
    std::optional<std::vector<Object>> clipObjects(const Tok& word); // after bounded_by / clipped_by
    // revolution.cpp: the bodies of lathe and sor, after '{'.
    Revolution revolutionShape(const Tok& keyword);
    // blob.cpp: the body of blob after '{' (components; textures in them are ignored with a warning).
    Blob blobShape(const Tok& keyword);
    // height_field.cpp: the body of height_field after '{'; none if left out (a warning says why).
    std::optional<Mesh> heightFieldShape(SourceLoc keyword);
    static bool isImageTypeWord(const Tok& t); // gif tga png jpeg ... before an image file name
    // An image file named in the scene, found like an include file (image extensions tried
    // for a name without one); "" if not found.
    std::string findDataFile(const std::string& name) const;
    // image_map.cpp: after 'image_map'; none if unsupported (a warning says why).
    std::optional<Pigment> imageMapPigment(SourceLoc keyword);
    void applyTransform(PovObject& o, const Transform& t);
    // motion.cpp: drt's motion block, after 'motion' (scene/motion.h).
    Motion motionBlock();
    // ------------------------------------------------------------ algebraic.cpp
    static bool isAlgebraicWord(const std::string& w);
    Shape algebraicShape(const Tok& keyword); // after the shape's '{'
    std::vector<double> coefficientList(const std::string& what, int expected);

    // ------------------------------------------------------------ scene (scene_items.cpp)
    void statement(const Tok& t);
    CameraSpec camera(const CameraSpec& base, SourceLoc loc);
    // `looksLike`, if given, receives the looks_like object (placed, no_shadow).
    Light lightSource(SourceLoc loc, std::optional<PovObject>* looksLike = nullptr);
    void globalSettings();
    void fog(const Tok& keyword); // after 'fog'
    void resolveParallelSky(CameraSpec& cam);
    std::vector<Pigment> skySphere(); // after 'sky_sphere'
    void defaultBlock();              // after '#default' or 'default'
    void addToScene(PovObject o);
    void finishScene(); // gamma rules, defaults

    Scene scene_;
    bool cameraSeen_ = false;
    std::optional<double> assumedGamma_;
    // The gamma of the working colour space so far: assumed_gamma, else 2.2
    // under a #version below 3.7, else 1 (docs/pov.md, "Gamma").
    double workingGamma() const { return assumedGamma_ ? *assumedGamma_ : (version_ < 3.7 ? 2.2 : 1.0); }
    double version_ = 3.7;
    bool versionSeen_ = false;
    Texture defaultTexture_; // #default { texture / pigment / finish }
    std::vector<uint32_t> randomStreams_; // seed(n) returns an index into this

private:
    friend class DirectiveRunner;
    struct Frame {
        std::shared_ptr<const std::vector<Tok>> tokens;
        size_t pos = 0;
        bool isMacro = false;
        SourceLoc includedFrom; // include frames: the #include directive
        size_t condDepth = 0;   // conds_.size() when the frame started
        std::string dir;        // include frames: folder of the file
        // Look-ahead read from this frame before a child frame (include, macro
        // call) started; it is read again when the child ends.
        std::vector<Tok> savedPushback;
    };
    void pushFrame(Frame f);
    void popFrame();
    struct Cond {
        enum class Type { If, While, For, Switch } type = Type::If;
        size_t frame = 0;
        size_t pos = 0; // While: the condition; For: the first body token
        SourceLoc loc;
        std::string forName;
        double forEnd = 0, forStep = 1;
        long iterations = 0;
        double switchValue = 0;
        bool switchMatched = false;
    };

    Tok rawNext();
    const Tok& rawPeek() const;
    void endFrame();
    void directive(const Tok& t);
    void declareDirective(const Tok& t, bool local);
    void includeDirective(const Tok& t);
    void ifDirective(const Tok& t, int kind); // 0 #if, 1 #ifdef, 2 #ifndef
    void branchSkip(const Tok& start);       // skip a false branch: to #else / #elseif / #end
    void whileHead(const Tok& t);
    void forDirective(const Tok& t);
    void switchDirective(const Tok& t);
    void switchScan(const Tok& t); // find the matching #case / #range / #else / #end
    void endDirective(const Tok& t);
    void breakDirective(const Tok& t);
    void macroDefinition(const Tok& t);
    void invokeMacro(const Tok& t);
    void messageDirective(const Tok& t);
    void fileDirective(const Tok& t);
    void versionDirective(const Tok& t);
    // Limits (core/limits.h): a loop's passes, the memory a scene takes.
    void countIteration(Cond& c, const char* directive);
    void checkMemoryAt(SourceLoc loc);
    long macroCalls_ = 0;
    int64_t objectsBuilt_ = 0;
    // Skips raw tokens until a directive in `stops` at nesting depth 0; returns it.
    Tok skipTo(const std::set<std::string>& stops, const Tok& start);
    std::vector<SourceLoc> includeChain() const;
    std::string findInclude(const std::string& name, const std::string& fromDir) const;
    void pushFile(int fileId, SourceLoc includedFrom, const std::string& dir);
    Cell* arrayElementForAssignment(const Tok& name, Cell cell);

    Diagnostics& diags_;
    PovOptions options_;
    std::vector<Frame> frames_;
    std::vector<Cond> conds_;
    std::vector<Tok> pushed_;
    std::vector<std::map<std::string, Cell>> scopes_;
    std::set<std::string> warned_;
    std::vector<PendingWarning>* pending_ = nullptr; // while evaluating a #declare
    std::map<std::string, std::shared_ptr<const std::vector<Tok>>> lexedFiles_;
    int expressionDepth_ = 0;
    bool noExpand_ = false;
    friend struct DepthGuard;
};

// The world-space bounding box of an object (POV-Ray's min_extent / max_extent);
// unbounded shapes give +-1e10 as POV-Ray's BOUND_HUGE/2 does.
void objectBounds(const PovObject& o, Vec3& lower, Vec3& upper);
// The scene-model object (CSG members included).
Object toObject(const PovObject& po);

// POV-Ray colour (r g b filter transmit) -> scene colour.
ColorFT toColorFT(const std::array<double, 5>& c);

// The mean colour of a pigment (patterns averaged over their colour map or sub-pigments).
ColorFT pigmentAverage(const Pigment& p);

// Counts nesting of a recursive parse function and stops runaway recursion.
struct DepthGuard {
    DepthGuard(PovParser& p, SourceLoc loc);
    ~DepthGuard();
    int& depth;
};


} // namespace drt::pov

// The evaluator of both dialects (private to src/lang). The scene language is a
// macro language evaluated while it is read, as POV-Ray's is, so parsing and
// evaluation are one pass: the token stream (reader.cpp) runs directives
// (directives.cpp), includes, loops and macro calls as the item readers pull
// tokens; expressions (expressions.cpp, primary.cpp, functions.cpp), textures
// (textures.cpp, pigments.cpp, ...), objects (objects.cpp, shapes_*.cpp) and the
// scene statements (scene_items.cpp, camera.cpp, lights.cpp) consume it. The
// dialect table (lang/dialect.h) is consulted where the dialects differ.
#pragma once

#include "lang/dialect.h"
#include "lang/keywords.h"
#include "lang/lexer.h"
#include "lang/load.h"
#include "lang/symbols.h"
#include "lang/value.h"
#include "scene/texture_sharing.h"
#include "scene/weight.h"

#include <cstdint>
#include <functional>
#include <map>
#include <set>

namespace drt::lang {

// uv_mapping on or off for a pigment and all its sub-pigments (pigments.cpp, textures.cpp).
inline void setUvMapping(Pigment& p, bool on) {
    p.uvMapping = on;
    for (Pigment& child : p.children) setUvMapping(child, on);
    for (Pigment::MapEntry& entry : p.pigmentMap) setUvMapping(entry.pigment, on);
}

// Loop passes and macro calls between two looks at the memory in use
// (Limits::memoryMB).
inline constexpr long kMemoryCheckInterval = 1024;

// Thrown after an error has been reported: unwinds to the statement loop,
// which skips to the next statement (or stops, as POV-Ray does).
struct Abort {};

// Moves a light's projected_through objects (Light::projectedThrough) by `t`.
void transformProjectedThrough(Light& l, const Transform& t);

class Evaluator {
public:
    Evaluator(Diagnostics& diags, const LoadOptions& options, DialectKind dialect);

    // Evaluates a file (already added to SourceFiles as `fileId`) into scene_.
    std::optional<Scene> run(int fileId, const std::string& baseDir);

    // ------------------------------------------------------------ tokens (reader.cpp)
    // The next token, directives run and macros expanded. The reference is to
    // the last token read (lastToken()): it holds until the next is read.
    const Token& next();
    // The same token next() will return. The reference is to the look-ahead:
    // it holds until the next token is taken or given back.
    const Token& peek();
    // Stops at a directive or a macro name (returned unconsumed, unexpanded). The
    // reference holds, as peek()'s, until the next token is taken or given back.
    const Token& peekOperator();
    void pushBack(Token t);
    bool acceptSymbol(std::string_view s);
    // The next token, which must be the symbol `s`: else an error, "expected 's' <context>".
    // A literal context goes to the const char* form, which makes no string unless it fails.
    const Token& expectSymbol(const char* s, const std::string& context);
    const Token& expectSymbol(const char* s, const char* context);
    // The context `before + name + after` ("after 'sphere'"), made only when the symbol is missing.
    const Token& expectSymbol(const char* s, const char* before, const std::string& name, const char* after);
    bool acceptWord(std::string_view w);
    Token expectWord(const std::string& context); // any word
    // After '{' was consumed: skips to its matching '}', directives included.
    void skipBlock();
    // A ',' between arguments: required in the .drt dialect ("',' after the
    // <what>"), optional in POV-Ray's.
    void comma(const std::string& after);
    // The location of the last token consumed.
    SourceLoc lastLoc() const { return lastToken_.loc; }
    const Token& lastToken() const { return lastToken_; }
    // The current file's token stream at its frontier, for reading long lists
    // of literals without tokens (mesh vertices and indices: TokenStream's
    // scans); nullptr when the file is replayed (a loop in it, a macro body) or
    // a look-ahead cannot be given back. After a scan that consumed something,
    // call rawRead() with the place of the last symbol it consumed.
    TokenStream* rawStream();
    void rawRead(SourceLoc last, const char* lastSymbol);

    // ------------------------------------------------------------ dialects
    // The dialect of the file being read (its syntax rules) and of the scene
    // (its defaults and legacy rules: the main file's).
    const Dialect& syntax() const;
    const Dialect& scene() const { return dialectOf(sceneDialect_); }
    bool isDrt() const { return sceneDialect_ == DialectKind::Drt; }

    // ------------------------------------------------------------ diagnostics (diagnose.cpp)
    [[noreturn]] void fail(SourceLoc loc, const std::string& message);
    // A resource limit (objects, loop passes, nesting, memory, ...) was reached:
    // the error ends the whole read, with no recovery at the next statement,
    // since whatever filled the limit would only fill it again.
    [[noreturn]] void failLimit(SourceLoc loc, const std::string& message);
    [[noreturn]] void failExpected(const Token& got, const std::string& what);
    // An unknown word in `block`: "did you mean", or where the keyword belongs.
    // `extra` are further words valid here (declared names, ...).
    [[noreturn]] void failUnknown(const Token& word, Block block, const std::vector<std::string>& extra = {},
                                  const char* kind = "keyword");
    [[noreturn]] void failUnknownIn(const Token& word, const std::vector<std::string>& known,
                                    const char* kind = "keyword");
    // A value error: reported; evaluation goes on in the .drt dialect.
    void error(SourceLoc loc, const std::string& message);
    // A value drt's rules refuse: an error in the .drt dialect (and in both
    // when `always`); POV-Ray accepts it, so in that dialect it is kept silently.
    void refuse(SourceLoc loc, const std::string& message, bool always = false);
    void warn(SourceLoc loc, const std::string& message);
    // One warning per `kind` for the whole scene.
    void warnOnce(const std::string& kind, SourceLoc loc, const std::string& message);
    void note(SourceLoc loc, const std::string& message);
    // One note per `kind`; like warnings, waits for the use of a declared identifier.
    void noteOnce(const std::string& kind, SourceLoc loc, const std::string& message);
    // A construct drt lacks: an error in the .drt dialect, a warning (once per
    // kind) in POV-Ray's, where the caller then leaves it out.
    void unsupported(const std::string& kind, SourceLoc loc, const std::string& message);
    // ", got -0.5 (R = 0.5 - 1)": the value of the last expression read, and
    // the declaration it came from when it was a lone identifier.
    std::string got(double value) const;
    std::string got(const Vec3& value) const;
    std::string got(int value) const { return got(double(value)); }

    // Blocks being read, for "the 'sphere' opened here is not closed".
    struct BlockScope {
        Evaluator& e;
        BlockScope(Evaluator& ev, const std::string& keyword, SourceLoc loc);
        ~BlockScope();
    };
    // failExpected for the token that ends a block's items: adds a note at the
    // block's keyword when the token shows its '}' is missing.
    [[noreturn]] void failInBlock(const Token& got, const std::string& what);

    // ------------------------------------------------------------ symbols (reader.cpp)
    Cell lookup(const std::string& name) const;
    Cell lookup(const Token& word) const { return scopes_.find(word); } // the same, for a word token
    // lookup() for a use of the identifier: reports the warnings its declaration deferred.
    Cell use(const std::string& name);
    Cell use(const Token& word);
    // use() for an identifier just read, following `[i]...` indices into an array.
    Cell useIndexed(const Token& name);
    // The element of array `cell` named by the `[i]...` that follow.
    Cell indexArray(Cell cell, const Token& name);
    // Reads one `[i]` per dimension of `a` (array `name`): the row-major index of the element.
    size_t arrayIndex(const lang::Array& a, const Token& name);
    // `scopeCount`: how many scopes were open when the directive began (a
    // value may end inside a macro that is still open, as POV-Ray's
    // `#local V = M();` with the `;` in M's body); the name goes to those.
    void declare(const std::string& name, Value value, bool local, size_t scopeCount = SIZE_MAX);
    bool isMacro(const std::string& name) const;
    bool isMacro(const Token& word) const; // the same, for a word token
    // Declared names whose value is one of `kinds` (all names when empty), for suggestions.
    std::vector<std::string> declaredNames(std::initializer_list<Value::Kind> kinds = {}) const;

    // ------------------------------------------------------------ expressions
    Value expression();
    double floatExpr(const char* what = "a number");
    Vec3 vectorExpr(const char* what = "a vector");
    int intExpr(const char* what); // a whole number
    // A number that becomes a count or an index: it must be finite and in
    // [lowest, highest] (a located error names `what` otherwise); truncated
    // toward zero as POV-Ray does.
    int countExpr(const char* what, double lowest, double highest);
    int countValue(double value, SourceLoc loc, const char* what, double lowest, double highest);
    std::array<double, 5> colorExpr(); // colour keywords and expressions
    Color rgbExpr() { return toColorFT(colorExpr()).rgb; }
    std::string stringExpr();
    bool boolExpr() { return floatExpr() != 0; }
    // An optional boolean after a flag keyword (`hollow`, `jitter on`): absent is `fallback`.
    bool optionalBool(bool fallback = true);
    // Whether `t` starts a float expression (a number, '(', a sign, a float identifier, a function).
    bool startsFloat(const Token& t) const;
    // Whether the peeked token starts a colour (a colour keyword, '<', a number or a numeric identifier).
    bool startsColor(const Token& t) const;
    // The right-hand side of #declare and of a macro argument: an expression or a scene item.
    Value rvalue();
    bool builtin(const Token& name, Value& out); // functions.cpp
    Value traceOrInside(const Token& name);      // trace(object, from, direction [, normal]) and inside(object, point)
    // User-defined functions (function_syntax.cpp). After 'function': its
    // parameters and body, compiled.
    std::shared_ptr<const Function> functionBody(const Token& keyword);
    // After 'pattern' or 'pigment' inside a function: the pattern or pigment.
    Pigment functionPattern(const Token& keyword);
    // After 'function' in a pigment, texture or normal: a function of x, y, z.
    std::shared_ptr<const Function> patternFunction(const Token& keyword);
    // `pigment_pattern { PIGMENT }`, read after its keyword: the grey value of the pigment.
    std::shared_ptr<const Function> pigmentPatternFunction(const Token& keyword);
    // A call of the declared function `f` (named `name`, consumed): its arguments, then its value.
    Value callFunction(const Token& name, const Function& f);
    std::shared_ptr<const Spline> splineBlock(SourceLoc keyword); // after 'spline'
    Value callSpline(const Token& name, const Spline& s);          // at '(' after a spline's name
    std::string declaringName_; // the name a #declare is giving a value, while it is read
    Value primary();
    Value postfix(Value v, SourceLoc loc);
    Value arrayLiteral(SourceLoc loc); // after 'array'
    bool inVector_ = false;            // '>' closes a vector literal, not a comparison
    bool countBeforeVector_ = false;   // '<' after a count or thickness starts a vector, not a comparison
    double toFloat(const Value& v, SourceLoc loc, const char* what = "a number");
    Vec3 toVector(const Value& v, SourceLoc loc, const char* what = "a vector");
    std::array<double, 5> toColor(const Value& v, SourceLoc loc);
    static ColorFT toColorFT(const std::array<double, 5>& c) { return {Color(c[0], c[1], c[2]), c[3], c[4]}; }
    // The working gamma of colours (POV-Ray's rules), or 1.
    double workingGamma() const;

    // ------------------------------------------------------------ textures
    Texture texture(const Texture& base); // after 'texture'
    Pigment pigment(const Pigment& base); // after 'pigment'
    // The items of a texture / pigment up to `closer` ("}", or "]" in a map entry).
    Texture textureBody(const Texture& base, const char* closer, const std::string& where);
    Pigment pigmentBody(const Pigment& base, const char* closer, const std::string& where);
    bool pigmentItem(Pigment& p, const Token& t);
    bool isTexturePatternWord(const Token& t) const;
    Texture patternedTexture(const Token& patternWord, const char* closer, const std::string& where);
    std::vector<Texture::MapEntry> textureMap(bool average); // after 'texture_map'
    std::vector<Pigment::MapEntry> pigmentMap(bool average); // after 'pigment_map' or a density's 'density_map'
    double mapEntryValue(bool average, const char* map, const double* previous);
    // Adds `top` on top of `below`, with POV-Ray's errors for layers over or of patterned textures.
    void layerOnTop(Texture& below, Texture top, SourceLoc loc);
    std::vector<ColorMapEntry> colorMap(); // after 'color_map'
    Finish finish(const Finish& base);     // after 'finish'
    void reflectionBlock(Finish& f);       // after 'reflection' '{'
    Interior interior(const Interior& base);
    Media media(const Media& base); // after 'media'
    void scattering(Media& m);      // after 'scattering'
    Pigment density(const Pigment& base); // after 'density'
    Material material(const Material& base);
    // After 'normal': the bump pattern, or none (POV-Ray dialect: a warning says why).
    std::optional<Normal> normalBlock(SourceLoc keyword, const std::optional<Normal>& base);
    std::vector<SlopeMapEntry> slopeMap(SourceLoc keyword); // after 'slope_map'
    bool turbulenceItem(const Token& t, Turbulence& turbulence); // turbulence/octaves/omega/lambda
    bool waveItem(const Token& t, PatternWave& wave); // frequency/phase/wave types
    void warpBlock(const Token& t, Pigment& p);       // at 'warp'
    void noiseNote(const std::string& kind, SourceLoc loc);
    // Fractal patterns (fractal_syntax.cpp): after 'mandel', 'julia' or 'magnet'
    // (`keyword`, consumed), the pattern's own arguments; then its modifiers
    // (exponent, exterior, interior, max_iteration) at the peeked token `t`,
    // consumed with their values when `fractal` is set and `t` is one.
    static bool isFractalWord(const std::string& word);
    std::shared_ptr<const FractalPattern> fractalPattern(const Token& keyword);
    bool fractalModifier(const Token& t, std::shared_ptr<const FractalPattern>& fractal);
    // After 'image_map', or after 'image_pattern' (`pattern`: a colour-map pattern of the image's grey).
    std::optional<Pigment> imageMapPigment(SourceLoc keyword, bool pattern = false);
    // The file and modifiers of an image_map, an image_pattern (`pattern`: use_alpha is known) or a
    // material_map, after its '{', up to its '}'. `item`, when set, is offered each token first
    // (material_map's textures) and returns true if it took it.
    std::shared_ptr<ImageMap> imageMapBody(const std::function<bool(const Token&)>& item, bool pattern = false);
    // `density_file df3 "file" [interpolate n]`, read after 'density_file'.
    std::shared_ptr<const DensityFile> densityFile(const Token& keyword);
    // `interpolate n` of a density_file, read after 'interpolate': `d` with it.
    std::shared_ptr<const DensityFile> densityInterpolate(const std::shared_ptr<const DensityFile>& d);
    // A transform keyword (translate rotate scale matrix transform) at the current token, or nothing.
    std::optional<Transform> transformItem();
    Transform transformBlock(); // after 'transform'
    void requireNonZero(const Vec3& v, SourceLoc loc, const std::string& what);

    // ------------------------------------------------------------ objects
    bool isObjectWord(const Token& t) const;
    ObjectValue object(const Token& keyword); // keyword consumed
    ObjectValue lightGroup(const Token& keyword); // after 'light_group {' (light_groups.cpp)
    void objectModifiers(ObjectValue& po, const Token& keyword);
    void applyTransform(ObjectValue& o, const Transform& t, SourceLoc loc);
    void setTexture(ObjectValue& o, const Texture& texture);
    void setInterior(ObjectValue& o, const Interior& interior);
    void addChild(ObjectValue& parent, ObjectValue child);
    Motion motionBlock(); // after 'motion': objects, cameras and lights
    std::optional<std::vector<Object>> clipObjects(const Token& word); // after bounded_by / clipped_by
    Object placed(ObjectValue po); // a clip or CSG member as a model object
    // Finds a data file (image, font) like an include file; "" if not found.
    std::string findDataFile(const std::string& name, bool imageExtensions) const;
    // The file name of an image_map or density_file (a string; in .drt a literal one), found by
    // findDataFile: a located error names the `kind` of file that was not found.
    void dataFileName(const char* format, const char* kind, bool imageExtensions, std::string& file,
                      std::string& path, SourceLoc& loc);
    std::string currentDir() const;
    const std::string& mainDir() const { return mainDir_; }
    std::string findInclude(const std::string& name, const std::string& fromDir) const;
    // Shape readers (shapes_*.cpp), after the shape's '{'.
    void readShape(const Token& keyword, ObjectValue& po);

    // ------------------------------------------------------------ scene (scene_items.cpp, camera.cpp, lights.cpp)
    void statement(const Token& t);
    CameraSpec camera(const CameraSpec& base, SourceLoc loc);
    // `looksLike`, if given, receives the looks_like object (placed, no_shadow).
    Light lightSource(SourceLoc loc, std::optional<ObjectValue>* looksLike = nullptr);
    void globalSettings();
    void renderBlock();
    void adaptiveBlock(SourceLoc keyword);
    void fog(const Token& keyword); // after 'fog'
    std::vector<Pigment> skySphere(); // after 'sky_sphere'
    void background();
    void defaultBlock();              // after '#default' or 'default'
    void addToScene(ObjectValue o);
    // Limits (core/limits.h): objects and pattern nodes built or copied
    // (Limits::objects), and the memory the scene takes.
    void countBuilt(SourceLoc loc, int64_t weight);
    // Whether a #while or #for loop is running (in any file or macro).
    bool loopRunning() const;
    // A triangle (keyword at `loc`) of the mesh opened at `mesh`, read while a
    // loop runs: it counts as an object, so a loop adding a triangle a pass
    // without end stops at Limits::objects, with notes naming the mesh and the loop.
    void countLoopTriangle(SourceLoc loc, SourceLoc mesh);
    void checkMemoryAt(SourceLoc loc);
    void finishScene(); // gamma rules, defaults

    Scene scene_;
    bool cameraSeen_ = false;
    std::optional<double> assumedGamma_;
    double version_ = 3.7;
    bool versionSeen_ = false;
    Texture defaultTexture_; // #default { texture / pigment / finish / normal }
    bool defaultSet_ = false; // a #default was given: untextured objects get it when placed
    TextureSharing textureSharing_; // objects placed with equal textures share one (scene/texture_sharing.h)
    std::vector<uint32_t> randomStreams_; // seed(n) returns an index into this
    Diagnostics& diags() { return diags_; }
    const LoadOptions& options() const { return options_; }

    // Counts nesting of a recursive read and stops runaway recursion.
    struct DepthGuard {
        DepthGuard(Evaluator& e, SourceLoc loc);
        ~DepthGuard();
        int& depth;
    };

private:
    friend struct DepthGuard;
    struct Frame {
        std::shared_ptr<TokenStream> tokens;
        size_t pos = 0;
        bool isMacro = false;
        SourceLoc includedFrom; // include frames: the #include directive; macro frames: the call
        std::string macroName;  // macro frames
        size_t condDepth = 0;   // conds_.size() when the frame started
        std::string dir;        // include frames: folder of the file
        std::string canonicalPath; // include frames: for cycle detection
        DialectKind dialect = DialectKind::Drt;
        // Look-ahead read from this frame before a child frame (include, macro
        // call) started; it is read again when the child ends.
        std::vector<Token> savedPushback;
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

    Token rawNext() { return rawNextRef(); }
    // rawNext() without a copy: the token in its file's stream (valid until the
    // stream forgets or frees it: TokenStream::rewind, release).
    const Token& rawNextRef();
    // Frees the tokens no frame, loop or macro can go back to (after each
    // statement; TokenStream::release).
    void releaseReadTokens();
    void endFrame();
    void directive(const Token& t);
    void declareDirective(const Token& t, bool local);
    void includeDirective(const Token& t);
    void ifDirective(const Token& t, int kind); // 0 #if, 1 #ifdef, 2 #ifndef
    void branchSkip(const Token& start);        // skip a false branch: to #else / #elseif / #end
    void whileHead(const Token& t);
    void forDirective(const Token& t);
    void switchDirective(const Token& t);
    void switchScan(const Token& t); // find the matching #case / #range / #else / #end
    void endDirective(const Token& t);
    void breakDirective(const Token& t);
    void macroDefinition(const Token& t);
    void invokeMacro(const Token& t);
    void messageDirective(const Token& t);
    void fileDirective(const Token& t);
    void versionDirective(const Token& t);
    // Counts a pass of the innermost loop against Limits::loopIterations, and
    // against Limits::passesAndCalls with every other pass and macro call of the read.
    void countIteration(const char* directive);
    // The error for passesAndCalls_ over Limits::passesAndCalls, at the pass or call
    // `loc`, with a note at the outermost loop still running. Ends the read.
    [[noreturn]] void failPassesAndCalls(SourceLoc loc);
    // The note under a limit's error that names the outermost loop still running, if any.
    void noteOutermostLoop();
    // Skips raw tokens until a directive in `stops` at nesting depth 0; returns it.
    // `stops`: the directives (without '#') that end the skip, as literals (no set is built per skip).
    Token skipTo(std::initializer_list<std::string_view> stops, const Token& start);
    // The #include directives that opened the first `frameCount` frames, innermost first.
    std::vector<SourceLoc> includeChain(size_t frameCount = SIZE_MAX) const;
    // "'#while' has no matching #end": the directive that opened `c`.
    static const char* condDirective(const Cond& c);
    // Forgets the conditionals opened in the current frame (after their #end was found missing).
    void dropFrameConds();
    // Runs the directive `t` that opens a block (#if, #while, #for, #switch). When
    // its head has an error, its body and #end are skipped too, so that the
    // error is not followed by "#end without a matching #if".
    void openingDirective(const Token& t, const std::function<void()>& run);
    void pushFile(int fileId, SourceLoc includedFrom, const std::string& dir, const std::string& canonicalPath,
                  DialectKind dialect);
    Cell* arrayElementForAssignment(const Token& name, Cell cell);
    void report(Severity severity, SourceLoc loc, const std::string& message);
    void synchronize(); // after an error: to the next statement
    std::string declarationText(SourceLoc start) const;

    Diagnostics& diags_;
    LoadOptions options_;
    DialectKind sceneDialect_;
    std::string mainDir_ = ".";
    std::vector<Frame> frames_;
    std::vector<Cond> conds_;
    std::vector<Token> pushed_;
    Cell deferredWarnings(Cell c); // use()'s reports
    Scopes scopes_; // lang/symbols.h
    NameFilter macroNames_; // every name a macro was ever bound to: isMacro's quick "no"
    std::set<std::string> warned_;
    // Files opened by `#fopen ID "file" read`, by ID (file_input.cpp).
    struct DataFile;
    std::map<std::string, std::shared_ptr<DataFile>> dataFiles_;
    void openDataFile(const Token& handle, const std::string& name, SourceLoc nameLoc);
    void closeDataFile(const std::string& handle); // also undefines ID
    void readDirective();                          // after '#read'
    std::vector<PendingWarning>* pending_ = nullptr; // while evaluating a #declare
    std::map<std::string, std::shared_ptr<TokenStream>> lexedFiles_;
    int expressionDepth_ = 0;
    bool noExpand_ = false;
    Token lastToken_, beforeLastToken_;
    // beforeLastToken_ stands for a copy of lastToken_ (peek() leaves them equal; the copy is not made).
    bool beforeIsLast_ = false;
    int braceDepth_ = 0; // since the statement started, for recovery
    struct OpenBlock {
        std::string keyword;
        SourceLoc loc;
    };
    std::vector<OpenBlock> openBlocks_;
    std::shared_ptr<const Origin> lastOrigin_; // of the last expression read by floatExpr/vectorExpr
    SourceLoc lastExpressionLoc_;
    int errorsSeen_ = 0;
    // Loop passes and macro calls so far (Limits::passesAndCalls): nested loops, a loop
    // that resets its own counter and a macro calling itself twice stay bounded.
    int64_t passesAndCalls_ = 0;
    int64_t built_ = 0;      // Limits::objects: nodes built and copied so far
    bool limitReached_ = false; // a resource limit ended the read (failLimit)
    int abandonedFile_ = -1; // an included file that is no scene, read no further after its first error
};

// The first element given a value in an array (through nested arrays), or
// null: what an indexed element of it is likely to be.
const Value* arrayItemSample(const Value& array);
// Whether every element given a value in an array (through nested arrays) is a
// number, vector or colour, and there is one: an element then reads as a colour.
bool arrayOfNumbers(const Value& array);

// functions.inc's internal function `number` (one drt has: internalArity(number) >= 0) as a function.
std::shared_ptr<const Function> internalFunction(int number);

// The world-space bounding box of an object (POV-Ray's min_extent / max_extent);
// unbounded shapes give +-1e10 as POV-Ray's BOUND_HUGE/2 does.
void objectBounds(const ObjectValue& o, Vec3& lower, Vec3& upper);

// The mean colour of a pigment (patterns averaged over their colour map or sub-pigments).
ColorFT pigmentAverage(const Pigment& p);

} // namespace drt::lang

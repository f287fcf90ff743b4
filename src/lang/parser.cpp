// Token stream, #include, errors and recovery, top-level statements.
#include "lang/parser.h"

#include "lang/load.h"

#include "core/source_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace drt {

namespace fs = std::filesystem;

std::string kindName(const Value& v) {
    switch (v.index()) {
    case 0: return "a number";
    case 1: return std::get<VectorValue>(v).size == 5 ? "a colour" : "a vector";
    case 2: return "a pigment";
    case 3: return "a finish";
    case 4: return "a texture";
    case 5: return "an interior";
    default: return "an object";
    }
}

static const std::vector<std::string>& topLevelWords() {
    static const std::vector<std::string> words{
        "camera", "light_source", "background", "sky_sphere", "fog", "media", "global_settings", "render", "sphere", "plane", "box", "cylinder",
        "cone",   "disc",         "torus",      "triangle",        "smooth_triangle", "mesh", "union", "merge",
        "difference", "intersection", "object"};
    return words;
}

static const std::vector<std::string>& directiveWords() {
    static const std::vector<std::string> words{"declare", "local", "include", "version"};
    return words;
}

static std::string identity(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
    return ec ? fs::path(path).lexically_normal().string() : p.string();
}

Parser::DepthGuard::DepthGuard(Parser& p, const SourceLoc& loc) : parser(p) {
    if (++parser.depth_ > parser.diags_.limits().nestingDepth) {
        --parser.depth_;
        parser.fail(loc, limitExceeded(parser.diags_.limits(), &Limits::nestingDepth, "nesting depth",
                                       double(parser.depth_ + 1)));
    }
}

// ---------------------------------------------------------------- tokens

void Parser::advance() {
    previous_ = current_;
    ++tokensRead_;
    if (previous_.kind == TokenKind::LeftBrace) ++braceDepth_;
    if (previous_.kind == TokenKind::RightBrace) --braceDepth_;
    for (;;) {
        if (sources_.size() > 1 && sources_.back().fileId == abandonedFile_) {
            sources_.pop_back();
            continue;
        }
        Token t = sources_.back().lexer->next();
        if (t.kind == TokenKind::Error) {
            error(t.loc, t.text);
            continue;
        }
        if (t.kind == TokenKind::EndOfFile && sources_.size() > 1) {
            sources_.pop_back(); // back to the including file
            continue;
        }
        if (t.kind == TokenKind::Directive && t.text == "include") {
            include(t);
            continue;
        }
        current_ = std::move(t);
        return;
    }
}

// `#include "file"`: the file's tokens are read in place of the directive.
void Parser::include(const Token& directive) {
    Token name = sources_.back().lexer->next();
    if (name.kind != TokenKind::String) {
        error(name.loc, "expected a file name in quotes after '#include', found " + describe(name));
        return;
    }
    const std::string path = (fs::path(sources_.back().dir) / name.text).lexically_normal().string();
    const std::string id = identity(path);
    for (size_t i = 0; i < sources_.size(); ++i) {
        if (sources_[i].canonicalPath != id) continue;
        std::string chain;
        for (size_t j = i; j < sources_.size(); ++j)
            chain += fs::path(sources_[j].canonicalPath).filename().string() + " -> ";
        error(name.loc, "include cycle: " + chain + fs::path(id).filename().string());
        return;
    }
    // sources_ holds the scene file and the includes open now; this include
    // would make sources_.size() includes open at once.
    if (int64_t(sources_.size()) > diags_.limits().includeDepth) {
        error(name.loc, limitExceeded(diags_.limits(), &Limits::includeDepth, "include depth",
                                      double(sources_.size())));
        return;
    }
    std::string text;
    if (std::string problem = readSourceFile(path, diags_.limits().includeBytes, text); !problem.empty()) {
        error(name.loc, "cannot include '" + name.text + "': " + problem);
        return;
    }
    const int fileId = diags_.files().add(path, text, hasSceneExtension(path));
    std::vector<SourceLoc> chain{directive.loc};
    const std::vector<SourceLoc> outer = includeChain(directive.loc);
    chain.insert(chain.end(), outer.begin(), outer.end());
    includeChains_[fileId] = std::move(chain);
    sources_.push_back(
        {std::make_unique<Lexer>(std::move(text), fileId), id, fs::path(path).parent_path().string(), fileId});
}

bool Parser::match(TokenKind kind) {
    if (!check(kind)) return false;
    advance();
    return true;
}

bool Parser::matchWord(const char* word) {
    if (!checkWord(word)) return false;
    advance();
    return true;
}

const Token& Parser::expect(TokenKind kind, const char* what) {
    if (!check(kind)) failExpected(what);
    advance();
    return previous_;
}

// ---------------------------------------------------------------- errors

std::vector<SourceLoc> Parser::includeChain(const SourceLoc& loc) const {
    auto it = includeChains_.find(loc.file);
    return it == includeChains_.end() ? std::vector<SourceLoc>{} : it->second;
}

void Parser::error(const SourceLoc& loc, const std::string& message) {
    diags_.report(Severity::Error, loc, message, includeChain(loc));
    // An included file that is no scene (an #include of /etc/passwd) is read
    // no further after its first error, so its contents do not leak into the
    // messages token by token.
    if (loc.valid() && !diags_.files().quotable(loc.file)) abandonedFile_ = loc.file;
}

void Parser::warning(const SourceLoc& loc, const std::string& message) {
    diags_.report(Severity::Warning, loc, message, includeChain(loc));
}

void Parser::fail(const SourceLoc& loc, const std::string& message) {
    error(loc, message);
    throw ParseAbort{};
}

void Parser::failExpected(const char* what) {
    fail(current_.loc, std::string("expected ") + what + ", found " + describe(current_));
}

// nearestWord, widened for two common typos it does not count as close:
// swapped neighbours ("widht") and a cut-short keyword ("max_trace").
void Parser::failUnknown(const Token& word, const std::vector<std::string>& known, const char* kind) {
    std::string message = std::string("unknown ") + kind + " '" + word.text + "'";
    const std::string suggestion = nearestWord(word.text, known);
    if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
    fail(word.loc, message);
}

bool Parser::isTopLevelWord(const std::string& word) const {
    const auto& words = topLevelWords();
    return std::find(words.begin(), words.end(), word) != words.end();
}

// After a syntax error: skip to the next statement, i.e. past the '}' that
// closes the broken statement, or to a top-level keyword at brace depth 0, or
// to a directive or scene-level block at any depth (a missing '}').
void Parser::synchronize() {
    depth_ = 0;
    for (;;) {
        if (check(TokenKind::EndOfFile)) return;
        if (check(TokenKind::Directive)) break;
        if (check(TokenKind::Identifier)) {
            const std::string& w = current_.text;
            if (w == "camera" || w == "light_source" || w == "global_settings" || w == "background" ||
                w == "render" || w == "sky_sphere" || w == "fog" || w == "media")
                break;
            if (braceDepth_ <= 0 && isTopLevelWord(w)) break;
        }
        advance();
        if (previous_.kind == TokenKind::RightBrace && braceDepth_ <= 0) break;
        if (previous_.kind == TokenKind::Semicolon && braceDepth_ <= 0) break;
    }
    braceDepth_ = 0;
}

// ---------------------------------------------------------------- statements

void Parser::parseFile(int fileId, const std::string& path, const std::string& dir) {
    sources_.push_back({std::make_unique<Lexer>(diags_.files().text(fileId), fileId), identity(path), dir, fileId});
    advance();
    while (!check(TokenKind::EndOfFile)) {
        const long start = tokensRead_;
        try {
            braceDepth_ = 0;
            statement();
        } catch (const ParseAbort&) {
            if (tokensRead_ == start) advance(); // always make progress
            synchronize();
        }
    }
}

void Parser::statement() {
    if (check(TokenKind::Directive)) {
        const std::string& d = current_.text;
        if (d == "declare" || d == "local") return declare();
        if (d == "version") { // accepted for POV-Ray habits; drt has one version
            advance();
            floatExpr();
            match(TokenKind::Semicolon);
            return;
        }
        Token shown = current_;
        shown.text = "#" + shown.text;
        std::vector<std::string> known;
        for (const auto& w : directiveWords()) known.push_back("#" + w);
        failUnknown(shown, known, "directive");
    }
    if (match(TokenKind::Semicolon)) return; // stray ';' as after an object declaration
    if (!check(TokenKind::Identifier)) failExpected("a statement (an object, camera, light_source, ...)");
    const std::string word = current_.text;
    if (word == "camera") return camera();
    if (word == "light_source") return lightSource();
    if (word == "background") return background();
    if (word == "sky_sphere") return skySphere();
    if (word == "fog") return fog();
    if (word == "media") return scene_.media.push_back(media());
    if (word == "global_settings") return globalSettings();
    if (word == "render") return renderBlock();
    if (atObjectWord()) return addObjectToScene(object());
    if (const Value* v = lookup(word))
        fail(current_.loc, "'" + word + "' is " + kindName(*v) + ", not a statement" +
                               (std::holds_alternative<ParsedObject>(*v) ? "; write object { " + word + " }" : ""));
    failUnknown(current_, topLevelWords());
}

// `#declare Name = value [;]`: the `;` is required after numbers, vectors and
// colours (as in POV-Ray 3.7) and optional after blocks.
void Parser::declare() {
    advance(); // #declare / #local
    const Token& name = expect(TokenKind::Identifier, "a name after '#declare'");
    const Token nameToken = name;
    if (isTopLevelWord(nameToken.text) || nameToken.text == "x" || nameToken.text == "y" ||
        nameToken.text == "z" || nameToken.text == "pi")
        fail(nameToken.loc, "cannot declare '" + nameToken.text + "': it is a keyword");
    expect(TokenKind::Equals, "'=' after the declared name");
    Value value;
    bool block = true;
    if (checkWord("texture")) { // `texture {A} texture {B}`: B layered on top of A
        Texture layered = texture();
        while (checkWord("texture")) layerTexture(layered, current_.loc);
        value = std::move(layered);
    }
    else if (checkWord("pigment")) value = pigment();
    else if (checkWord("finish")) value = finish();
    else if (checkWord("interior")) value = interior();
    else if (atObjectWord()) value = object();
    else {
        value = expression();
        block = std::holds_alternative<double>(value) || std::holds_alternative<VectorValue>(value) ? false : true;
    }
    if (block) {
        match(TokenKind::Semicolon);
    } else if (!match(TokenKind::Semicolon)) {
        fail(previous_.loc, "expected ';' after the value of '" + nameToken.text + "'");
    }
    // What a use of the name will copy: counted against Limits::objects there,
    // and a large value is a moment to look at the memory the scene takes.
    const int64_t weight = valueWeight(value, diags_.limits().objects);
    if (weight > kMemoryCheckWeight)
        if (std::string problem = checkMemory(diags_.limits()); !problem.empty()) fail(nameToken.loc, problem);
    symbolWeights_[nameToken.text] = weight;
    symbols_[nameToken.text] = std::move(value);
}

// An object's nodes: its own (weight.h) and its union children's, which stay
// ParsedObjects until the union reaches the scene.
static int64_t objectWeight(const ParsedObject& po, int64_t cap) {
    int64_t total = weightOf(po.object, cap).total();
    for (const ParsedObject& child : po.children)
        if (total <= cap) total += objectWeight(child, cap - total);
    return total;
}

int64_t Parser::valueWeight(const Value& value, int64_t cap) {
    if (const ParsedObject* po = std::get_if<ParsedObject>(&value)) return objectWeight(*po, cap);
    if (const Pigment* pigment = std::get_if<Pigment>(&value)) return weightOf(*pigment, cap).total();
    if (const Texture* texture = std::get_if<Texture>(&value)) return weightOf(*texture, cap).total();
    if (const Interior* interior = std::get_if<Interior>(&value)) return weightOf(*interior, cap).total();
    return 1;
}

void Parser::countBuilt(const SourceLoc& loc, int64_t weight) {
    const int64_t before = built_;
    built_ += weight;
    if (built_ > diags_.limits().objects)
        fail(loc, limitExceeded(diags_.limits(), &Limits::objects, "the scene's objects and patterns number",
                                double(built_)));
    if (built_ / kMemoryCheckWeight != before / kMemoryCheckWeight)
        if (std::string problem = checkMemory(diags_.limits()); !problem.empty()) fail(loc, problem);
}

const Value* Parser::lookup(const std::string& name) const {
    auto it = symbols_.find(name);
    return it == symbols_.end() ? nullptr : &it->second;
}

// ---------------------------------------------------------------- entry points

std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const std::string& baseDir, const FrameClock& frame) {
    const int errorsBefore = diags.errorCount();
    std::string withoutMark = text;
    stripByteOrderMark(withoutMark);
    const int fileId = diags.files().add(name, std::move(withoutMark));
    Scene scene;
    Parser parser(diags, scene, frame);
    parser.parseFile(fileId, (fs::path(baseDir) / fs::path(name).filename()).string(), baseDir);
    if (diags.errorCount() > errorsBefore) return std::nullopt;
    return scene;
}

std::optional<Scene> loadSceneFile(const std::string& path, Diagnostics& diags, const FrameClock& frame) {
    std::string text;
    if (std::string problem = readSourceFile(path, -1, text); !problem.empty()) {
        diags.error({}, "cannot read scene file: " + problem);
        return std::nullopt;
    }
    std::string dir = fs::path(path).parent_path().string();
    if (dir.empty()) dir = ".";
    const int errorsBefore = diags.errorCount();
    const int fileId = diags.files().add(path, std::move(text));
    Scene scene;
    Parser parser(diags, scene, frame);
    parser.parseFile(fileId, path, dir);
    if (diags.errorCount() > errorsBefore) return std::nullopt;
    return scene;
}

} // namespace drt

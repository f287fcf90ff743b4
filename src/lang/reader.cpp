// The token stream: files, includes, conditionals, loops and macro calls.
// As in POV-Ray, directives run as the item readers pull tokens, loops and
// macros replay an already-lexed token vector by index, and every #include
// and macro call opens a new scope for #local.
#include "lang/evaluator.h"

#include "core/source_file.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt::lang {

Evaluator::DepthGuard::DepthGuard(Evaluator& e, SourceLoc loc) : depth(e.expressionDepth_) {
    if (++depth > e.diags_.limits().nestingDepth) {
        --depth;
        e.failLimit(loc, limitExceeded(e.diags_.limits(), &Limits::nestingDepth, "nesting depth", double(depth + 1)));
    }
}
Evaluator::DepthGuard::~DepthGuard() { --depth; }

Evaluator::Evaluator(Diagnostics& diags, const LoadOptions& options, DialectKind dialect)
    : diags_(diags), options_(options), sceneDialect_(dialect) {
    scopes_.push();
}

const Dialect& Evaluator::syntax() const {
    return frames_.empty() ? scene() : dialectOf(frames_.back().dialect);
}

// ------------------------------------------------------------ symbols

Cell Evaluator::lookup(const std::string& name) const { return scopes_.find(name); }

Cell Evaluator::use(const std::string& name) { return deferredWarnings(lookup(name)); }
Cell Evaluator::use(const Token& word) { return deferredWarnings(lookup(word)); }

Cell Evaluator::deferredWarnings(Cell c) {
    if (c && c->warnings) {
        for (const PendingWarning& p : *c->warnings) {
            if (pending_) {
                bool seen = false;
                for (const PendingWarning& q : *pending_) seen = seen || q.kind == p.kind;
                if (!seen) pending_->push_back(p);
            } else if (warned_.insert(p.kind).second) {
                Severity s = p.severity;
                if (s == Severity::Warning && options_.strict) s = Severity::Error;
                diags_.report(s, p.loc, p.message, p.includedFrom);
            }
        }
    }
    return c;
}

bool Evaluator::isMacro(const std::string& name) const {
    if (!macroNames_.mayHold(name)) return false;
    const Value* v = scopes_.get(name);
    return v && v->kind == Value::Kind::Macro;
}

bool Evaluator::isMacro(const Token& word) const {
    if (!macroNames_.mayHold(word.text)) return false;
    const Value* v = scopes_.get(word);
    return v && v->kind == Value::Kind::Macro;
}

std::vector<std::string> Evaluator::declaredNames(std::initializer_list<Value::Kind> kinds) const {
    std::vector<std::string> names;
    scopes_.forEach([&](const std::string& name, const Cell& cell) {
        if (kinds.size() > 0 && std::find(kinds.begin(), kinds.end(), cell->kind) == kinds.end()) return;
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    });
    return names;
}

// #local writes the innermost scope; #declare updates the nearest existing
// identifier (so a macro parameter bound to the caller's identifier writes
// through) or creates a global one.
void Evaluator::declare(const std::string& name, Value value, bool local, size_t scopeCount) {
    const size_t open = std::min(scopeCount, scopes_.size());
    if (value.kind == Value::Kind::Macro) macroNames_.add(name);
    if (local) {
        if (Cell* c = scopes_.findIn(open - 1, name)) **c = std::move(value);
        else scopes_.set(open - 1, name, std::make_shared<Value>(std::move(value)));
        return;
    }
    if (Cell* c = scopes_.findBelow(open, name)) **c = std::move(value);
    else scopes_.set(0, name, std::make_shared<Value>(std::move(value)));
}

// ------------------------------------------------------------ files

void Evaluator::pushFile(int fileId, SourceLoc includedFrom, const std::string& dir,
                         const std::string& canonicalPath, DialectKind dialect) {
    if (int64_t(frames_.size()) >= diags_.limits().callDepth)
        failLimit(includedFrom, limitExceeded(diags_.limits(), &Limits::callDepth, "macro calls and includes nested",
                                         double(frames_.size() + 1)));
    const std::string& path = diags_.files().path(fileId);
    auto& tokens = lexedFiles_[path + "#" + std::to_string(fileId)];
    tokens = std::make_shared<TokenStream>(diags_.files(), fileId, dialectOf(dialect).strictLexing);
    Frame f;
    f.tokens = tokens;
    f.includedFrom = includedFrom;
    f.condDepth = conds_.size();
    f.dir = dir;
    f.canonicalPath = canonicalPath;
    f.dialect = dialect;
    pushFrame(std::move(f));
    scopes_.push();
}

void Evaluator::pushFrame(Frame f) {
    if (!frames_.empty()) frames_.back().savedPushback = std::move(pushed_);
    pushed_.clear();
    frames_.push_back(std::move(f));
}

void Evaluator::popFrame() {
    frames_.pop_back();
    scopes_.pop();
    if (!frames_.empty()) {
        // pushed_ is a stack: the saved look-ahead was read first, so it goes on top.
        std::vector<Token>& saved = frames_.back().savedPushback;
        saved.insert(saved.begin(), pushed_.begin(), pushed_.end());
        pushed_ = std::move(saved);
        frames_.back().savedPushback.clear();
    }
}

std::string Evaluator::currentDir() const {
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
        if (!it->isMacro) return it->dir;
    return mainDir_;
}

std::string Evaluator::findInclude(const std::string& name, const std::string& fromDir) const {
    // POV-Ray's library-path search looks for a regular file; a .drt scene
    // names the file it means, so whatever is there is read (and a device or
    // a folder is refused with the reason).
    const bool anyFile = syntax().kind == DialectKind::Drt;
    const auto usable = [&](const fs::path& p) {
        std::error_code ec;
        return anyFile ? fs::exists(p, ec) : fs::is_regular_file(p, ec);
    };
    if (fs::path(name).is_absolute()) return usable(name) ? name : "";
    std::vector<std::string> dirs{fromDir};
    dirs.insert(dirs.end(), options_.includePaths.begin(), options_.includePaths.end());
    for (const std::string& dir : dirs) {
        const fs::path candidate = (fs::path(dir) / name).lexically_normal();
        if (usable(candidate)) return candidate.string();
    }
    return "";
}

namespace {

std::string canonical(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
    return ec ? fs::path(path).lexically_normal().string() : p.string();
}

} // namespace

void Evaluator::includeDirective(const Token& t) {
    const Token at = peek();
    if (syntax().kind == DialectKind::Drt && at.kind != TokenKind::String) {
        next();
        failExpected(at, "a file name in quotes after '#include'");
    }
    // A plain string is taken as is: looking past it could end the current file
    // before the include starts, losing it from the include chain.
    const std::string name = at.kind == TokenKind::String ? next().text : stringExpr();
    const std::string fromDir = currentDir();
    const std::string path = findInclude(name, fromDir);
    if (path.empty()) {
        std::string looked;
        std::vector<std::string> dirs{fromDir};
        dirs.insert(dirs.end(), options_.includePaths.begin(), options_.includePaths.end());
        for (const std::string& dir : dirs) {
            const std::string candidate = (fs::path(dir) / name).lexically_normal().string();
            if (looked.find(candidate) == std::string::npos) looked += (looked.empty() ? "" : ", ") + candidate;
        }
        const char quote = syntax().kind == DialectKind::Drt ? '\'' : '"';
        fail(at.loc, "cannot find include file " + (quote + name + quote) + " (looked for " + looked + ")");
    }
    const std::string id = canonical(path);
    // A file including itself is a cycle in .drt files; POV-Ray's include
    // files guard such recursion with #ifndef, so there only the depth stops it.
    if (syntax().kind == DialectKind::Drt) {
        for (size_t i = 0; i < frames_.size(); ++i) {
            if (frames_[i].isMacro || frames_[i].canonicalPath != id) continue;
            std::string chain;
            for (size_t j = i; j < frames_.size(); ++j)
                if (!frames_[j].isMacro) chain += fs::path(frames_[j].canonicalPath).filename().string() + " -> ";
            fail(at.loc, "include cycle: " + chain + fs::path(id).filename().string());
        }
    }
    // The files open now (the scene's and its includes'); with this one,
    // `depth` includes are open at once.
    int64_t depth = 0;
    for (const Frame& f : frames_) depth += f.isMacro ? 0 : 1;
    if (depth > diags_.limits().includeDepth)
        failLimit(at.loc, limitExceeded(diags_.limits(), &Limits::includeDepth, "include depth", double(depth)));
    std::string text;
    if (std::string problem = readSourceFile(path, diags_.limits().includeBytes, text); !problem.empty())
        fail(at.loc, "cannot include '" + name + "': " + problem);
    const int fileId = diags_.files().add(path, std::move(text), hasSceneExtension(path));
    std::string dir = fs::path(path).parent_path().string();
    // An include file's syntax follows its extension; a .drt file's own includes
    // without a POV-Ray extension are .drt.
    pushFile(fileId, t.loc, dir.empty() ? "." : dir, id, dialectForPath(path));
}

void Evaluator::releaseReadTokens() {
    // Tokens a little before the earliest place still needed stay: the reader
    // looks back at its last few (rawStream, TokenStream::rewind).
    constexpr size_t kMargin = 256;
    for (size_t i = 0; i < frames_.size(); ++i) {
        TokenStream* stream = frames_[i].tokens.get();
        bool first = true; // each stream once, at its first frame
        for (size_t j = 0; j < i && first; ++j) first = frames_[j].tokens.get() != stream;
        if (!first) continue;
        size_t low = frames_[i].pos;
        for (size_t j = i + 1; j < frames_.size(); ++j)
            if (frames_[j].tokens.get() == stream) low = std::min(low, frames_[j].pos);
        // A loop goes back to its condition (#while) or first body token (#for).
        for (const Cond& c : conds_)
            if ((c.type == Cond::Type::While || c.type == Cond::Type::For) && frames_[c.frame].tokens.get() == stream)
                low = std::min(low, c.pos);
        if (low > kMargin) stream->release(low - kMargin);
    }
}

void Evaluator::endFrame() {
    Frame& f = frames_.back();
    if (conds_.size() > f.condDepth) {
        const Cond c = conds_.back();
        dropFrameConds();
        fail(c.loc, fmt::format("'{}' has no matching #end before the end of the file", condDirective(c)));
    }
    // A file read to its end is not read again: only its macros' bodies stay.
    if (!f.isMacro) f.tokens->release(f.tokens->lexed());
    popFrame();
}

// ------------------------------------------------------------ raw tokens

// The next token of the innermost frame; ends included files on the way.
const Token& Evaluator::rawNextRef() {
    for (;;) {
        Frame& f = frames_.back();
        const Token& t = (*f.tokens)[f.pos];
        if (frames_.size() > 1 && !f.isMacro && t.loc.file == abandonedFile_ && abandonedFile_ >= 0) {
            dropFrameConds();
            popFrame();
            continue;
        }
        if (t.kind == TokenKind::EndOfFile) {
            if (f.isMacro) fail(t.loc, "macro body has no #end");
            if (frames_.size() == 1) {
                if (conds_.size() > f.condDepth) {
                    const Cond c = conds_.back();
                    conds_.clear();
                    fail(c.loc, fmt::format("'{}' has no matching #end", condDirective(c)));
                }
                return t;
            }
            endFrame();
            continue;
        }
        ++f.pos;
        if (t.kind == TokenKind::Error) {
            error(t.loc, t.text);
            continue;
        }
        return t;
    }
}

// A token becomes the last one read with a move from the look-ahead or a
// copy from its stream, not through a temporary: a token's text is a string,
// and reading a token used to cost ten string copies and moves.
const Token& Evaluator::next() {
    for (;;) {
        const bool pushed = !pushed_.empty();
        const Token& t = pushed ? pushed_.back() : rawNextRef();
        if (t.kind == TokenKind::Directive || (t.kind == TokenKind::Word && !noExpand_ && isMacro(t))) {
            const Token taken = t;
            if (pushed) pushed_.pop_back();
            if (taken.kind == TokenKind::Directive) directive(taken);
            else invokeMacro(taken);
            continue;
        }
        if (t.is("{")) ++braceDepth_;
        else if (t.is("}")) --braceDepth_;
        beforeLastToken_ = std::move(lastToken_);
        beforeIsLast_ = false;
        if (pushed) {
            lastToken_ = std::move(pushed_.back());
            pushed_.pop_back();
        } else {
            if (t.kind == TokenKind::Word) scopes_.remember(t); // for its copies' lookups, in every pass
            lastToken_ = t;
        }
        return lastToken_;
    }
}

void Evaluator::pushBack(Token t) {
    if (t.is("{")) --braceDepth_;
    else if (t.is("}")) ++braceDepth_;
    if (!beforeIsLast_) lastToken_ = beforeLastToken_;
    pushed_.push_back(std::move(t));
}

const Token& Evaluator::peek() {
    // When the token next() would return is already pushed back and next()
    // would return it as it is (no directive to run, no macro to expand),
    // return it: taking it and pushing it back costs three token copies. The
    // state left is next() then pushBack()'s.
    if (!pushed_.empty()) {
        const Token& t = pushed_.back();
        if (t.kind != TokenKind::Directive && !(t.kind == TokenKind::Word && !noExpand_ && isMacro(t))) {
            beforeIsLast_ = true; // beforeLastToken_ = lastToken_, without the copy
            return t;
        }
    }
    // next() then pushBack(), without their copies: with nothing pushed back,
    // the token goes from its stream to the look-ahead.
    if (pushed_.empty()) {
        for (;;) {
            const Token& t = rawNextRef();
            if (t.kind == TokenKind::Directive || (t.kind == TokenKind::Word && !noExpand_ && isMacro(t))) {
                const Token taken = t;
                if (taken.kind == TokenKind::Directive) directive(taken);
                else invokeMacro(taken);
                if (!pushed_.empty()) break; // the directive or the call left a look-ahead: next()'s way
                continue;
            }
            if (t.kind == TokenKind::Word) scopes_.remember(t); // for its copies' lookups, in every pass
            pushed_.push_back(t);
            beforeIsLast_ = true; // beforeLastToken_ = lastToken_, without the copy
            return pushed_.back();
        }
    }
    pushBack(next());
    return pushed_.back();
}

const Token& Evaluator::peekOperator() {
    if (!pushed_.empty()) return pushed_.back();
    for (;;) {
        Frame& f = frames_.back();
        const Token& t = (*f.tokens)[f.pos];
        if (t.kind == TokenKind::EndOfFile && frames_.size() > 1 && !f.isMacro) {
            endFrame();
            continue;
        }
        // A macro's #end returns to the caller: the expression may go on there.
        if (t.kind == TokenKind::Directive && t.text == "end" && f.isMacro && conds_.size() == f.condDepth) {
            ++f.pos;
            popFrame();
            continue;
        }
        // The end of an #if branch (#else, #elseif, #end) does not end the
        // expression: `#if (C) A #else B #end * 2` (a macro returning A or B
        // then `* 2`, as POV-Ray's advanced/isocacti.pov does) goes on after it.
        if (t.kind == TokenKind::Directive && (t.text == "else" || t.text == "elseif" || t.text == "end") &&
            conds_.size() > f.condDepth && conds_.back().type == Cond::Type::If &&
            conds_.back().frame == frames_.size() - 1) {
            const Token branchEnd = t;
            ++f.pos;
            directive(branchEnd);
            continue;
        }
        if (t.kind == TokenKind::Directive) return t;
        // A macro name cannot continue an expression: return it unexpanded, or
        // `#declare S = "" M(S)` would run M before S is declared.
        if (t.kind == TokenKind::Word && isMacro(t)) return t;
        return peek();
    }
}

TokenStream* Evaluator::rawStream() {
    if (frames_.empty() || noExpand_) return nullptr;
    Frame& f = frames_.back();
    if (f.isMacro || f.tokens->fileId() == abandonedFile_) return nullptr;
    // A loop in this file jumps back to token indices: its tokens must all be made.
    const size_t current = frames_.size() - 1;
    for (const Cond& c : conds_)
        if (c.frame == current && (c.type == Cond::Type::While || c.type == Cond::Type::For)) return nullptr;
    // The look-ahead goes back to the stream when it is exactly this file's last tokens.
    const size_t k = pushed_.size();
    if (k > f.pos || !f.tokens->available(f.pos - k)) return nullptr;
    for (size_t i = 0; i < k; ++i) {
        const Token& made = (*f.tokens)[f.pos - 1 - i];
        const Token& held = pushed_[i];
        if (made.kind != held.kind || made.loc.file != held.loc.file || made.loc.line != held.loc.line ||
            made.loc.column != held.loc.column || made.text != held.text)
            return nullptr;
    }
    if (!f.tokens->rewind(f.pos - k)) return nullptr;
    f.pos -= k;
    pushed_.clear();
    return f.tokens.get();
}

void Evaluator::rawRead(SourceLoc last, const char* lastSymbol) {
    beforeLastToken_ = std::move(lastToken_);
    beforeIsLast_ = false;
    lastToken_ = Token{TokenKind::Symbol, lastSymbol, 0, last};
    lastOrigin_ = nullptr;
}

bool Evaluator::acceptSymbol(std::string_view s) {
    if (peek().is(s)) {
        next();
        return true;
    }
    return false;
}

namespace {

std::string expectedSymbol(const char* s, std::string_view context) {
    return context.empty() ? fmt::format("'{}'", s) : fmt::format("'{}' {}", s, context);
}

} // namespace

const Token& Evaluator::expectSymbol(const char* s, const std::string& context) {
    const Token& t = next();
    if (!t.is(s)) failExpected(t, expectedSymbol(s, context));
    return t;
}

const Token& Evaluator::expectSymbol(const char* s, const char* context) {
    const Token& t = next();
    if (!t.is(s)) failExpected(t, expectedSymbol(s, context)); // the message is made only when it fails
    return t;
}

const Token& Evaluator::expectSymbol(const char* s, const char* before, const std::string& name, const char* after) {
    const Token& t = next();
    if (!t.is(s)) failExpected(t, expectedSymbol(s, before + name + after));
    return t;
}

bool Evaluator::acceptWord(std::string_view w) {
    if (peek().isWord(w)) {
        next();
        return true;
    }
    return false;
}

Token Evaluator::expectWord(const std::string& context) {
    Token t = next();
    if (t.kind != TokenKind::Word) failExpected(t, context);
    return t;
}

void Evaluator::comma(const std::string& after) {
    if (syntax().requireCommas) expectSymbol(",", "after the " + after);
    else acceptSymbol(",");
}

void Evaluator::skipBlock() {
    int depth = 1;
    while (depth > 0) {
        const Token t = next();
        if (t.kind == TokenKind::EndOfFile) fail(t.loc, "unbalanced '{': end of file inside a block");
        if (t.is("{")) ++depth;
        else if (t.is("}")) --depth;
    }
}

// ------------------------------------------------------------ recovery

// After an error in the .drt dialect: skip to the next statement, i.e. past
// the '}' that closes the broken statement, or to a top-level keyword outside
// any block, or to a directive or scene-level block at any depth (a missing '}').
void Evaluator::synchronize() {
    expressionDepth_ = 0;
    openBlocks_.clear();
    inVector_ = countBeforeVector_ = false;
    noExpand_ = false;
    pending_ = nullptr;
    for (;;) {
        const Token t = peekOperator();
        if (t.kind == TokenKind::EndOfFile || t.kind == TokenKind::Directive) break;
        if (t.kind == TokenKind::Word) {
            const std::string& w = t.text;
            if (w == "camera" || w == "light_source" || w == "global_settings" || w == "background" ||
                w == "render" || w == "sky_sphere" || w == "fog" || w == "media")
                break;
            if (braceDepth_ <= 0 && (isObjectWord(t) || lookup(w) == nullptr)) {
                const auto& top = blockKeywords(Block::Statement);
                if (isObjectWord(t) || std::find(top.begin(), top.end(), w) != top.end()) break;
            }
        }
        const Token consumed = next();
        if (consumed.kind == TokenKind::EndOfFile) break;
        if ((consumed.is("}") || consumed.is(";")) && braceDepth_ <= 0) break;
    }
    braceDepth_ = 0;
}

// ------------------------------------------------------------ entry

std::optional<Scene> Evaluator::run(int fileId, const std::string& baseDir) {
    mainDir_ = baseDir;
    const std::string& path = diags_.files().path(fileId);
    const std::string id = canonical((fs::path(baseDir) / fs::path(path).filename()).string());
    if (scene().kind == DialectKind::Pov) scene_.camera.right = Vec3(1.33, 0, 0);
    try {
        pushFile(fileId, SourceLoc{}, baseDir, id, sceneDialect_);
        scopes_.pop(); // the main file shares the global scope
    } catch (const Abort&) {
        return std::nullopt;
    }
    for (;;) {
        try {
            braceDepth_ = 0;
            const Token t = next();
            if (t.kind == TokenKind::EndOfFile) break;
            statement(t);
            releaseReadTokens();
        } catch (const Abort&) {
            if (!scene().recoverAfterErrors || limitReached_ || frames_.empty()) return std::nullopt;
            try {
                synchronize();
            } catch (const Abort&) {
                return std::nullopt;
            }
        }
    }
    if (diags_.hasErrors()) return std::nullopt;
    try {
        finishScene();
    } catch (const Abort&) {
        return std::nullopt;
    }
    if (diags_.hasErrors()) return std::nullopt;
    return std::move(scene_);
}

} // namespace drt::lang

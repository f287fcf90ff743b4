// The token stream: files, includes, conditionals, loops and macro calls.
// As in POV-Ray, directives run as the parser pulls tokens, loops and macros
// replay an already-lexed token vector by index, and every #include and macro
// call opens a new scope for #local.
#include "pov/parser.h"

#include "core/source_file.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt::pov {

DepthGuard::DepthGuard(PovParser& p, SourceLoc loc) : depth(p.expressionDepth_) {
    if (++depth > p.diags_.limits().nestingDepth) {
        --depth;
        p.fail(loc, limitExceeded(p.diags_.limits(), &Limits::nestingDepth, "nesting depth", double(depth + 1)));
    }
}
DepthGuard::~DepthGuard() { --depth; }

PovParser::PovParser(Diagnostics& diags, const PovOptions& options) : diags_(diags), options_(options) {
    scopes_.emplace_back();
}

// ------------------------------------------------------------ diagnostics

std::vector<SourceLoc> PovParser::includeChain() const {
    std::vector<SourceLoc> chain;
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
        if (!it->isMacro && it->includedFrom.valid()) chain.push_back(it->includedFrom);
    return chain;
}

void PovParser::fail(SourceLoc loc, const std::string& message) {
    diags_.report(Severity::Error, loc, message, includeChain());
    throw PovAbort{};
}

void PovParser::failExpected(const Tok& got, const std::string& what) {
    fail(got.loc, "expected " + what + ", found " + describe(got));
}

void PovParser::warn(SourceLoc loc, const std::string& message) {
    diags_.report(options_.strict ? Severity::Error : Severity::Warning, loc, message, includeChain());
}

void PovParser::warnOnce(const std::string& kind, SourceLoc loc, const std::string& message) {
    if (pending_) {
        for (const PendingWarning& p : *pending_)
            if (p.kind == kind) return;
        pending_->push_back({kind, loc, message, includeChain()});
        return;
    }
    if (!warned_.insert(kind).second) return;
    diags_.report(options_.strict ? Severity::Error : Severity::Warning, loc, message, includeChain());
}

void PovParser::note(SourceLoc loc, const std::string& message) {
    diags_.report(Severity::Note, loc, message, includeChain());
}

// ------------------------------------------------------------ symbols

Cell PovParser::lookup(const std::string& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
        if (auto found = it->find(name); found != it->end()) return found->second;
    return nullptr;
}

Cell PovParser::use(const std::string& name) {
    Cell c = lookup(name);
    if (c && c->warnings) {
        for (const PendingWarning& p : *c->warnings) {
            if (pending_) {
                bool seen = false;
                for (const PendingWarning& q : *pending_) seen = seen || q.kind == p.kind;
                if (!seen) pending_->push_back(p);
            } else if (warned_.insert(p.kind).second) {
                diags_.report(options_.strict ? Severity::Error : Severity::Warning, p.loc, p.message, p.includedFrom);
            }
        }
    }
    return c;
}

bool PovParser::isMacro(const std::string& name) const {
    const Cell c = lookup(name);
    return c && c->kind == PovValue::Kind::Macro;
}

// #local writes the innermost scope; #declare updates the nearest existing
// identifier (so a macro parameter bound to the caller's identifier writes
// through) or creates a global one.
void PovParser::declare(const std::string& name, const PovValue& value, bool local) {
    if (local) {
        auto& scope = scopes_.back();
        if (auto it = scope.find(name); it != scope.end()) *it->second = value;
        else scope[name] = std::make_shared<PovValue>(value);
        return;
    }
    if (Cell c = lookup(name)) {
        *c = value;
        return;
    }
    scopes_.front()[name] = std::make_shared<PovValue>(value);
}

// ------------------------------------------------------------ files

void PovParser::pushFile(int fileId, SourceLoc includedFrom, const std::string& dir) {
    if (int64_t(frames_.size()) >= diags_.limits().callDepth)
        fail(includedFrom, limitExceeded(diags_.limits(), &Limits::callDepth, "macro calls and includes nested",
                                         double(frames_.size() + 1)));
    const std::string& path = diags_.files().path(fileId);
    auto& tokens = lexedFiles_[path + "#" + std::to_string(fileId)];
    tokens = std::make_shared<const std::vector<Tok>>(lexPov(diags_.files().text(fileId), fileId));
    Frame f;
    f.tokens = tokens;
    f.includedFrom = includedFrom;
    f.condDepth = conds_.size();
    f.dir = dir;
    pushFrame(std::move(f));
    scopes_.emplace_back();
}

void PovParser::pushFrame(Frame f) {
    if (!frames_.empty()) frames_.back().savedPushback = std::move(pushed_);
    pushed_.clear();
    frames_.push_back(std::move(f));
}

void PovParser::popFrame() {
    frames_.pop_back();
    scopes_.pop_back();
    if (!frames_.empty()) {
        // pushed_ is a stack: the saved look-ahead was read first, so it goes on top.
        std::vector<Tok>& saved = frames_.back().savedPushback;
        saved.insert(saved.begin(), pushed_.begin(), pushed_.end());
        pushed_ = std::move(saved);
        frames_.back().savedPushback.clear();
    }
}

std::string PovParser::findInclude(const std::string& name, const std::string& fromDir) const {
    std::error_code ec;
    if (fs::path(name).is_absolute()) return fs::is_regular_file(name, ec) ? name : "";
    std::vector<std::string> dirs{fromDir};
    dirs.insert(dirs.end(), options_.includePaths.begin(), options_.includePaths.end());
    for (const std::string& dir : dirs) {
        const fs::path candidate = fs::path(dir) / name;
        if (fs::is_regular_file(candidate, ec)) return candidate.string();
    }
    return "";
}

void PovParser::includeDirective(const Tok& t) {
    const Tok at = peek();
    // A plain string is taken as is: looking past it could end the current file
    // before the include starts, losing it from the include chain.
    const std::string name = at.kind == TokKind::String ? next().text : stringExpr();
    std::string fromDir = ".";
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
        if (!it->isMacro) {
            fromDir = it->dir;
            break;
        }
    const std::string path = findInclude(name, fromDir);
    if (path.empty()) fail(at.loc, "cannot find include file \"" + name + "\" (searched the scene's folder and the -L paths)");
    std::string text;
    if (std::string problem = readSourceFile(path, diags_.limits().includeBytes, text); !problem.empty())
        fail(at.loc, "cannot include \"" + name + "\": " + problem);
    const int id = diags_.files().add(path, std::move(text), hasSceneExtension(path));
    std::string dir = fs::path(path).parent_path().string();
    pushFile(id, t.loc, dir.empty() ? "." : dir);
}

void PovParser::endFrame() {
    Frame& f = frames_.back();
    if (conds_.size() > f.condDepth) {
        const Cond& c = conds_.back();
        fail(c.loc, "this directive has no matching #end before the end of the file");
    }
    popFrame();
}

// ------------------------------------------------------------ raw tokens

const Tok& PovParser::rawPeek() const { return (*frames_.back().tokens)[frames_.back().pos]; }

// The next token of the innermost frame; ends included files on the way.
Tok PovParser::rawNext() {
    for (;;) {
        Frame& f = frames_.back();
        const Tok& t = (*f.tokens)[f.pos];
        if (t.kind == TokKind::EndOfFile) {
            if (f.isMacro) fail(t.loc, "macro body has no #end");
            if (frames_.size() == 1) {
                if (conds_.size() > f.condDepth) fail(conds_.back().loc, "this directive has no matching #end");
                return t;
            }
            endFrame();
            continue;
        }
        ++f.pos;
        if (t.kind == TokKind::Error) fail(t.loc, t.text);
        return t;
    }
}

Tok PovParser::next() {
    for (;;) {
        Tok t;
        if (!pushed_.empty()) {
            t = std::move(pushed_.back());
            pushed_.pop_back();
        } else {
            t = rawNext();
        }
        if (t.kind == TokKind::Directive) {
            directive(t);
            continue;
        }
        if (t.kind == TokKind::Word && !noExpand_ && isMacro(t.text)) {
            invokeMacro(t);
            continue;
        }
        return t;
    }
}

Tok PovParser::peek() {
    Tok t = next();
    pushBack(t);
    return t;
}

Tok PovParser::peekOperator() {
    if (!pushed_.empty()) return pushed_.back();
    for (;;) {
        Frame& f = frames_.back();
        const Tok& t = (*f.tokens)[f.pos];
        if (t.kind == TokKind::EndOfFile && frames_.size() > 1 && !f.isMacro) {
            endFrame();
            continue;
        }
        // A macro's #end returns to the caller: the expression may go on there.
        if (t.kind == TokKind::Directive && t.text == "end" && f.isMacro && conds_.size() == f.condDepth) {
            ++f.pos;
            popFrame();
            continue;
        }
        if (t.kind == TokKind::Directive) return t;
        // A macro name cannot continue an expression: return it unexpanded, or
        // `#declare S = "" M(S)` would run M before S is declared.
        if (t.kind == TokKind::Word && isMacro(t.text)) return t;
        return peek();
    }
}

bool PovParser::acceptSymbol(const char* s) {
    if (peek().is(s)) {
        next();
        return true;
    }
    return false;
}

Tok PovParser::expectSymbol(const char* s, const char* context) {
    Tok t = next();
    if (!t.is(s)) failExpected(t, std::string("'") + s + "' " + context);
    return t;
}

bool PovParser::acceptWord(const char* w) {
    if (peek().isWord(w)) {
        next();
        return true;
    }
    return false;
}

Tok PovParser::expectWord(const char* context) {
    Tok t = next();
    if (t.kind != TokKind::Word) failExpected(t, context);
    return t;
}

void PovParser::skipBlock() {
    int depth = 1;
    while (depth > 0) {
        const Tok t = next();
        if (t.kind == TokKind::EndOfFile) fail(t.loc, "unbalanced '{': end of file inside a block");
        if (t.is("{")) ++depth;
        else if (t.is("}")) --depth;
    }
}

// ------------------------------------------------------------ entry

std::optional<Scene> PovParser::run(int fileId, const std::string& baseDir) {
    try {
        pushFile(fileId, SourceLoc{}, baseDir);
        scopes_.pop_back(); // the main file shares the global scope
        for (;;) {
            const Tok t = next();
            if (t.kind == TokKind::EndOfFile) break;
            statement(t);
        }
    } catch (const PovAbort&) {
        return std::nullopt;
    }
    if (diags_.hasErrors()) return std::nullopt;
    finishScene();
    return std::move(scene_);
}

} // namespace drt::pov

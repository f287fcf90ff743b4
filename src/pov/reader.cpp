// The token stream: files, includes, conditionals, loops and macro calls.
// As in POV-Ray, directives run as the parser pulls tokens, loops and macros
// replay an already-lexed token vector by index, and every #include and macro
// call opens a new scope for #local.
#include "pov/parser.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt::pov {

namespace {
constexpr size_t kMaxFrames = 400;          // nested includes + macro calls
constexpr long kMaxLoopIterations = 10000000; // per #while / #for
constexpr int kMaxExpressionDepth = 400;
} // namespace

DepthGuard::DepthGuard(PovParser& p, SourceLoc loc) : depth(p.expressionDepth_) {
    if (++depth > kMaxExpressionDepth) {
        --depth;
        p.fail(loc, "nesting too deep (more than " + std::to_string(kMaxExpressionDepth) + " levels)");
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
    if (frames_.size() >= kMaxFrames) fail(includedFrom, "includes or macro calls nested too deep");
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
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    if (!in && !in.eof()) fail(at.loc, "cannot read include file \"" + path + "\"");
    const int id = diags_.files().add(path, buffer.str());
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

// ------------------------------------------------------------ skipping

namespace {
bool opensBlock(const std::string& d) {
    return d == "if" || d == "ifdef" || d == "ifndef" || d == "switch" || d == "while" || d == "for" || d == "macro";
}
} // namespace

Tok PovParser::skipTo(const std::set<std::string>& stops, const Tok& start) {
    int depth = 0;
    for (;;) {
        Frame& f = frames_.back();
        const Tok& t = (*f.tokens)[f.pos];
        if (t.kind == TokKind::EndOfFile) fail(start.loc, "'#" + start.text + "' has no matching #end");
        ++f.pos;
        if (t.kind != TokKind::Directive) continue;
        if (depth == 0 && stops.count(t.text)) return t;
        if (opensBlock(t.text)) ++depth;
        else if (t.text == "end") --depth;
    }
}

// ------------------------------------------------------------ directives

void PovParser::directive(const Tok& t) {
    const std::string& d = t.text;
    if (d == "declare") declareDirective(t, false);
    else if (d == "local") declareDirective(t, true);
    else if (d == "undef") {
        noExpand_ = true;
        const Tok name = expectWord("an identifier after #undef");
        noExpand_ = false;
        for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
            if (it->erase(name.text)) break;
    } else if (d == "include") includeDirective(t);
    else if (d == "if") ifDirective(t, 0);
    else if (d == "ifdef") ifDirective(t, 1);
    else if (d == "ifndef") ifDirective(t, 2);
    else if (d == "else" || d == "elseif") {
        if (conds_.empty() || conds_.back().frame != frames_.size() - 1) fail(t.loc, "#" + d + " without #if");
        Cond& c = conds_.back();
        if (c.type == Cond::Type::Switch) {
            if (d == "elseif") fail(t.loc, "#elseif inside #switch");
            return; // reached while running a matched case: fall through
        }
        if (c.type != Cond::Type::If) fail(t.loc, "#" + d + " without #if");
        // The taken branch ends here: skip the rest of the chain.
        skipTo({"end"}, t);
        conds_.pop_back();
    } else if (d == "end") endDirective(t);
    else if (d == "while") whileHead(t);
    else if (d == "for") forDirective(t);
    else if (d == "switch") switchDirective(t);
    else if (d == "case" || d == "range") {
        if (conds_.empty() || conds_.back().type != Cond::Type::Switch) fail(t.loc, "#" + d + " outside #switch");
        // Fall-through from a matched case: read and ignore the value.
        expectSymbol("(", "after #case/#range");
        floatExpr();
        if (d == "range") {
            expectSymbol(",", "in #range");
            floatExpr();
        }
        expectSymbol(")", "after #case/#range value");
    } else if (d == "break") breakDirective(t);
    else if (d == "macro") macroDefinition(t);
    else if (d == "debug" || d == "warning" || d == "error" || d == "render" || d == "statistics")
        messageDirective(t);
    else if (d == "version") versionDirective(t);
    else if (d == "default") {
        warnOnce("#default", t.loc, "#default is not supported; its block is ignored");
        expectSymbol("{", "after #default");
        skipBlock();
    } else if (d == "fopen" || d == "fclose" || d == "read" || d == "write") {
        fail(t.loc, "#" + d + " (file input/output) is not supported");
    } else {
        fail(t.loc, "unknown directive '#" + d + "'");
    }
}

void PovParser::versionDirective(const Tok& t) {
    (void)t;
    version_ = floatExpr();
    versionSeen_ = true;
    if (peekOperator().is(";")) next();
}

void PovParser::messageDirective(const Tok& t) {
    const std::string text = stringExpr();
    if (t.text == "error") fail(t.loc, "#error: " + text);
    if (t.text == "warning") warn(t.loc, "#warning: " + text);
    // #debug, #render, #statistics: POV-Ray prints them to its message streams;
    // drt keeps them quiet so `drt check` output stays about the scene.
}

Cell* PovParser::arrayElementForAssignment(const Tok& name, Cell cell) {
    Cell* target = nullptr;
    while (peek().is("[")) {
        if (!cell || cell->kind != PovValue::Kind::Array) fail(name.loc, "'" + name.text + "' is not an array");
        PovArray& a = *cell->array;
        size_t index = 0;
        for (size_t d = 0; d < a.sizes.size(); ++d) {
            const Tok open = expectSymbol("[", "for an array index");
            const double i = floatExpr();
            expectSymbol("]", "after an array index");
            const int ii = static_cast<int>(i);
            if (ii < 0 || ii >= a.sizes[d])
                fail(open.loc, fmt::format("array index {} out of range 0..{}", ii, a.sizes[d] - 1));
            index = index * size_t(a.sizes[d]) + size_t(ii);
        }
        target = &a.items[index];
        if (!*target) *target = std::make_shared<PovValue>();
        cell = *target;
    }
    return target;
}

void PovParser::declareDirective(const Tok& t, bool local) {
    noExpand_ = true;
    Tok name = next();
    if (name.isWord("deprecated")) {
        // #declare deprecated [once] "message" Name = ...: the message is for users of Name.
        name = next();
        if (name.isWord("once")) name = next();
        if (name.kind != TokKind::String) {
            noExpand_ = false;
            failExpected(name, "the deprecation message");
        }
        name = next();
    }
    noExpand_ = false;
    if (name.kind != TokKind::Word) failExpected(name, "an identifier after #" + t.text);
    Cell* element = nullptr;
    if (peek().is("[")) element = arrayElementForAssignment(name, lookup(name.text));
    expectSymbol("=", "after the identifier in #declare");
    // Warnings wait until the identifier is used (PendingWarning).
    std::vector<PendingWarning> pending;
    std::vector<PendingWarning>* outer = pending_;
    pending_ = &pending;
    PovValue value;
    try {
        value = rvalue();
    } catch (...) {
        pending_ = outer;
        throw;
    }
    pending_ = outer;
    value.warnings = pending.empty() ? nullptr : std::make_shared<const std::vector<PendingWarning>>(std::move(pending));
    if (element) **element = value;
    else declare(name.text, value, local);
    if (peekOperator().is(";")) next();
}

void PovParser::ifDirective(const Tok& t, int kind) {
    bool taken;
    if (kind == 0) {
        expectSymbol("(", "after #if");
        taken = boolExpr();
        expectSymbol(")", "after the #if condition");
    } else {
        expectSymbol("(", "after #ifdef");
        noExpand_ = true;
        const Tok name = expectWord("an identifier");
        noExpand_ = false;
        bool defined = lookup(name.text) != nullptr;
        if (defined && peek().is("[")) {
            // #ifdef(A[i]): is the element initialised?
            const Cell c = lookup(name.text);
            if (c->kind != PovValue::Kind::Array) fail(name.loc, "'" + name.text + "' is not an array");
            size_t index = 0;
            for (size_t d = 0; d < c->array->sizes.size(); ++d) {
                expectSymbol("[", "");
                const int i = static_cast<int>(floatExpr());
                expectSymbol("]", "");
                if (i < 0 || i >= c->array->sizes[d]) fail(name.loc, "array index out of range");
                index = index * size_t(c->array->sizes[d]) + size_t(i);
            }
            defined = c->array->items[index] != nullptr;
        }
        expectSymbol(")", "after the identifier");
        taken = (kind == 1) == defined;
    }
    Cond c;
    c.type = Cond::Type::If;
    c.frame = frames_.size() - 1;
    c.loc = t.loc;
    if (taken) {
        conds_.push_back(c);
        return;
    }
    conds_.push_back(c);
    branchSkip(t);
}

// Skips a false branch. Lands after #else (the branch is taken), or on a true
// #elseif, or pops the conditional at #end.
void PovParser::branchSkip(const Tok& start) {
    for (;;) {
        const Tok stop = skipTo({"else", "elseif", "end"}, start);
        if (stop.text == "end") {
            conds_.pop_back();
            return;
        }
        if (stop.text == "else") return;
        expectSymbol("(", "after #elseif");
        const bool taken = boolExpr();
        expectSymbol(")", "after the #elseif condition");
        if (taken) return;
    }
}

void PovParser::whileHead(const Tok& t) {
    Cond c;
    c.type = Cond::Type::While;
    c.frame = frames_.size() - 1;
    c.pos = frames_.back().pos; // the condition's first token
    c.loc = t.loc;
    expectSymbol("(", "after #while");
    const bool go = boolExpr();
    expectSymbol(")", "after the #while condition");
    if (!go) {
        skipTo({"end"}, t);
        return;
    }
    conds_.push_back(c);
}

void PovParser::forDirective(const Tok& t) {
    expectSymbol("(", "after #for");
    noExpand_ = true;
    const Tok name = expectWord("the loop identifier");
    noExpand_ = false;
    expectSymbol(",", "after the #for identifier");
    const double from = floatExpr();
    expectSymbol(",", "after the #for start");
    const double to = floatExpr();
    double step = 1;
    if (acceptSymbol(",")) step = floatExpr();
    expectSymbol(")", "after #for");
    if (step == 0) fail(t.loc, "#for step is 0");
    declare(name.text, PovValue::makeFloat(from), true);
    Cond c;
    c.type = Cond::Type::For;
    c.frame = frames_.size() - 1;
    c.pos = frames_.back().pos;
    c.loc = t.loc;
    c.forName = name.text;
    c.forEnd = to;
    c.forStep = step;
    if (step > 0 ? from > to : from < to) {
        skipTo({"end"}, t);
        return;
    }
    conds_.push_back(c);
}

void PovParser::switchDirective(const Tok& t) {
    expectSymbol("(", "after #switch");
    Cond c;
    c.type = Cond::Type::Switch;
    c.frame = frames_.size() - 1;
    c.loc = t.loc;
    c.switchValue = floatExpr();
    expectSymbol(")", "after the #switch value");
    conds_.push_back(c);
    switchScan(t);
}

// Looks for the first #case / #range that matches, or #else, or #end.
void PovParser::switchScan(const Tok& start) {
    for (;;) {
        const Tok stop = skipTo({"case", "range", "else", "end"}, start);
        if (stop.text == "end") {
            conds_.pop_back();
            return;
        }
        if (stop.text == "else") break;
        expectSymbol("(", "after #case/#range");
        const double a = floatExpr();
        bool match;
        if (stop.text == "range") {
            expectSymbol(",", "in #range");
            const double b = floatExpr();
            match = conds_.back().switchValue >= a && conds_.back().switchValue <= b;
        } else {
            match = conds_.back().switchValue == a;
        }
        expectSymbol(")", "after the #case value");
        if (match) break;
    }
    conds_.back().switchMatched = true;
}

void PovParser::breakDirective(const Tok& t) {
    // Leave the innermost #switch, #while or #for: skip to its #end.
    int levels = 0;
    for (auto it = conds_.rbegin(); it != conds_.rend(); ++it) {
        ++levels;
        if (it->frame != frames_.size() - 1) fail(t.loc, "#break outside #switch, #while or #for");
        if (it->type != Cond::Type::If) {
            for (int i = 0; i < levels; ++i) {
                skipTo({"end"}, t);
                conds_.pop_back();
            }
            return;
        }
    }
    fail(t.loc, "#break outside #switch, #while or #for");
}

void PovParser::endDirective(const Tok& t) {
    Frame& f = frames_.back();
    if (conds_.size() == f.condDepth) {
        if (f.isMacro) {
            popFrame();
            return;
        }
        fail(t.loc, "#end without a matching #if, #while, #for, #switch or #macro");
    }
    Cond& c = conds_.back();
    if (c.type == Cond::Type::While) {
        if (++c.iterations > kMaxLoopIterations)
            fail(c.loc, fmt::format("#while loop ran more than {} times; stopping", kMaxLoopIterations));
        const long iterations = c.iterations;
        const Cond saved = c;
        conds_.pop_back();
        frames_[saved.frame].pos = saved.pos;
        expectSymbol("(", "after #while");
        const bool go = boolExpr();
        expectSymbol(")", "after the #while condition");
        if (go) {
            Cond again = saved;
            again.iterations = iterations;
            conds_.push_back(again);
        } else {
            skipTo({"end"}, Tok{TokKind::Directive, "while", 0, saved.loc});
        }
        return;
    }
    if (c.type == Cond::Type::For) {
        if (++c.iterations > kMaxLoopIterations)
            fail(c.loc, fmt::format("#for loop ran more than {} times; stopping", kMaxLoopIterations));
        const Cell v = lookup(c.forName);
        if (!v || v->kind != PovValue::Kind::Float) fail(c.loc, "#for loop identifier '" + c.forName + "' is no longer a float");
        const double value = v->number + c.forStep;
        v->number = value;
        if (c.forStep > 0 ? value <= c.forEnd : value >= c.forEnd) {
            frames_[c.frame].pos = c.pos;
        } else {
            conds_.pop_back();
        }
        return;
    }
    conds_.pop_back();
}

void PovParser::macroDefinition(const Tok& t) {
    noExpand_ = true;
    const Tok name = next();
    if (name.kind != TokKind::Word) {
        noExpand_ = false;
        failExpected(name, "a macro name");
    }
    auto m = std::make_shared<PovMacro>();
    m->name = name.text;
    m->loc = name.loc;
    noExpand_ = false;
    expectSymbol("(", "after the macro name");
    // The parameter list is read raw: looking ahead must not run the body.
    if (!pushed_.empty()) fail(t.loc, "internal: look-ahead across a macro definition");
    for (Tok p = rawNext(); !p.is(")");) {
        if (p.kind != TokKind::Word) failExpected(p, "a parameter name or ')'");
        m->params.push_back(p.text);
        p = rawNext();
        if (p.is(",")) p = rawNext();
        else if (!p.is(")")) failExpected(p, "',' or ')' in the macro parameters");
    }
    m->tokens = frames_.back().tokens;
    m->bodyStart = frames_.back().pos;
    skipTo({"end"}, t);
    PovValue v;
    v.kind = PovValue::Kind::Macro;
    v.macro = m;
    scopes_.front()[m->name] = std::make_shared<PovValue>(v);
}

void PovParser::invokeMacro(const Tok& t) {
    const std::shared_ptr<const PovMacro> m = lookup(t.text)->macro;
    expectSymbol("(", ("to call macro '" + t.text + "'").c_str());
    std::map<std::string, Cell> scope;
    size_t count = 0;
    if (!peek().is(")")) {
        do {
            if (count >= m->params.size())
                fail(t.loc, fmt::format("macro '{}' takes {} parameter{}", m->name, m->params.size(),
                                        m->params.size() == 1 ? "" : "s"));
            // A lone identifier is passed by reference: the macro may assign it.
            noExpand_ = true;
            Tok first = next();
            noExpand_ = false;
            Cell byReference;
            if (first.kind == TokKind::Word && !isMacro(first.text)) {
                if (Cell c = lookup(first.text)) {
                    const Tok after = peek();
                    if (after.is(",") || after.is(")")) byReference = c;
                }
            }
            if (byReference) {
                scope[m->params[count]] = byReference;
            } else {
                pushBack(first);
                scope[m->params[count]] = std::make_shared<PovValue>(rvalue());
            }
            ++count;
        } while (acceptSymbol(","));
    }
    expectSymbol(")", "after the macro arguments");
    if (count != m->params.size())
        fail(t.loc, fmt::format("macro '{}' takes {} parameter{}, given {}", m->name, m->params.size(),
                                m->params.size() == 1 ? "" : "s", count));
    if (frames_.size() >= kMaxFrames) fail(t.loc, "macro calls nested too deep (runaway recursion?)");
    Frame f;
    f.tokens = m->tokens;
    f.pos = m->bodyStart;
    f.isMacro = true;
    f.condDepth = conds_.size();
    pushFrame(std::move(f));
    scopes_.push_back(std::move(scope));
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

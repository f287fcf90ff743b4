// Directives: #declare/#local, #include, conditionals, loops, #switch, macro
// definitions and calls, messages, files, #version and #default. Loops jump
// back by token index; a false branch is skipped raw, counting nested directives.
#include "lang/evaluator.h"

#include <algorithm>
#include <fmt/format.h>

namespace drt::lang {

namespace {

bool opensBlock(std::string_view d) {
    return d == "if" || d == "ifdef" || d == "ifndef" || d == "switch" || d == "while" || d == "for" || d == "macro";
}

const std::vector<std::string>& directiveNames() {
    static const std::vector<std::string> names{
        "declare", "local",  "undef", "include", "if",      "ifdef",   "ifndef", "else",  "elseif", "end",
        "while",   "for",    "switch", "case",   "range",   "break",   "macro",  "debug", "warning", "error",
        "render",  "statistics", "version", "default", "fopen", "fclose", "read", "write"};
    return names;
}

} // namespace

// ------------------------------------------------------------ skipping

const char* Evaluator::condDirective(const Cond& c) {
    switch (c.type) {
    case Cond::Type::If: return "#if";
    case Cond::Type::While: return "#while";
    case Cond::Type::For: return "#for";
    case Cond::Type::Switch: return "#switch";
    }
    return "#if";
}

void Evaluator::openingDirective(const Token& t, const std::function<void()>& run) {
    const size_t frameCount = frames_.size();
    const size_t condCount = conds_.size();
    try {
        run();
    } catch (const Abort&) {
        // Only when the error left the reader in this directive's own file, before its end.
        if (frames_.size() == frameCount && !frames_.empty()) {
            const Frame& f = frames_.back();
            if ((*f.tokens)[f.pos].kind != TokenKind::EndOfFile) {
                if (conds_.size() > condCount) conds_.resize(condCount);
                pushed_.clear();
                try {
                    skipTo({"end"}, t);
                } catch (const Abort&) {
                }
            }
        }
        throw;
    }
}

void Evaluator::dropFrameConds() {
    if (!frames_.empty() && conds_.size() > frames_.back().condDepth) conds_.resize(frames_.back().condDepth);
}

Token Evaluator::skipTo(std::initializer_list<std::string_view> stops, const Token& start) {
    int depth = 0;
    for (;;) {
        Frame& f = frames_.back();
        const Token& t = (*f.tokens)[f.pos];
        if (t.kind == TokenKind::EndOfFile) {
            dropFrameConds(); // none of them can be closed now: one error is enough
            fail(start.loc, "'#" + start.text + "' has no matching #end");
        }
        ++f.pos;
        if (t.kind != TokenKind::Directive) continue;
        const std::string_view d = t.text;
        if (depth == 0 && std::find(stops.begin(), stops.end(), d) != stops.end()) return t;
        if (opensBlock(d)) ++depth;
        else if (d == "end") --depth;
    }
}

// ------------------------------------------------------------ directives

void Evaluator::directive(const Token& t) {
    // A directive met while another one reads its tokens (`#declare A = #if (#declare B = ...`) runs
    // inside it: the nesting limit bounds that recursion as it bounds nested blocks.
    DepthGuard guard(*this, t.loc);
    const std::string_view d = t.text; // compared with literals: lengths known at compile time
    if (d == "declare") declareDirective(t, false);
    else if (d == "local") declareDirective(t, true);
    else if (d == "undef") {
        noExpand_ = true;
        const Token name = expectWord("an identifier after #undef");
        noExpand_ = false;
        scopes_.eraseInnermost(name.text);
    } else if (d == "include") includeDirective(t);
    else if (d == "if") openingDirective(t, [&] { ifDirective(t, 0); });
    else if (d == "ifdef") openingDirective(t, [&] { ifDirective(t, 1); });
    else if (d == "ifndef") openingDirective(t, [&] { ifDirective(t, 2); });
    else if (d == "else" || d == "elseif") {
        if (conds_.empty() || conds_.back().frame != frames_.size() - 1) fail(t.loc, "#" + t.text + " without #if");
        Cond& c = conds_.back();
        if (c.type == Cond::Type::Switch) {
            if (d == "elseif") fail(t.loc, "#elseif inside #switch");
            return; // reached while running a matched case: fall through
        }
        if (c.type != Cond::Type::If) fail(t.loc, "#" + t.text + " without #if");
        // The taken branch ends here: skip the rest of the chain.
        skipTo({"end"}, t);
        conds_.pop_back();
    } else if (d == "end") endDirective(t);
    else if (d == "while") openingDirective(t, [&] { whileHead(t); });
    else if (d == "for") openingDirective(t, [&] { forDirective(t); });
    else if (d == "switch") openingDirective(t, [&] { switchDirective(t); });
    else if (d == "case" || d == "range") {
        if (conds_.empty() || conds_.back().type != Cond::Type::Switch) fail(t.loc, "#" + t.text + " outside #switch");
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
    else if (d == "default") defaultBlock();
    else if (d == "fopen" || d == "fclose" || d == "read" || d == "write") fileDirective(t);
    else {
        Token shown = t;
        shown.text = "#" + t.text;
        std::vector<std::string> known;
        for (const std::string& w : directiveNames()) known.push_back("#" + w);
        failUnknownIn(shown, known, "directive");
    }
}

// Files: what a scene writes (#fopen .. write/append, #write) is read and
// dropped, so scenes that write HTML or logs still render; reading (#fopen ..
// read, #read, #fclose) is file_input.cpp's.
void Evaluator::fileDirective(const Token& t) {
    const std::string& d = t.text;
    if (d == "read") return readDirective(); // file_input.cpp
    noExpand_ = true;
    const Token handle = d == "write" ? Token{} : expectWord("a file identifier");
    noExpand_ = false;
    if (d == "fclose") return closeDataFile(handle.text);
    if (d == "fopen") {
        const SourceLoc nameLoc = peek().loc;
        const std::string name = stringExpr();
        const Token mode = expectWord("'read', 'write' or 'append' after the file name");
        if (mode.text == "read") return openDataFile(handle, name, nameLoc);
        if (mode.text != "write" && mode.text != "append")
            failExpected(mode, "'read', 'write' or 'append' after the file name");
        if (warned_.insert("note-fopen").second)
            note(t.loc, "#fopen ... " + mode.text + ": drt does not create the files a scene writes");
        Value file;
        file.kind = Value::Kind::Opaque;
        file.text = "file";
        declare(handle.text, file, false);
        return;
    }
    // #write (handle, item, item ...): the commas are optional.
    expectSymbol("(", "after #write");
    noExpand_ = true;
    expectWord("a file identifier");
    noExpand_ = false;
    while (!acceptSymbol(")")) {
        acceptSymbol(",");
        if (peek().is(")")) continue;
        rvalue();
    }
}

void Evaluator::versionDirective(const Token&) {
    version_ = floatExpr();
    versionSeen_ = true;
    if (peekOperator().is(";")) next();
}

void Evaluator::messageDirective(const Token& t) {
    const std::string text = stringExpr();
    if (t.text == "error") fail(t.loc, "#error: " + text);
    if (t.text == "warning") warn(t.loc, "#warning: " + text);
    // #debug, #render, #statistics: POV-Ray prints them to its message streams;
    // drt keeps them quiet so `drt check` output stays about the scene.
}

Cell* Evaluator::arrayElementForAssignment(const Token& name, Cell cell) {
    Cell* target = nullptr;
    while (peek().is("[")) {
        if (!cell || cell->kind != Value::Kind::Array) fail(name.loc, "'" + name.text + "' is not an array");
        lang::Array& a = *cell->array;
        target = &a.items[arrayIndex(a, name)];
        if (!*target) *target = std::make_shared<Value>();
        cell = *target;
    }
    return target;
}

// The source text of a declaration's value on its line ("0.5 - 1"), or "".
std::string Evaluator::declarationText(SourceLoc start) const {
    const SourceLoc end = lastToken_.loc;
    if (!start.valid() || end.file != start.file || end.line != start.line || end.column < start.column) return "";
    const std::string line = diags_.files().line(start.file, start.line);
    size_t endColumn = size_t(end.column) - 1 + lastToken_.text.size();
    if (lastToken_.kind == TokenKind::String) endColumn += 2;
    if (endColumn > line.size()) return "";
    return line.substr(size_t(start.column) - 1, endColumn - (size_t(start.column) - 1));
}

// #declare Name = value [;]: in .drt files the ';' is required after numbers,
// vectors and colours (as in POV-Ray 3.7, which only warns) and optional after blocks.
void Evaluator::declareDirective(const Token& t, bool local) {
    const size_t scopeCount = scopes_.size();
    noExpand_ = true;
    Token name = next();
    if (name.isWord("deprecated")) {
        // #declare deprecated [once] "message" Name = ...: the message is for users of Name.
        name = next();
        if (name.isWord("once")) name = next();
        if (name.kind != TokenKind::String) {
            noExpand_ = false;
            failExpected(name, "the deprecation message");
        }
        name = next();
    }
    noExpand_ = false;
    if (name.kind != TokenKind::Word) failExpected(name, "a name after '#" + t.text + "'");
    if (syntax().kind == DialectKind::Drt) {
        const auto& top = blockKeywords(Block::Statement);
        const std::string& n = name.text;
        if (isObjectWord(name) || std::find(top.begin(), top.end(), n) != top.end() || n == "x" || n == "y" ||
            n == "z" || n == "pi")
            fail(name.loc, "cannot declare '" + n + "': it is a keyword");
    }
    Cell* element = nullptr;
    if (peek().is("[")) element = arrayElementForAssignment(name, lookup(name.text));
    expectSymbol("=", element ? "after the array element" : "after the declared name");
    // Warnings wait until the identifier is used (PendingWarning).
    std::vector<PendingWarning> pending;
    std::vector<PendingWarning>* outer = pending_;
    pending_ = &pending;
    Value value;
    const SourceLoc start = peek().loc;
    const std::string outerName = std::exchange(declaringName_, name.text);
    try {
        value = rvalue();
    } catch (...) {
        pending_ = outer;
        declaringName_ = outerName;
        throw;
    }
    pending_ = outer;
    declaringName_ = outerName;
    value.warnings = pending.empty() ? nullptr : std::make_shared<const std::vector<PendingWarning>>(std::move(pending));
    if (value.kind == Value::Kind::Float || value.kind == Value::Kind::Vector || value.kind == Value::Kind::Color) {
        const std::string text = declarationText(start);
        value.origin = text.empty() ? nullptr : std::make_shared<const Origin>(Origin{name.text, text});
    }
    const bool needsSemicolon = value.isNumeric() && syntax().requireCommas;
    // A declared scene item may be a copy of copies (a doubling "billion
    // laughs"): look at the memory the scene takes before keeping it.
    if (!value.isNumeric() && value.kind != Value::Kind::String) checkMemoryAt(name.loc);
    if (element) **element = std::move(value);
    else declare(name.text, std::move(value), local, scopeCount);
    if (peekOperator().is(";")) next();
    else if (needsSemicolon) fail(lastToken_.loc, "expected ';' after the value of '" + name.text + "'");
}

void Evaluator::ifDirective(const Token& t, int kind) {
    bool taken;
    if (kind == 0) {
        expectSymbol("(", "after #if");
        taken = boolExpr();
        expectSymbol(")", "after the #if condition");
    } else {
        expectSymbol("(", kind == 1 ? "after #ifdef" : "after #ifndef");
        noExpand_ = true;
        const Token name = expectWord("an identifier");
        noExpand_ = false;
        bool defined = lookup(name.text) != nullptr;
        if (defined && peek().is("[")) {
            // #ifdef(A[i]): is the element initialised?
            const Cell c = lookup(name.text);
            if (c->kind != Value::Kind::Array) fail(name.loc, "'" + name.text + "' is not an array");
            defined = c->array->items[arrayIndex(*c->array, name)] != nullptr;
        }
        expectSymbol(")", "after the identifier");
        taken = (kind == 1) == defined;
    }
    Cond c;
    c.type = Cond::Type::If;
    c.frame = frames_.size() - 1;
    c.loc = t.loc;
    conds_.push_back(c);
    if (!taken) branchSkip(t);
}

// Skips a false branch. Lands after #else (the branch is taken), or on a true
// #elseif, or pops the conditional at #end.
void Evaluator::branchSkip(const Token& start) {
    for (;;) {
        const Token stop = skipTo({"else", "elseif", "end"}, start);
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

void Evaluator::whileHead(const Token& t) {
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

void Evaluator::forDirective(const Token& t) {
    expectSymbol("(", "after #for");
    noExpand_ = true;
    const Token name = expectWord("the loop identifier");
    noExpand_ = false;
    expectSymbol(",", "after the #for identifier");
    const double from = floatExpr();
    expectSymbol(",", "after the #for start");
    const double to = floatExpr();
    double step = 1;
    if (acceptSymbol(",")) step = floatExpr();
    expectSymbol(")", "after #for");
    if (step == 0) fail(t.loc, "#for step is 0");
    declare(name.text, Value::makeFloat(from), true);
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

void Evaluator::switchDirective(const Token& t) {
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
void Evaluator::switchScan(const Token& start) {
    for (;;) {
        const Token stop = skipTo({"case", "range", "else", "end"}, start);
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

void Evaluator::breakDirective(const Token& t) {
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

void Evaluator::endDirective(const Token& t) {
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
        countIteration("#while");
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
            skipTo({"end"}, Token{TokenKind::Directive, "while", 0, saved.loc});
        }
        return;
    }
    if (c.type == Cond::Type::For) {
        countIteration("#for");
        const Cell v = lookup(c.forName);
        if (!v || v->kind != Value::Kind::Float)
            fail(c.loc, "#for loop identifier '" + c.forName + "' is no longer a number");
        const double value = v->number + c.forStep;
        v->number = value;
        v->origin = nullptr;
        if (c.forStep > 0 ? value <= c.forEnd : value >= c.forEnd) {
            frames_[c.frame].pos = c.pos;
        } else {
            conds_.pop_back();
        }
        return;
    }
    conds_.pop_back();
}

void Evaluator::macroDefinition(const Token& t) {
    noExpand_ = true;
    const Token name = next();
    if (name.kind != TokenKind::Word) {
        noExpand_ = false;
        failExpected(name, "a macro name");
    }
    auto m = std::make_shared<lang::Macro>();
    m->name = name.text;
    m->loc = name.loc;
    noExpand_ = false;
    expectSymbol("(", "after the macro name");
    // The parameter list is read raw: looking ahead must not run the body.
    if (!pushed_.empty()) fail(t.loc, "internal: look-ahead across a macro definition");
    for (Token p = rawNext(); !p.is(")");) {
        if (p.kind != TokenKind::Word) failExpected(p, "a parameter name or ')'");
        m->params.push_back(p.text);
        p = rawNext();
        if (p.is(",")) p = rawNext();
        else if (!p.is(")")) failExpected(p, "',' or ')' in the macro parameters");
    }
    m->tokens = frames_.back().tokens;
    m->bodyStart = frames_.back().pos;
    m->dialect = frames_.back().dialect;
    skipTo({"end"}, t);
    // Each call replays the body: the reader must not free it.
    if (frames_.back().tokens == m->tokens) m->tokens->keep(m->bodyStart, frames_.back().pos);
    else m->tokens->keep(m->bodyStart, m->tokens->lexed());
    Value v;
    v.kind = Value::Kind::Macro;
    v.macro = m;
    macroNames_.add(m->name);
    scopes_.set(0, m->name, std::make_shared<Value>(v));
}

void Evaluator::invokeMacro(const Token& t) {
    const std::shared_ptr<const lang::Macro> m = lookup(t.text)->macro;
    expectSymbol("(", "to call macro '", t.text, "'");
    std::vector<std::pair<const std::string*, Cell>> scope; // the parameters' cells, bound when the body starts
    size_t count = 0;
    if (!peek().is(")")) {
        do {
            if (count >= m->params.size())
                fail(t.loc, fmt::format("macro '{}' takes {} parameter{}", m->name, m->params.size(),
                                        m->params.size() == 1 ? "" : "s"));
            // A lone identifier is passed by reference: the macro may assign it.
            noExpand_ = true;
            Token first = next();
            noExpand_ = false;
            Cell byReference;
            if (first.kind == TokenKind::Word && !isMacro(first.text)) {
                if (Cell c = lookup(first.text)) {
                    const Token after = peek();
                    if (after.is(",") || after.is(")")) byReference = c;
                }
            }
            if (byReference) {
                scope.emplace_back(&m->params[count], byReference);
            } else {
                pushBack(first);
                scope.emplace_back(&m->params[count], std::make_shared<Value>(rvalue()));
            }
            ++count;
            // POV-Ray's commas between arguments are optional: `M(Obj -y)`.
        } while (acceptSymbol(",") ||
                 (!syntax().requireCommas && count < m->params.size() && !peek().is(")")));
    }
    expectSymbol(")", "after the macro arguments");
    if (count != m->params.size())
        fail(t.loc, fmt::format("macro '{}' takes {} parameter{}, given {}", m->name, m->params.size(),
                                m->params.size() == 1 ? "" : "s", count));
    if (int64_t(frames_.size()) >= diags_.limits().callDepth)
        failLimit(t.loc, limitExceeded(diags_.limits(), &Limits::callDepth, "macro calls and includes nested",
                                  double(frames_.size() + 1)) +
                        " (runaway recursion?)");
    if (++passesAndCalls_ > diags_.limits().passesAndCalls) failPassesAndCalls(t.loc);
    if (passesAndCalls_ % kMemoryCheckInterval == 0) checkMemoryAt(t.loc);
    Frame f;
    f.tokens = m->tokens;
    f.pos = m->bodyStart;
    f.isMacro = true;
    f.includedFrom = t.loc;
    f.macroName = m->name;
    f.condDepth = conds_.size();
    f.dialect = m->dialect;
    pushFrame(std::move(f));
    scopes_.push();
    for (auto& [param, cell] : scope) {
        if (cell->kind == Value::Kind::Macro) macroNames_.add(*param);
        scopes_.set(scopes_.size() - 1, *param, std::move(cell));
    }
}

void Evaluator::countIteration(const char* directive) {
    Cond& c = conds_.back();
    const Limits& limits = diags_.limits();
    const bool overLoop = ++c.iterations > limits.loopIterations;
    if (overLoop || ++passesAndCalls_ > limits.passesAndCalls) {
        const SourceLoc loc = c.loc;
        const long iterations = c.iterations;
        conds_.pop_back(); // its #end was just read
        if (!overLoop) failPassesAndCalls(loc);
        failLimit(loc, limitExceeded(limits, &Limits::loopIterations, fmt::format("this {} loop's pass", directive),
                                     double(iterations)));
    }
    if (passesAndCalls_ % kMemoryCheckInterval == 0) checkMemoryAt(c.loc);
}

void Evaluator::failPassesAndCalls(SourceLoc loc) {
    limitReached_ = true;
    report(Severity::Error, loc,
           limitExceeded(diags_.limits(), &Limits::passesAndCalls, "the scene's loop passes and macro calls number",
                         double(passesAndCalls_)));
    // The count runs out wherever the next pass or call happens to be, often deep
    // in a macro of an include file; the outermost loop still running is the
    // likely runaway, so it is named too.
    noteOutermostLoop();
    throw Abort{};
}

void Evaluator::noteOutermostLoop() {
    for (const Cond& c : conds_) {
        if (c.type != Cond::Type::While && c.type != Cond::Type::For) continue;
        diags_.attachNote(c.loc, fmt::format("in pass {} of this {} loop", c.iterations + 1, condDirective(c)),
                          includeChain(c.frame + 1));
        break;
    }
}

bool Evaluator::loopRunning() const {
    for (const Cond& c : conds_)
        if (c.type == Cond::Type::While || c.type == Cond::Type::For) return true;
    return false;
}

void Evaluator::countLoopTriangle(SourceLoc loc, SourceLoc mesh) {
    if (built_ + 1 <= diags_.limits().objects) return countBuilt(loc, 1);
    limitReached_ = true;
    report(Severity::Error, loc,
           limitExceeded(diags_.limits(), &Limits::objects, "the scene's objects and patterns number",
                         double(built_ + 1)));
    diags_.attachNote(mesh, "the triangles this mesh is given while a loop runs count as objects", includeChain());
    noteOutermostLoop();
    throw Abort{};
}

void Evaluator::checkMemoryAt(SourceLoc loc) {
    if (std::string problem = checkMemory(diags_.limits()); !problem.empty()) failLimit(loc, problem);
}

} // namespace drt::lang

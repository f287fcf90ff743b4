// Directives: #declare/#local, #include, conditionals, loops, #switch, macro
// definitions and calls, messages. Loops jump back by token index; a false
// branch is skipped raw, counting nested directives.
#include "pov/parser.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt::pov {

namespace {
} // namespace

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
        defaultBlock();
    } else if (d == "fopen" || d == "fclose" || d == "read" || d == "write") {
        fileDirective(t);
    } else {
        fail(t.loc, "unknown directive '#" + d + "'");
    }
}

// Files: what a scene writes (#fopen .. write/append, #write, #fclose) is
// read and dropped, so scenes that write HTML or logs still render; reading
// (#fopen .. read, #read) needs the file's contents and is an error.
void PovParser::fileDirective(const Tok& t) {
    const std::string& d = t.text;
    if (d == "read") fail(t.loc, "#read (file input) is not supported");
    noExpand_ = true;
    const Tok handle = d == "write" ? Tok{} : expectWord("a file identifier");
    noExpand_ = false;
    if (d == "fclose") return;
    if (d == "fopen") {
        stringExpr(); // the file name
        const Tok mode = expectWord("'read', 'write' or 'append' after the file name");
        if (mode.text == "read") fail(mode.loc, "#fopen ... read (file input) is not supported");
        if (mode.text != "write" && mode.text != "append")
            failExpected(mode, "'read', 'write' or 'append' after the file name");
        if (warned_.insert("note-fopen").second)
            note(t.loc, "#fopen ... " + mode.text + ": drt does not create the files a scene writes");
        PovValue file;
        file.kind = PovValue::Kind::Opaque;
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
            expectSymbol("[", "for an array index");
            const int ii = countExpr("array index", 0, a.sizes[d] - 1);
            expectSymbol("]", "after an array index");
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
    // A declared scene item may be a copy of copies (a doubling "billion
    // laughs"): look at the memory the scene takes before keeping it.
    if (value.kind != PovValue::Kind::Float && value.kind != PovValue::Kind::Vector &&
        value.kind != PovValue::Kind::Color)
        checkMemoryAt(name.loc);
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
                const int i = countExpr("array index", 0, c->array->sizes[d] - 1);
                expectSymbol("]", "");
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
        countIteration(c, "#while");
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
        countIteration(c, "#for");
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
    if (int64_t(frames_.size()) >= diags_.limits().callDepth)
        fail(t.loc, limitExceeded(diags_.limits(), &Limits::callDepth, "macro calls and includes nested",
                                  double(frames_.size() + 1)) +
                        " (runaway recursion?)");
    if (++macroCalls_ % kMemoryCheckInterval == 0) checkMemoryAt(t.loc);
    Frame f;
    f.tokens = m->tokens;
    f.pos = m->bodyStart;
    f.isMacro = true;
    f.condDepth = conds_.size();
    pushFrame(std::move(f));
    scopes_.push_back(std::move(scope));
}

// #default { texture {..} | pigment {..} | finish {..} | normal {..} }: the
// texture of objects created after it that have none of their own. POV-Ray
// also accepts the old form without '#'.
void PovParser::defaultBlock() {
    expectSymbol("{", "after #default");
    for (;;) {
        const Tok item = next();
        if (item.is("}")) break;
        if (item.isWord("texture")) defaultTexture_ = texture(defaultTexture_);
        else if (item.isWord("pigment")) defaultTexture_.pigment = pigment(defaultTexture_.pigment);
        else if (item.isWord("finish")) defaultTexture_.finish = finish(defaultTexture_.finish);
        else if (item.isWord("normal")) normalBlock(item.loc);
        else failExpected(item, "'texture', 'pigment', 'finish', 'normal' or '}' in #default");
    }
}

void PovParser::countIteration(Cond& c, const char* directive) {
    const Limits& limits = diags_.limits();
    if (++c.iterations > limits.loopIterations)
        fail(c.loc, limitExceeded(limits, &Limits::loopIterations, fmt::format("this {} loop's pass", directive),
                                  double(c.iterations)));
    if (c.iterations % kMemoryCheckInterval == 0) checkMemoryAt(c.loc);
}

void PovParser::checkMemoryAt(SourceLoc loc) {
    if (std::string problem = checkMemory(diags_.limits()); !problem.empty()) fail(loc, problem);
}

} // namespace drt::pov

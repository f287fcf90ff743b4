// User-defined functions (scene/function.h): reading `function { ... }` and
// `function(a, b, ...) { ... }` into a compiled program, and calling a
// declared function in an expression. Both dialects:
//   function [ "(" name { "," name } ")" ] "{" body "}"
//   body = expression | "pattern" "{" pattern "}" | "pigment" "{" pigment "}" | "internal" "(" N ")"
// An expression in a function is a float expression of the parameters, with
// POV-Ray's operators and built-ins, declared numbers (taken as constants),
// calls of declared functions and of functions.inc's internal functions
// (f_sphere, f_r, ...: also known without functions.inc), and drt's
// `pattern { ... } (a, b, c)` / `pigment { ... } (a, b, c) [.channel]`
// (what `drt convert` writes for a call of a pattern function).
#include "lang/evaluator.h"
#include "lang/writer_function.h"
#include "scene/function.h"

#include <cmath>
#include <fmt/format.h>

namespace drt::lang {

using Kind = Value::Kind;

const std::map<std::string, FnMath1>& functionMath1Words() {
    static const std::map<std::string, FnMath1> names = {
        {"abs", FnMath1::Abs},         {"acos", FnMath1::Acos},   {"acosh", FnMath1::Acosh}, {"asin", FnMath1::Asin},
        {"asinh", FnMath1::Asinh},     {"atanh", FnMath1::Atanh}, {"ceil", FnMath1::Ceil},   {"cos", FnMath1::Cos},
        {"cosh", FnMath1::Cosh},       {"degrees", FnMath1::Degrees}, {"exp", FnMath1::Exp}, {"floor", FnMath1::Floor},
        {"int", FnMath1::Int},         {"ln", FnMath1::Ln},       {"log", FnMath1::Log},     {"radians", FnMath1::Radians},
        {"sin", FnMath1::Sin},         {"sinh", FnMath1::Sinh},   {"sqrt", FnMath1::Sqrt},   {"sqr", FnMath1::Sqr},
        {"tan", FnMath1::Tan},         {"tanh", FnMath1::Tanh}};
    return names;
}

const std::map<std::string, FnMath2>& functionMath2Words() {
    static const std::map<std::string, FnMath2> names = {{"pow", FnMath2::Pow}, {"atan2", FnMath2::Atan2},
                                                         {"mod", FnMath2::Mod}, {"div", FnMath2::Div},
                                                         {"min", FnMath2::Min}, {"max", FnMath2::Max}};
    return names;
}

namespace {

const std::map<std::string, FnMath1>& math1Names() { return functionMath1Words(); }
const std::map<std::string, FnMath2>& math2Names() { return functionMath2Words(); }

// Channels of a colour: .red .green .blue .filter .transmit .gray (and x y z t u v).
int channelNamed(const std::string& m) {
    if (m == "x" || m == "u" || m == "red") return 0;
    if (m == "y" || m == "v" || m == "green") return 1;
    if (m == "z" || m == "blue") return 2;
    if (m == "t" || m == "filter") return 3;
    if (m == "transmit") return 4;
    if (m == "gray" || m == "grey") return 5;
    return -1;
}

// Names that are constants at the time the function is read.
bool isConstantWord(const std::string& w) {
    static const std::set<std::string> words = {
        "pi", "tau", "true", "false", "yes", "no", "on", "off", "clock", "clock_delta", "clock_on", "frame_number",
        "initial_frame", "final_frame", "initial_clock", "final_clock", "image_width", "image_height", "version"};
    return words.count(w) > 0;
}

// Builds one function's code, tracking the stack's depth.
class FunctionCompiler {
public:
    FunctionCompiler(Evaluator& e, Function& f, const std::string& declaring) : e_(e), f_(f), declaring_(declaring) {}

    void expression() {
        Evaluator::DepthGuard guard(e_, e_.peek().loc);
        binary(1);
        if (!e_.peekOperator().is("?")) return;
        e_.next();
        expression();
        e_.expectSymbol(":", "in a ?: expression");
        expression();
        emit({FnOp::Cond}, -2);
    }

    void emit(FnInstr i, int stackChange) {
        f_.code.push_back(i);
        depth_ += stackChange;
        f_.stackSize = std::max(f_.stackSize, depth_);
    }
    // Before an instruction that pushes: room for it.
    void push(FnInstr i) { emit(i, 1); }

private:
    void binary(int level) {
        if (level == 6) return unary();
        binary(level + 1);
        for (;;) {
            const Token op = e_.peekOperator();
            FnOp code{};
            if (op.kind != TokenKind::Symbol || !levelOp(level, op.text, code)) return;
            e_.next();
            binary(level + 1);
            emit({code}, -1);
        }
    }

    static bool levelOp(int level, const std::string& s, FnOp& code) {
        static const std::map<std::string, std::pair<int, FnOp>> ops = {
            {"|", {1, FnOp::Or}},  {"&", {2, FnOp::And}}, {"<", {3, FnOp::Lt}},  {"<=", {3, FnOp::Le}},
            {"=", {3, FnOp::Eq}},  {"!=", {3, FnOp::Ne}}, {">=", {3, FnOp::Ge}}, {">", {3, FnOp::Gt}},
            {"+", {4, FnOp::Add}}, {"-", {4, FnOp::Sub}}, {"*", {5, FnOp::Mul}}, {"/", {5, FnOp::Div}}};
        const auto it = ops.find(s);
        if (it == ops.end() || it->second.first != level) return false;
        code = it->second.second;
        return true;
    }

    void unary() {
        const Token t = e_.peek();
        if (t.is("-") || t.is("+") || t.is("!")) {
            e_.next();
            Evaluator::DepthGuard guard(e_, t.loc);
            unary();
            if (t.is("-") && f_.code.back().op == FnOp::Const) f_.code.back().value = -f_.code.back().value; // -2: one constant
            else if (t.is("-")) emit({FnOp::Neg}, 0);
            else if (t.is("!")) emit({FnOp::Not}, 0);
            return;
        }
        primary();
    }

    // "(" expression { "," expression } ")": the number of arguments read.
    int arguments(const std::string& of) {
        e_.expectSymbol("(", "after '", of, "'");
        int n = 0;
        if (e_.acceptSymbol(")")) return 0;
        const bool saved = e_.inVector_;
        e_.inVector_ = false;
        do {
            expression();
            ++n;
        } while (e_.acceptSymbol(","));
        e_.inVector_ = saved;
        e_.expectSymbol(")", "to close the arguments of '", of, "'");
        return n;
    }

    void checkCount(const Token& name, int got, int want) {
        if (got != want)
            e_.fail(name.loc, fmt::format("'{}' takes {} argument{}, got {}", name.text, want, want == 1 ? "" : "s", got));
    }

    // An optional ".channel" after a call of a colour function.
    int channelSuffix() {
        if (!e_.peekOperator().is(".")) return 0;
        e_.next();
        const Token member = e_.expectWord("a channel name after '.'");
        const int c = channelNamed(member.text);
        if (c < 0) e_.fail(member.loc, "unknown channel '." + member.text + "' (use .red .green .blue .filter .transmit .gray)");
        return c;
    }

    // An optional ".x" (.y .z .t .u .v) after a call of a spline: its component.
    int componentSuffix(int terms) {
        if (!e_.peekOperator().is(".")) return 0;
        e_.next();
        const Token member = e_.expectWord("a component name after '.'");
        const std::string& m = member.text;
        const int c = m == "x" || m == "u" ? 0 : m == "y" || m == "v" ? 1 : m == "z" ? 2 : m == "t" ? 3 : -1;
        if (c < 0) e_.fail(member.loc, "unknown component '." + m + "' of a spline (use .x .y .z .t .u .v)");
        if (c >= terms) e_.fail(member.loc, fmt::format("'.{}' of a {}-component spline", m, terms));
        return c;
    }

    void call(const Token& name, const std::shared_ptr<const Function>& callee) {
        const int n = arguments(name.text);
        if (!callee->anyArity) checkCount(name, n, int(callee->params.size()));
        const int channel = callee->colour   ? channelSuffix()
                            : callee->vector ? componentSuffix(callee->splines.empty() ? 3 : callee->splines.at(0)->terms)
                                             : 0;
        size_t index = 0;
        while (index < f_.callees.size() && f_.callees[index] != callee) ++index;
        if (index == f_.callees.size()) f_.callees.push_back(callee);
        emit({FnOp::Call, uint8_t(n), uint8_t(channel), uint16_t(index)}, 1 - n);
        calleeStack_ = std::max(calleeStack_, callee->totalStack);
    }

    // `pattern { ... } (a, b, c)` or `pigment { ... } (a, b, c) [.channel]`.
    void inlinePattern(const Token& keyword) {
        const bool colour = keyword.text == "pigment";
        auto pattern = std::make_shared<const Pigment>(e_.functionPattern(keyword));
        const int n = arguments(keyword.text);
        checkCount(keyword, n, 3);
        const int channel = colour ? channelSuffix() : 0;
        f_.patterns.push_back(pattern);
        emit({colour ? FnOp::Colour : FnOp::Pattern, 3, uint8_t(channel), uint16_t(f_.patterns.size() - 1)}, -2);
    }

    // `spline { ... } (t) [.component]`: a spline's component at t.
    void inlineSpline(const Token& keyword) {
        auto spline = e_.splineBlock(keyword.loc);
        checkCount(keyword, arguments(keyword.text), 1);
        const int component = componentSuffix(spline->terms);
        f_.splines.push_back(std::move(spline));
        emit({FnOp::Spline, 1, uint8_t(component), uint16_t(f_.splines.size() - 1)}, 0);
    }

    void primary() {
        const Token t = e_.next();
        if (t.kind == TokenKind::Number) return push({FnOp::Const, 0, 0, 0, t.number});
        if (t.is("(")) {
            const bool saved = e_.inVector_;
            e_.inVector_ = false;
            expression();
            e_.inVector_ = saved;
            e_.expectSymbol(")", "to close '('");
            return;
        }
        if (t.kind != TokenKind::Word) e_.failExpected(t, "a number, a parameter or a function in the function");
        const std::string& w = t.text;
        for (size_t i = 0; i < f_.params.size(); ++i)
            if (f_.params[i] == w) return push({FnOp::Param, 0, 0, uint16_t(i)});
        if (defaultParams_ && (w == "u" || w == "v")) return push({FnOp::Param, 0, 0, uint16_t(w == "u" ? 0 : 1)});
        if (w == declaring_ && !e_.lookup(w))
            e_.fail(t.loc, "function '" + w + "' calls itself: a function can only call functions declared before it");
        if (const Cell c = e_.useIndexed(t)) {
            if (c->kind == Kind::Function) return call(t, c->function);
            if (c->kind == Kind::Float) return push({FnOp::Const, 0, 0, 0, c->number});
            if ((c->kind == Kind::Vector || c->kind == Kind::Color) && e_.peekOperator().is(".")) {
                const Value v = e_.postfix(*c, t.loc);
                if (v.kind == Kind::Float) return push({FnOp::Const, 0, 0, 0, v.number});
            }
            e_.fail(t.loc, "'" + w + "' is " + kindName(*c) + "; a function takes numbers and functions only");
        }
        if (w == "pattern" || w == "pigment") return inlinePattern(t);
        if (w == "spline") return inlineSpline(t);
        if (const auto it = math1Names().find(w); it != math1Names().end()) {
            checkCount(t, arguments(w), 1);
            return emit({FnOp::Math1, 1, 0, uint16_t(it->second)}, 0);
        }
        if (w == "atan") { // atan(a) or atan(a, b)
            const int n = arguments(w);
            if (n != 1 && n != 2) e_.fail(t.loc, fmt::format("'atan' takes 1 or 2 arguments, got {}", n));
            if (n == 1) emit({FnOp::Math1, 1, 0, uint16_t(FnMath1::Atan)}, 0);
            else emit({FnOp::Math2, 2, 0, uint16_t(FnMath2::Atan2)}, -1);
            return;
        }
        if (const auto it = math2Names().find(w); it != math2Names().end()) {
            const int n = arguments(w);
            const bool variadic = it->second == FnMath2::Min || it->second == FnMath2::Max;
            if (variadic ? n < 2 : n != 2)
                e_.fail(t.loc, fmt::format("'{}' takes {} arguments, got {}", w, variadic ? "at least 2" : "2", n));
            for (int i = 1; i < n; ++i) emit({FnOp::Math2, 2, 0, uint16_t(it->second)}, -1);
            return;
        }
        if (w == "select") {
            const int n = arguments(w);
            if (n != 3 && n != 4) e_.fail(t.loc, fmt::format("'select' takes 3 or 4 arguments, got {}", n));
            return emit({FnOp::Select, uint8_t(n)}, 1 - n);
        }
        if (const int number = internalNamed(w); number >= 0) {
            const int n = arguments(w);
            checkCount(t, n, internalArity(number));
            return emit({FnOp::Internal, uint8_t(n), 0, uint16_t(number)}, 1 - n);
        }
        if (Value v; isConstantWord(w) && e_.builtin(t, v) && v.kind == Kind::Float)
            return push({FnOp::Const, 0, 0, 0, v.number});
        if (w == "x" || w == "y" || w == "z")
            e_.fail(t.loc, "'" + w + "' is not a parameter of this function (its parameters are " + paramList() + ")");
        std::vector<std::string> known = f_.params;
        for (const auto& [name, f] : math1Names()) known.push_back(name);
        for (const auto& [name, f] : math2Names()) known.push_back(name);
        for (const std::string& n : e_.declaredNames({Kind::Function, Kind::Float})) known.push_back(n);
        e_.failUnknownIn(t, known, "function or parameter");
    }

    std::string paramList() const {
        std::string s;
        for (const std::string& p : f_.params) s += (s.empty() ? "" : ", ") + p;
        return s;
    }

public:
    bool defaultParams_ = true;
    int calleeStack_ = 0;

private:
    Evaluator& e_;
    Function& f_;
    const std::string& declaring_;
    int depth_ = 0;
};

} // namespace

Pigment Evaluator::functionPattern(const Token& keyword) {
    if (keyword.text == "pigment") return pigment(Pigment{});
    // `pattern { PATTERN modifiers }`: the pattern's value, no colours.
    expectSymbol("{", "after 'pattern'");
    BlockScope scope(*this, "pattern", keyword.loc);
    Pigment p = pigmentBody(Pigment{}, "}", "'}' in pattern");
    return p;
}

// POV-Ray's pigment_pattern: the pattern's value at a point is the grey of
// the pigment there, 0.297 red + 0.589 green + 0.114 blue, its filter and
// transmit left out (both measured against POV-Ray 3.7). It is the function
// `function { (pigment { ... }(x, y, z).gray) }`, which is how it is written
// back in .drt.
std::shared_ptr<const Function> Evaluator::pigmentPatternFunction(const Token& keyword) {
    DepthGuard guard(*this, keyword.loc);
    expectSymbol("{", "after 'pigment_pattern'");
    BlockScope scope(*this, "pigment_pattern", keyword.loc);
    auto f = std::make_shared<Function>();
    f->params = {"x", "y", "z"};
    f->patterns.push_back(std::make_shared<const Pigment>(pigmentBody(Pigment{}, "}", "'}' in pigment_pattern")));
    for (uint16_t i = 0; i < 3; ++i) f->code.push_back({FnOp::Param, 0, 0, i});
    f->code.push_back({FnOp::Colour, 3, uint8_t(channelNamed("gray")), 0});
    f->stackSize = f->totalStack = 3;
    return f;
}

std::shared_ptr<const Function> Evaluator::functionBody(const Token& keyword) {
    DepthGuard guard(*this, keyword.loc);
    auto f = std::make_shared<Function>();
    bool defaultParams = true;
    if (acceptSymbol("(")) {
        defaultParams = false;
        if (!peek().is(")")) {
            do {
                noExpand_ = true;
                const Token p = next();
                noExpand_ = false;
                if (p.kind != TokenKind::Word) failExpected(p, "a parameter name");
                if (std::find(f->params.begin(), f->params.end(), p.text) != f->params.end())
                    fail(p.loc, "parameter '" + p.text + "' is named twice");
                f->params.push_back(p.text);
            } while (acceptSymbol(","));
        }
        expectSymbol(")", "after the function's parameters");
    } else {
        f->params = {"x", "y", "z"};
    }
    const Token open = expectSymbol("{", "to open the function's body");
    BlockScope scope(*this, "function", keyword.loc);
    FunctionCompiler compiler(*this, *f, declaringName_);
    compiler.defaultParams_ = defaultParams;
    const Token first = peek();
    if (first.isWord("pattern") || first.isWord("pigment")) {
        next();
        const Token after = peek();
        if (after.is("{")) {
            f->colour = first.text == "pigment";
            f->patterns.push_back(std::make_shared<const Pigment>(functionPattern(first)));
            if (f->params.size() < 3) fail(first.loc, "a pattern or pigment function needs 3 parameters (x, y, z)");
            for (uint16_t i = 0; i < 3; ++i) compiler.push({FnOp::Param, 0, 0, i});
            compiler.emit({f->colour ? FnOp::Colour : FnOp::Pattern, 3, 0, 0}, -2);
            if (peek().is("("))
                fail(peek().loc, "a body that starts with '" + first.text + " { }' is that " + first.text +
                                     "; to call it at a point, write (" + first.text + " { ... }(a, b, c))");
            expectSymbol("}", "to close the function's body");
            f->totalStack = f->stackSize;
            return f;
        }
        pushBack(first);
    }
    if (first.isWord("spline")) { // function { spline { ... } }: a vector function of one parameter
        next();
        f->vector = true;
        f->splines.push_back(splineBlock(first.loc));
        if (peek().is("("))
            fail(peek().loc, "a body that starts with 'spline { }' is that spline; to call it at a point, write "
                             "(spline { ... }(t))");
        if (defaultParams) f->params = {"t"};
        if (f->params.size() != 1) fail(first.loc, "a spline function has one parameter");
        compiler.push({FnOp::Param, 0, 0, 0});
        compiler.emit({FnOp::Spline, 1, 0, 0}, 0);
        expectSymbol("}", "to close the function's body");
        f->totalStack = f->stackSize;
        return f;
    }
    if (first.isWord("transform")) { // function { transform { ... } }: a vector function of x, y, z
        next();
        f->vector = true;
        f->transforms.push_back(transformBlock());
        if (f->params.size() != 3) fail(first.loc, "a transform function has three parameters (x, y, z)");
        for (uint16_t i = 0; i < 3; ++i) compiler.push({FnOp::Param, 0, 0, i});
        compiler.emit({FnOp::Transform, 3, 0, 0}, -2);
        expectSymbol("}", "to close the function's body");
        f->totalStack = f->stackSize;
        return f;
    }
    if (first.isWord("internal")) {
        next();
        expectSymbol("(", "after 'internal'");
        const SourceLoc at = peek().loc;
        const int number = countExpr("the internal function's number", 0, 1000);
        expectSymbol(")", "after the internal function's number");
        const int arity = internalArity(number);
        if (arity < 0) {
            // functions.inc declares all of them; only a use is an error.
            unsupported("internal-function", at,
                        fmt::format("internal function {} is not supported; it gives 0", number));
            f->params = {"x", "y", "z"};
            f->anyArity = true;
            compiler.push({FnOp::Const});
            f->totalStack = f->stackSize;
        }
        expectSymbol("}", "to close the function's body");
        return arity < 0 ? f : internalFunction(number);
    }
    compiler.expression();
    expectSymbol("}", "to close the function's body");
    f->totalStack = f->stackSize + compiler.calleeStack_;
    if (f->totalStack > kFunctionTotalStackLimit)
        fail(open.loc, fmt::format("the function is too deep to evaluate: it needs {} stack slots, at most {}",
                                   f->totalStack, kFunctionTotalStackLimit));
    return f;
}

std::shared_ptr<const Function> Evaluator::patternFunction(const Token& keyword) {
    std::shared_ptr<const Function> f = functionBody(keyword);
    if (f->params.size() != 3 && !f->anyArity)
        fail(keyword.loc, fmt::format("a function pattern needs a function of 3 parameters (x, y, z), this one has {}",
                                      f->params.size()));
    return f;
}

std::shared_ptr<const Function> internalFunction(int number) {
    auto f = std::make_shared<Function>();
    const int arity = internalArity(number);
    f->params = {"x", "y", "z"};
    for (int i = 3; i < arity; ++i) f->params.push_back(fmt::format("P{}", i - 3));
    for (int i = 0; i < arity; ++i) f->code.push_back({FnOp::Param, 0, 0, uint16_t(i)});
    f->code.push_back({FnOp::Internal, uint8_t(arity), 0, uint16_t(number)});
    f->stackSize = f->totalStack = arity;
    return f;
}

Value Evaluator::callFunction(const Token& name, const Function& f) {
    expectSymbol("(", "after the function '", name.text, "'");
    std::vector<double> args;
    if (!peek().is(")")) {
        const bool saved = inVector_;
        inVector_ = false;
        do {
            args.push_back(floatExpr("a number (an argument of a function)"));
        } while (acceptSymbol(","));
        inVector_ = saved;
    }
    expectSymbol(")", "to close the arguments of '", name.text, "'");
    if (args.size() != f.params.size() && !f.anyArity)
        fail(name.loc, fmt::format("'{}' takes {} argument{}, got {}", name.text, f.params.size(),
                                   f.params.size() == 1 ? "" : "s", args.size()));
    if (f.colour) {
        std::array<double, 5> c{};
        for (int i = 0; i < 5; ++i) c[size_t(i)] = f(args.data(), i);
        return Value::makeColor(c);
    }
    if (f.vector) { // a spline or transform function
        Value v;
        v.kind = Value::Kind::Vector;
        v.size = f.splines.empty() ? 3 : f.splines.at(0)->terms;
        for (int i = 0; i < 5; ++i) v.v[size_t(i)] = f(args.data(), i);
        return v;
    }
    return Value::makeFloat(f(args.data()));
}

} // namespace drt::lang

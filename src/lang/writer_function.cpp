#include "lang/writer_function.h"

#include "lang/writer_detail.h"
#include "scene/scene.h"

#include <vector>

namespace drt::writer {

namespace {

template <class Enum> std::string nameOf(const std::map<std::string, Enum>& words, uint16_t index) {
    for (const auto& [name, value] : words)
        if (uint16_t(value) == index) return name;
    return "?";
}

const char* channelName(int channel) {
    static const char* names[] = {"red", "green", "blue", "filter", "transmit", "gray"};
    return channel >= 0 && channel < 6 ? names[channel] : "red";
}

std::string operatorText(FnOp op) {
    switch (op) {
    case FnOp::Add: return "+";
    case FnOp::Sub: return "-";
    case FnOp::Mul: return "*";
    case FnOp::Div: return "/";
    case FnOp::Lt: return "<";
    case FnOp::Le: return "<=";
    case FnOp::Eq: return "=";
    case FnOp::Ne: return "!=";
    case FnOp::Ge: return ">=";
    case FnOp::Gt: return ">";
    case FnOp::And: return "&";
    case FnOp::Or: return "|";
    default: return "?";
    }
}

std::string joined(const std::vector<std::string>& items) {
    std::string s;
    for (const std::string& item : items) s += (s.empty() ? "" : ", ") + item;
    return s;
}

// spline { kind t, <v>, ... } with the spline's components.
std::string splineText(const Spline& s) {
    std::string text = "spline { ";
    text += splineKindWord(s.kind);
    for (const Spline::Entry& e : s.entries) {
        // Appended piece by piece: gcc 12 warns (-Wrestrict, a false positive) on "literal" + a temporary string.
        text += " ";
        text += number(e.t);
        text += ", <";
        for (int k = 0; k < s.terms; ++k) {
            if (k) text += ", ";
            text += number(e.v[size_t(k)]);
        }
        text += ">";
    }
    return text + " }";
}

const char* componentName(int c) {
    static const char* names[] = {"x", "y", "z", "t"};
    return c >= 0 && c < 4 ? names[c] : "x";
}

// The expression of `f` with its parameters replaced by `args`.
std::string expressionText(const Function& f, const std::vector<std::string>& args, int channel,
                           std::set<std::string>& problems) {
    std::vector<std::string> stack;
    auto pop = [&](size_t n) {
        std::vector<std::string> items(stack.end() - long(n), stack.end());
        stack.resize(stack.size() - n);
        return items;
    };
    for (const FnInstr& i : f.code) {
        switch (i.op) {
        case FnOp::Const: {
            const std::string n = number(i.value);
            stack.push_back(i.value < 0 || n[0] == '-' ? "(" + n + ")" : n);
            break;
        }
        case FnOp::Param: stack.push_back(args[i.index]); break;
        case FnOp::Neg: stack.back() = "(-" + stack.back() + ")"; break;
        case FnOp::Not: stack.back() = "(!" + stack.back() + ")"; break;
        case FnOp::Cond: {
            const auto a = pop(3);
            stack.push_back("(" + a[0] + " ? " + a[1] + " : " + a[2] + ")");
            break;
        }
        case FnOp::Math1:
            stack.back() = nameOf(lang::functionMath1Words(), i.index) + "(" + stack.back() + ")";
            break;
        case FnOp::Math2: {
            const auto a = pop(2);
            stack.push_back(nameOf(lang::functionMath2Words(), i.index) + "(" + a[0] + ", " + a[1] + ")");
            break;
        }
        case FnOp::Select: stack.push_back("select(" + joined(pop(i.count)) + ")"); break;
        case FnOp::Internal: stack.push_back(std::string(internalName(i.index)) + "(" + joined(pop(i.count)) + ")"); break;
        case FnOp::Call: {
            const Function& callee = *f.callees[i.index];
            std::vector<std::string> a = pop(i.count);
            if (callee.anyArity) {
                problems.insert("an internal function drt lacks");
                stack.push_back("0");
                break;
            }
            // The callee's text is one primary or one parenthesised operation: no parentheses needed.
            stack.push_back(expressionText(callee, a, i.channel, problems));
            break;
        }
        case FnOp::Pattern:
        case FnOp::Colour: {
            const auto a = pop(3);
            bool exact = true;
            const Pigment& p = *f.patterns[i.index];
            std::string body = pigmentBody(p, {}, exact, problems);
            if (!exact) problems.insert("a function pattern's transform");
            // In parentheses: a body that starts with `pattern {` is a pattern function.
            if (i.op == FnOp::Pattern) {
                stack.push_back("(pattern {" + body + " }(" + joined(a) + "))");
            } else {
                // A colour function's body takes the call's channel; a pigment in an expression its own.
                const int c = f.colour ? channel : i.channel;
                stack.push_back("(pigment {" + body + " }(" + joined(a) + ")." + channelName(c) + ")");
            }
            break;
        }
        case FnOp::Transform: {
            const auto a = pop(3);
            const int c = f.vector ? channel : i.channel;
            problems.insert("a transform function inside an expression (its x, y, z kept)");
            stack.push_back(a[size_t(c >= 0 && c < 3 ? c : 0)]);
            break;
        }
        case FnOp::Spline: {
            // A spline function's body takes the call's component; a spline inside an expression its own.
            const int c = f.vector ? channel : i.channel;
            if (c > 3) problems.insert("a spline's fifth component");
            std::string text = "("; // appended piece by piece, as in splineText
            text += splineText(*f.splines[i.index]);
            text += "(";
            text += stack.back();
            text += ").";
            text += componentName(c);
            text += ")";
            stack.back() = std::move(text);
            break;
        }
        default: {
            const auto a = pop(2);
            stack.push_back("(" + a[0] + " " + operatorText(i.op) + " " + a[1] + ")");
        }
        }
    }
    return stack.empty() ? "0" : stack.back();
}

} // namespace

std::string functionText(const Function& f, std::set<std::string>& problems) {
    if (f.anyArity) {
        problems.insert("an internal function drt lacks");
        return "0";
    }
    if (f.vector && f.code.size() == 2 && f.code.back().op == FnOp::Spline) return splineText(*f.splines[0]);
    if (f.vector && f.code.size() == 4 && f.code.back().op == FnOp::Transform)
        return "transform {" + formatSteps(decompose(f.transforms[0])) + " }";
    const bool wholeBody = f.code.size() == 4 && f.params.size() == 3 && f.code[0].op == FnOp::Param &&
                           f.code[0].index == 0 && f.code[1].index == 1 && f.code[2].index == 2;
    if (wholeBody && (f.colour ? f.code.back().op == FnOp::Colour : f.code.back().op == FnOp::Pattern)) {
        // function { pigment { ... } } or function { pattern { ... } }
        bool exact = true;
        std::string body = std::string(f.code.back().op == FnOp::Colour ? "pigment {" : "pattern {") +
                           pigmentBody(*f.patterns[0], {}, exact, problems) + " }";
        if (!exact) problems.insert("a function pattern's transform");
        return body;
    }
    return expressionText(f, f.params, 0, problems);
}

std::string functionHead(const Function& f) {
    if (f.params == std::vector<std::string>{"x", "y", "z"}) return "function ";
    return "function(" + joined(f.params) + ") ";
}

} // namespace drt::writer

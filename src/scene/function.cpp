#include "scene/function.h"

#include "scene/scene.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

namespace drt {

namespace {

FunctionHooks gHooks;

struct InternalInfo {
    int number;
    const char* name;
    int arity;
};
constexpr InternalInfo kInternals[] = {
    {47, "f_ph", 3},           {57, "f_r", 3},      {60, "f_rounded_box", 7}, {61, "f_sphere", 4},
    {68, "f_superellipsoid", 5}, {69, "f_th", 3},   {70, "f_torus", 5},       {76, "f_noise3d", 3},
    {78, "f_noise_generator", 4},
};

const InternalInfo* internalInfo(int number) {
    for (const InternalInfo& i : kInternals)
        if (i.number == number) return &i;
    return nullptr;
}

double noiseAt(const Vec3& p) { return gHooks.noise ? gHooks.noise(p) : 0.5; }

double internal(FnInternal f, const double* a) {
    const double x = a[0], y = a[1], z = a[2];
    switch (f) {
    case FnInternal::Ph: {
        const double r = std::sqrt(x * x + y * y + z * z);
        return r > 0 ? std::acos(std::clamp(y / r, -1.0, 1.0)) : 0.0;
    }
    case FnInternal::R: return std::sqrt(x * x + y * y + z * z);
    case FnInternal::RoundedBox: {
        // The distance outside a box of half-sizes a[4..6] whose edges are
        // rounded by radius a[3] (POV-Ray's values are 1e-6 lower).
        const double r = a[3];
        const double qx = std::max(std::fabs(x) - (a[4] - r), 0.0), qy = std::max(std::fabs(y) - (a[5] - r), 0.0),
                     qz = std::max(std::fabs(z) - (a[6] - r), 0.0);
        return std::sqrt(qx * qx + qy * qy + qz * qz) - r - 1e-6;
    }
    case FnInternal::Sphere: return std::sqrt(x * x + y * y + z * z) - a[3];
    case FnInternal::Superellipsoid: {
        const double e = a[3], n = a[4];
        const double xy = std::pow(std::fabs(x), 2 / e) + std::pow(std::fabs(y), 2 / e);
        return 1 - std::pow(std::pow(xy, e / n) + std::pow(std::fabs(z), 2 / n), n / 2);
    }
    case FnInternal::Th: return std::atan2(x, z);
    case FnInternal::Torus: {
        const double ring = std::sqrt(x * x + z * z) - a[3];
        return std::sqrt(ring * ring + y * y) - a[4];
    }
    case FnInternal::Noise3d:
    case FnInternal::NoiseGenerator: return noiseAt(Vec3(x, y, z));
    }
    return 0;
}

double math1(FnMath1 f, double a) {
    switch (f) {
    case FnMath1::Abs: return std::fabs(a);
    case FnMath1::Acos: return std::acos(a);
    case FnMath1::Acosh: return std::acosh(a);
    case FnMath1::Asin: return std::asin(a);
    case FnMath1::Asinh: return std::asinh(a);
    case FnMath1::Atan: return std::atan(a);
    case FnMath1::Atanh: return std::atanh(a);
    case FnMath1::Ceil: return std::ceil(a);
    case FnMath1::Cos: return std::cos(a);
    case FnMath1::Cosh: return std::cosh(a);
    case FnMath1::Degrees: return a * 180.0 / kPi;
    case FnMath1::Exp: return std::exp(a);
    case FnMath1::Floor: return std::floor(a);
    case FnMath1::Int: return std::trunc(a);
    case FnMath1::Ln: return std::log(a);
    case FnMath1::Log: return std::log10(a);
    case FnMath1::Radians: return a * kPi / 180.0;
    case FnMath1::Sin: return std::sin(a);
    case FnMath1::Sinh: return std::sinh(a);
    case FnMath1::Sqrt: return std::sqrt(a);
    case FnMath1::Sqr: return a * a;
    case FnMath1::Tan: return std::tan(a);
    case FnMath1::Tanh: return std::tanh(a);
    }
    return 0;
}

double math2(FnMath2 f, double a, double b) {
    switch (f) {
    case FnMath2::Pow: return std::pow(a, b);
    case FnMath2::Atan2: return std::atan2(a, b);
    case FnMath2::Mod: return std::fmod(a, b);
    case FnMath2::Div: return std::trunc(a / b);
    case FnMath2::Min: return std::min(a, b);
    case FnMath2::Max: return std::max(a, b);
    }
    return 0;
}

double finiteOrZero(double v) {
    if (std::isnan(v)) return 0;
    return std::clamp(v, -1e300, 1e300);
}

// The operations beyond arithmetic, as both evaluators do them (run: the stack
// program; runCompiled), from the instruction's operands a(0), a(1), ...
// Eq and Ne: within 1e-10 of each other, and beyond it (with a NaN, neither).
bool nearlyEqual(double a, double b) { return std::fabs(a - b) <= 1e-10; }
bool clearlyDiffer(double a, double b) { return std::fabs(a - b) > 1e-10; }

template <class Operand>
double selectValue(const FnInstr& i, const Operand& a) {
    return a(0) < 0 ? a(1) : (i.count == 3 || a(0) == 0) ? a(2) : a(3);
}

// Pattern and Colour: a colour function's body takes the call's channel; a
// pigment inside an expression its own.
template <class Operand>
double patternValue(const Function& f, const FnInstr& i, int channel, const Operand& a) {
    const Vec3 p(a(0), a(1), a(2));
    const Pigment& pattern = *f.patterns[i.index];
    if (i.op == FnOp::Pattern) return gHooks.pattern ? gHooks.pattern(pattern, p) : 0.0;
    return gHooks.colour ? gHooks.colour(pattern, p, f.colour ? channel : i.channel) : 0.0;
}

template <class Operand>
double transformValue(const Function& f, const FnInstr& i, int channel, const Operand& a) {
    const int c = f.vector ? channel : i.channel;
    return f.transforms[i.index].point(Vec3(a(0), a(1), a(2)))[c >= 0 && c < 3 ? c : 0];
}

double splineValue(const Function& f, const FnInstr& i, int channel, double t) {
    const int c = f.vector ? channel : i.channel;
    return f.splines[i.index]->at(t)[size_t(c >= 0 && c < 5 ? c : 0)];
}

// Runs `f` with its stack at `stack` (callees use the part above it).
double run(const Function& f, const double* args, int channel, double* stack) {
    double* top = stack; // one past the last value
    for (const FnInstr& i : f.code) {
        switch (i.op) {
        case FnOp::Const: *top++ = i.value; break;
        case FnOp::Param: *top++ = args[i.index]; break;
        case FnOp::Neg: top[-1] = -top[-1]; break;
        case FnOp::Not: top[-1] = top[-1] == 0 ? 1 : 0; break;
        case FnOp::Math1: top[-1] = math1(FnMath1(i.index), top[-1]); break;
        case FnOp::Math2:
            --top;
            top[-1] = math2(FnMath2(i.index), top[-1], top[0]);
            break;
        case FnOp::Cond:
            top -= 2;
            top[-1] = top[-1] != 0 ? top[0] : top[1];
            break;
        case FnOp::Select: {
            top -= i.count;
            const double* in = top;
            top[0] = selectValue(i, [in](int n) { return in[n]; });
            ++top;
            break;
        }
        case FnOp::Call: {
            top -= i.count;
            const Function& callee = *f.callees[i.index];
            top[0] = run(callee, top, i.channel, top + i.count);
            ++top;
            break;
        }
        case FnOp::Internal:
            top -= i.count;
            top[0] = internal(FnInternal(i.index), top);
            ++top;
            break;
        case FnOp::Pattern:
        case FnOp::Colour:
        case FnOp::Transform: {
            top -= 3;
            const double* in = top;
            const auto a = [in](int n) { return in[n]; };
            top[0] = i.op == FnOp::Transform ? transformValue(f, i, channel, a) : patternValue(f, i, channel, a);
            ++top;
            break;
        }
        case FnOp::Spline: top[-1] = splineValue(f, i, channel, top[-1]); break;
        // Binary operators: a b -> a op b.
        case FnOp::Add: --top, top[-1] = top[-1] + top[0]; break;
        case FnOp::Sub: --top, top[-1] = top[-1] - top[0]; break;
        case FnOp::Mul: --top, top[-1] = top[-1] * top[0]; break;
        case FnOp::Div: --top, top[-1] = top[-1] / top[0]; break;
        case FnOp::Lt: --top, top[-1] = top[-1] < top[0]; break;
        case FnOp::Le: --top, top[-1] = top[-1] <= top[0]; break;
        case FnOp::Eq: --top, top[-1] = nearlyEqual(top[-1], top[0]); break;
        case FnOp::Ne: --top, top[-1] = clearlyDiffer(top[-1], top[0]); break;
        case FnOp::Ge: --top, top[-1] = top[-1] >= top[0]; break;
        case FnOp::Gt: --top, top[-1] = top[-1] > top[0]; break;
        case FnOp::And: --top, top[-1] = top[-1] != 0 && top[0] != 0; break;
        case FnOp::Or: --top, top[-1] = top[-1] != 0 || top[0] != 0; break;
        }
    }
    return top > stack ? finiteOrZero(top[-1]) : 0.0;
}

} // namespace

int internalArity(int number) {
    const InternalInfo* i = internalInfo(number);
    return i ? i->arity : -1;
}

const char* internalName(int number) {
    const InternalInfo* i = internalInfo(number);
    return i ? i->name : "";
}

int internalNamed(const std::string& name) {
    for (const InternalInfo& i : kInternals)
        if (name == i.name) return i.number;
    return -1;
}

// ---------------------------------------------------------------- compiled programs

// A function's program as a list of its distinct subexpressions, each one's
// operands before it: every value `code` computes, computed once into a slot of
// its own. The operations, and the values they are given, are those of the
// stack program, so every value is the same double.
struct CompiledFunction {
    std::vector<FnInstr> steps;
    std::vector<int> operandStart; // step k's operand slots: operands[operandStart[k] .. operandStart[k + 1])
    std::vector<int> operands;
    int result = -1;      // the slot of the value; -1: an empty program, whose value is 0
    int slots = 0;        // steps.size()
    int need = 0;         // slots plus the most that a callee's evaluation needs
    bool usable = false;  // else the stack program runs (few repeats, a short stack, a call of another count, too deep)
    size_t codeSize = 0;  // code.size() when made: a function changed since runs its stack program
};

namespace {

// How many values an instruction takes from the stack (it always leaves one).
int operandCount(const FnInstr& i) {
    switch (i.op) {
    case FnOp::Const:
    case FnOp::Param: return 0;
    case FnOp::Neg:
    case FnOp::Not:
    case FnOp::Math1:
    case FnOp::Spline: return 1;
    case FnOp::Cond:
    case FnOp::Pattern:
    case FnOp::Colour:
    case FnOp::Transform: return 3;
    case FnOp::Select:
    case FnOp::Call:
    case FnOp::Internal: return i.count;
    default: return 2; // Math2 and the binary operators
    }
}

// The slots a function's evaluation needs: compiled, or as a stack program.
int evaluationNeed(const Function& f) {
    const CompiledFunction& c = f.compiled.get(f);
    return c.usable ? c.need : f.totalStack;
}

const CompiledFunction* compile(const Function& f) {
    auto* c = new CompiledFunction;
    c->codeSize = f.code.size();
    std::vector<int> stack;
    std::map<std::vector<uint64_t>, int> seen; // a step and its operands' slots -> its slot
    bool usable = true;
    for (const FnInstr& i : f.code) {
        const int count = operandCount(i);
        if (count > int(stack.size())) {
            usable = false;
            break;
        }
        if (i.op == FnOp::Internal && count != internalArity(i.index)) usable = false;
        if (i.op == FnOp::Call && count != int(f.callees[i.index]->params.size()) && !f.callees[i.index]->anyArity)
            usable = false;
        std::vector<uint64_t> key = {uint64_t(i.op) | uint64_t(i.count) << 8 | uint64_t(i.channel) << 16 |
                                         uint64_t(i.index) << 32,
                                     std::bit_cast<uint64_t>(i.value)};
        key.insert(key.end(), stack.end() - count, stack.end());
        stack.resize(stack.size() - size_t(count));
        const auto [at, added] = seen.try_emplace(std::move(key), c->slots);
        if (added) {
            c->steps.push_back(i);
            c->operandStart.push_back(int(c->operands.size()));
            c->operands.insert(c->operands.end(), at->first.begin() + 2, at->first.end());
            ++c->slots;
        }
        stack.push_back(at->second);
    }
    c->operandStart.push_back(int(c->operands.size()));
    c->result = stack.empty() ? -1 : stack.back();
    c->need = c->slots;
    for (const FnInstr& i : c->steps)
        if (i.op == FnOp::Call) c->need = std::max(c->need, c->slots + evaluationNeed(*f.callees[i.index]));
    // A program of few repeats runs faster on the stack (values in order, no
    // operand lists): the compiled one must save a quarter of the steps.
    c->usable = usable && c->need <= kFunctionTotalStackLimit && 4 * size_t(c->slots) <= 3 * f.code.size();
    return c;
}

double evaluate(const Function& f, const double* args, int channel, double* buffer);

// Runs a compiled program with its slots at `slots` (callees use the part above them).
double runCompiled(const Function& f, const CompiledFunction& c, const double* args, int channel, double* slots) {
    const int* operands = c.operands.data();
    const int* starts = c.operandStart.data();
    for (int k = 0; k < c.slots; ++k) {
        const FnInstr& i = c.steps[size_t(k)];
        const int* in = operands + starts[k];
        const auto a = [&](int n) { return slots[in[n]]; };
        double v = 0;
        switch (i.op) {
        case FnOp::Const: v = i.value; break;
        case FnOp::Param: v = args[i.index]; break;
        case FnOp::Neg: v = -a(0); break;
        case FnOp::Not: v = a(0) == 0 ? 1 : 0; break;
        case FnOp::Math1: v = math1(FnMath1(i.index), a(0)); break;
        case FnOp::Math2: v = math2(FnMath2(i.index), a(0), a(1)); break;
        case FnOp::Cond: v = a(0) != 0 ? a(1) : a(2); break;
        case FnOp::Select: v = selectValue(i, a); break;
        case FnOp::Call:
        case FnOp::Internal: {
            double values[256]; // count is 8 bits
            for (int n = 0; n < i.count; ++n) values[n] = a(n);
            v = i.op == FnOp::Internal ? internal(FnInternal(i.index), values)
                                       : evaluate(*f.callees[i.index], values, i.channel, slots + c.slots);
            break;
        }
        case FnOp::Pattern:
        case FnOp::Colour: v = patternValue(f, i, channel, a); break;
        case FnOp::Transform: v = transformValue(f, i, channel, a); break;
        case FnOp::Spline: v = splineValue(f, i, channel, a(0)); break;
        case FnOp::Add: v = a(0) + a(1); break;
        case FnOp::Sub: v = a(0) - a(1); break;
        case FnOp::Mul: v = a(0) * a(1); break;
        case FnOp::Div: v = a(0) / a(1); break;
        case FnOp::Lt: v = a(0) < a(1); break;
        case FnOp::Le: v = a(0) <= a(1); break;
        case FnOp::Eq: v = nearlyEqual(a(0), a(1)); break;
        case FnOp::Ne: v = clearlyDiffer(a(0), a(1)); break;
        case FnOp::Ge: v = a(0) >= a(1); break;
        case FnOp::Gt: v = a(0) > a(1); break;
        case FnOp::And: v = a(0) != 0 && a(1) != 0; break;
        case FnOp::Or: v = a(0) != 0 || a(1) != 0; break;
        }
        slots[k] = v;
    }
    return c.result >= 0 ? finiteOrZero(slots[c.result]) : 0.0;
}

// The compiled program where it can run, else the stack program; `buffer` holds
// kFunctionTotalStackLimit values less what the callers use.
double evaluate(const Function& f, const double* args, int channel, double* buffer) {
    const CompiledFunction& c = f.compiled.get(f);
    return c.usable ? runCompiled(f, c, args, channel, buffer) : run(f, args, channel, buffer);
}

} // namespace

const CompiledFunction& CompiledFunctionCache::get(const Function& f) const {
    const CompiledFunction* c = program_.load(std::memory_order_acquire);
    if (c && c->codeSize == f.code.size()) return *c;
    if (c) { // changed since: a stale program is never run
        static const CompiledFunction unusable;
        return unusable;
    }
    const CompiledFunction* made = compile(f);
    if (program_.compare_exchange_strong(c, made, std::memory_order_acq_rel)) return *made;
    delete made; // another thread's was kept
    return *c;
}

bool CompiledFunctionCache::runs(const Function& f) const { return get(f).usable; }

void CompiledFunctionCache::reset() { delete program_.exchange(nullptr); }

double Function::operator()(const double* args, int channel) const {
    // The front end keeps every function's totalStack within this, and a
    // compiled program is run only when it needs no more.
    double buffer[kFunctionTotalStackLimit];
    return evaluate(*this, args, channel, buffer);
}

double Function::interpret(const double* args, int channel) const {
    double stack[kFunctionTotalStackLimit];
    return run(*this, args, channel, stack);
}

bool Function::operator==(const Function& o) const {
    if (params != o.params || colour != o.colour || vector != o.vector || code.size() != o.code.size() ||
        callees.size() != o.callees.size() || patterns.size() != o.patterns.size() ||
        splines.size() != o.splines.size() || transforms != o.transforms)
        return false;
    for (size_t i = 0; i < code.size(); ++i) {
        const FnInstr &a = code[i], &b = o.code[i];
        if (a.op != b.op || a.count != b.count || a.channel != b.channel || a.index != b.index ||
            !(a.value == b.value || (std::isnan(a.value) && std::isnan(b.value))))
            return false;
    }
    for (size_t i = 0; i < callees.size(); ++i)
        if (callees[i] != o.callees[i] && !(*callees[i] == *o.callees[i])) return false;
    for (size_t i = 0; i < patterns.size(); ++i)
        if (patterns[i] != o.patterns[i]) return false; // patterns: the same objects
    for (size_t i = 0; i < splines.size(); ++i)
        if (splines[i] != o.splines[i] && !(*splines[i] == *o.splines[i])) return false;
    return true;
}

void setFunctionHooks(const FunctionHooks& hooks) { gHooks = hooks; }

} // namespace drt

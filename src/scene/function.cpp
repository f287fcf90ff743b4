#include "scene/function.h"

#include "scene/scene.h"

#include <algorithm>
#include <cmath>

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
            const double s = top[0];
            top[0] = s < 0 ? top[1] : (i.count == 3 || s == 0) ? top[2] : top[3];
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
        case FnOp::Colour: {
            top -= 3;
            const Vec3 p(top[0], top[1], top[2]);
            const Pigment& pattern = *f.patterns[i.index];
            if (i.op == FnOp::Pattern) top[0] = gHooks.pattern ? gHooks.pattern(pattern, p) : 0.0;
            else // a colour function's body takes the call's channel; a pigment inside an expression its own
                top[0] = gHooks.colour ? gHooks.colour(pattern, p, f.colour ? channel : i.channel) : 0.0;
            ++top;
            break;
        }
        case FnOp::Transform: {
            top -= 3;
            const int c = f.vector ? channel : i.channel;
            top[0] = f.transforms[i.index].point(Vec3(top[0], top[1], top[2]))[c >= 0 && c < 3 ? c : 0];
            ++top;
            break;
        }
        case FnOp::Spline: {
            const int c = f.vector ? channel : i.channel;
            top[-1] = f.splines[i.index]->at(top[-1])[size_t(c >= 0 && c < 5 ? c : 0)];
            break;
        }
        default: {
            --top;
            const double a = top[-1], b = top[0];
            double r = 0;
            switch (i.op) {
            case FnOp::Add: r = a + b; break;
            case FnOp::Sub: r = a - b; break;
            case FnOp::Mul: r = a * b; break;
            case FnOp::Div: r = a / b; break;
            case FnOp::Lt: r = a < b; break;
            case FnOp::Le: r = a <= b; break;
            case FnOp::Eq: r = std::fabs(a - b) <= 1e-10; break;
            case FnOp::Ne: r = std::fabs(a - b) > 1e-10; break;
            case FnOp::Ge: r = a >= b; break;
            case FnOp::Gt: r = a > b; break;
            case FnOp::And: r = a != 0 && b != 0; break;
            case FnOp::Or: r = a != 0 || b != 0; break;
            default: break;
            }
            top[-1] = r;
        }
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

double Function::operator()(const double* args, int channel) const {
    // The front end keeps every function's totalStack within this.
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

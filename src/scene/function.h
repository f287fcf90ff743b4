// User-defined functions (POV-Ray's `function { ... }`): a compiled float
// expression of its parameters (x, y, z by default), evaluated by the
// front end (a call in an expression) and by the renderer (function
// patterns, isosurfaces, height fields). The program is a small postfix
// code run on a fixed stack, or, where it repeats subexpressions, its compiled
// form (CompiledFunctionCache, below), made by the first evaluation: later ones
// allocate nothing and only read, so one Function serves every thread.
//
// A function calls only functions declared before it (they are held here by
// pointer), so no call can recurse. Its body may instead be a pattern or a
// pigment (`function { pattern { ... } }`, `function { pigment { ... } }`):
// those are evaluated by the renderer's pattern code through the hooks at the
// end of this header. A spline (`function { spline { ... } }`) is a function
// too: of one parameter, its value a vector whose component a call picks;
// so is a transform (`function { transform { ... } }`): of x, y, z, its value
// the transformed point (transforms.inc's vtransform).
#pragma once

#include "core/transform.h"
#include "core/vec.h"
#include "scene/spline.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace drt {

struct Pigment;

enum class FnOp : uint8_t {
    Const,   // push value
    Param,   // push args[index]
    Add, Sub, Mul, Div, Neg, Not,
    Lt, Le, Eq, Ne, Ge, Gt, And, Or,
    Cond,    // c a b -> c != 0 ? a : b
    Math1,   // a -> f(a), f = FnMath1(index)
    Math2,   // a b -> f(a, b), f = FnMath2(index)
    Select,  // count 3: s a b -> s < 0 ? a : b; count 4: s a b c -> s < 0 ? a : s == 0 ? b : c
    Call,    // count arguments -> callees[index](arguments), channel `channel` of a colour function
    Internal,// count arguments -> the internal function `index` (FnInternal)
    Pattern, // x y z -> the value of patterns[index] at <x, y, z> (in [0, 1])
    Colour,  // x y z -> channel `channel` of pigment patterns[index] at <x, y, z>
    Spline,  // t -> component `channel` of splines[index] at t
    Transform, // x y z -> component `channel` of transforms[index] applied to the point <x, y, z>
};

enum class FnMath1 : uint16_t {
    Abs, Acos, Acosh, Asin, Asinh, Atan, Atanh, Ceil, Cos, Cosh, Degrees, Exp, Floor, Int, Ln, Log, Radians,
    Sin, Sinh, Sqrt, Sqr, Tan, Tanh,
};
enum class FnMath2 : uint16_t { Pow, Atan2, Mod, Div, Min, Max };

// POV-Ray's internal functions of functions.inc that drt implements, by
// their number there (internal(N)).
enum class FnInternal : uint16_t {
    Ph = 47,            // f_ph(x, y, z): the angle from +y, acos(y / r)
    R = 57,             // f_r(x, y, z): distance from the origin
    RoundedBox = 60,    // f_rounded_box(x, y, z, radius, sx, sy, sz)
    Sphere = 61,        // f_sphere(x, y, z, radius)
    Superellipsoid = 68,// f_superellipsoid(x, y, z, e, n): 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2)
    Th = 69,            // f_th(x, y, z): atan2(x, z)
    Torus = 70,         // f_torus(x, y, z, major, minor)
    Noise3d = 76,       // f_noise3d(x, y, z): noise in [0, 1] (drt's noise)
    NoiseGenerator = 78,// f_noise_generator(x, y, z, generator): drt's one noise
};
// The number of arguments of internal function `number`, or -1 when drt lacks it.
int internalArity(int number);
// functions.inc's name of internal function `number` ("f_sphere"), or "" when drt lacks it.
const char* internalName(int number);
// The number of the internal function called `name` ("f_sphere" -> 61), or -1.
int internalNamed(const std::string& name);

struct FnInstr {
    FnOp op = FnOp::Const;
    uint8_t count = 0;   // arguments (Call, Internal, Select)
    uint8_t channel = 0; // Call of a colour function, Colour: 0 red .. 4 transmit, 5 gray
    uint16_t index = 0;  // Param, Math1, Math2, Call, Internal, Pattern, Colour, Spline
    double value = 0;    // Const
};

struct Function;
struct CompiledFunction; // function.cpp

// A function's program with each repeated subexpression computed once, made on
// its first evaluation and kept with it (a copy of the function starts
// without). Threads that evaluate a function first at once each make one; one
// is kept, the others are freed.
class CompiledFunctionCache {
public:
    CompiledFunctionCache() = default;
    CompiledFunctionCache(const CompiledFunctionCache&) {}
    CompiledFunctionCache& operator=(const CompiledFunctionCache&) {
        reset();
        return *this;
    }
    ~CompiledFunctionCache() { reset(); }
    const CompiledFunction& get(const Function& f) const;
    // Whether f's evaluation runs its compiled program (else its stack program).
    bool runs(const Function& f) const;

private:
    void reset();
    mutable std::atomic<const CompiledFunction*> program_{nullptr};
};

struct Function {
    std::vector<std::string> params; // names, in order (x y z for `function { }`)
    std::vector<FnInstr> code;
    std::vector<std::shared_ptr<const Function>> callees;
    std::vector<std::shared_ptr<const Pigment>> patterns; // Pattern and Colour operands
    std::vector<std::shared_ptr<const Spline>> splines;   // Spline operands
    std::vector<drt::Transform> transforms;               // Transform operands
    int stackSize = 0;  // the deepest the stack gets, callees excluded
    int totalStack = 0; // stackSize plus the largest totalStack of the callees
    // `function { pigment { ... } }`: a colour function, whose value is a
    // colour; a call picks its channel (`F(x, y, z).red`), red by default.
    bool colour = false;
    // `function { spline { ... } }`: a vector function of one parameter; a
    // call picks its component (`F(t).y`), x by default. Also
    // `function { transform { ... } }`, of x, y, z (its value has 3 components).
    bool vector = false;
    // An internal function drt lacks: it takes any arguments and gives 0.
    bool anyArity = false;

    // The value at `args` (params.size() of them): channel `channel` of a
    // colour function. Never NaN: a NaN result is 0, infinities are +-1e300.
    double operator()(const double* args, int channel = 0) const;
    // The same value from `code` run as written, on a stack, each
    // subexpression as often as it is written (tests compare the two).
    double interpret(const double* args, int channel = 0) const;
    double at(const Vec3& p) const {
        const double a[3] = {p.x, p.y, p.z};
        return (*this)(a);
    }
    bool operator==(const Function& o) const; // the same program and operands

    CompiledFunctionCache compiled;
};

// The most stack slots a function may need, its callees' included (the front
// end refuses deeper expressions and call chains).
inline constexpr int kFunctionTotalStackLimit = 1024;

// The renderer's pattern code, for noise and for pattern and pigment bodies
// (set by src/render when it is linked; without it noise is 0.5 and patterns
// 0). `channel` as FnInstr::channel.
struct FunctionHooks {
    double (*noise)(const Vec3& p) = nullptr;
    double (*pattern)(const Pigment& pattern, const Vec3& p) = nullptr;
    double (*colour)(const Pigment& pigment, const Vec3& p, int channel) = nullptr;
};
void setFunctionHooks(const FunctionHooks& hooks);

} // namespace drt

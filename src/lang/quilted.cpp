#include "lang/quilted.h"

#include <algorithm>
#include <cmath>

namespace drt::lang {

namespace {

// A postfix program and the deepest its stack gets.
class Emitter {
public:
    explicit Emitter(Function& f) : f_(f) {}
    void constant(double v) { push({FnOp::Const, 0, 0, 0, v}, +1); }
    void param(int i) { push({FnOp::Param, 0, 0, uint16_t(i), 0}, +1); }
    void op(FnOp o) { push({o, 0, 0, 0, 0}, -1); } // a binary operator
    void math1(FnMath1 m) { push({FnOp::Math1, 0, 0, uint16_t(m), 0}, 0); }
    // v on axis i: p - floor(p) - 1/2
    void axis(int i) {
        param(i);
        param(i);
        math1(FnMath1::Floor);
        op(FnOp::Sub);
        constant(0.5);
        op(FnOp::Sub);
    }
    // t = |v|
    void length() {
        for (int i = 0; i < 3; ++i) {
            axis(i);
            axis(i);
            op(FnOp::Mul);
            if (i > 0) op(FnOp::Add);
        }
        math1(FnMath1::Sqrt);
    }

private:
    void push(FnInstr in, int change) {
        f_.code.push_back(in);
        depth_ += change;
        f_.stackSize = std::max(f_.stackSize, depth_);
    }
    Function& f_;
    int depth_ = 0;
};

const double kScale = 2 / (3 * std::sqrt(3.0));

} // namespace

std::shared_ptr<const Function> quiltedFunction(double control0, double control1) {
    auto f = std::make_shared<Function>();
    f->params = {"x", "y", "z"};
    Emitter e(*f);
    // B(t) = t (a1 + t (a2 + t a3)), the cubic's power form; a1 and a2 are the
    // program's first constants after the first |v| (quiltedControls).
    const double a1 = 3 * control0, a2 = 3 * control1 - 6 * control0, a3 = 3 * control0 - 3 * control1 + 1;
    e.length();
    e.constant(a1);
    e.length();
    e.constant(a2);
    e.length();
    e.constant(a3);
    e.op(FnOp::Mul);
    e.op(FnOp::Add);
    e.op(FnOp::Mul);
    e.op(FnOp::Add);
    e.op(FnOp::Mul);
    for (int i = 0; i < 3; ++i) {
        e.axis(i);
        e.math1(FnMath1::Abs);
        if (i > 0) e.op(FnOp::Add);
    }
    e.op(FnOp::Mul);
    e.constant(kScale);
    e.op(FnOp::Mul);
    f->totalStack = f->stackSize;
    return f;
}

bool quiltedControls(const Function& f, double& control0, double& control1) {
    // The program quiltedFunction makes, whatever its controls: the same
    // instructions, the same constants but for the cubic's three.
    static const std::shared_ptr<const Function> shape = quiltedFunction(1, 1);
    if (f.params != shape->params || f.code.size() != shape->code.size() || !f.callees.empty() ||
        !f.patterns.empty() || !f.splines.empty() || f.colour || f.vector)
        return false;
    std::vector<double> cubic;
    for (size_t i = 0; i < f.code.size(); ++i) {
        const FnInstr &a = f.code[i], &b = shape->code[i];
        if (a.op != b.op || a.index != b.index || a.count != b.count || a.channel != b.channel) return false;
        if (a.op != FnOp::Const) continue;
        if (b.value == 0.5 || b.value == kScale) {
            if (a.value != b.value) return false;
        } else {
            cubic.push_back(a.value);
        }
    }
    if (cubic.size() != 3) return false;
    control0 = cubic[0] / 3;
    control1 = (cubic[1] + 6 * control0) / 3;
    return true;
}

} // namespace drt::lang

// A function's compiled program (scene/function.h: each repeated subexpression
// computed once) against its stack program run as written: random programs
// full of repeats, with every operator, math function, internal function,
// calls of other functions and transforms, at random points, to the bit.
#include "scene/function.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <memory>
#include <random>

namespace drt {
namespace {

bool sameBits(double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); }

// Random postfix programs: a subexpression is often one made before, written
// again (as quilted's |v| is three times).
class ProgramMaker {
public:
    ProgramMaker(std::mt19937_64& rng, Function& f, int params) : rng_(rng), f_(f), params_(params) {}

    // The program, and its stack's depth bounded by its length (the stack
    // program's buffer holds far more).
    void make(int depth) {
        f_.code = expression(depth);
        f_.stackSize = f_.totalStack = int(f_.code.size());
        for (const auto& callee : f_.callees) f_.totalStack = std::max(f_.totalStack, f_.stackSize + callee->totalStack);
    }

private:
    double constant() {
        static const double kValues[] = {0.0, -0.0, 1.0, -2.5, 0.5, 1e-10, 3.0, 1e300, -1e300, 1e-300, 4.0 * kPi};
        std::uniform_real_distribution<double> u(-3, 3);
        return rng_() % 3 == 0 ? u(rng_) : kValues[rng_() % std::size(kValues)];
    }

    void append(std::vector<FnInstr>& out, const std::vector<FnInstr>& part) { out.insert(out.end(), part.begin(), part.end()); }

    std::vector<FnInstr> expression(int depth) {
        if (!pool_.empty() && rng_() % 3 == 0) return pool_[rng_() % pool_.size()];
        std::vector<FnInstr> out;
        if (depth == 0 || rng_() % 6 == 0) {
            if (rng_() % 2 == 0) out.push_back({FnOp::Param, 0, 0, uint16_t(rng_() % uint64_t(params_))});
            else out.push_back({FnOp::Const, 0, 0, 0, constant()});
            return out;
        }
        const auto operands = [&](int n) {
            for (int k = 0; k < n; ++k) append(out, expression(depth - 1));
        };
        switch (rng_() % 10) {
        case 0:
            operands(1);
            out.push_back({rng_() % 2 ? FnOp::Neg : FnOp::Not});
            break;
        case 1:
            operands(1);
            out.push_back({FnOp::Math1, 0, 0, uint16_t(rng_() % (uint64_t(FnMath1::Tanh) + 1))});
            break;
        case 2:
            operands(2);
            out.push_back({FnOp::Math2, 2, 0, uint16_t(rng_() % (uint64_t(FnMath2::Max) + 1))});
            break;
        case 3:
            operands(3);
            out.push_back({FnOp::Cond});
            break;
        case 4: {
            const int n = 3 + int(rng_() % 2);
            operands(n);
            out.push_back({FnOp::Select, uint8_t(n)});
            break;
        }
        case 5: {
            static const int kInternals[] = {47, 57, 60, 61, 68, 69, 70};
            const int number = kInternals[rng_() % std::size(kInternals)];
            operands(internalArity(number));
            out.push_back({FnOp::Internal, uint8_t(internalArity(number)), 0, uint16_t(number)});
            break;
        }
        case 6:
            if (!f_.callees.empty()) {
                const size_t index = rng_() % f_.callees.size();
                const int n = int(f_.callees[index]->params.size());
                operands(n);
                out.push_back({FnOp::Call, uint8_t(n), 0, uint16_t(index)});
                break;
            }
            [[fallthrough]];
        case 7:
            if (!f_.transforms.empty()) { // two components of one transformed point, added
                operands(3);
                const std::vector<FnInstr> point(out.begin(), out.end());
                const uint16_t index = uint16_t(rng_() % f_.transforms.size());
                const uint8_t first = uint8_t(rng_() % 3);
                out.push_back({FnOp::Transform, 3, first, index});
                append(out, point);
                out.push_back({FnOp::Transform, 3, uint8_t((first + 1) % 3), index});
                out.push_back({FnOp::Add});
                break;
            }
            [[fallthrough]];
        default: {
            static const FnOp kBinary[] = {FnOp::Add, FnOp::Sub, FnOp::Mul, FnOp::Div, FnOp::Lt, FnOp::Le,
                                           FnOp::Eq,  FnOp::Ne,  FnOp::Ge,  FnOp::Gt,  FnOp::And, FnOp::Or};
            operands(2);
            out.push_back({kBinary[rng_() % std::size(kBinary)]});
        }
        }
        pool_.push_back(out);
        return out;
    }

    std::mt19937_64& rng_;
    Function& f_;
    int params_;
    std::vector<std::vector<FnInstr>> pool_;
};

// A point's coordinate: small, large, or one of a few integers and signed zeros.
double argument(std::mt19937_64& rng) {
    static const double kSpecial[] = {0.0, -0.0, -2.0, -1.0, 1.0, 2.0};
    std::uniform_real_distribution<double> u(-2, 2);
    const uint64_t kind = rng() % 8;
    if (kind < 2) return kSpecial[rng() % std::size(kSpecial)];
    return kind == 2 ? u(rng) * 1e8 : u(rng);
}

TEST(FunctionCompiled, ValuesAreThoseOfTheStackProgramToTheBit) {
    std::mt19937_64 rng(53);
    int compiled = 0, evaluations = 0, nonZero = 0;
    for (int trial = 0; trial < 400; ++trial) {
        // Two callees (one calling the other), then the function calling them.
        std::vector<std::shared_ptr<const Function>> callees;
        for (int k = 0; k < 2; ++k) {
            auto callee = std::make_shared<Function>();
            const int params = 1 + int(rng() % 4);
            for (int p = 0; p < params; ++p) callee->params.push_back(std::string(1, char('a' + p)));
            callee->callees = callees;
            ProgramMaker(rng, *callee, params).make(3);
            callees.push_back(callee);
        }
        Function f;
        f.params = {"x", "y", "z"};
        f.callees = callees;
        f.transforms = {Transform::rotate(Vec3(30, 10 * double(trial % 7), 5)), Transform::scale(Vec3(2, 0.5, -1))};
        ProgramMaker(rng, f, 3).make(2 + trial % 5);
        compiled += f.compiled.runs(f);
        for (int point = 0; point < 60; ++point) {
            const double args[3] = {argument(rng), argument(rng), argument(rng)};
            const double got = f(args), expected = f.interpret(args);
            ASSERT_TRUE(sameBits(got, expected)) << "trial " << trial << " point " << point << ": " << got << " "
                                                 << expected;
            ++evaluations;
            nonZero += got != 0;
        }
        // A copy starts without the compiled program, and gives the same values.
        const Function copy = f;
        const double args[3] = {0.25, -1.5, 2};
        EXPECT_TRUE(sameBits(copy(args), f.interpret(args)));
    }
    // Most programs ran compiled, and most values were not zero.
    EXPECT_GT(compiled, 200);
    EXPECT_GT(nonZero, evaluations / 2);
}

} // namespace
} // namespace drt

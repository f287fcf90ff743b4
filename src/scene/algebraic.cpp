#include "scene/algebraic.h"

#include <cmath>

namespace drt {

void algebraicTermExponents(int order, int index, int& i, int& j, int& k) {
    for (i = order; i >= 0; --i)
        for (j = order - i; j >= 0; --j)
            for (k = order - i - j; k >= 0; --k)
                if (index-- == 0) return;
    i = j = k = 0;
}

std::vector<Monomial> algebraicTerms(const Algebraic& a) {
    std::vector<Monomial> terms;
    auto add = [&](int x, int y, int z, double c) {
        if (c != 0) terms.push_back({x, y, z, c});
    };
    if (a.form == Algebraic::Form::Quadric) {
        static const int exponents[10][3] = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {1, 0, 1},
                                             {0, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}};
        for (size_t t = 0; t < a.coefficients.size() && t < 10; ++t)
            add(exponents[t][0], exponents[t][1], exponents[t][2], a.coefficients[t]);
        return terms;
    }
    const int order = a.form == Algebraic::Form::Cubic ? 3 : a.form == Algebraic::Form::Quartic ? 4 : a.order;
    int index = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k, ++index)
                if (size_t(index) < a.coefficients.size()) add(i, j, k, a.coefficients[size_t(index)]);
    return terms;
}

static double power(double v, int e) {
    double r = 1;
    for (int i = 0; i < e; ++i) r *= v;
    return r;
}

double evaluateAlgebraic(const std::vector<Monomial>& terms, double x, double y, double z) {
    double sum = 0;
    for (const Monomial& m : terms) sum += m.coefficient * power(x, m.x) * power(y, m.y) * power(z, m.z);
    return sum;
}

int algebraicCoefficientCount(Algebraic::Form form, int order) {
    switch (form) {
    case Algebraic::Form::Quadric: return 10;
    case Algebraic::Form::Cubic: return algebraicTermCount(3);
    case Algebraic::Form::Quartic: return algebraicTermCount(4);
    case Algebraic::Form::Poly: return algebraicTermCount(order);
    }
    return 0;
}

} // namespace drt

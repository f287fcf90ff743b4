#include "render/pattern_fractal.h"

#include <cmath>
#include <complex>

namespace drt {

namespace {

using Complex = std::complex<double>;

double exterior(const FractalPattern& f, long long step, const Complex& z) {
    const double a = z.real(), b = z.imag(), factor = f.exteriorFactor;
    switch (f.exteriorType) {
    case 0: return factor;
    case 1: return f.iterations > 0 ? double(step) / double(f.iterations) : 0.0;
    case 2: return a * factor;
    case 3: return b * factor;
    case 4: return a * a * factor;
    case 5: return b * b * factor;
    case 6: return std::sqrt(a * a + b * b) * factor;
    case 7: return std::fmod(double(step), factor) / factor;
    case 8: return std::fmod(double(step), factor + 1) / factor;
    default: return 0;
    }
}

double interior(const FractalPattern& f, const Complex& z, double smallestNorm) {
    const double a = z.real(), b = z.imag(), factor = f.interiorFactor;
    switch (f.interiorType) {
    case 0: return factor;
    case 1: return std::sqrt(smallestNorm) * factor;
    case 2: return a * factor;
    case 3: return b * factor;
    case 4: return a * a * factor;
    case 5: return b * b * factor;
    case 6: return a * a + b * b * factor;
    default: return 0;
    }
}

// z^n for an integer n >= 2, by repeated squaring.
Complex power(Complex z, int n) {
    Complex result(1, 0);
    while (n > 0) {
        if (n & 1) result *= z;
        z *= z;
        n >>= 1;
    }
    return result;
}

Complex step(const FractalPattern& f, const Complex& z, const Complex& c) {
    switch (f.kind) {
    case FractalKind::Mandel:
    case FractalKind::Julia:
        if (f.exponent == 2) return Complex(z.real() * z.real() - z.imag() * z.imag() + c.real(),
                                            2 * z.real() * z.imag() + c.imag());
        return power(z, f.exponent) + c;
    case FractalKind::Magnet1Mandel:
    case FractalKind::Magnet1Julia: {
        const Complex q = (z * z + c - 1.0) / (2.0 * z + c - 2.0);
        return q * q;
    }
    case FractalKind::Magnet2Mandel:
    case FractalKind::Magnet2Julia: {
        const Complex c1 = c - 1.0, c2 = c - 2.0;
        const Complex q = (z * z * z + 3.0 * c1 * z + c1 * c2) / (3.0 * z * z + 3.0 * c2 * z + c1 * c2 + 1.0);
        return q * q;
    }
    }
    return z;
}

} // namespace

double fractalValue(const FractalPattern& f, double x, double y) {
    const Complex p(x, y);
    const bool julia = isJuliaForm(f.kind);
    const bool magnet = isMagnet(f.kind);
    const Complex c = julia ? Complex(f.cx, f.cy) : p;
    Complex z = magnet && !julia ? Complex(0, 0) : p;
    double smallest = std::norm(p);
    for (long long i = 0; i < f.iterations; ++i) {
        z = step(f, z, c);
        const double n = std::norm(z);
        if (magnet ? (n > 1e4 || std::norm(z - 1.0) < 1e-4) : n > 4) return exterior(f, i, z);
        if (!(n == n)) return 0; // NaN (a magnet's pole): no value
        smallest = std::min(smallest, n);
    }
    return interior(f, z, smallest);
}

} // namespace drt

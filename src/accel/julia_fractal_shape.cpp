#include "accel/julia_fractal_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

using Quad = JuliaFractalGeometry::Quad;
using Function = JuliaFractal::Function;

constexpr double kTolerance = 1e-7;            // the bisection's end, POV-Ray's Fractal_Tolerance
constexpr double kHypercomplexTolerance = 1e-8; // its hypercomplex step test

void require(bool ok, const char* message) {
    if (!ok) throw std::invalid_argument(message);
}

double norm2(const Quad& q) { return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w; }

// The hypercomplex product (commutative: i j = k, i^2 = j^2 = -1, k^2 = 1).
Quad hyperMultiply(const Quad& a, const Quad& b) {
    return {a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w, a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w,
            a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w, a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w};
}

Quad hyperSquare(const Quad& q) {
    return {q.x * q.x - q.y * q.y - q.z * q.z + q.w * q.w, 2 * (q.x * q.y - q.z * q.w), 2 * (q.z * q.x - q.w * q.y),
            2 * (q.w * q.x + q.z * q.y)};
}

// 1/q; a number with no inverse (on the null cone) maps far outside every
// bound, so its orbit escapes at the next step.
Quad hyperReciprocal(const Quad& q) {
    const double det = ((q.x - q.w) * (q.x - q.w) + (q.y + q.z) * (q.y + q.z)) *
                       ((q.x + q.w) * (q.x + q.w) + (q.y - q.z) * (q.y - q.z));
    if (det == 0) return {1e30, 0, 0, 0};
    const double mod = norm2(q), xwMinusYz = q.x * q.w - q.y * q.z;
    return {(q.x * mod - 2 * q.w * xwMinusYz) / det, (-q.y * mod - 2 * q.z * xwMinusYz) / det,
            (-q.z * mod - 2 * q.y * xwMinusYz) / det, (q.w * mod - 2 * q.x * xwMinusYz) / det};
}

// ---- complex functions, as POV-Ray defines them (principal branches)

struct Complex {
    double x = 0, y = 0;
};

Complex multiply(const Complex& a, const Complex& b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }
Complex divide(const Complex& a, const Complex& b) {
    const double mod = b.x * b.x + b.y * b.y;
    if (mod == 0) return {};
    const double rx = b.x / mod, ry = -b.y / mod;
    return {a.x * rx - a.y * ry, a.x * ry + a.y * rx};
}
Complex complexLn(const Complex& a) { return {std::log(std::sqrt(a.x * a.x + a.y * a.y)), std::atan2(a.y, a.x)}; }
Complex complexSqrt(const Complex& a) {
    if (a.x == 0 && a.y == 0) return {};
    const double magnitude = std::sqrt(std::sqrt(a.x * a.x + a.y * a.y)), theta = std::atan2(a.y, a.x) / 2;
    return {magnitude * std::cos(theta), magnitude * std::sin(theta)};
}
Complex complexAtanh(const Complex& a) {
    if (a.x == 0) return {0, std::atan(a.y)};
    if (std::fabs(a.x) == 1 && a.y == 0) return {};
    if (std::fabs(a.x) < 1 && a.y == 0) return {std::log((1 + a.x) / (1 - a.x)) / 2, 0};
    const Complex l = complexLn(divide({1 + a.x, a.y}, {1 - a.x, -a.y})); // atanh z = ln((1 + z) / (1 - z)) / 2
    return {0.5 * l.x, 0.5 * l.y};
}

Complex applyComplex(Function f, const Complex& a, const std::array<double, 2>& exponent) {
    switch (f) {
    case Function::Exp: {
        const double e = std::exp(a.x);
        return {e * std::cos(a.y), e * std::sin(a.y)};
    }
    case Function::Ln: return complexLn(a);
    case Function::Sin: return {std::sin(a.x) * std::cosh(a.y), std::cos(a.x) * std::sinh(a.y)};
    case Function::Cos: return {std::cos(a.x) * std::cosh(a.y), -std::sin(a.x) * std::sinh(a.y)};
    case Function::Sinh: return {std::sinh(a.x) * std::cos(a.y), std::cosh(a.x) * std::sin(a.y)};
    case Function::Cosh: return {std::cosh(a.x) * std::cos(a.y), std::sinh(a.x) * std::sin(a.y)};
    case Function::Tan: { // tan z = (sin 2x + i sinh 2y) / (cos 2x + cosh 2y)
        const double denominator = std::cos(2 * a.x) + std::cosh(2 * a.y);
        if (denominator == 0) return {};
        return {std::sin(2 * a.x) / denominator, std::sinh(2 * a.y) / denominator};
    }
    case Function::Tanh: { // tanh z = (sinh 2x + i sin 2y) / (cosh 2x + cos 2y)
        const double denominator = std::cosh(2 * a.x) + std::cos(2 * a.y);
        if (denominator == 0) return {};
        return {std::sinh(2 * a.x) / denominator, std::sin(2 * a.y) / denominator};
    }
    case Function::Asin: { // asin z = -i ln(i z + sqrt(1 - z^2))
        Complex s = multiply(a, a);
        s = complexSqrt({1 - s.x, -s.y});
        const Complex l = complexLn({s.x - a.y, s.y + a.x});
        return {l.y, -l.x};
    }
    case Function::Acos: { // POV-Ray's acos z = -i ln(z + sqrt(z^2 - 1))
        Complex s = multiply(a, a);
        s = complexSqrt({s.x - 1, s.y});
        const Complex l = complexLn({s.x + a.x, s.y + a.y});
        return {l.y, -l.x};
    }
    case Function::Asinh: { // asinh z = ln(z + sqrt(z^2 + 1))
        Complex s = multiply(a, a);
        s = complexSqrt({s.x + 1, s.y});
        return complexLn({s.x + a.x, s.y + a.y});
    }
    case Function::Acosh: { // acosh z = ln(z + sqrt(z^2 - 1))
        Complex s = multiply(a, a);
        s = complexSqrt({s.x - 1, s.y});
        return complexLn({s.x + a.x, s.y + a.y});
    }
    case Function::Atanh: return complexAtanh(a);
    case Function::Atan: { // atan z = i/2 ln((1 - i z) / (1 + i z))
        if (a.x == 0 && a.y == 0) return {};
        if (a.y == 0) return {std::atan(a.x), 0};
        if (a.x == 0) {
            const Complex h = complexAtanh({a.y, 0});
            return {-h.y, h.x};
        }
        const Complex iz{-a.y, a.x};
        const Complex l = complexLn(divide({1 - iz.x, -iz.y}, {1 + iz.x, iz.y}));
        return {-0.5 * l.y, 0.5 * l.x};
    }
    case Function::Pwr: { // z^e = exp(e ln z), 0^e = 0
        if (a.x == 0 && a.y == 0) return {};
        const Complex t = multiply(complexLn(a), {exponent[0], exponent[1]});
        const double e = t.x < -690 ? 0 : std::exp(t.x);
        return {e * std::cos(t.y), e * std::sin(t.y)};
    }
    default: return a;
    }
}

} // namespace

JuliaFractalGeometry::JuliaFractalGeometry(const JuliaFractal& f) : f_(f) {
    for (double v : f.parameter) require(std::isfinite(v), "julia_fractal's parameter must be finite");
    for (double v : f.slice) require(std::isfinite(v), "julia_fractal's slice must be finite");
    require(std::isfinite(f.sliceDistance) && std::isfinite(f.exponent[0]) && std::isfinite(f.exponent[1]),
            "julia_fractal's numbers must be finite");
    require(f.maxIteration >= 1, "julia_fractal's max_iteration must be at least 1");
    require(std::isfinite(f.precision) && f.precision >= 1, "julia_fractal's precision must be at least 1");
    require(f.slice[3] != 0, "julia_fractal's slice normal needs a non-zero fourth component");
    require(f.algebra == JuliaFractal::Algebra::Hypercomplex || f.function == Function::Sqr ||
                f.function == Function::Cube,
            "a quaternion julia_fractal iterates sqr or cube only");
    const double len = std::sqrt(f.slice[0] * f.slice[0] + f.slice[1] * f.slice[1] + f.slice[2] * f.slice[2] +
                                 f.slice[3] * f.slice[3]);
    for (double& c : f_.slice) c /= len; // POV-Ray's unit slice normal
    radius_ = f.radius();
    exitValue_ = f.exitValue();
    smallestStep_ = 1 / f.precision;
}

JuliaFractalGeometry::Quad JuliaFractalGeometry::map(const Quad& q) const {
    switch (f_.function) {
    case Function::Sqr:
    case Function::Cube: return hyperSquare(q); // POV-Ray 3.7's hypercomplex cube iterates the square too
    case Function::Reciprocal: return hyperReciprocal(q);
    default: {
        // The duplex form: q = a (1 - k)/2 + b (1 + k)/2 with complex a and b,
        // and f(q) = f(a) (1 - k)/2 + f(b) (1 + k)/2.
        const Complex a = applyComplex(f_.function, {q.x - q.w, q.y + q.z}, f_.exponent);
        const Complex b = applyComplex(f_.function, {q.x + q.w, q.y - q.z}, f_.exponent);
        return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.y - b.y), 0.5 * (b.x - a.x)};
    }
    }
}

JuliaFractalGeometry::Quad JuliaFractalGeometry::next(const Quad& q) const {
    const auto& c = f_.parameter;
    if (f_.algebra == JuliaFractal::Algebra::Quaternion) {
        const double v2 = q.y * q.y + q.z * q.z + q.w * q.w; // |vector part|^2
        if (f_.function == Function::Cube) { // (x^3 - 3 x |v|^2, (3 x^2 - |v|^2) v)
            const double x2 = q.x * q.x, s = 3 * x2 - v2;
            return {q.x * (x2 - 3 * v2) + c[0], q.y * s + c[1], q.z * s + c[2], q.w * s + c[3]};
        }
        return {q.x * q.x - v2 + c[0], 2 * q.x * q.y + c[1], 2 * q.x * q.z + c[2], 2 * q.x * q.w + c[3]};
    }
    const Quad m = map(q);
    return {m.x + c[0], m.y + c[1], m.z + c[2], m.w + c[3]};
}

bool JuliaFractalGeometry::iterate(const Vec3& p, std::vector<Quad>& orbit, int& escapedAt) const {
    const int n = f_.maxIteration;
    orbit.resize(size_t(n) + 1);
    Quad q{p.x, p.y, p.z, 0};
    // POV-Ray 3.7 starts a hypercomplex function's inside test (not its march)
    // with z taken from y; kept so the surfaces agree.
    const bool hyper = f_.algebra == JuliaFractal::Algebra::Hypercomplex;
    if (hyper && f_.function > Function::Reciprocal) q.z = p.y;
    q.w = (f_.sliceDistance - f_.slice[0] * q.x - f_.slice[1] * q.y - f_.slice[2] * q.z) / f_.slice[3];
    orbit[0] = q;
    for (int i = 1; i <= n; ++i) {
        if (norm2(q) > exitValue_) {
            escapedAt = i;
            return false;
        }
        q = orbit[size_t(i)] = next(q);
    }
    escapedAt = n + 1;
    return true;
}

Vec3 JuliaFractalGeometry::orbitNormal(const std::vector<Quad>& orbit, int n) const {
    if (f_.algebra == JuliaFractal::Algebra::Quaternion) {
        // Rows of d q_n / d (x, y, z), propagated through each step's derivative.
        double r[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
        for (int i = 1; i <= n; ++i) {
            const Quad& q = orbit[size_t(i) - 1];
            for (auto& row : r) {
                if (f_.function == Function::Cube) {
                    const double v2 = q.y * q.y + q.z * q.z + q.w * q.w, x2 = q.x * q.x;
                    const double a = x2 - v2, b = 3 * x2 - v2;
                    const double s = 2 * (row[1] * q.y + row[2] * q.z + row[3] * q.w);
                    const double s2 = 6 * q.x * row[0] - s;
                    row[0] = (row[0] * a - q.x * s) * 3;
                    row[1] = row[1] * b + q.y * s2;
                    row[2] = row[2] * b + q.z * s2;
                    row[3] = row[3] * b + q.w * s2;
                } else {
                    const double first = row[0] * q.x - row[1] * q.y - row[2] * q.z - row[3] * q.w;
                    row[1] = row[0] * q.y + q.x * row[1];
                    row[2] = row[0] * q.z + q.x * row[2];
                    row[3] = row[0] * q.w + q.x * row[3];
                    row[0] = first;
                }
            }
        }
        const Quad& last = orbit[size_t(n)];
        Vec3 result;
        for (int k = 0; k < 3; ++k)
            result[k] = r[k][0] * last.x + r[k][1] * last.y + r[k][2] * last.z + r[k][3] * last.w;
        return result;
    }
    // Hypercomplex: the product of the derivatives f'(q_i) (up to a constant
    // factor) applied to q_n, read back as its x, y, z components.
    Quad a = orbit[0];
    double scale = 2;
    for (int i = 1; i < n; ++i) {
        const Quad& q = orbit[size_t(i)];
        if (f_.function == Function::Sqr || f_.function == Function::Cube) {
            a = hyperMultiply(q, a);
            scale *= 2;
        } else if (f_.function == Function::Reciprocal) {
            const Quad s = hyperSquare(hyperReciprocal(q));
            a = hyperMultiply(a, {-s.x, -s.y, -s.z, -s.w});
        } else {
            a = hyperMultiply(map(q), a); // POV-Ray uses f itself here, not f'
        }
    }
    if (f_.function != Function::Sqr) scale = 1;
    const Quad& q = orbit[size_t(n)];
    const double n1 = q.x * scale, n2 = q.y * scale, n3 = q.z * scale, n4 = q.w * scale;
    return {a.x * n1 + a.y * n2 + a.z * n3 + a.w * n4, -a.y * n1 + a.x * n2 - a.w * n3 + a.z * n4,
            -a.z * n1 - a.w * n2 + a.x * n3 + a.y * n4};
}

bool JuliaFractalGeometry::stepFrom(const Vec3& p, const Vec3& direction, double& step,
                                    std::vector<Quad>& orbit) const {
    step = smallestStep_;
    const bool hyper = f_.algebra == JuliaFractal::Algebra::Hypercomplex;
    // The march evaluates the true starting number even where iterate() keeps POV-Ray's quirk.
    Quad start{p.x, p.y, p.z, 0};
    start.w = (f_.sliceDistance - f_.slice[0] * p.x - f_.slice[1] * p.y - f_.slice[2] * p.z) / f_.slice[3];
    const int n = f_.maxIteration;
    orbit.resize(size_t(n) + 1);
    orbit[0] = start;
    Quad q = start;
    for (int i = 1; i <= n; ++i) {
        const double norm = norm2(q);
        if (norm > exitValue_) {
            if (!hyper) {
                // |q_i| / |q_i'| * log|q_i|^2 / 2^i (3^i for cube), q_i' the orbit's
                // derivative product q_0 q_1 ... q_{i-1}.
                Quad a = orbit[0];
                double power = f_.function == Function::Cube ? 1.0 / 3 : 0.5;
                for (int j = 1; j < i; ++j) {
                    const Quad& b = orbit[size_t(j)];
                    a = {a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w, a.x * b.y + a.y * b.x + a.w * b.z - a.z * b.w,
                         a.x * b.z + a.z * b.x + a.y * b.w - a.w * b.y, a.x * b.w + a.w * b.x + a.z * b.y - a.y * b.z};
                    power /= f_.function == Function::Cube ? 3 : 2;
                }
                const double derivative = norm2(a);
                if (derivative > 0) {
                    const double estimate = power * std::sqrt(norm / derivative) * std::log(norm);
                    if (std::isfinite(estimate)) step = estimate;
                }
                return false;
            }
            const Vec3 normal = orbitNormal(orbit, i - 1);
            double along = dot(normal, direction);
            if (along < -kHypercomplexTolerance) {
                along *= -2;
                if (norm > smallestStep_ * along && norm < 30 * smallestStep_ * along) step = norm / along;
            }
            return false;
        }
        q = orbit[size_t(i)] = next(q);
    }
    return true;
}

namespace {

// The orbits of inside and intersect, kept per thread (accel/thread_scratch.h).
struct JuliaScratch {
    std::vector<JuliaFractalGeometry::Quad> insideOrbit, marchOrbit;
};

} // namespace

std::unique_ptr<InstalledScratch> installJuliaScratch() { return ThreadScratch<JuliaScratch>::install(); }

bool JuliaFractalGeometry::inside(const Vec3& p) const {
    std::vector<Quad>& orbit = ThreadScratch<JuliaScratch>::get().insideOrbit;
    int escapedAt = 0;
    return iterate(p, orbit, escapedAt);
}

void JuliaFractalGeometry::intersect(const Vec3& o, const Vec3& d, double tMin, double tMax, size_t limit,
                                     std::vector<Crossing>& out) const {
    out.clear();
    const double speed = length(d);
    if (limit == 0 || !(speed > 0) || !std::isfinite(speed)) return;
    const Vec3 direction = d / speed;
    // The bounding sphere along the unit direction.
    const double b = dot(o, direction), c = dot(o, o) - radius_ * radius_;
    const double discriminant = b * b - c;
    if (!(discriminant > 0)) return;
    const double root = std::sqrt(discriminant);
    const double lo = std::max(-b - root, tMin * speed), hi = std::min(-b + root, tMax * speed);
    if (!(lo < hi)) return;

    std::vector<Quad>& orbit = ThreadScratch<JuliaScratch>::get().marchOrbit;
    double depth = lo, step = 0;
    Vec3 point = o + depth * direction;
    bool inside = stepFrom(point, direction, step, orbit);
    if (inside) { // starting inside: nudge, as POV-Ray does
        point += (2 * kTolerance) * direction;
        depth += 2 * kTolerance;
        if (depth > hi) return;
        inside = stepFrom(point, direction, step, orbit);
    }
    while (depth < hi && out.size() < limit) {
        // Advance until inside/outside changes between `before` and `point`.
        Vec3 before;
        double nextStep = 0;
        bool nextInside = inside;
        for (;;) {
            step = std::max(step, smallestStep_);
            if (depth + step > hi) return;
            before = point;
            point += step * direction;
            nextInside = stepFrom(point, direction, nextStep, orbit);
            if (nextInside != inside) break;
            depth += step;
            step = nextStep;
        }
        // Bisect; `before + half` stays on the far side's state throughout.
        double half = step, offset = 0;
        while (half > kTolerance) {
            half *= 0.5;
            int escapedAt = 0;
            if (iterate(before + (offset + half) * direction, orbit, escapedAt) == inside) offset += half;
        }
        if (!inside) offset += half; // the inside end
        const double at = depth + offset;
        const Vec3 surface = before + offset * direction;
        int escapedAt = 0;
        iterate(surface, orbit, escapedAt);
        Vec3 normal = orbitNormal(orbit, std::min(f_.maxIteration, escapedAt - 1));
        const double facing = dot(normal, direction);
        if (!isFinite(normal) || facing == 0) normal = inside ? direction : -direction;
        else if ((facing < 0) != !inside) normal = -normal; // outward: against an entering ray
        if (at / speed > tMin && at / speed < tMax) out.push_back({at / speed, normal});
        depth += step;
        step = nextStep;
        inside = nextInside;
    }
}

} // namespace drt::accel

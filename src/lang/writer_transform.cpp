// Number formatting and transform decomposition for the .drt writer.
//
// A transform in the scene model is one matrix (with its inverse); the text
// that built it is gone. The writer looks for translate / rotate / scale items
// that the parser would compose back to the very same matrix, because they
// read better than 12 numbers, and checks each candidate by composing it
// exactly as the parser does. The inverse matters too (the renderer intersects
// in object space and evaluates patterns with it), so a candidate that also
// reproduces the inverse is preferred; `matrix` computes its inverse by Gauss-
// Jordan elimination, which can differ from a composed inverse in the last bit.
#include "lang/writer_detail.h"

#include <charconv>
#include <cmath>
#include <optional>

namespace drt::writer {

std::string number(double v) {
    if (!std::isfinite(v))
        return "0"; // the scene model never holds these; keep the text loadable
    if (v == 0)
        return "0"; // also turns -0 into 0 (equal under ==)
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v); // shortest round-trip form
    return std::string(buffer, result.ptr);
}

std::string vector(const Vec3& v) {
    std::string text = "<";
    text.append(number(v.x)).append(", ").append(number(v.y)).append(", ").append(number(v.z)).append(">");
    return text;
}

Transform Step::transform() const {
    switch (kind) {
    case Kind::Translate:
        return Transform::translate(v);
    case Kind::Rotate:
        return Transform::rotate(v);
    case Kind::Scale:
        return Transform::scale(v);
    case Kind::Matrix:
        return Transform::fromPovMatrix(m).value_or(Transform{});
    }
    return {};
}

Transform compose(const std::vector<Step>& steps, const Transform& start) {
    Transform t = start;
    for (const Step& s : steps)
        t = t.then(s.transform());
    return t;
}

bool sameTransform(const Transform& a, const Transform& b) {
    return a.matrix() == b.matrix() && a.inverseMatrix() == b.inverseMatrix();
}

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

Step matrixStep(const Transform& t) {
    Step s;
    s.kind = Step::Kind::Matrix;
    const Mat4& m = t.matrix();
    // POV-Ray's row-vector order: entry (row, col) of its matrix is m[col][row].
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 3; ++col)
            s.m[size_t(row * 3 + col)] = m.m[col][row];
    return s;
}

double determinant(const Mat3& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

// POV-Ray's `rotate <a, b, c>` is R = Rz(c) Ry(b) Rx(a) (x first), so
// R[2][0] = -sin b, R[2][1] = cos b sin a, R[2][2] = cos b cos a,
// R[1][0] = sin c cos b, R[0][0] = cos c cos b. At cos b = 0 only a - c (or
// a + c) is defined; then a = 0 and c = atan2(-R[0][1], R[1][1]).
Vec3 eulerDegrees(const Mat3& r) {
    const double toDegrees = 180.0 / kPi;
    const double sinB = std::fmax(-1.0, std::fmin(1.0, -r[2][0]));
    const double b = std::asin(sinB);
    if (std::fabs(std::cos(b)) > 1e-9)
        return Vec3(std::atan2(r[2][1], r[2][2]), b, std::atan2(r[1][0], r[0][0])) * toDegrees;
    return Vec3(0, b, std::atan2(-r[0][1], r[1][1])) * toDegrees;
}

// Rounds to a multiple of 1/perUnit: written values such as 30 or 1.3 come
// back from atan2 and sqrt a few ulps off; rounding recovers them.
double roundTo(double v, double perUnit) {
    if (perUnit == 0 || std::fabs(v) > 1e5)
        return v;
    const double r = std::round(v * perUnit) / perUnit;
    return r == 0 ? 0.0 : r;
}
Vec3 roundTo(const Vec3& v, double perUnit) {
    return {roundTo(v.x, perUnit), roundTo(v.y, perUnit), roundTo(v.z, perUnit)};
}

enum class Order { ScaleFirst, RotateFirst }; // L = R S, or L = S R

// The scale factors and rotation of L in the given order, if L is one.
bool splitLinear(const Mat3& l, Order order, Vec3& scale, Mat3& rotation) {
    for (int i = 0; i < 3; ++i) {
        double sum = 0;
        for (int j = 0; j < 3; ++j)
            sum += order == Order::ScaleFirst ? l[j][i] * l[j][i] : l[i][j] * l[i][j];
        scale[i] = std::sqrt(sum);
        if (!(scale[i] > 0) || !std::isfinite(scale[i]))
            return false;
    }
    if (determinant(l) < 0)
        scale.x = -scale.x;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            rotation[i][j] = l[i][j] / (order == Order::ScaleFirst ? scale[j] : scale[i]);
    return true;
}

Step makeStep(Step::Kind kind, const Vec3& v) {
    Step s;
    s.kind = kind;
    s.v = v;
    return s;
}

} // namespace

std::vector<Step> decompose(const Transform& t) {
    if (t.isIdentity() && t.inverseMatrix() == Mat4::identity())
        return {};
    const Mat4& m = t.matrix();
    const Mat4& inv = t.inverseMatrix();
    Mat3 linear;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            linear[i][j] = m.m[i][j];
    const Vec3 last(m.m[0][3], m.m[1][3], m.m[2][3]);           // translation applied last
    const Vec3 first(-inv.m[0][3], -inv.m[1][3], -inv.m[2][3]); // translation applied first: L^-1 * last

    std::vector<std::vector<Step>> candidates;
    for (Order order : {Order::ScaleFirst, Order::RotateFirst}) {
        Vec3 scale;
        Mat3 rotation;
        if (!splitLinear(linear, order, scale, rotation))
            continue;
        // Both Euler solutions: (a, b, c) and (a + 180, 180 - b, c + 180) give
        // the same rotation, and asin only returns the first, so `rotate y*160`
        // would come back as <180, 20, 180>, a last bit off.
        const Vec3 primary = eulerDegrees(rotation);
        const auto wrap = [](double d) { return d > 180 ? d - 360 : (d <= -180 ? d + 360 : d); };
        const Vec3 alternative(wrap(primary.x + 180), wrap(180 - primary.y), wrap(primary.z + 180));
        // Each also in [0, 360): `rotate y*200` is not `rotate y*-160` to the last bit.
        const auto positive = [](const Vec3& a) {
            const auto up = [](double d) { return d < 0 ? d + 360 : d; };
            return Vec3(up(a.x), up(a.y), up(a.z));
        };
        for (const Vec3& angles : {primary, alternative, positive(primary), positive(alternative)})
        for (double perUnit : {1e10, 1e6, 0.0}) {
            std::vector<Step> linearSteps;
            const Vec3 s = roundTo(scale, perUnit), a = roundTo(angles, perUnit);
            const bool hasScale = !(s == Vec3(1)), hasRotation = !(a == Vec3(0));
            if (order == Order::ScaleFirst && hasScale)
                linearSteps.push_back(makeStep(Step::Kind::Scale, s));
            if (hasRotation)
                linearSteps.push_back(makeStep(Step::Kind::Rotate, a));
            if (order == Order::RotateFirst && hasScale)
                linearSteps.push_back(makeStep(Step::Kind::Scale, s));
            std::vector<Step> translateLast = linearSteps;
            if (!(last == Vec3(0)))
                translateLast.push_back(makeStep(Step::Kind::Translate, last));
            candidates.push_back(translateLast);
            const Vec3 t0 = roundTo(first, perUnit);
            if (!(t0 == Vec3(0)) && !linearSteps.empty()) {
                std::vector<Step> translateFirst{makeStep(Step::Kind::Translate, t0)};
                translateFirst.insert(translateFirst.end(), linearSteps.begin(), linearSteps.end());
                candidates.push_back(translateFirst);
            }
        }
    }
    // Exact readable form, else an exact `matrix`, else the readable form that
    // gives the matrix (its inverse a last bit off), else `matrix`.
    // Among exact candidates the shortest text wins (the commuting scale and
    // rotation of `rotate 30*y scale <1, 2, 1>` have two exact forms).
    const std::vector<Step>* exact = nullptr;
    const std::vector<Step>* matrixOnly = nullptr;
    for (const auto& c : candidates) {
        const Transform composed = compose(c);
        if (sameTransform(composed, t) && (!exact || formatSteps(c).size() < formatSteps(*exact).size()))
            exact = &c;
        if (!matrixOnly && composed.matrix() == m)
            matrixOnly = &c;
    }
    if (exact)
        return *exact;
    const std::vector<Step> asMatrix{matrixStep(t)};
    if (sameTransform(compose(asMatrix), t) || !matrixOnly)
        return asMatrix;
    return *matrixOnly;
}

std::string formatSteps(const std::vector<Step>& steps) {
    std::string out;
    for (const Step& s : steps) {
        switch (s.kind) {
        case Step::Kind::Translate:
            out += " translate " + vector(s.v);
            break;
        case Step::Kind::Rotate:
            out += " rotate " + vector(s.v);
            break;
        case Step::Kind::Scale:
            out += " scale " + (s.v.x == s.v.y && s.v.y == s.v.z ? number(s.v.x) : vector(s.v));
            break;
        case Step::Kind::Matrix:
            out += " matrix <";
            for (size_t i = 0; i < s.m.size(); ++i)
                out += (i ? ", " : "") + number(s.m[i]);
            out += ">";
            break;
        }
    }
    return out;
}

} // namespace drt::writer

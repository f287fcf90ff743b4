#include "scene/motion.h"

#include <algorithm>
#include <cmath>

namespace drt {

namespace {

using Quaternion = std::array<double, 4>; // w, x, y, z

// (1 - s) a + s b: exactly a at s = 0 and exactly b at s = 1.
double mix(double a, double b, double s) { return (1 - s) * a + s * b; }
Vec3 mix(const Vec3& a, const Vec3& b, double s) { return (1 - s) * a + s * b; }

// Cubic Hermite: values p0, p1 with slopes m0, m1 (per unit s).
Vec3 hermite(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

Transform keyTransform(const Vec3& translate, const Vec3& rotate, const Vec3& scale) {
    // A spline may overshoot a scale through zero, which has no inverse.
    Vec3 s = scale;
    for (int i = 0; i < 3; ++i)
        if (std::fabs(s[i]) < 1e-12) s[i] = std::copysign(1e-12, s[i]);
    return Transform::scale(s).then(Transform::rotate(rotate)).then(Transform::translate(translate));
}

Transform keyTransform(const MotionKey& k) { return keyTransform(k.translate, k.rotate, k.scale); }

// The slope at key i of one component sequence (finite differences over the
// neighbouring keys, one-sided at the ends), per unit time.
template <class Get>
Vec3 keySlope(const std::vector<MotionKey>& keys, size_t i, Get get) {
    const size_t lo = i == 0 ? 0 : i - 1, hi = std::min(keys.size() - 1, i + 1);
    return (get(keys[hi]) - get(keys[lo])) / (keys[hi].time - keys[lo].time);
}

double dot4(const Quaternion& a, const Quaternion& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }

Quaternion normalized(const Quaternion& q) {
    const double n = std::sqrt(dot4(q, q));
    return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

// Rotation matrix (rows) -> unit quaternion (Shepperd's method).
Quaternion quaternionOf(const double r[3][3]) {
    const double trace = r[0][0] + r[1][1] + r[2][2];
    Quaternion q;
    if (trace > 0) {
        const double s = 2 * std::sqrt(trace + 1);
        q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
    } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
        const double s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);
        q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
    } else if (r[1][1] > r[2][2]) {
        const double s = 2 * std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]);
        q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
    } else {
        const double s = 2 * std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]);
        q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
    }
    return normalized(q);
}

void matrixOf(const Quaternion& q, double r[3][3]) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    r[0][0] = 1 - 2 * (y * y + z * z), r[0][1] = 2 * (x * y - w * z), r[0][2] = 2 * (x * z + w * y);
    r[1][0] = 2 * (x * y + w * z), r[1][1] = 1 - 2 * (x * x + z * z), r[1][2] = 2 * (y * z - w * x);
    r[2][0] = 2 * (x * z - w * y), r[2][1] = 2 * (y * z + w * x), r[2][2] = 1 - 2 * (x * x + y * y);
}

// Slerp along the shorter arc; nearly equal rotations are blended linearly
// and normalised, as Embree does.
Quaternion slerp(const Quaternion& a, Quaternion b, double s) {
    double d = dot4(a, b);
    if (d < 0) {
        d = -d;
        for (double& c : b) c = -c;
    }
    if (d > 0.9995) return normalized({mix(a[0], b[0], s), mix(a[1], b[1], s), mix(a[2], b[2], s), mix(a[3], b[3], s)});
    const double theta = std::acos(d), sinTheta = std::sin(theta);
    const double wa = std::sin((1 - s) * theta) / sinTheta, wb = std::sin(s * theta) / sinTheta;
    return {wa * a[0] + wb * b[0], wa * a[1] + wb * b[1], wa * a[2] + wb * b[2], wa * a[3] + wb * b[3]};
}

// Upper-triangular U times v.
Vec3 upperTimes(const std::array<double, 6>& u, const Vec3& v) {
    return {u[0] * v.x + u[1] * v.y + u[2] * v.z, u[3] * v.y + u[4] * v.z, u[5] * v.z};
}

// The segment of `times` holding t and the fraction s within it; times has at least two entries.
size_t segmentOf(const std::vector<double>& times, double t, double& s) {
    const size_t i = std::upper_bound(times.begin(), times.end(), t) - times.begin() - 1;
    const size_t k = std::min(i, times.size() - 2);
    s = (t - times[k]) / (times[k + 1] - times[k]);
    return k;
}

} // namespace

Transform Motion::at(double t) const {
    if (sampled()) {
        if (samples.size() == 1 || t <= sampleTimes.front()) return samples.front();
        if (t >= sampleTimes.back()) return samples.back();
        double s = 0;
        const size_t k = segmentOf(sampleTimes, t, s);
        AffineParts a = decomposeAbout(samples[k], pivot), b = decomposeAbout(samples[k + 1], pivot);
        return composeParts(interpolateParts(a, b, s));
    }
    if (keys.empty()) return Transform();
    if (keys.size() == 1 || t <= keys.front().time) return keyTransform(keys.front());
    if (t >= keys.back().time) return keyTransform(keys.back());
    std::vector<double> times;
    for (const MotionKey& k : keys) times.push_back(k.time);
    double s = 0;
    const size_t i = segmentOf(times, t, s);
    const MotionKey &a = keys[i], &b = keys[i + 1];
    if (!spline) return keyTransform(mix(a.translate, b.translate, s), mix(a.rotate, b.rotate, s), mix(a.scale, b.scale, s));
    const double span = b.time - a.time;
    const auto along = [&](auto get) {
        return hermite(get(a), span * keySlope(keys, i, get), get(b), span * keySlope(keys, i + 1, get), s);
    };
    return keyTransform(along([](const MotionKey& k) { return k.translate; }),
                        along([](const MotionKey& k) { return k.rotate; }),
                        along([](const MotionKey& k) { return k.scale; }));
}

std::vector<double> Motion::knotTimes() const {
    if (sampled()) return sampleTimes;
    std::vector<double> times;
    for (const MotionKey& k : keys) times.push_back(k.time);
    return times;
}

Motion motionTo(const Vec3& translate, const Vec3& rotate, const Vec3& scale) {
    Motion m;
    m.keys = {MotionKey{0}, MotionKey{1, translate, rotate, scale}};
    return m;
}

Motion sampledMotion(std::vector<double> times, std::vector<Transform> samples, const Vec3& fallbackPivot) {
    Motion m;
    std::vector<PivotSample> triples;
    for (size_t k = 1; k + 1 < samples.size(); ++k)
        triples.push_back({samples[k - 1], samples[k], samples[k + 1],
                           (times[k] - times[k - 1]) / (times[k + 1] - times[k - 1])});
    m.pivot = bestPivot(triples, fallbackPivot);
    m.sampleTimes = std::move(times);
    m.samples = std::move(samples);
    return m;
}

Transform placementAt(const Transform& before, const MotionChain& chain, double t) {
    Transform r = before;
    for (const MotionStage& stage : chain) r = r.then(stage.motion.at(t)).then(stage.after);
    return r;
}

Transform restPlacement(const Transform& before, const MotionChain& chain) {
    Transform r = before;
    for (const MotionStage& stage : chain) r = r.then(stage.after);
    return r;
}

void appendTransform(Transform& before, MotionChain& chain, const Transform& t) {
    if (chain.empty()) before = before.then(t);
    else chain.back().after = chain.back().after.then(t);
}

void appendPlacement(Transform& before, MotionChain& chain, const Transform& outerBefore,
                     const MotionChain& outerChain) {
    appendTransform(before, chain, outerBefore);
    chain.insert(chain.end(), outerChain.begin(), outerChain.end());
}

// ------------------------------------------------------------ affine motion

AffineParts decomposeAbout(const Transform& a, const Vec3& pivot) {
    const Mat4& m = a.matrix();
    const Vec3 c0{m.m[0][0], m.m[1][0], m.m[2][0]}, c1{m.m[0][1], m.m[1][1], m.m[2][1]},
        c2{m.m[0][2], m.m[1][2], m.m[2][2]};
    // Gram-Schmidt QR of the linear part: L = Q U, Q's columns q0 q1 q2.
    AffineParts p;
    auto& u = p.upper;
    u[0] = length(c0);
    const Vec3 q0 = c0 / u[0];
    u[1] = dot(q0, c1);
    const Vec3 v1 = c1 - u[1] * q0;
    u[3] = length(v1);
    const Vec3 q1 = v1 / u[3];
    u[2] = dot(q0, c2);
    u[4] = dot(q1, c2);
    const Vec3 v2 = c2 - u[2] * q0 - u[4] * q1;
    u[5] = length(v2);
    Vec3 q2 = v2 / u[5];
    if (dot(q0, cross(q1, q2)) < 0) { // a mirror: keep Q a rotation, U takes the sign
        q2 = -q2;
        u[5] = -u[5];
    }
    const double r[3][3] = {{q0.x, q1.x, q2.x}, {q0.y, q1.y, q2.y}, {q0.z, q1.z, q2.z}};
    p.rotation = quaternionOf(r);
    p.shift = -upperTimes(u, pivot);
    p.translation = a.point(pivot);
    return p;
}

Transform composeParts(const AffineParts& parts) {
    double r[3][3];
    matrixOf(parts.rotation, r);
    const auto& u = parts.upper;
    if (u[0] == 0 || u[3] == 0 || u[5] == 0 || !std::isfinite(u[0] * u[3] * u[5]))
        return Transform(); // a singular interpolated step (a scale through zero): never asked for by drt's paths
    const double um[3][3] = {{u[0], u[1], u[2]}, {0, u[3], u[4]}, {0, 0, u[5]}};
    Mat4 m;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m.m[i][j] = r[i][0] * um[0][j] + r[i][1] * um[1][j] + r[i][2] * um[2][j];
        m.m[i][3] = r[i][0] * parts.shift.x + r[i][1] * parts.shift.y + r[i][2] * parts.shift.z + parts.translation[i];
    }
    // x' = R (U x + shift) + translation, so x = U^-1 (R^T (x' - translation) - shift):
    // the inverse in closed form (U is upper triangular, R^T = R^-1), rather than
    // a general 4x4 elimination for every ray that meets a moving object.
    const double i0 = 1 / u[0], i3 = 1 / u[3], i5 = 1 / u[5];
    const double ui[3][3] = {{i0, -u[1] * i0 * i3, (u[1] * u[4] - u[2] * u[3]) * i0 * i3 * i5},
                             {0, i3, -u[4] * i3 * i5},
                             {0, 0, i5}};
    Mat4 inv;
    double back[3]; // R^T translation + shift
    for (int i = 0; i < 3; ++i)
        back[i] = r[0][i] * parts.translation.x + r[1][i] * parts.translation.y + r[2][i] * parts.translation.z +
                  parts.shift[i];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) inv.m[i][j] = ui[i][0] * r[j][0] + ui[i][1] * r[j][1] + ui[i][2] * r[j][2];
        inv.m[i][3] = -(ui[i][0] * back[0] + ui[i][1] * back[1] + ui[i][2] * back[2]);
    }
    return Transform::fromMatrixAndInverse(m, inv);
}

AffineParts interpolateParts(const AffineParts& a, const AffineParts& b, double s) {
    AffineParts p;
    p.translation = mix(a.translation, b.translation, s);
    p.shift = mix(a.shift, b.shift, s);
    for (int i = 0; i < 6; ++i) p.upper[i] = mix(a.upper[i], b.upper[i], s);
    p.rotation = slerp(a.rotation, b.rotation, s);
    return p;
}

double rotationBetween(const AffineParts& a, const AffineParts& b) {
    const double d = std::min(1.0, std::fabs(dot4(a.rotation, b.rotation)));
    return 2 * std::acos(d) * 180 / kPi;
}

void alignRotation(const AffineParts& a, AffineParts& b) {
    if (dot4(a.rotation, b.rotation) < 0)
        for (double& c : b.rotation) c = -c;
}

Vec3 bestPivot(const std::vector<PivotSample>& samples, const Vec3& fallback) {
    // Residual of p for one sample: B p + b, with B and b the linear parts and
    // translations of middle - ((1 - w) first + w last): the normal equations
    // M p = v with M = sum B^T B, v = -sum B^T b.
    double m[3][3] = {}, v[3] = {};
    for (const PivotSample& s : samples) {
        const Mat4 &f = s.first.matrix(), &c = s.middle.matrix(), &l = s.last.matrix();
        double bm[3][4];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) bm[i][j] = c.m[i][j] - ((1 - s.weight) * f.m[i][j] + s.weight * l.m[i][j]);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                for (int k = 0; k < 3; ++k) m[i][j] += bm[k][i] * bm[k][j];
            }
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) v[i] -= bm[k][i] * bm[k][3];
    }
    const double trace = m[0][0] + m[1][1] + m[2][2];
    if (!(trace > 0) || !std::isfinite(trace)) return fallback;
    const double lambda = 1e-9 * trace;
    Mat4 a;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) a.m[i][j] = m[i][j] + (i == j ? lambda : 0);
        a.m[i][3] = 0;
    }
    const std::optional<Mat4> inv = inverse(a);
    if (!inv) return fallback;
    // Iterated Tikhonov: from the fallback, each step removes all but a
    // fraction lambda / (sigma + lambda) of the error along every direction the
    // samples decide (eigenvalue sigma), and leaves the free directions alone.
    Vec3 p = fallback;
    for (int iteration = 0; iteration < 4; ++iteration) {
        Vec3 r;
        for (int i = 0; i < 3; ++i) r[i] = v[i] - (m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z);
        for (int i = 0; i < 3; ++i) p[i] += inv->m[i][0] * r.x + inv->m[i][1] * r.y + inv->m[i][2] * r.z;
    }
    return isFinite(p) ? p : fallback;
}

} // namespace drt

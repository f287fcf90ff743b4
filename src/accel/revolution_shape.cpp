#include "accel/revolution_shape.h"

#include "accel/polynomial.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

double evaluate(const double* c, int degree, double x) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
    return v;
}

double derivative(const double c[4], double x) { return (3 * c[3] * x + 2 * c[2]) * x + c[1]; }

// out = a * b for cubics (degree 6 result), accumulated.
void addProduct(const double a[4], const double b[4], double scale, double out[7]) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i + j] += scale * a[i] * b[j];
}

// Extremes of a cubic on [0, span]: the ends and the roots of its derivative.
void cubicRange(const double c[4], double span, double& lo, double& hi) {
    lo = std::min(c[0], evaluate(c, 3, span));
    hi = std::max(c[0], evaluate(c, 3, span));
    double roots[2];
    const int n = (c[3] == 0 && c[2] == 0) ? 0 : solveQuadratic(3 * c[3], 2 * c[2], c[1], roots);
    for (int i = 0; i < n; ++i) {
        if (roots[i] < 0 || roots[i] > span) continue;
        const double v = evaluate(c, 3, roots[i]);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
}

} // namespace

// Lathe segments as POV-Ray defines them, written as P(s) = D + C s + B s^2 + A s^3:
//  linear     P[i] .. P[i+1]:            C = P1 - P0, D = P0
//  quadratic  through P[i+1], P[i+2]:    B = (P0 - 2 P1 + P2) / 2, C = (P2 - P0) / 2, D = P1
//  cubic      Catmull-Rom P[i+1]..P[i+2] with P[i], P[i+3] setting the tangents
//  bezier     P[4k] .. P[4k+3] Bernstein.
// Sor segment i runs from P[i+1] to P[i+2]: the Hermite cubic of r^2 in y with
// slopes d(r^2)/dy = 2 r (r_next - r_prev) / (y_next - y_prev) at both ends,
// stored in u = y - y[i+1] (better conditioned than POV-Ray's powers of y).
RevolutionGeometry::RevolutionGeometry(const Revolution& rev) : kind_(rev.kind) {
    const std::vector<Vec2>& P = rev.points;
    const int n = static_cast<int>(P.size());
    if (n < minimumRevolutionPoints(rev.kind, rev.spline))
        throw std::invalid_argument(rev.kind == Revolution::Kind::Sor ? "sor needs at least 4 points"
                                                                      : "too few lathe points for its spline");
    for (const Vec2& p : P)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("revolution points must be finite");
    if (rev.kind == Revolution::Kind::Sor) {
        for (int i = 2; i < n - 1; ++i)
            if (!(P[i].y > P[i - 1].y)) throw std::invalid_argument("sor heights must increase");
        for (int i = 0; i + 3 < n; ++i) {
            if (P[i + 2].y == P[i].y || P[i + 3].y == P[i + 1].y)
                throw std::invalid_argument("sor heights must increase");
            const double k0 = P[i + 1].x * P[i + 1].x, k1 = P[i + 2].x * P[i + 2].x;
            const double k2 = 2 * P[i + 1].x * (P[i + 2].x - P[i].x) / (P[i + 2].y - P[i].y);
            const double k3 = 2 * P[i + 2].x * (P[i + 3].x - P[i + 1].x) / (P[i + 3].y - P[i + 1].y);
            const double h = P[i + 2].y - P[i + 1].y;
            const double slope = (k1 - k0) / h;
            Segment s{};
            s.r[0] = k0;
            s.r[1] = k2;
            s.r[2] = (3 * slope - 2 * k2 - k3) / h;
            s.r[3] = (k2 + k3 - 2 * slope) / (h * h);
            s.yLow = P[i + 1].y;
            s.yHigh = P[i + 2].y;
            double lo, hi;
            cubicRange(s.r, h, lo, hi);
            s.radiusMax = std::sqrt(std::max(0.0, hi));
            radiusMax_ = std::max(radiusMax_, s.radiusMax);
            segments_.push_back(s);
        }
        yMin_ = segments_.front().yLow;
        yMax_ = segments_.back().yHigh;
        baseRadius2_ = std::max(0.0, segments_.front().r[0]);
        capRadius2_ = std::max(0.0, evaluate(segments_.back().r, 3, yMax_ - segments_.back().yLow));
        solid_ = !rev.open;
        return;
    }
    using S = Revolution::Spline;
    if (rev.spline == S::Bezier && n % 4 != 0)
        throw std::invalid_argument("a Bezier lathe needs 4 points per segment");
    const int count = rev.spline == S::Linear ? n - 1
                      : rev.spline == S::Quadratic ? n - 2
                      : rev.spline == S::Cubic ? n - 3
                                               : n / 4;
    // Coefficients (D, C, B, A) of one coordinate from that coordinate of the points q.
    auto coefficients = [&](const double* q, double out[4]) {
        double A = 0, B = 0, C, D;
        if (rev.spline == S::Linear) {
            C = q[1] - q[0], D = q[0];
        } else if (rev.spline == S::Quadratic) {
            B = 0.5 * q[0] - q[1] + 0.5 * q[2], C = 0.5 * (q[2] - q[0]), D = q[1];
        } else if (rev.spline == S::Cubic) {
            A = -0.5 * q[0] + 1.5 * q[1] - 1.5 * q[2] + 0.5 * q[3];
            B = q[0] - 2.5 * q[1] + 2.0 * q[2] - 0.5 * q[3];
            C = 0.5 * (q[2] - q[0]), D = q[1];
        } else {
            A = q[3] - 3.0 * q[2] + 3.0 * q[1] - q[0];
            B = 3.0 * q[2] - 6.0 * q[1] + 3.0 * q[0];
            C = 3.0 * (q[1] - q[0]), D = q[0];
        }
        out[0] = D, out[1] = C, out[2] = B, out[3] = A;
    };
    const int used = rev.spline == S::Linear ? 2 : rev.spline == S::Quadratic ? 3 : 4;
    for (int k = 0; k < count; ++k) {
        const int base = rev.spline == S::Bezier ? 4 * k : k;
        double qr[4] = {0, 0, 0, 0}, qy[4] = {0, 0, 0, 0};
        for (int j = 0; j < used; ++j) qr[j] = P[size_t(base + j)].x, qy[j] = P[size_t(base + j)].y;
        Segment s{};
        coefficients(qr, s.r);
        coefficients(qy, s.y);
        double rlo, rhi;
        cubicRange(s.r, 1, rlo, rhi);
        cubicRange(s.y, 1, s.yLow, s.yHigh);
        s.radiusMax = std::max(std::fabs(rlo), std::fabs(rhi));
        radiusMax_ = std::max(radiusMax_, s.radiusMax);
        yMin_ = k == 0 ? s.yLow : std::min(yMin_, s.yLow);
        yMax_ = k == 0 ? s.yHigh : std::max(yMax_, s.yHigh);
        segments_.push_back(s);
    }
    // Closed: the outline returns to its start, or both ends lie on the axis
    // (the revolution closes there). Only then is there an inside.
    const Segment& first = segments_.front();
    const Segment& last = segments_.back();
    const Vec2 start{first.r[0], first.y[0]};
    const Vec2 end{evaluate(last.r, 3, 1), evaluate(last.y, 3, 1)};
    const double scale = std::max({radiusMax_, yMax_ - yMin_, 1e-300});
    closedOutline_ = std::hypot(end.x - start.x, end.y - start.y) <= 1e-12 * scale;
    solid_ = closedOutline_ || (std::fabs(start.x) <= 1e-12 * scale && std::fabs(end.x) <= 1e-12 * scale);
    // Orientation from the shoelace area of the sampled outline, closed back
    // to its start (along the axis when both ends lie on it).
    double area = 0;
    Vec2 previous = start;
    for (const Segment& s : segments_)
        for (int j = 1; j <= 16; ++j) {
            const double u = j / 16.0;
            const Vec2 q{evaluate(s.r, 3, u), evaluate(s.y, 3, u)};
            area += previous.x * q.y - q.x * previous.y;
            previous = q;
        }
    area += previous.x * start.y - start.x * previous.y;
    orientation_ = area >= 0 ? 1 : -1;
}

// |o_xz + t d_xz|^2 is a parabola in t; its least value over the t range in
// which the line is within [yLow, yHigh] (all t for a horizontal line) is
// compared with radiusMax^2, with a relative margin for rounding.
bool RevolutionGeometry::missesSegmentBound(const Segment& seg, const Vec3& o, const Vec3& d) {
    const double a = d.x * d.x + d.z * d.z, b = o.x * d.x + o.z * d.z;
    double lo = -INFINITY, hi = INFINITY;
    if (d.y != 0) {
        lo = (seg.yLow - o.y) / d.y, hi = (seg.yHigh - o.y) / d.y;
        if (lo > hi) std::swap(lo, hi);
        const double pad = 1e-9 * (std::fabs(lo) + std::fabs(hi)) + 1e-300;
        lo -= pad, hi += pad;
    } else if (o.y < seg.yLow || o.y > seg.yHigh) {
        return true;
    }
    double t = a > 0 ? -b / a : 0;
    t = std::clamp(t, lo, hi);
    if (!std::isfinite(t)) return false;
    const double px = o.x + t * d.x, pz = o.z + t * d.z;
    const double bound = seg.radiusMax * (1 + 1e-9) + 1e-300;
    return px * px + pz * pz > bound * bound;
}

// Half-open segments [0, 1) so a shared end is counted once; the last
// segment of an open outline keeps its end.
bool RevolutionGeometry::acceptS(size_t index, double s) const {
    if (s < 0) return false;
    if (s < 1) return true;
    return s == 1 && index + 1 == segments_.size() && !closedOutline_;
}

// Outward normal of the revolved curve: the 2D outward normal (y', -r') of a
// counter-clockwise outline, turned about the axis.
void RevolutionGeometry::addLatheHit(const Segment& seg, double s, double t, const Vec3& o, const Vec3& d,
                                     std::vector<Crossing>& out) const {
    // Newton steps on g1 = y(s) - oy - t dy, g2 = r(s)^2 - |p_xz(t)|^2 polish
    // the root (s from the polynomial alone is ill-conditioned for rays close
    // to horizontal); a step is kept only if it lowers the residual.
    auto residual = [&](double ss, double tt, double g[2]) {
        const Vec3 p = o + tt * d;
        const double r = evaluate(seg.r, 3, ss);
        g[0] = evaluate(seg.y, 3, ss) - p.y;
        g[1] = r * r - (p.x * p.x + p.z * p.z);
        return std::fabs(g[0]) + std::fabs(g[1]) / std::max(std::fabs(r), 1e-300);
    };
    double g[2];
    double err = residual(s, t, g);
    for (int iteration = 0; iteration < 3 && err > 0; ++iteration) {
        const Vec3 p = o + t * d;
        const double r = evaluate(seg.r, 3, s);
        const double j11 = derivative(seg.y, s), j12 = -d.y;
        const double j21 = 2 * r * derivative(seg.r, s), j22 = -2 * (p.x * d.x + p.z * d.z);
        const double det = j11 * j22 - j12 * j21;
        if (det == 0 || !std::isfinite(det)) break;
        const double ns = s - (g[0] * j22 - j12 * g[1]) / det;
        const double nt = t - (j11 * g[1] - j21 * g[0]) / det;
        double ng[2];
        const double nerr = residual(ns, nt, ng);
        if (!(nerr < err) || std::fabs(ns - s) > 1e-3) break;
        s = ns, t = nt, err = nerr, g[0] = ng[0], g[1] = ng[1];
    }
    const Vec3 p = o + t * d;
    const double rp = std::sqrt(p.x * p.x + p.z * p.z);
    const double dr = derivative(seg.r, s), dy = derivative(seg.y, s);
    // Sign of r(s) matters for splines dipping below the axis: the surface
    // point is at |r(s)|.
    const double side = evaluate(seg.r, 3, s) < 0 ? -1 : 1;
    Vec3 n = rp > 0 ? Vec3{dy * p.x / rp, -dr * side, dy * p.z / rp} : Vec3{0, -dr * side, 0};
    if (n.x == 0 && n.y == 0 && n.z == 0) n = {0, 1, 0};
    out.push_back({t, orientation_ * side * n});
}

void RevolutionGeometry::latheCrossings(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const {
    const double horizontalPart = std::sqrt(d.x * d.x + d.z * d.z);
    const bool horizontal = std::fabs(d.y) <= 1e-9 * horizontalPart;
    for (size_t k = 0; k < segments_.size(); ++k) {
        const Segment& seg = segments_[k];
        if (missesSegmentBound(seg, o, d)) continue;
        double Y[4] = {seg.y[0] - o.y, seg.y[1], seg.y[2], seg.y[3]};
        if (horizontal) {
            if (o.y < seg.yLow || o.y > seg.yHigh) continue;
            double roots[4];
            const int n = polynomialRootsInInterval(Y, 3, 0, 1, roots);
            for (int i = 0; i < n; ++i) {
                if (!acceptS(k, roots[i])) continue;
                const double r = evaluate(seg.r, 3, roots[i]);
                double ts[2];
                const int m = solveQuadratic(d.x * d.x + d.z * d.z, 2 * (o.x * d.x + o.z * d.z),
                                             o.x * o.x + o.z * o.z - r * r, ts);
                if (m == 2 && ts[0] == ts[1]) continue; // tangent graze
                for (int j = 0; j < m; ++j) addLatheHit(seg, roots[i], ts[j], o, d, out);
            }
            continue;
        }
        // (dy ox + dx Y)^2 + (dy oz + dz Y)^2 - dy^2 r^2 = 0 in s.
        double U[4], V[4];
        for (int i = 0; i < 4; ++i) U[i] = d.x * Y[i], V[i] = d.z * Y[i];
        U[0] += d.y * o.x;
        V[0] += d.y * o.z;
        double F[7] = {0, 0, 0, 0, 0, 0, 0};
        addProduct(U, U, 1, F);
        addProduct(V, V, 1, F);
        addProduct(seg.r, seg.r, -d.y * d.y, F);
        double roots[7];
        const int n = polynomialRootsInInterval(F, 6, 0, 1, roots);
        for (int i = 0; i < n; ++i) {
            if (!acceptS(k, roots[i])) continue;
            addLatheHit(seg, roots[i], evaluate(Y, 3, roots[i]) / d.y, o, d, out);
        }
    }
}

void RevolutionGeometry::sorCrossings(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const {
    for (size_t k = 0; k < segments_.size(); ++k) {
        const Segment& seg = segments_[k];
        const bool last = k + 1 == segments_.size();
        if (missesSegmentBound(seg, o, d)) continue;
        const double* a = seg.r;
        const double w0 = o.y - seg.yLow;
        // G(t) = f(w0 + t dy) - (ox + t dx)^2 - (oz + t dz)^2, f(u) = sum a_i u^i.
        const double G[4] = {
            evaluate(a, 3, w0) - (o.x * o.x + o.z * o.z),
            derivative(a, w0) * d.y - 2 * (o.x * d.x + o.z * d.z),
            (a[2] + 3 * a[3] * w0) * d.y * d.y - (d.x * d.x + d.z * d.z),
            a[3] * d.y * d.y * d.y,
        };
        double roots[4];
        int n = 0;
        if (d.y != 0) {
            double lo = (seg.yLow - o.y) / d.y, hi = (seg.yHigh - o.y) / d.y;
            if (lo > hi) std::swap(lo, hi);
            n = polynomialRootsInInterval(G, 3, lo, hi, roots);
        } else {
            if (o.y < seg.yLow || o.y > seg.yHigh) continue;
            n = solveQuadratic(G[2], G[1], G[0], roots);
            if (n == 2 && (roots[0] == roots[1] || G[2] == 0)) n = G[2] == 0 ? 1 : 0;
        }
        for (int i = 0; i < n; ++i) {
            const double t = roots[i];
            const Vec3 p = o + t * d;
            if (p.y < seg.yLow || (p.y >= seg.yHigh && !(last && p.y == seg.yHigh))) continue;
            out.push_back({t, Vec3{p.x, -0.5 * derivative(a, p.y - seg.yLow), p.z}});
        }
    }
    if (solid_ && d.y != 0) {
        const double tBase = (yMin_ - o.y) / d.y;
        const Vec3 pb = o + tBase * d;
        if (baseRadius2_ > 0 && pb.x * pb.x + pb.z * pb.z <= baseRadius2_) out.push_back({tBase, {0, -1, 0}});
        const double tCap = (yMax_ - o.y) / d.y;
        const Vec3 pc = o + tCap * d;
        if (capRadius2_ > 0 && pc.x * pc.x + pc.z * pc.z <= capRadius2_) out.push_back({tCap, {0, 1, 0}});
    }
}

void RevolutionGeometry::intersect(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const {
    out.clear();
    if (kind_ == Revolution::Kind::Sor) sorCrossings(o, d, out);
    else latheCrossings(o, d, out);
    out.erase(std::remove_if(out.begin(), out.end(), [](const Crossing& c) { return !std::isfinite(c.t); }),
              out.end());
    std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

// Lathe: odd count of outline crossings on the way from (r, y) towards
// larger r (POV-Ray's test). Sor: r^2 below the profile between the caps.
bool RevolutionGeometry::inside(const Vec3& p) const {
    if (!solid_ || p.y < yMin_ || p.y > yMax_) return false;
    const double r2 = p.x * p.x + p.z * p.z;
    if (kind_ == Revolution::Kind::Sor) {
        for (const Segment& seg : segments_)
            if (p.y >= seg.yLow && p.y <= seg.yHigh) return r2 < evaluate(seg.r, 3, p.y - seg.yLow);
        return false;
    }
    const double r = std::sqrt(r2);
    int crossings = 0;
    for (size_t k = 0; k < segments_.size(); ++k) {
        const Segment& seg = segments_[k];
        if (p.y < seg.yLow || p.y > seg.yHigh) continue;
        const double Y[4] = {seg.y[0] - p.y, seg.y[1], seg.y[2], seg.y[3]};
        double roots[4];
        const int n = polynomialRootsInInterval(Y, 3, 0, 1, roots);
        for (int i = 0; i < n; ++i)
            if (acceptS(k, roots[i]) && std::fabs(evaluate(seg.r, 3, roots[i])) > r) ++crossings;
    }
    return crossings % 2 == 1;
}

void RevolutionGeometry::bounds(Vec3& lower, Vec3& upper) const {
    lower = {-radiusMax_, yMin_, -radiusMax_};
    upper = {radiusMax_, yMax_, radiusMax_};
}

} // namespace drt::accel

#include "accel/extrusion_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

double cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
Vec2 sub(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }

} // namespace

ExtrusionGeometry::ExtrusionGeometry(const Extrusion& e)
    : plane_(e.plane), fill_(e.fill), h1_(std::min(e.height1, e.height2)), h2_(std::max(e.height1, e.height2)),
      conic_(e.conic), open_(e.open) {
    if (!std::isfinite(h1_) || !std::isfinite(h2_) || !(h2_ > h1_))
        throw std::invalid_argument("extrusion needs two different finite heights");
    if (conic_ && h1_ < 0 && h2_ > 0)
        throw std::invalid_argument("conic sweep heights must not lie on both sides of the apex (0)");
    lo_ = {INFINITY, INFINITY};
    hi_ = {-INFINITY, -INFINITY};
    for (const auto& contour : e.contours) {
        const size_t n = contour.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 a = contour[i], b = contour[(i + 1) % n];
            if (!std::isfinite(a.x) || !std::isfinite(a.y))
                throw std::invalid_argument("extrusion outline point is not finite");
            lo_ = {std::min(lo_.x, a.x), std::min(lo_.y, a.y)};
            hi_ = {std::max(hi_.x, a.x), std::max(hi_.y, a.y)};
            if (a.x != b.x || a.y != b.y) edges_.push_back({a, b, {}, false});
        }
    }
    if (e.contours.empty()) { // e.g. a text of spaces: nothing to hit
        lo_ = hi_ = {0, 0};
        empty_ = true;
        return;
    }
    if (edges_.size() < 3 || !(hi_.x > lo_.x) || !(hi_.y > lo_.y))
        throw std::invalid_argument("extrusion outline encloses no area");

    // Grid of about two cells per edge, shaped like the outline's bounds.
    const double w = hi_.x - lo_.x, h = hi_.y - lo_.y;
    const double cells = std::clamp(2.0 * double(edges_.size()), 1.0, double(1 << 20));
    nx_ = std::clamp(int(std::lround(std::sqrt(cells * w / h))), 1, 4096);
    ny_ = std::clamp(int(std::lround(cells / nx_)), 1, 4096);
    cell_ = {w / nx_, h / ny_};
    std::vector<uint32_t> counts(size_t(nx_) * ny_ + 1, 0);
    auto forCells = [&](const Edge& edge, auto&& visit) {
        const int c0 = column(std::min(edge.a.x, edge.b.x)), c1 = column(std::max(edge.a.x, edge.b.x));
        const int r0 = row(std::min(edge.a.y, edge.b.y)), r1 = row(std::max(edge.a.y, edge.b.y));
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) visit(size_t(r) * nx_ + c);
    };
    for (const Edge& edge : edges_) forCells(edge, [&](size_t cell) { ++counts[cell + 1]; });
    for (size_t i = 1; i < counts.size(); ++i) counts[i] += counts[i - 1];
    cellStart_ = counts;
    cellEdges_.resize(counts.back());
    for (uint32_t i = 0; i < edges_.size(); ++i) forCells(edges_[i], [&](size_t cell) { cellEdges_[counts[cell]++] = i; });

    // An edge is a wall where the fill differs on its two sides (with the
    // non-zero rule an edge inside another contour bounds nothing); its
    // outward normal points to the unfilled side.
    const double extent = std::max(w, h);
    for (Edge& edge : edges_) {
        const Vec2 along = sub(edge.b, edge.a);
        const double len = std::hypot(along.x, along.y);
        const Vec2 right{along.y / len, -along.x / len};
        const double step = std::min(1e-6 * extent, 0.25 * len);
        const Vec2 mid{0.5 * (edge.a.x + edge.b.x), 0.5 * (edge.a.y + edge.b.y)};
        const bool rightFilled = filled({mid.x + step * right.x, mid.y + step * right.y});
        const bool leftFilled = filled({mid.x - step * right.x, mid.y - step * right.y});
        edge.boundary = rightFilled != leftFilled;
        edge.outward = !edge.boundary ? Vec2{} : leftFilled ? right : Vec2{-right.x, -right.y};
    }
    if (std::none_of(edges_.begin(), edges_.end(), [](const Edge& edge) { return edge.boundary; }))
        throw std::invalid_argument("extrusion outline encloses no area");
}

int ExtrusionGeometry::column(double u) const {
    return std::clamp(int(std::floor((u - lo_.x) / cell_.x)), 0, nx_ - 1);
}
int ExtrusionGeometry::row(double v) const { return std::clamp(int(std::floor((v - lo_.y) / cell_.y)), 0, ny_ - 1); }

Vec3 ExtrusionGeometry::toLocal(const Vec3& p) const {
    return plane_ == Extrusion::Plane::XZ ? Vec3{p.x, p.z, p.y} : p;
}
Vec3 ExtrusionGeometry::fromLocal(const Vec3& l) const {
    return plane_ == Extrusion::Plane::XZ ? Vec3{l.x, l.z, l.y} : l;
}

// Crossings of a horizontal half-line from p, towards whichever end of the
// grid row is nearer, each counted in the grid cell of its crossing point
// only (an edge is listed in every cell its bounds overlap). Edges are
// half-open in v so a vertex counts once. An edge crossing upwards adds 1 to
// the winding number on the right of p and takes 1 off on the left.
bool ExtrusionGeometry::filled(Vec2 p) const {
    if (empty_) return false;
    if (!(p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y)) return false;
    const int r = row(p.y), start = column(p.x);
    const bool rightwards = start >= nx_ / 2;
    int winding = 0, crossings = 0;
    for (int c = start; c >= 0 && c < nx_; c += rightwards ? 1 : -1) {
        const size_t cell = size_t(r) * nx_ + c;
        for (uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
            const Edge& e = edges_[cellEdges_[k]];
            if ((e.a.y <= p.y) == (e.b.y <= p.y)) continue;
            double u = e.a.x + (p.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
            u = std::clamp(u, std::min(e.a.x, e.b.x), std::max(e.a.x, e.b.x));
            if ((rightwards ? !(u > p.x) : !(u < p.x)) || column(u) != c) continue;
            ++crossings;
            winding += (e.b.y > e.a.y) == rightwards ? 1 : -1;
        }
    }
    return fill_ == Extrusion::Fill::EvenOdd ? (crossings & 1) != 0 : winding != 0;
}

bool ExtrusionGeometry::inside(const Vec3& p) const {
    if (open_) return false;
    const Vec3 l = toLocal(p);
    if (!(l.z > h1_ && l.z < h2_)) return false;
    return conic_ ? filled({l.x / l.z, l.y / l.z}) : filled({l.x, l.y});
}

void ExtrusionGeometry::bounds(Vec3& lower, Vec3& upper) const {
    Vec3 lo{lo_.x, lo_.y, h1_}, hi{hi_.x, hi_.y, h2_};
    if (conic_) {
        lo.x = std::min({lo_.x * h1_, lo_.x * h2_, hi_.x * h1_, hi_.x * h2_});
        hi.x = std::max({lo_.x * h1_, lo_.x * h2_, hi_.x * h1_, hi_.x * h2_});
        lo.y = std::min({lo_.y * h1_, lo_.y * h2_, hi_.y * h1_, hi_.y * h2_});
        hi.y = std::max({lo_.y * h1_, lo_.y * h2_, hi_.y * h1_, hi_.y * h2_});
    }
    const Vec3 a = fromLocal(lo), b = fromLocal(hi);
    lower = min(a, b);
    upper = max(a, b);
}

// Linear sweep: the ray's shadow on the outline plane, clipped to the heights
// and the outline bounds, meets wall (a, b) where O + t D = a + s (b - a).
void ExtrusionGeometry::wallCrossingsLinear(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const {
    double t0 = -INFINITY, t1 = INFINITY;
    auto clip = [&](double origin, double dir, double lo, double hi) {
        if (dir == 0) {
            if (origin < lo || origin > hi) t0 = INFINITY;
            return;
        }
        double a = (lo - origin) / dir, b = (hi - origin) / dir;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    };
    clip(o.z, d.z, h1_, h2_);
    clip(o.x, d.x, lo_.x, hi_.x);
    clip(o.y, d.y, lo_.y, hi_.y);
    if (!(t0 <= t1) || (d.x == 0 && d.y == 0)) return;
    const Vec2 O{o.x, o.y}, D{d.x, d.y};
    const size_t first = out.size();
    // The cells each grid row's part of the clipped shadow passes through.
    const double va = o.y + t0 * d.y, vb = o.y + t1 * d.y;
    const int r0 = std::max(0, row(std::min(va, vb)) - 1), r1 = std::min(ny_ - 1, row(std::max(va, vb)) + 1);
    for (int r = r0; r <= r1; ++r) {
        double s0 = t0, s1 = t1;
        if (d.y != 0) {
            const double a = (lo_.y + r * cell_.y - o.y) / d.y, b = (lo_.y + (r + 1) * cell_.y - o.y) / d.y;
            s0 = std::max(t0, std::min(a, b));
            s1 = std::min(t1, std::max(a, b));
        }
        // One extra column each side absorbs rounding at cell borders.
        const double ua = o.x + s0 * d.x, ub = o.x + s1 * d.x;
        const int c0 = std::max(0, column(std::min(ua, ub)) - 1), c1 = std::min(nx_ - 1, column(std::max(ua, ub)) + 1);
        for (int c = c0; c <= c1; ++c) {
            const size_t cell = size_t(r) * nx_ + c;
            for (uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
                const Edge& e = edges_[cellEdges_[k]];
                if (!e.boundary) continue;
                const Vec2 along = sub(e.b, e.a);
                const double denom = cross2(D, along);
                if (denom == 0) continue;
                const Vec2 w = sub(e.a, O);
                const double t = cross2(w, along) / denom;
                const double s = cross2(w, D) / denom;
                if (!(s >= 0 && s < 1)) continue;
                const double height = o.z + t * d.z;
                if (!(height >= h1_ && height <= h2_)) continue;
                // The edge index rides in the normal's z until duplicates are removed.
                out.push_back({t, {e.outward.x, e.outward.y, double(cellEdges_[k])}});
            }
        }
    }
    // An edge listed in several cells was met once per cell.
    std::sort(out.begin() + first, out.end(),
              [](const Crossing& a, const Crossing& b) { return a.normal.z < b.normal.z; });
    out.erase(std::unique(out.begin() + first, out.end(),
                          [](const Crossing& a, const Crossing& b) { return a.normal.z == b.normal.z; }),
              out.end());
    for (size_t i = first; i < out.size(); ++i) out[i].normal.z = 0;
}

// Conic sweep: wall (a, b) lies in the plane through the apex spanned by
// (a, 1) and (b, 1) in (u, v, h); its points at height h are h (a + s (b - a)).
void ExtrusionGeometry::wallCrossingsConic(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const {
    for (const Edge& e : edges_) {
        if (!e.boundary) continue;
        const Vec3 A{e.a.x, e.a.y, 1}, B{e.b.x, e.b.y, 1};
        Vec3 n = cross(A, B);
        const double dn = dot(n, d);
        if (dn == 0) continue;
        const double t = -dot(n, o) / dn;
        const Vec3 p = o + t * d;
        if (!(p.z >= h1_ && p.z <= h2_) || p.z == 0) continue;
        const Vec2 q{p.x / p.z, p.y / p.z};
        const Vec2 along = sub(e.b, e.a);
        const double s = ((q.x - e.a.x) * along.x + (q.y - e.a.y) * along.y) / (along.x * along.x + along.y * along.y);
        if (!(s >= 0 && s < 1)) continue;
        // Outward at height h > 0 is the side of (outward, 0); the outline is mirrored below the apex.
        if ((dot(n, Vec3{e.outward.x, e.outward.y, 0}) < 0) != (p.z < 0)) n = -n;
        out.push_back({t, n});
    }
}

void ExtrusionGeometry::intersect(const Vec3& oObject, const Vec3& dObject, std::vector<Crossing>& out) const {
    out.clear();
    if (empty_) return;
    const Vec3 o = toLocal(oObject), d = toLocal(dObject);
    if (conic_) wallCrossingsConic(o, d, out);
    else wallCrossingsLinear(o, d, out);
    if (!open_ && d.z != 0) {
        const double heights[2] = {h1_, h2_};
        for (int i = 0; i < 2; ++i) {
            const double h = heights[i];
            if (conic_ && h == 0) continue; // the apex: a point, not a cap
            const double t = (h - o.z) / d.z;
            Vec2 q{o.x + t * d.x, o.y + t * d.y};
            if (conic_) q = {q.x / h, q.y / h};
            if (filled(q)) out.push_back({t, {0, 0, i == 0 ? -1.0 : 1.0}});
        }
    }
    for (Crossing& c : out) c.normal = fromLocal(c.normal);
    std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
}

} // namespace drt::accel

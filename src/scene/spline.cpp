#include "scene/spline.h"

#include <algorithm>
#include <cstddef>

namespace drt {

namespace {

using Values = std::array<double, 5>;

Values mix(const Values& a, const Values& b, double wa, double wb) {
    Values r{};
    for (size_t k = 0; k < 5; ++k) r[k] = wa * a[k] + wb * b[k];
    return r;
}

// The index of the first entry with t above `t` (0 at or below the first, size at or above the last).
size_t above(const std::vector<Spline::Entry>& e, double t) {
    if (!(t > e.front().t)) return 0;
    if (t >= e.back().t) return e.size();
    size_t lo = 0, hi = e.size() - 1; // e[lo].t < t < e[hi].t... t <= e[hi].t
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (t > e[mid].t) lo = mid;
        else hi = mid;
    }
    return hi;
}

// The parabola through entries i-1, i, i+1, at t (Lagrange form).
double parabola(const std::vector<Spline::Entry>& e, size_t i, size_t k, double t) {
    const double t0 = e[i - 1].t, t1 = e[i].t, t2 = e[i + 1].t;
    return e[i - 1].v[k] * (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2)) +
           e[i].v[k] * (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2)) +
           e[i + 1].v[k] * (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
}

// Catmull-Rom on the interval from entry i to i+1 (entries i-1 and i+2 exist).
double catmullRom(const std::vector<Spline::Entry>& e, size_t i, size_t k, double t) {
    const double dt = e[i + 1].t - e[i].t;
    const double s = (t - e[i].t) / dt, s2 = s * s, s3 = s2 * s;
    const double before = (e[i].v[k] - e[i - 1].v[k]) / (e[i].t - e[i - 1].t);
    const double within = (e[i + 1].v[k] - e[i].v[k]) / dt;
    const double after = (e[i + 2].v[k] - e[i + 1].v[k]) / (e[i + 2].t - e[i + 1].t);
    const double m0 = (before + within) / 2 * dt, m1 = (within + after) / 2 * dt;
    return e[i].v[k] * (2 * s3 - 3 * s2 + 1) + e[i + 1].v[k] * (3 * s2 - 2 * s3) + m0 * (s3 - 2 * s2 + s) +
           m1 * (s3 - s2);
}

// The second derivatives of the natural cubic spline through the entries' component k.
std::vector<double> naturalCurvatures(const std::vector<Spline::Entry>& e, size_t k) {
    const size_t n = e.size();
    std::vector<double> m(n, 0.0);
    if (n < 3) return m;
    // Tridiagonal system for m[1..n-2], m[0] = m[n-1] = 0 (Thomas algorithm).
    std::vector<double> diag(n, 0.0), rhs(n, 0.0);
    auto h = [&](size_t i) { return e[i + 1].t - e[i].t; };
    auto slope = [&](size_t i) { return (e[i + 1].v[k] - e[i].v[k]) / h(i); };
    diag[1] = 2 * (h(0) + h(1));
    rhs[1] = 6 * (slope(1) - slope(0));
    for (size_t i = 2; i + 1 < n; ++i) {
        const double w = h(i - 1) / diag[i - 1];
        diag[i] = 2 * (h(i - 1) + h(i)) - w * h(i - 1);
        rhs[i] = 6 * (slope(i) - slope(i - 1)) - w * rhs[i - 1];
    }
    for (size_t i = n - 2; i > 0; --i) m[i] = (rhs[i] - h(i) * m[i + 1]) / diag[i];
    return m;
}

} // namespace

void Spline::insert(std::vector<Entry> added) {
    const auto earlier = [](const Entry& a, const Entry& b) { return a.t < b.t; };
    std::stable_sort(added.begin(), added.end(), earlier); // equal t stay in the order given
    std::vector<Entry> merged;
    merged.reserve(entries.size() + added.size());
    size_t old = 0;
    for (size_t j = 0; j < added.size();) {
        // A run of equal t: the first one's t (or the old entry's), the last one's value.
        size_t last = j;
        while (last + 1 < added.size() && added[last + 1].t == added[j].t) ++last;
        while (old < entries.size() && entries[old].t < added[j].t) merged.push_back(entries[old++]);
        Entry e{added[j].t, added[last].v};
        if (old < entries.size() && entries[old].t == e.t) e.t = entries[old++].t;
        merged.push_back(e);
        j = last + 1;
    }
    merged.insert(merged.end(), entries.begin() + std::ptrdiff_t(old), entries.end());
    entries = std::move(merged);
    for (size_t k = 0; k < 5; ++k) curvatures[k] = naturalCurvatures(entries, k);
}

Values Spline::at(double t, Kind as) const {
    const std::vector<Entry>& e = entries;
    if (e.empty()) return Values{};
    if (e.size() == 1) return e.front().v;
    const size_t i = above(e, t); // t lies between e[i-1] and e[i]
    const size_t n = e.size();
    if (as == Kind::Cubic) {
        if (n == 2) return mix(e[0].v, e[1].v, 0.5, 0.5);
        if (i < 2) return e[1].v;
        if (i >= n - 1) return e[n - 2].v;
    } else {
        if (i == 0) return e.front().v;
        if (i >= n) return e.back().v;
    }
    Values r{};
    switch (as) {
    case Kind::Linear: {
        const double w = (t - e[i - 1].t) / (e[i].t - e[i - 1].t);
        return mix(e[i - 1].v, e[i].v, 1 - w, w);
    }
    case Kind::Quadratic:
        if (n == 2) return at(t, Kind::Linear);
        for (size_t k = 0; k < 5; ++k) r[k] = parabola(e, i > 1 ? i - 1 : i, k, t);
        return r;
    case Kind::Cubic:
        for (size_t k = 0; k < 5; ++k) r[k] = catmullRom(e, i - 1, k, t);
        return r;
    case Kind::Natural:
        for (size_t k = 0; k < 5; ++k) {
            const std::vector<double>& m = curvatures[k];
            const size_t a = i - 1;
            const double h = e[a + 1].t - e[a].t, d = t - e[a].t;
            const double slope = (e[a + 1].v[k] - e[a].v[k]) / h - h * (m[a + 1] + 2 * m[a]) / 6;
            r[k] = e[a].v[k] + d * (slope + d * (m[a] / 2 + d * (m[a + 1] - m[a]) / (6 * h)));
        }
        return r;
    }
    return r;
}

bool Spline::operator==(const Spline& o) const {
    if (kind != o.kind || terms != o.terms || entries.size() != o.entries.size()) return false;
    for (size_t i = 0; i < entries.size(); ++i)
        if (entries[i].t != o.entries[i].t || entries[i].v != o.entries[i].v) return false;
    return true;
}

const char* splineKindWord(Spline::Kind kind) {
    switch (kind) {
    case Spline::Kind::Linear: return "linear_spline";
    case Spline::Kind::Quadratic: return "quadratic_spline";
    case Spline::Kind::Cubic: return "cubic_spline";
    case Spline::Kind::Natural: return "natural_spline";
    }
    return "linear_spline";
}

} // namespace drt

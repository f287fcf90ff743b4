// POV-Ray's `spline { ... }` value: entries (a parameter and up to five
// components) read as a curve of one of four kinds, evaluated at a parameter
// as the scene is read (`S(t)`) or inside a function (`F(x).y`).
#pragma once

#include <array>
#include <vector>

namespace drt {

struct Spline {
    enum class Kind { Linear, Quadratic, Cubic, Natural };
    struct Entry {
        double t = 0;
        std::array<double, 5> v{};
    };
    Kind kind = Kind::Linear;
    std::vector<Entry> entries; // by increasing t, no two alike
    int terms = 2;              // components of a value: the most any entry gave, at least 2
    // The natural spline's second derivatives at the entries, per component (kept by insert).
    std::array<std::vector<double>, 5> curvatures;

    // Adds entries in order of t, as if each were inserted in turn: an entry of
    // the same t as one before it (given earlier or already there) replaces that
    // one's value, which keeps its t. The entries are sorted and the curvatures
    // solved once for the lot, so a scene's loop that adds entries one by one
    // costs O(n log n), not O(n^2).
    void insert(std::vector<Entry> added);
    void insert(double t, const std::array<double, 5>& v) { insert(std::vector<Entry>{Entry{t, v}}); }
    // The value at t by `as`'s rules (POV-Ray 3.7's): outside the entries, the
    // end entry's value. linear: straight between neighbours. quadratic: the
    // parabola through the entry before, the two around t (the first three
    // before the second entry). cubic: Catmull-Rom between the second and the
    // next-to-last entries (the ends are control points), each tangent the mean
    // of the slopes of its two neighbouring intervals; fewer than four entries
    // give the second (three) or the mean of both (two). natural: the natural
    // cubic spline through all entries (zero second derivative at the ends).
    std::array<double, 5> at(double t, Kind as) const;
    std::array<double, 5> at(double t) const { return at(t, kind); }
    bool operator==(const Spline& o) const;
};

const char* splineKindWord(Spline::Kind kind); // "linear_spline", ...

} // namespace drt

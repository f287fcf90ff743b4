// Surfaces of revolution about the y axis: POV-Ray's `lathe` (a 2D spline in
// (radius, height) revolved) and `sor` (r^2 a piecewise cubic of the height).
// The points are kept as written; accel/revolution_shape builds the segments.
#pragma once

#include "core/vec.h"

#include <vector>

namespace drt {

struct Revolution {
    enum class Kind { Lathe, Sor };
    enum class Spline { Linear, Quadratic, Cubic, Bezier }; // lathe only; a sor is always cubic
    Kind kind = Kind::Lathe;
    Spline spline = Spline::Linear;
    std::vector<Vec2> points; // <radius, height>
    bool open = false;        // sor: no base and cap discs
    bool sturm = false;       // POV-Ray's root-finder choice; kept for round trips only
    bool closedSolid() const { return kind == Kind::Sor && !open; }
    bool operator==(const Revolution& o) const {
        return kind == o.kind && spline == o.spline && points == o.points && open == o.open;
    }
};

// The fewest points each form accepts (a Bezier lathe also needs a multiple of 4).
inline int minimumRevolutionPoints(Revolution::Kind kind, Revolution::Spline spline) {
    if (kind == Revolution::Kind::Sor) return 4;
    switch (spline) {
    case Revolution::Spline::Linear: return 2;
    case Revolution::Spline::Quadratic: return 3;
    case Revolution::Spline::Cubic: return 4;
    case Revolution::Spline::Bezier: return 4;
    }
    return 2;
}

} // namespace drt

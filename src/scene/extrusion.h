// The extrusion shape of the scene model: closed 2D outlines swept along an
// axis between two heights. POV-Ray's `prism` and `text` objects are both
// extrusions; how each was written is kept beside the outline so the .drt
// writer can write it back the same way (src/outline builds the outlines).
#pragma once

#include "core/heap_optional.h"
#include "core/vec.h"

#include <optional>
#include <string>
#include <vector>

namespace drt {

// A prism as written: points of a spline in the x-z plane (POV-Ray's prism).
struct PrismSource {
    enum class Spline { Linear, Quadratic, Cubic, Bezier };
    Spline spline = Spline::Linear;
    std::vector<Vec2> points; // <x, z>
};

// A text object as written: glyphs of `string` from a TrueType font.
struct TextSource {
    std::string font;     // as written in the scene
    std::string fontPath; // the file it was found at
    std::string string;   // UTF-8
    Vec3 offset{0, 0, 0}; // extra shift after each glyph (x and y; POV-Ray ignores z)
    // Derived: POV-Ray's bounding box of the glyphs in x and y (each glyph's
    // control box at its place, a glyph without outline a point at its origin).
    Vec2 boxLower, boxUpper;
};

struct Extrusion {
    // Which object-space plane holds the outline and which axis it is swept along.
    enum class Plane {
        XZ, // 2D point (u, v) is (x, z); swept along y (prism)
        XY, // 2D point (u, v) is (x, y); swept along z (text)
    };
    // Inside of the outline: odd crossing count (POV-Ray's prism) or non-zero
    // winding number (TrueType glyphs).
    enum class Fill { EvenOdd, NonZero };

    // Closed polylines: each contour's last point joins its first.
    std::vector<std::vector<Vec2>> contours;
    Plane plane = Plane::XZ;
    Fill fill = Fill::EvenOdd;
    double height1 = 0, height2 = 1; // along the sweep axis
    // Conic sweep: the outline at height h is the given one scaled by h about
    // the axis (apex at the origin), POV-Ray's conic_sweep.
    bool conic = false;
    bool open = false; // no end caps
    // The source the outline was built from, if any (for the writer).
    // (On the heap: they are large, and most shapes in a scene are not extrusions.)
    HeapOptional<PrismSource> prism;
    HeapOptional<TextSource> text;
    bool closedSolid() const { return !open; }
    bool operator==(const Extrusion& o) const { // the outline, not the source it was built from
        return contours == o.contours && plane == o.plane && fill == o.fill && height1 == o.height1 &&
               height2 == o.height2 && conic == o.conic && open == o.open;
    }
};

} // namespace drt

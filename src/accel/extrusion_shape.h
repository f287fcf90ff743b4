// Ray crossings of an extrusion (scene/extrusion.h) in double precision:
// the end caps (ray-plane, then a point-in-outline test) and the side walls
// (each outline edge swept along the axis). A uniform 2D grid over the outline
// keeps both tests near constant time for outlines with thousands of edges
// (text): the point test walks one grid row, the wall test only the cells the
// ray's shadow on the outline plane passes through.
#pragma once

#include "accel/shapes.h"
#include "scene/extrusion.h"

#include <cstdint>
#include <vector>

namespace drt::accel {

class ExtrusionGeometry {
public:
    // Throws std::invalid_argument for a non-finite outline, one without area,
    // or equal heights. No contours at all (a text of spaces) is an empty shape.
    explicit ExtrusionGeometry(const Extrusion& e);

    // Every crossing of the line o + t d (object space), sorted by t, with
    // outward object-space normals; replaces `out`.
    void intersect(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;
    bool inside(const Vec3& p) const; // strictly inside (false for open extrusions)
    bool solid() const { return !open_; }
    void bounds(Vec3& lower, Vec3& upper) const;

    // Whether the 2D point is inside the outline (at height 1 for conic sweeps).
    bool filled(Vec2 p) const;

private:
    struct Edge {
        Vec2 a, b;
        Vec2 outward;      // unit, 2D; zero for edges that bound nothing
        bool boundary = false;
    };
    // Object space <-> (u, v, h): outline plane coordinates and height.
    Vec3 toLocal(const Vec3& p) const;
    Vec3 fromLocal(const Vec3& l) const;
    int column(double u) const;
    int row(double v) const;
    void wallCrossingsLinear(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;
    void wallCrossingsConic(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;

    std::vector<Edge> edges_;
    Extrusion::Plane plane_;
    Extrusion::Fill fill_;
    double h1_, h2_;
    bool conic_, open_;
    bool empty_ = false;
    Vec2 lo_, hi_;      // outline bounds
    Vec2 cell_;         // grid cell size
    int nx_ = 1, ny_ = 1;
    std::vector<uint32_t> cellStart_; // nx * ny + 1 offsets into cellEdges_
    std::vector<uint32_t> cellEdges_;
};

} // namespace drt::accel

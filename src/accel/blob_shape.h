// Ray crossings of POV-Ray's blob (scene/blob.h) in double precision. Each
// component splits into pieces on which (d/r)^2 is a quadratic q(t) along the
// ray: a sphere is one piece; a cylinder is its body (distance to the axis
// line, where the projection on the axis lies within the segment) and two
// hemispherical ends (distance to an end point, beyond it). On a piece the
// field strength (1 - q)^2 is a quartic in t. The line is cut at every
// piece's interval ends; on each cut the sum of the active quartics minus the
// threshold is solved with the robust root finder (accel/polynomial.h).
// Normals are minus the field's gradient.
#pragma once

#include "accel/line_cull.h"
#include "accel/shapes.h"
#include "scene/blob.h"

#include <vector>

namespace drt::accel {

class BlobGeometry {
public:
    // Throws std::invalid_argument for no component, a non-positive or
    // non-finite radius, threshold or strength, or a cylinder with equal ends.
    // `spatialIndex` false tests every component for every line and point (the
    // same results, to the bit; for tests).
    explicit BlobGeometry(const Blob& blob, bool spatialIndex = true);

    // Every crossing of the line o + t d, sorted by t, outward normals.
    void intersect(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const;
    bool inside(const Vec3& p) const { return field(p) > threshold_; }
    void bounds(Vec3& lower, Vec3& upper) const { lower = lower_, upper = upper_; }

    double field(const Vec3& p) const;
    Vec3 gradient(const Vec3& p) const;

private:
    struct Component {
        BlobComponent::Kind kind;
        Vec3 center, axis; // component space; axis: unit, cylinders only
        double length = 0;  // cylinders: |end - center|
        double radius2 = 1, strength = 1;
        Transform toBlob;
        bool transformed = false;
    };
    // Component-space vector from the nearest point of the component's core
    // (centre or axis segment) to q.
    static Vec3 offsetFromCore(const Component& c, const Vec3& q);

    // The components a line or a point may meet, in their order (so sums are
    // made in the same order as over all of them): with many components, a
    // bounding-box hierarchy over the untransformed spheres skips those whose
    // box, grown by a margin far above the rounding of the tests it replaces,
    // the line misses or the point lies outside; the others are always taken.
    // The candidates' indices in `scratch`, or nullptr for every component;
    // `count` is set to their number.
    const int* lineCandidates(const Vec3& o, const Vec3& d, std::vector<int>& scratch, size_t& count) const;
    const int* pointCandidates(const Vec3& p, std::vector<int>& scratch, size_t& count) const;
    void buildIndex();
    BoxHierarchy index_;         // over the untransformed spheres; empty: every component is a candidate
    std::vector<int> unindexed_; // the rest, in order
    double reach_ = 0;             // max |coordinate| of the indexed boxes plus their largest side
    double smallestRadius_ = 0;    // of the indexed spheres

    std::vector<Component> components_;
    double threshold_ = 1;
    Vec3 lower_, upper_;
};

} // namespace drt::accel

// A conservative test of whether a whole line o + t d (every t) misses a box,
// for skipping parts of a shape that a line cannot meet (CSG leaves, blob
// components), and a bounding-box hierarchy over such parts, so that a line
// finds the few it may meet in about a logarithm of their number. Callers grow
// the boxes by a margin far above their solvers' rounding, so that a skipped
// part is one the solver would have found no crossing with; the test's own
// rounding is of order 1e-16 |o|.
#pragma once

#include "core/vec.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace drt::accel {

struct CullLine {
    Vec3 o, inverseD;  // the direction's reciprocals, 0 on an axis the line runs across
    bool across[3];    // d is 0 on this axis: the line keeps o's coordinate
    double originNorm; // max |o_i|
    bool usable;       // o and the reciprocals are finite; else nothing may be skipped
};

inline CullLine cullLine(const Vec3& o, const Vec3& d) {
    CullLine line{o, Vec3(0.0), {}, maxComponent(abs(o)), isFinite(o) && isFinite(d)};
    for (int axis = 0; axis < 3; ++axis) {
        line.across[axis] = d[axis] == 0;
        if (!line.across[axis]) line.inverseD[axis] = 1 / d[axis];
    }
    line.usable = line.usable && isFinite(line.inverseD) && std::isfinite(line.originNorm);
    return line;
}

// Whether the line misses [lower - margin, upper + margin] (a usable line only).
inline bool lineMissesBox(const CullLine& line, const Vec3& lower, const Vec3& upper, double margin) {
    double tNear = -HUGE_VAL, tFar = HUGE_VAL;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = lower[axis] - margin - line.o[axis], hi = upper[axis] + margin - line.o[axis];
        if (line.across[axis]) {
            if (lo > 0 || hi < 0) return true;
            continue;
        }
        const double t0 = lo * line.inverseD[axis], t1 = hi * line.inverseD[axis];
        tNear = std::max(tNear, std::min(t0, t1));
        tFar = std::min(tFar, std::max(t0, t1));
    }
    return tNear > tFar;
}

// A bounding-box hierarchy over numbered items: median splits along the longest
// side of the box of the items' centres, up to kLeafSize items a leaf.
class BoxHierarchy {
public:
    static constexpr int kLeafSize = 4;
    struct Node {
        Vec3 lower, upper;        // the union of its items' boxes
        int first = 0, count = 0; // a leaf: items()[first, first + count)
        int second = 0;           // an inner node: its first child follows it, its second is here
    };

    // Builds over `items` (at least one), whose boxes and centres are
    // lower[i], upper[i] and centre[i] for item i.
    void build(std::vector<int> items, const std::vector<Vec3>& lower, const std::vector<Vec3>& upper,
               const std::vector<Vec3>& centre) {
        items_ = std::move(items);
        nodes_.clear();
        const auto split = [&](auto& self, int first, int count) -> void {
            const size_t node = nodes_.size();
            nodes_.push_back({});
            Vec3 lo(HUGE_VAL), hi(-HUGE_VAL), centreLower(HUGE_VAL), centreUpper(-HUGE_VAL);
            for (int k = first; k < first + count; ++k) {
                const size_t item = size_t(items_[size_t(k)]);
                lo = min(lo, lower[item]);
                hi = max(hi, upper[item]);
                centreLower = min(centreLower, centre[item]);
                centreUpper = max(centreUpper, centre[item]);
            }
            nodes_[node].lower = lo;
            nodes_[node].upper = hi;
            if (count <= kLeafSize) {
                nodes_[node].first = first;
                nodes_[node].count = count;
                return;
            }
            const Vec3 extent = centreUpper - centreLower;
            const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
            const int half = count / 2;
            std::nth_element(items_.begin() + first, items_.begin() + first + half, items_.begin() + first + count,
                             [&](int a, int b) { return centre[size_t(a)][axis] < centre[size_t(b)][axis]; });
            self(self, first, half);
            nodes_[node].second = int(nodes_.size());
            self(self, first + half, count - half);
        };
        split(split, 0, int(items_.size()));
    }

    bool empty() const { return nodes_.empty(); }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<int>& items() const { return items_; }

    // Appends to `out` the items of every leaf whose box and whose ancestors'
    // boxes `overlaps(nodeIndex)` accepts, in no particular order.
    template <class Overlaps>
    void gather(Overlaps overlaps, std::vector<int>& out) const {
        int stack[64], depth = 0; // the depth is about log2(items / kLeafSize)
        stack[depth++] = 0;
        while (depth > 0) {
            const int at = stack[--depth];
            const Node& node = nodes_[size_t(at)];
            if (!overlaps(at)) continue;
            if (node.count > 0) {
                out.insert(out.end(), items_.begin() + node.first, items_.begin() + node.first + node.count);
                continue;
            }
            stack[depth++] = node.second;
            stack[depth++] = at + 1;
        }
    }

private:
    std::vector<Node> nodes_;
    std::vector<int> items_;
};

} // namespace drt::accel

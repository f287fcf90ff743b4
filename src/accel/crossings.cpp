// Ray crossings of analytic primitives in level space: single shapes and CSG
// trees (Roth 1982: classify the ray's spans against each leaf, combine the
// leaves' inside/outside states with the tree's operations, and report the
// points where the combined state changes).
#include "accel/built_scene.h"

#include <algorithm>
#include <cmath>

namespace drt::accel {

namespace {



struct LeafEvent {
    double t;
    int order; // position in the list before sorting: ties keep it
    int leaf;
    bool entering;
    Vec3 normal; // object space
};

// Scratch space kept per thread (no allocation per ray once warm:
// accel/thread_scratch.h), one list per use.
struct CrossingScratch {
    std::vector<const CsgNode*> leaves;
    std::vector<char> silent;
    std::vector<LeafEvent> events;
    std::vector<char> state;
    std::vector<Crossing> leafMany, closestMany;
    std::vector<SurfaceCrossing> nearestAll, closestAll;
};
CrossingScratch& crossingScratch() { return ThreadScratch<CrossingScratch>::get(); }

// Leaves in DFS order (children, then clips); a leaf under a clip is silent:
// its crossings change the state but are not surfaces.
void collectLeaves(const CsgNode& node, bool silent, std::vector<const CsgNode*>& leaves,
                   std::vector<char>& silentLeaves) {
    if (node.leaf) {
        leaves.push_back(&node);
        silentLeaves.push_back(silent);
    }
    for (const CsgNode& child : node.children) collectLeaves(child, silent, leaves, silentLeaves);
    for (const CsgNode& clip : node.clips) collectLeaves(clip, true, leaves, silentLeaves);
}

// Evaluates the tree on the leaves' current states (leaves in collectLeaves'
// order). A leaf's state already includes its inversion.
bool evaluate(const CsgNode& node, const std::vector<char>& state, int& nextLeaf) {
    bool inside = false;
    if (node.leaf) {
        inside = state[nextLeaf++] != 0;
    } else {
        bool first = true;
        for (const CsgNode& child : node.children) {
            const bool c = evaluate(child, state, nextLeaf);
            switch (node.op) {
            case Csg::Op::Union:
            case Csg::Op::Merge: inside = first ? c : (inside || c); break;
            case Csg::Op::Intersection: inside = first ? c : (inside && c); break;
            case Csg::Op::Difference: inside = first ? c : (inside && !c); break;
            }
            first = false;
        }
        inside = inside != node.inverse;
    }
    for (const CsgNode& clip : node.clips) {
        const bool c = evaluate(clip, state, nextLeaf); // always: it advances nextLeaf
        inside = inside && c;
    }
    return inside;
}


} // namespace

bool insideNode(const CsgNode& node, const Vec3& p) {
    bool inside = false;
    if (node.leaf) {
        inside = isSolidShape(node.shape) && insideShape(node.shape, node.toLevel.inversePoint(p));
    } else {
        bool first = true;
        for (const CsgNode& child : node.children) {
            const bool c = insideNode(child, p);
            switch (node.op) {
            case Csg::Op::Union:
            case Csg::Op::Merge: inside = first ? c : (inside || c); break;
            case Csg::Op::Intersection: inside = first ? c : (inside && c); break;
            case Csg::Op::Difference: inside = first ? c : (inside && !c); break;
            }
            first = false;
        }
    }
    inside = inside != node.inverse;
    for (const CsgNode& clip : node.clips) inside = inside && insideNode(clip, p);
    return inside;
}

std::unique_ptr<InstalledScratch> installCrossingScratch() { return ThreadScratch<CrossingScratch>::install(); }

void csgCrossings(const CsgNode& root, const Vec3& o, const Vec3& d, std::vector<SurfaceCrossing>& out) {
    out.clear();
    CrossingScratch& scratch = crossingScratch();
    std::vector<const CsgNode*>& leaves = scratch.leaves;
    std::vector<char>& silent = scratch.silent;
    std::vector<LeafEvent>& events = scratch.events;
    std::vector<char>& state = scratch.state;
    leaves.clear();
    silent.clear();
    events.clear();
    collectLeaves(root, false, leaves, silent);
    state.assign(leaves.size(), 0);
    for (size_t i = 0; i < leaves.size(); ++i) {
        const CsgNode& leaf = *leaves[i];
        const Vec3 lo = leaf.toLevel.inversePoint(o), ld = leaf.toLevel.inverseVector(d);
        thread_local Crossing fixed[kMaxCrossings]; // not zero-initialised per leaf
        std::vector<Crossing>& many = scratch.leafMany;
        const Crossing* c = nullptr;
        const int n = allCrossings(leaf.shape, lo, ld, fixed, many, c);
        const bool solid = isSolidShape(leaf.shape);
        for (int k = 0; solid && k < n; ++k)
            events.push_back({c[k].t, static_cast<int>(events.size()), static_cast<int>(i), dot(c[k].normal, ld) < 0,
                              c[k].normal});
        // State before the first crossing along the whole line.
        bool inside = false;
        if (solid) inside = n > 0 ? dot(c[0].normal, ld) > 0 : insideShape(leaf.shape, lo);
        state[i] = inside != leaf.inverse;
    }
    // A stable sort by t without std::stable_sort's temporary buffer.
    std::sort(events.begin(), events.end(),
              [](const LeafEvent& a, const LeafEvent& b) { return a.t < b.t || (a.t == b.t && a.order < b.order); });
    int cursor = 0;
    bool inside = evaluate(root, state, cursor);
    for (const LeafEvent& e : events) {
        const CsgNode& leaf = *leaves[e.leaf];
        state[e.leaf] = e.entering != leaf.inverse;
        cursor = 0;
        const bool now = evaluate(root, state, cursor);
        if (now == inside) continue;
        inside = now;
        if (silent[e.leaf]) continue;
        Vec3 n = unitOrZero(leaf.toLevel.normal(e.normal));
        // Outward from the combined solid: against the ray when entering it.
        if ((dot(n, d) < 0) != now) n = -n;
        out.push_back({e.t, n, leaf.object});
    }
}

bool clipBounds(const std::vector<CsgNode>& clips, bool bounded, Vec3& lower, Vec3& upper) {
    for (const CsgNode& clip : clips) {
        Vec3 lo, hi;
        if (!csgBounds(clip, lo, hi)) continue;
        lower = bounded ? max(lower, lo) : lo;
        upper = bounded ? min(upper, hi) : hi;
        bounded = true;
    }
    if (bounded) upper = max(upper, lower); // nothing left: a point-sized box
    return bounded;
}

namespace {
// Bounds of the node without its clips.
bool unclippedBounds(const CsgNode& node, Vec3& lower, Vec3& upper) {
    if (node.inverse) return false;
    if (node.leaf) {
        if (!shapeBounds(node.shape, lower, upper)) return false;
        transformBounds(node.toLevel, lower, upper);
        return true;
    }
    bool any = false;
    for (size_t i = 0; i < node.children.size(); ++i) {
        Vec3 lo, hi;
        const bool bounded = csgBounds(node.children[i], lo, hi);
        switch (node.op) {
        case Csg::Op::Union:
        case Csg::Op::Merge:
            if (!bounded) return false;
            lower = any ? min(lower, lo) : lo;
            upper = any ? max(upper, hi) : hi;
            any = true;
            break;
        case Csg::Op::Intersection:
            if (!bounded) break;
            lower = any ? max(lower, lo) : lo;
            upper = any ? min(upper, hi) : hi;
            any = true;
            break;
        case Csg::Op::Difference:
            if (i == 0) {
                if (!bounded) return false;
                lower = lo;
                upper = hi;
                any = true;
            }
            break;
        }
    }
    if (any) upper = max(upper, lower); // an empty intersection: a point-sized box
    return any;
}
} // namespace

bool csgBounds(const CsgNode& node, Vec3& lower, Vec3& upper) {
    return clipBounds(node.clips, unclippedBounds(node, lower, upper), lower, upper);
}

void transformBounds(const Transform& transform, Vec3& lower, Vec3& upper) {
    Vec3 lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{(corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                     (corner & 4) ? upper.z : lower.z};
        const Vec3 q = transform.point(p);
        lo = min(lo, q);
        hi = max(hi, q);
    }
    lower = lo;
    upper = hi;
}

namespace {
bool insideClips(const Primitive& p, const Vec3& o, const Vec3& d, double t) {
    for (const CsgNode& clip : p.clips)
        if (!insideNode(clip, o + t * d)) return false;
    return true;
}

// Every crossing of the primitive along the whole line, sorted, clips applied.
void primitiveCrossings(const Primitive& p, const Vec3& o, const Vec3& d, std::vector<SurfaceCrossing>& out) {
    if (p.csg) {
        csgCrossings(*p.csg, o, d, out);
    } else {
        out.clear();
        Crossing c[kMaxCrossings];
        const int n = intersectShape(p.shape, p.toLevel.inversePoint(o), p.toLevel.inverseVector(d), c);
        for (int i = 0; i < n; ++i) out.push_back(levelCrossing(p, c[i]));
    }
    if (!p.clips.empty())
        std::erase_if(out, [&](const SurfaceCrossing& c) { return !insideClips(p, o, d, c.t); });
}
} // namespace

bool nearestCrossing(const Primitive& p, const Vec3& o, const Vec3& d, double tMin, double tMax,
                     SurfaceCrossing& out) {
    if (p.csg || !p.clips.empty()) {
        std::vector<SurfaceCrossing>& all = crossingScratch().nearestAll;
        primitiveCrossings(p, o, d, all);
        for (const SurfaceCrossing& c : all)
            if (c.t > tMin && c.t < tMax) {
                out = c;
                return true;
            }
        return false;
    }
    Crossing c;
    const bool found = firstPlainCrossing(p, o, d, tMin, tMax, c);
    if (found) out = levelCrossing(p, c);
    return found;
}

bool closestCrossingTo(const Primitive& p, const Vec3& o, const Vec3& d, double tGuess, SurfaceCrossing& out) {
    bool found = false;
    double best = INFINITY;
    if (p.csg || !p.clips.empty()) {
        std::vector<SurfaceCrossing>& all = crossingScratch().closestAll;
        primitiveCrossings(p, o, d, all);
        for (const SurfaceCrossing& c : all)
            if (std::fabs(c.t - tGuess) < best) {
                best = std::fabs(c.t - tGuess);
                out = c;
                found = true;
            }
        return found;
    }
    thread_local Crossing fixed[kMaxCrossings]; // not zero-initialised per call
    std::vector<Crossing>& many = crossingScratch().closestMany;
    const Crossing* c = nullptr;
    const int n = allCrossings(p.shape, p.toLevel.inversePoint(o), p.toLevel.inverseVector(d), fixed, many, c);
    for (int i = 0; i < n; ++i)
        if (std::fabs(c[i].t - tGuess) < best) {
            best = std::fabs(c[i].t - tGuess);
            out = levelCrossing(p, c[i]);
            found = true;
        }
    return found;
}

} // namespace drt::accel

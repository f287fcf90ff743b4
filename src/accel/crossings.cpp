// Ray crossings of analytic primitives in level space: single shapes and CSG
// trees (Roth 1982: classify the ray's spans against each leaf, combine the
// leaves' inside/outside states with the tree's operations, and report the
// points where the combined state changes).
#include "accel/built_scene.h"
#include "accel/line_cull.h"

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

using NodeState = CsgPlan::NodeState;

// Scratch space kept per thread (no allocation per ray once warm:
// accel/thread_scratch.h), one list per use.
struct CrossingScratch {
    std::vector<int> candidates;
    std::vector<LeafEvent> events;
    std::vector<NodeState> nodes;
    std::vector<Crossing> leafMany, closestMany;
    std::vector<SurfaceCrossing> nearestAll, closestAll;
};
CrossingScratch& crossingScratch() { return ThreadScratch<CrossingScratch>::get(); }

void planNode(const CsgNode& node, int parent, bool clipOfParent, bool firstChild, bool silent, CsgPlan& plan) {
    const int index = static_cast<int>(plan.nodes.size());
    CsgPlan::Node n;
    n.parent = parent;
    n.clipOfParent = clipOfParent;
    n.firstChild = firstChild;
    n.leaf = node.leaf;
    n.op = node.op;
    n.inverse = node.inverse;
    n.children = static_cast<int>(node.children.size());
    n.clips = static_cast<int>(node.clips.size());
    plan.nodes.push_back(n);
    if (node.leaf) {
        plan.leaves.push_back(&node);
        plan.leafNode.push_back(index);
        plan.silent.push_back(silent);
    }
    for (size_t i = 0; i < node.children.size(); ++i) planNode(node.children[i], index, false, i == 0, silent, plan);
    for (const CsgNode& clip : node.clips) planNode(clip, index, true, false, true, plan);
}

// A node's value from its leaf state or its children's, then its clips': an
// operation combines its children (union and merge: any; intersection: all, and
// at least one; difference: the first and none of the others), then applies its
// inversion; every clip must be inside too.
bool nodeValue(const CsgPlan::Node& n, const NodeState& s) {
    bool inside = s.leafState;
    if (!n.leaf) {
        switch (n.op) {
        case Csg::Op::Union:
        case Csg::Op::Merge: inside = s.childrenInside > 0; break;
        case Csg::Op::Intersection: inside = n.children > 0 && s.childrenInside == n.children; break;
        case Csg::Op::Difference: inside = s.firstInside && s.childrenInside == 1; break;
        }
        inside = inside != n.inverse;
    }
    return inside && s.clipsInside == n.clips;
}

// Counts node `index`'s value in its parent by `delta` (+1 or -1).
void countInParent(const CsgPlan& plan, std::vector<NodeState>& states, int index, int delta) {
    const CsgPlan::Node& n = plan.nodes[size_t(index)];
    NodeState& parent = states[size_t(n.parent)];
    if (n.clipOfParent) {
        parent.clipsInside += delta;
    } else {
        parent.childrenInside += delta;
        if (n.firstChild) parent.firstInside = delta > 0;
    }
}

// Every node's state from the leaves' states, children before parents (the
// reverse of pre-order).
void evaluateAll(const CsgPlan& plan, const std::vector<char>& leafStates, std::vector<NodeState>& states) {
    states.assign(plan.nodes.size(), NodeState{});
    for (size_t i = 0; i < plan.leafNode.size(); ++i) states[size_t(plan.leafNode[i])].leafState = leafStates[i] != 0;
    for (size_t i = plan.nodes.size(); i-- > 0;) {
        states[i].value = nodeValue(plan.nodes[i], states[i]);
        if (states[i].value && plan.nodes[i].parent >= 0) countInParent(plan, states, int(i), +1);
    }
}

// Sets one leaf's state and re-evaluates the nodes above it while their values
// change; returns the root's value.
bool setLeafState(const CsgPlan& plan, std::vector<NodeState>& states, int leaf, bool state) {
    int index = plan.leafNode[size_t(leaf)];
    states[size_t(index)].leafState = state;
    while (true) {
        NodeState& s = states[size_t(index)];
        const bool value = nodeValue(plan.nodes[size_t(index)], s);
        if (value == s.value) break;
        s.value = value;
        const int parent = plan.nodes[size_t(index)].parent;
        if (parent < 0) break;
        countInParent(plan, states, index, value ? +1 : -1);
        index = parent;
    }
    return states[0].value;
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

namespace {

double linearNorm(const Mat4& m) {
    double norm = 0;
    for (int row = 0; row < 3; ++row)
        norm = std::max(norm, std::fabs(m.m[row][0]) + std::fabs(m.m[row][1]) + std::fabs(m.m[row][2]));
    return norm;
}

CsgPlan::LeafBounds leafBounds(const CsgNode& leaf) {
    CsgPlan::LeafBounds b;
    if (!isSolidShape(leaf.shape)) {
        b.neverCrossed = true;
        return b;
    }
    if (leaf.shape.kind != ShapeKind::Sphere && leaf.shape.kind != ShapeKind::Box) return b;
    if (!shapeBounds(leaf.shape, b.lower, b.upper)) return b;
    transformBounds(leaf.toLevel, b.lower, b.upper);
    b.size = maxComponent(b.upper - b.lower);
    b.reach = maxComponent(max(abs(b.lower), abs(b.upper))) + b.size;
    b.conditioning = linearNorm(leaf.toLevel.matrix()) * linearNorm(leaf.toLevel.inverseMatrix());
    b.boxed = isFinite(b.lower) && isFinite(b.upper) && b.size > 0 && std::isfinite(b.reach) &&
              std::isfinite(b.conditioning);
    return b;
}

// Whether the line misses the leaf's bounds grown by a margin well above what
// rounding moves its solver's crossings and inside test by: with S = |o| +
// reach and k the conditioning, m = 1e-6 k S (1 + k S / size), against errors
// of order 1e-16 k S in the leaf-space origin and 1e-16 k^2 S^2 / size in a
// sphere's discriminant (the slab test's own rounding is of order 1e-16 S).
bool lineMissesLeaf(const CsgPlan::LeafBounds& b, const CullLine& line) {
    const double reach = line.originNorm + b.reach;
    const double margin = 1e-6 * b.conditioning * reach * (1 + b.conditioning * reach / b.size);
    return lineMissesBox(line, b.lower, b.upper, margin);
}

constexpr size_t kIndexedFrom = 16; // fewer boxed leaves: test them all

void indexLeaves(CsgPlan& plan) {
    std::vector<int> indexed, unindexed;
    const size_t count = plan.leafBounds.size();
    for (size_t i = 0; i < count; ++i) {
        const CsgPlan::LeafBounds& b = plan.leafBounds[i];
        if (b.boxed) indexed.push_back(int(i));
        else if (!b.neverCrossed) unindexed.push_back(int(i));
    }
    if (indexed.size() < kIndexedFrom) return;
    std::vector<Vec3> lower(count), upper(count), centre(count);
    for (int i : indexed) {
        lower[size_t(i)] = plan.leafBounds[size_t(i)].lower;
        upper[size_t(i)] = plan.leafBounds[size_t(i)].upper;
        centre[size_t(i)] = 0.5 * (lower[size_t(i)] + upper[size_t(i)]);
    }
    plan.leafIndex.build(std::move(indexed), lower, upper, centre);
    plan.unindexedLeaves = std::move(unindexed);
    // Children follow their parents: from the last node back, each node's
    // children are done before it.
    const std::vector<BoxHierarchy::Node>& nodes = plan.leafIndex.nodes();
    plan.indexBounds.assign(nodes.size(), {});
    for (size_t at = nodes.size(); at-- > 0;) {
        CsgPlan::LeafBounds& b = plan.indexBounds[at];
        b.boxed = true;
        b.lower = nodes[at].lower;
        b.upper = nodes[at].upper;
        b.size = HUGE_VAL;
        b.conditioning = 0;
        const auto worst = [&](const CsgPlan::LeafBounds& part) {
            b.reach = std::max(b.reach, part.reach);
            b.size = std::min(b.size, part.size);
            b.conditioning = std::max(b.conditioning, part.conditioning);
        };
        if (nodes[at].count > 0) {
            for (int k = nodes[at].first; k < nodes[at].first + nodes[at].count; ++k)
                worst(plan.leafBounds[size_t(plan.leafIndex.items()[size_t(k)])]);
        } else {
            worst(plan.indexBounds[at + 1]);
            worst(plan.indexBounds[size_t(nodes[at].second)]);
        }
    }
}

} // namespace

CsgPlan planCsg(const CsgNode& root, bool leafIndex) {
    CsgPlan plan;
    planNode(root, -1, false, false, false, plan);
    std::vector<char> inversions;
    for (const CsgNode* leaf : plan.leaves) {
        plan.leafBounds.push_back(leafBounds(*leaf));
        inversions.push_back(leaf->inverse);
    }
    evaluateAll(plan, inversions, plan.outside);
    if (leafIndex) indexLeaves(plan);
    return plan;
}

std::unique_ptr<InstalledScratch> installCrossingScratch() { return ThreadScratch<CrossingScratch>::install(); }

void csgCrossings(const CsgPlan& plan, const Vec3& o, const Vec3& d, std::vector<SurfaceCrossing>& out) {
    out.clear();
    CrossingScratch& scratch = crossingScratch();
    const std::vector<const CsgNode*>& leaves = plan.leaves;
    std::vector<LeafEvent>& events = scratch.events;
    std::vector<NodeState>& nodes = scratch.nodes;
    events.clear();
    nodes = plan.outside;
    const CullLine line = cullLine(o, d);
    // The leaves the line may meet, in their order (so that events at equal t
    // keep the order of visiting every leaf).
    const bool indexed = !plan.leafIndex.empty() && line.usable;
    std::vector<int>& candidates = scratch.candidates;
    if (indexed) {
        candidates = plan.unindexedLeaves;
        plan.leafIndex.gather(
            [&](int node) { return !lineMissesLeaf(plan.indexBounds[size_t(node)], line); }, candidates);
        std::sort(candidates.begin(), candidates.end());
    }
    const size_t count = indexed ? candidates.size() : leaves.size();
    for (size_t visit = 0; visit < count; ++visit) {
        const size_t i = indexed ? size_t(candidates[visit]) : visit;
        const CsgNode& leaf = *leaves[i];
        const CsgPlan::LeafBounds& bounds = plan.leafBounds[i];
        if (bounds.neverCrossed || (bounds.boxed && line.usable && lineMissesLeaf(bounds, line)))
            continue; // outside, and no crossing: as in plan.outside
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
        if (inside) setLeafState(plan, nodes, int(i), !leaf.inverse);
    }
    // A stable sort by t without std::stable_sort's temporary buffer.
    std::sort(events.begin(), events.end(),
              [](const LeafEvent& a, const LeafEvent& b) { return a.t < b.t || (a.t == b.t && a.order < b.order); });
    bool inside = nodes[0].value;
    for (const LeafEvent& e : events) {
        const CsgNode& leaf = *leaves[size_t(e.leaf)];
        const bool now = setLeafState(plan, nodes, e.leaf, e.entering != leaf.inverse);
        if (now == inside) continue;
        inside = now;
        if (plan.silent[size_t(e.leaf)]) continue;
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
        csgCrossings(p.csgPlan, o, d, out);
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

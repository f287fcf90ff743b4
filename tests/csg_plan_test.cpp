// CSG crossings through a flattened tree (accel/built_scene.h's CsgPlan): a
// leaf's change of state re-evaluates only the nodes above it. The crossings
// must be exactly those of re-evaluating the whole tree at every leaf crossing,
// as csgCrossings first did; the reference below does that.
#include "accel/built_scene.h"
#include "accel/line_cull.h"
#include "accel/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

namespace drt::accel {
namespace {

// The whole tree's value from the leaves' states (leaves in pre-order, children
// before clips; a leaf's state includes its inversion).
bool wholeTree(const CsgNode& node, const std::vector<char>& state, int& nextLeaf) {
    bool inside = false;
    if (node.leaf) {
        inside = state[size_t(nextLeaf++)] != 0;
    } else {
        bool first = true;
        for (const CsgNode& child : node.children) {
            const bool c = wholeTree(child, state, nextLeaf);
            if (node.op == Csg::Op::Intersection) inside = first ? c : (inside && c);
            else if (node.op == Csg::Op::Difference) inside = first ? c : (inside && !c);
            else inside = first ? c : (inside || c);
            first = false;
        }
        inside = inside != node.inverse;
    }
    for (const CsgNode& clip : node.clips) {
        const bool c = wholeTree(clip, state, nextLeaf);
        inside = inside && c;
    }
    return inside;
}

void leavesOf(const CsgNode& node, bool silent, std::vector<const CsgNode*>& leaves, std::vector<char>& silentLeaves) {
    if (node.leaf) leaves.push_back(&node), silentLeaves.push_back(silent);
    for (const CsgNode& child : node.children) leavesOf(child, silent, leaves, silentLeaves);
    for (const CsgNode& clip : node.clips) leavesOf(clip, true, leaves, silentLeaves);
}

struct Event {
    double t;
    int order, leaf;
    bool entering;
    Vec3 normal;
};

std::vector<SurfaceCrossing> referenceCrossings(const CsgNode& root, const Vec3& o, const Vec3& d) {
    std::vector<const CsgNode*> leaves;
    std::vector<char> silent, state;
    leavesOf(root, false, leaves, silent);
    std::vector<Event> events;
    for (size_t i = 0; i < leaves.size(); ++i) {
        const CsgNode& leaf = *leaves[i];
        const Vec3 lo = leaf.toLevel.inversePoint(o), ld = leaf.toLevel.inverseVector(d);
        Crossing fixed[kMaxCrossings];
        std::vector<Crossing> many;
        const Crossing* c = nullptr;
        const int n = allCrossings(leaf.shape, lo, ld, fixed, many, c);
        const bool solid = isSolidShape(leaf.shape);
        for (int k = 0; solid && k < n; ++k)
            events.push_back({c[k].t, int(events.size()), int(i), dot(c[k].normal, ld) < 0, c[k].normal});
        bool inside = false;
        if (solid) inside = n > 0 ? dot(c[0].normal, ld) > 0 : insideShape(leaf.shape, lo);
        state.push_back(inside != leaf.inverse);
    }
    std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
    std::vector<SurfaceCrossing> out;
    int cursor = 0;
    bool inside = wholeTree(root, state, cursor);
    for (const Event& e : events) {
        const CsgNode& leaf = *leaves[size_t(e.leaf)];
        state[size_t(e.leaf)] = e.entering != leaf.inverse;
        cursor = 0;
        const bool now = wholeTree(root, state, cursor);
        if (now == inside) continue;
        inside = now;
        if (silent[size_t(e.leaf)]) continue;
        Vec3 n = unitOrZero(leaf.toLevel.normal(e.normal));
        if ((dot(n, d) < 0) != now) n = -n;
        out.push_back({e.t, n, leaf.object});
    }
    return out;
}

const Object kObjects[1024] = {};

// A random tree of spheres, boxes, some planes and discs (not solid: their
// crossings are ignored), each its own object, some inverted, some translated,
// rotated or squashed to a hundredth along one axis, up to `depth` levels of unions, merges, intersections and
// differences with up to 4 children, some inverted, some with clips.
CsgNode randomTree(std::mt19937_64& rng, int depth, int& nextObject) {
    std::uniform_real_distribution<double> u(-1, 1);
    CsgNode node;
    if (depth == 0 || rng() % 4 == 0) {
        node.leaf = true;
        const uint64_t kind = rng() % 10;
        if (kind == 0) {
            node.shape.kind = ShapeKind::Plane;
            node.shape.normal = normalize(Vec3(u(rng), u(rng), u(rng)));
            node.shape.distance = 0.5 * u(rng);
        } else if (kind == 1) {
            node.shape.kind = ShapeKind::Disc;
            node.shape.center = Vec3(u(rng), u(rng), u(rng)) * 0.5;
            node.shape.normal = normalize(Vec3(u(rng), u(rng), u(rng)));
            node.shape.radius = 0.8;
        } else if (kind < 6) {
            node.shape.kind = ShapeKind::Sphere;
            node.shape.center = Vec3(u(rng), u(rng), u(rng));
            node.shape.radius = 0.3 + 0.5 * (u(rng) + 1);
        } else {
            node.shape.kind = ShapeKind::Box;
            const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
            node.shape.lower = min(a, b) - Vec3(0.1);
            node.shape.upper = max(a, b) + Vec3(0.1);
        }
        const Vec3 angles = Vec3(u(rng), u(rng), u(rng)) * 180;
        const uint64_t placement = rng() % 6;
        if (placement == 0) node.toLevel = Transform::translate(Vec3(u(rng), u(rng), u(rng)) * 0.5);
        else if (placement == 1) node.toLevel = Transform::rotate(angles);
        else if (placement == 2) node.toLevel = Transform::scale(Vec3(1, 0.01, 1.5)).then(Transform::rotate(angles));
        node.inverse = rng() % 5 == 0;
        node.object = &kObjects[size_t(nextObject++ % 64)];
    } else {
        node.leaf = false;
        const Csg::Op ops[] = {Csg::Op::Union, Csg::Op::Merge, Csg::Op::Intersection, Csg::Op::Difference};
        node.op = ops[rng() % 4];
        node.inverse = rng() % 6 == 0;
        const int children = 1 + int(rng() % 4);
        for (int i = 0; i < children; ++i) node.children.push_back(randomTree(rng, depth - 1, nextObject));
    }
    if (rng() % 5 == 0) node.clips.push_back(randomTree(rng, std::max(0, depth - 2), nextObject));
    return node;
}

bool sameBits(double a, double b) { return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b); }

// Every crossing's t, normal and object the same, to the bit.
bool sameCrossings(const std::vector<SurfaceCrossing>& got, const std::vector<SurfaceCrossing>& expected) {
    if (got.size() != expected.size()) return false;
    for (size_t i = 0; i < got.size(); ++i)
        if (!sameBits(got[i].t, expected[i].t) || !sameBits(got[i].normal.x, expected[i].normal.x) ||
            !sameBits(got[i].normal.y, expected[i].normal.y) || !sameBits(got[i].normal.z, expected[i].normal.z) ||
            got[i].object != expected[i].object)
            return false;
    return true;
}

TEST(CsgPlan, CrossingsAreThoseOfTheWholeTreeReevaluatedAtEachLeafCrossing) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    int crossings = 0, trees = 0, boxed = 0, neverCrossed = 0;
    for (int tree = 0; tree < 300; ++tree) {
        int nextObject = 0;
        CsgNode root = randomTree(rng, 1 + tree % 4, nextObject);
        if (root.leaf) continue;
        ++trees;
        const CsgPlan plan = planCsg(root);
        ASSERT_EQ(plan.leaves.size(), plan.leafNode.size());
        ASSERT_EQ(plan.leaves.size(), plan.leafBounds.size());
        for (const CsgPlan::LeafBounds& b : plan.leafBounds) boxed += b.boxed, neverCrossed += b.neverCrossed;
        std::vector<SurfaceCrossing> got;
        for (int ray = 0; ray < 40; ++ray) {
            // Lines through the middle of the shapes; some along an axis, which
            // meets boxes' faces edge-on and crosses several leaves at equal t.
            const Vec3 target = Vec3(u(rng), u(rng), u(rng)) * 0.5;
            // Origins near and far (where the margin for rounding grows).
            const double distance = ray % 8 == 1 ? 1e3 : ray % 8 == 2 ? 1e6 : 4;
            const Vec3 o = ray % 4 == 0 ? target - Vec3(4, 0, 0) : Vec3(u(rng), u(rng), u(rng)) * distance;
            const Vec3 d = target - o;
            csgCrossings(plan, o, d, got);
            ASSERT_TRUE(sameCrossings(got, referenceCrossings(root, o, d))) << "tree " << tree << " ray " << ray;
            crossings += int(got.size());
        }
    }
    // The trees are not all empty or all solid: many crossings were compared.
    EXPECT_GT(trees, 200);
    EXPECT_GT(crossings, 3000);
    // Lines skip spheres and boxes they miss, and discs always.
    EXPECT_GT(boxed, 500);
    EXPECT_GT(neverCrossed, 50);
}

// A tree of many leaves, as POV-Ray's grenadine.pov (a merge of a sphere, a
// cylinder-like box and an intersection of a union of 240 hollow bubbles with a
// slab): spheres and boxes of sizes 0.003 to 0.3, some rotated or squashed, some
// inverted, differences of nested spheres, some twice (their crossings at equal t
// must keep the leaves' order), some cut in half by a plane (a leaf no box
// bounds) and a clip.
CsgNode manyLeaves(std::mt19937_64& rng, int bubbles) {
    std::uniform_real_distribution<double> u(-1, 1);
    int nextObject = 0;
    const auto leaf = [&](ShapeKind kind, const Vec3& centre, double size) {
        CsgNode node;
        node.shape.kind = kind;
        if (kind == ShapeKind::Sphere) {
            node.shape.center = centre;
            node.shape.radius = size;
        } else {
            node.shape.lower = centre - Vec3(size);
            node.shape.upper = centre + Vec3(size);
        }
        node.object = &kObjects[size_t(nextObject++ % 1024)];
        return node;
    };
    const auto operation = [](Csg::Op op) {
        CsgNode node;
        node.leaf = false;
        node.op = op;
        return node;
    };
    CsgNode group = operation(Csg::Op::Union);
    std::vector<CsgNode> twins; // placed after every bubble: far from their originals in the leaves' order
    for (int i = 0; i < bubbles; ++i) {
        const Vec3 centre(u(rng), 0.3 * u(rng), u(rng));
        const double size = 0.003 + 0.3 * std::pow(0.5 * (u(rng) + 1), 3);
        const ShapeKind kind = rng() % 4 == 0 ? ShapeKind::Box : ShapeKind::Sphere;
        CsgNode bubble = leaf(kind, centre, size);
        const uint64_t placement = rng() % 8;
        const Vec3 angles = Vec3(u(rng), u(rng), u(rng)) * 180;
        if (placement == 0) bubble.toLevel = Transform::rotate(angles);
        else if (placement == 1)
            bubble.toLevel = Transform::translate(-centre)
                                 .then(Transform::scale(Vec3(1, 0.7, 1)))
                                 .then(Transform::rotate(angles))
                                 .then(Transform::translate(centre));
        bubble.inverse = rng() % 16 == 0;
        if (rng() % 3 == 0) { // hollow: the bubble less a slightly smaller one
            CsgNode hollow = operation(Csg::Op::Difference);
            CsgNode inner = leaf(kind, centre, size * (1 - 1e-7));
            inner.toLevel = bubble.toLevel;
            hollow.children = {bubble, inner};
            group.children.push_back(hollow);
        } else {
            group.children.push_back(bubble);
        }
        if (group.children.back().leaf && rng() % 6 == 0) { // again, another object's: crossings at equal t
            twins.push_back(group.children.back());
            twins.back().object = &kObjects[size_t(nextObject++ % 1024)];
        }
        if (rng() % 20 == 0) { // half a bubble: cut by a plane, a leaf no box bounds
            CsgNode half = operation(Csg::Op::Intersection);
            CsgNode plane = leaf(ShapeKind::Sphere, {}, 1);
            plane.shape.kind = ShapeKind::Plane;
            plane.shape.normal = normalize(Vec3(u(rng), u(rng), u(rng)));
            plane.shape.distance = dot(plane.shape.normal, centre);
            half.children = {group.children.back(), plane};
            group.children.back() = half;
        }
    }
    group.children.insert(group.children.end(), twins.begin(), twins.end());
    CsgNode slab = operation(Csg::Op::Intersection);
    slab.children = {group, leaf(ShapeKind::Box, {0, 0, 0}, 0.25)};
    slab.children[1].shape.lower = Vec3(-0.95, -0.25, -0.95);
    slab.children[1].shape.upper = Vec3(0.95, 0.25, 0.95);
    CsgNode root = operation(Csg::Op::Merge);
    root.children = {leaf(ShapeKind::Sphere, {0, -1.2, 0}, 0.9), leaf(ShapeKind::Box, {0, -0.9, 0}, 0.6), slab};
    root.clips.push_back(leaf(ShapeKind::Sphere, {0, 0, 0}, 1.9));
    return root;
}

TEST(CsgPlan, LeafHierarchyGivesTheCrossingsOfVisitingEveryLeaf) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(-1, 1);
    int crossings = 0, skipped = 0, lines = 0;
    for (int tree = 0; tree < 6; ++tree) {
        const CsgNode root = manyLeaves(rng, tree == 0 ? 20 : 240);
        const CsgPlan plan = planCsg(root), flat = planCsg(root, false);
        ASSERT_FALSE(plan.leafIndex.empty());
        ASSERT_TRUE(flat.leafIndex.empty());
        std::vector<SurfaceCrossing> got, expected;
        for (int ray = 0; ray < 2000; ++ray, ++lines) {
            // Lines through the bubbles from near and far (where the margins
            // grow), some along an axis, some through a leaf's centre and some
            // grazing a leaf's box.
            Vec3 target = Vec3(u(rng), 0.3 * u(rng), u(rng));
            const CsgPlan::LeafBounds& b = plan.leafBounds[rng() % plan.leafBounds.size()];
            if (ray % 5 == 3 && b.boxed) target = Vec3(b.upper.x, 0.5 * (b.lower.y + b.upper.y), b.lower.z);
            if (ray % 5 == 4 && b.boxed) target = 0.5 * (b.lower + b.upper);
            const double distance = ray % 8 == 1 ? 1e3 : ray % 8 == 2 ? 1e6 : 4;
            const Vec3 o = ray % 4 == 0 ? target - Vec3(4, 0, 0)
                           : ray % 4 == 1 ? target + Vec3(0, 0, distance)
                                          : Vec3(u(rng), u(rng), u(rng)) * distance;
            const Vec3 d = target - o;
            csgCrossings(plan, o, d, got);
            csgCrossings(flat, o, d, expected);
            ASSERT_TRUE(sameCrossings(got, expected)) << "tree " << tree << " ray " << ray;
            if (ray % 50 == 0) { // and, now and then, as the whole tree re-evaluated
                ASSERT_TRUE(sameCrossings(got, referenceCrossings(root, o, d))) << "tree " << tree << " ray " << ray;
            }
            // How many leaves the hierarchy let the line skip.
            std::vector<int> candidates = plan.unindexedLeaves;
            const CullLine line = cullLine(o, d);
            plan.leafIndex.gather([&](int node) { return !lineMissesBox(line, plan.indexBounds[size_t(node)].lower,
                                                                        plan.indexBounds[size_t(node)].upper, 0); },
                                  candidates);
            skipped += int(plan.leaves.size() - candidates.size());
            crossings += int(got.size());
        }
    }
    EXPECT_GT(crossings, 20000);
    // Most leaves are skipped: the hierarchy is in use.
    EXPECT_GT(skipped, lines * 100);
}

TEST(CsgPlan, NodesArePreOrderWithChildrenBeforeClips) {
    CsgNode root;
    root.leaf = false;
    root.op = Csg::Op::Difference;
    CsgNode a, b, clip;
    a.object = &kObjects[0];
    b.object = &kObjects[1];
    clip.object = &kObjects[2];
    a.clips.push_back(clip);
    root.children = {a, b};
    const CsgPlan plan = planCsg(root);
    ASSERT_EQ(plan.nodes.size(), 4u);
    ASSERT_EQ(plan.leaves.size(), 3u);
    EXPECT_EQ(plan.leaves[0]->object, &kObjects[0]);
    EXPECT_EQ(plan.leaves[1]->object, &kObjects[2]); // a's clip, before b
    EXPECT_EQ(plan.leaves[2]->object, &kObjects[1]);
    EXPECT_EQ(plan.silent, (std::vector<char>{0, 1, 0}));
    EXPECT_TRUE(plan.nodes[1].firstChild);
    EXPECT_TRUE(plan.nodes[2].clipOfParent);
    EXPECT_EQ(plan.nodes[2].parent, 1);
    EXPECT_EQ(plan.nodes[3].parent, 0);
    EXPECT_FALSE(plan.nodes[3].firstChild);
}

} // namespace
} // namespace drt::accel

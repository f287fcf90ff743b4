// Private to src/accel: what the Accelerator builds from the scene model and
// keeps beside Embree's scenes to turn an Embree hit into a drt Hit.
//
// Spaces: "level space" is the space an Embree scene's geometry lives in. For
// the top-level scene it is world space minus the frame origin (accel.h
// "Frame"; zero for most scenes); for a moving object it is world space at time
// its rest pose (scene/motion.h: every motion the identity) minus the frame
// origin, and the instance's transform maps it to the top level at the ray's time.
#pragma once

#include "accel/line_cull.h"
#include "accel/motion.h"
#include "accel/shapes.h"
#include "core/transform.h"
#include "scene/scene.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace drt::accel {

// One RTCDevice whose error callback records the first Embree error, so that
// it can be rethrown as RenderError from C++ (throwing through Embree's C
// frames is not allowed).
class EmbreeDevice {
public:
    EmbreeDevice(); // throws RenderError if Embree cannot start
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice get() const { return device_; }
    bool failed() const { return failed_.load(std::memory_order_relaxed); }
    // Throws RenderError("Embree error (<code>): <message> while <what>") if an
    // error was reported since construction.
    void throwIfFailed(const char* what) const;

private:
    static void onError(void* self, RTCError code, const char* message);
    RTCDevice device_ = nullptr;
    std::atomic<bool> failed_{false};
    mutable std::mutex mutex_;
    std::string message_;
};

// A surface crossing in level space, with the object whose surface it is.
struct SurfaceCrossing {
    double t = 0;
    Vec3 normal; // level space, unit, facing out of the (possibly inverted) shape
    const Object* object = nullptr;
};

// A CSG tree node: a leaf shape or an operation over children.
struct CsgNode {
    bool leaf = true;
    Csg::Op op = Csg::Op::Union;
    bool inverse = false;
    // Leaf:
    AnalyticShape shape;
    Transform toLevel; // leaf object space -> level space
    const Object* object = nullptr;
    // Operation:
    std::vector<CsgNode> children;
    // clipped_by: the node counts as inside only where every clip does too, and
    // the clips' own crossings change that state without being surfaces.
    std::vector<CsgNode> clips;
};

// A CSG tree flattened for csgCrossings: its nodes in pre-order (children before
// clips) with their parents, and its leaves in that order, so that a leaf's change
// of state re-evaluates only the nodes above it, instead of the whole tree at each
// crossing of each leaf.
struct CsgPlan {
    struct Node {
        int parent = -1;           // -1 for the root
        bool clipOfParent = false; // in the parent's clips, not its children
        bool firstChild = false;   // the parent's first child (a difference's base)
        bool leaf = true;
        Csg::Op op = Csg::Op::Union;
        bool inverse = false; // applied to operations only: a leaf's state includes its own
        int children = 0, clips = 0;
    };
    std::vector<Node> nodes;
    std::vector<const CsgNode*> leaves; // in pre-order
    std::vector<int> leafNode;          // each leaf's index in `nodes`
    std::vector<char> silent;           // a leaf under a clip: its crossings are not surfaces
    // Per leaf, what a line that cannot meet it skips (csgCrossings): a leaf that
    // is not solid never changes the state; a sphere or box that the line misses
    // by more than a margin (level-space bounds grown by the rounding of its
    // solver, below) has no crossing and the line starts outside it.
    struct LeafBounds {
        bool neverCrossed = false; // not solid: its crossings are ignored
        bool boxed = false;        // a sphere or box with finite level-space bounds
        Vec3 lower, upper;
        double reach = 0;        // |centre| + size, max norms
        double size = 0;         // the bounds' largest side
        double conditioning = 1; // |M| |M^-1| of toLevel's linear part, max-row-sum norms
    };
    std::vector<LeafBounds> leafBounds;
    // With many boxed leaves, a hierarchy of their bounds (leafIndex) finds those
    // a line may meet: each of its nodes has the bounds of its leaves and the
    // worst of their margins' terms (largest conditioning and reach, smallest
    // size), so that a line that misses a node's grown box misses every grown
    // leaf box below it. The solid leaves outside the hierarchy are always
    // visited (unindexedLeaves, in order). An empty leafIndex: every leaf is.
    BoxHierarchy leafIndex;
    std::vector<LeafBounds> indexBounds; // by leafIndex node
    std::vector<int> unindexedLeaves;
    // A node's state along a line: its value (inside or not) and how many of its
    // children and clips are inside.
    struct NodeState {
        bool value = false, leafState = false, firstInside = false;
        int childrenInside = 0, clipsInside = 0;
    };
    // Every node's state where the line meets no leaf (each leaf's state its
    // inversion): where csgCrossings starts, changing only the leaves it meets.
    std::vector<NodeState> outside;
};
// `leafIndex` false builds no hierarchy: every leaf is visited (for tests).
CsgPlan planCsg(const CsgNode& root, bool leafIndex = true);

// One analytic Embree user-geometry primitive: a single shape or a CSG tree.
struct Primitive {
    AnalyticShape shape;
    Transform toLevel; // object space -> level space
    // Set by the builder (addPrimitive):
    bool identity = false; // toLevel is the identity: the ray needs no transforming
    bool plain = false;    // no csg and no clips: the shape's own first crossing is the primitive's
    double frameUnit = 0;  // Hit::frameUnit for its level-space size; 0 if unbounded (the scene's then)
    const Object* object = nullptr;
    bool inverse = false;  // normals flipped
    bool noShadow = false;
    // Some surface of it may let light through (scene/light_through.h), in a
    // scene that has such surfaces: an opaque query records it (QueryContext).
    bool mayTransmit = false;
    std::unique_ptr<CsgNode> csg; // set for Merge, Difference, Intersection
    CsgPlan csgPlan;              // planCsg(*csg), set with it
    // clipped_by on the primitive as a whole: a crossing counts only if its
    // point is inside every one of these (level space).
    std::vector<CsgNode> clips;
    Vec3 lower, upper;            // level-space bounds (huge for planes)
    bool bounded = true;
};

// A triangle geometry (Box or Mesh), vertices already in level space.
struct MeshRecord {
    const Object* object = nullptr;
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles; // wound so that the winding normal faces out
    std::vector<Vec3> normals;                 // level space, may be empty
    std::vector<std::array<int, 3>> normalIndices;
    // A compact mesh: its uvs and corner textures. With `vertices` empty the
    // record is an instanced prototype and the triangles are the IndexedMesh's
    // own (object space); else `vertices`, `triangles` and `normals` are its
    // level-space copy, corners 1 and 2 swapped if `swapped`.
    std::shared_ptr<const IndexedMesh> indexed;
    bool swapped = false;
    bool inverse = false;
    bool mayTransmit = false; // as Primitive::mayTransmit
    double extent = 0; // largest side of the level-space bounds
    // clipped_by (level space): Embree's filter functions drop hits outside them.
    std::vector<CsgNode> clips;
};

enum class GeometryKind { Analytic, Mesh, Instance };
struct GeometryRef {
    GeometryKind kind = GeometryKind::Analytic;
    size_t index = 0; // into Level::meshes or BuiltScene::instances
};

// One Embree scene and the records behind its geometry ids.
struct Level {
    RTCScene scene = nullptr;
    std::vector<Primitive> primitives; // all in one user geometry
    std::vector<MeshRecord> meshes;
    std::vector<GeometryRef> geometries; // by Embree geometry id
    ~Level();
    void release(); // back to empty, the Embree scene released
};

// An Embree instance in the top level: a moving object's own level, or one
// placement of a compact mesh's shared level (`placed`).
struct Instance {
    std::shared_ptr<Level> level;        // shared by the placements of one compact mesh
    std::optional<InstanceMotion> motion; // moving objects
    bool shifted = false;
    Vec3 frameOrigin; // level space = rest-pose world minus this, if shifted
    // Compact-mesh placements: level (object) space -> world, the object,
    // its inversion and Hit::frameUnit for its world size.
    std::optional<Transform> placed;
    const Object* object = nullptr;
    bool inverse = false;
    bool mayTransmit = false; // a placement's object, as Primitive::mayTransmit
    double frameUnit = 0;
    // Level space -> world at time t.
    Transform toWorld(double t) const {
        if (placed) return *placed;
        return shifted ? Transform::translate(frameOrigin).then(motion->at(t)) : motion->at(t);
    }
};

struct AcceleratorState; // accel_impl.h

// What every query hands Embree as its context, so that a callback or filter
// can tell an opaque query (Accelerator::occludedOpaque) from the others. In
// an opaque query a surface that may let light through (mayTransmit) does not
// block the ray: the callback or filter sets crossedTransmitter[ray id] instead
// and lets the ray go on. Null in every other query.
struct QueryContext {
    RTCIntersectContext context; // first, so a context pointer is a query pointer
    uint8_t* crossedTransmitter = nullptr;
    static QueryContext& of(RTCIntersectContext* context) { return *reinterpret_cast<QueryContext*>(context); }
};

// One ray query (Accelerator::intersect, occluded). Embree hands the user
// geometry callbacks a pointer to `context`, its first member, through which
// they reach the ray in double precision: each analytic shape is solved once,
// in double, by the callback, and the crossing Embree accepted last (the
// nearest, once the query ends) is kept here for the hit record.
//
// A packet of rays (Accelerator::intersectPacket) has one query per ray; the
// first one's context goes to Embree, its `lanes` lists them all, and a
// callback finds a ray's query by the ray's id (lane()).
struct RayQuery : QueryContext {
    RayQuery* const* lanes = nullptr; // a packet's queries by ray id; null for a single ray
    const AcceleratorState* state = nullptr;
    Vec3 worldOrigin;
    Vec3 origin; // in the top level's frame (world minus the frame origin)
    Vec3 direction;
    // The ray in the space of the moving object's level `instance` (an Embree
    // geometry id of the top level), solved for on first need.
    unsigned instance = RTC_INVALID_GEOMETRY_ID;
    std::optional<Transform> instanceToWorld; // built in place, only for rays that reach a moving object
    // Set with instanceToWorld. The members in anonymous unions are left unset
    // by the constructor (each is written before it is read): a packet makes
    // 8 queries per pixel, and zeroing them was a tenth of its packing.
    union { Vec3 instanceOrigin; };
    union { Vec3 instanceDirection; };
    // The analytic crossing Embree accepted last: for a plain primitive in its
    // object space (objectCrossing: turned to level space once, for the hit
    // that wins), else in level space (crossing); set with hasCrossing.
    bool hasCrossing = false;
    bool objectSpace = false;
    unsigned primID = RTC_INVALID_GEOMETRY_ID, instID = RTC_INVALID_GEOMETRY_ID;
    union { Crossing objectCrossing; };
    union { SurfaceCrossing crossing; };

    RayQuery(const AcceleratorState& accelerator, const Vec3& rayOrigin, const Vec3& rayDirection); // accel_impl.h
    static RayQuery& of(RTCIntersectContext* context) { return *reinterpret_cast<RayQuery*>(context); }
    // The query of the ray with this id (RTCRay::id) in the query's packet.
    RayQuery& lane(unsigned id) { return lanes ? *lanes[id] : *this; }
    // The ray in the space of the level the callback runs in: the top level's
    // (instID invalid) or a moving object's at `time` (Instance::toWorld).
    void levelRay(unsigned instID, double time, Vec3& o, Vec3& d) {
        if (instID == RTC_INVALID_GEOMETRY_ID) {
            o = origin;
            d = direction;
            return;
        }
        instanceRay(instID, time, o, d);
    }

private:
    void instanceRay(unsigned instID, double time, Vec3& o, Vec3& d); // levelRay in a moving object's level
};

// Nearest crossing of a primitive with t in (tMin, tMax); the ray is in
// level space. Used by the Embree callbacks (float ray) and to refine hits in
// double precision.
bool nearestCrossing(const Primitive& primitive, const Vec3& o, const Vec3& d, double tMin, double tMax,
                     SurfaceCrossing& out);
// The first crossing with t in (tMin, tMax) of a plain primitive
// (Primitive::plain), in its object space (normal not normalised); the ray is
// in level space. Inline, as levelCrossing: every analytic hit passes here.
inline bool firstPlainCrossing(const Primitive& p, const Vec3& o, const Vec3& d, double tMin, double tMax,
                               Crossing& out) {
    return p.identity ? firstCrossing(p.shape, o, d, tMin, tMax, out)
                      : firstCrossing(p.shape, p.toLevel.inversePoint(o), p.toLevel.inverseVector(d), tMin, tMax, out);
}
// A unit vector along v, or zero if v has no finite length.
inline Vec3 unitOrZero(const Vec3& v) {
    const double len = length(v);
    return len > 0 && std::isfinite(len) ? v / len : Vec3{};
}
// A plain primitive's object-space crossing in level space: the same as
// nearestCrossing reports for it.
inline SurfaceCrossing levelCrossing(const Primitive& p, const Crossing& c) {
    Vec3 n = unitOrZero(p.identity ? c.normal : p.toLevel.normal(c.normal));
    if (p.inverse) n = -n;
    return {c.t, n, p.object};
}
// The crossing of a primitive whose t is closest to `tGuess` (hit refinement).
bool closestCrossingTo(const Primitive& primitive, const Vec3& o, const Vec3& d, double tGuess,
                       SurfaceCrossing& out);

// Every surface crossing of a CSG tree along the whole line, sorted (csg.cpp).
void csgCrossings(const CsgPlan& plan, const Vec3& o, const Vec3& d, std::vector<SurfaceCrossing>& out);
// Level-space bounds of a CSG tree; false if unbounded.
bool csgBounds(const CsgNode& node, Vec3& lower, Vec3& upper);
// Narrows [lower, upper] to the bounds of the clips; returns whether the
// result is bounded (`bounded` says whether the input was).
bool clipBounds(const std::vector<CsgNode>& clips, bool bounded, Vec3& lower, Vec3& upper);
// Whether the level-space point is inside the tree (clips included).
bool insideNode(const CsgNode& node, const Vec3& p);

// Level-space bounds of an object-space box under an affine transform.
void transformBounds(const Transform& transform, Vec3& lower, Vec3& upper);

// Adds the level's analytic primitives as one user geometry (embree_geometry.cpp).
void attachPrimitives(RTCDevice device, Level& level);
// Adds one triangle geometry; returns its geometry id.
void attachMesh(RTCDevice device, Level& level, MeshRecord mesh, bool noShadow);
// Adds a compact mesh's triangles over its own arrays (shared buffers), with
// `occludedFilter` (and `user` as its geometry's user data) if given.
void attachIndexedMesh(RTCDevice device, Level& level, std::shared_ptr<const IndexedMesh> mesh,
                       RTCFilterFunctionN occludedFilter = nullptr, void* user = nullptr);
// For an opaque query (QueryContext): the valid lanes of a filter's candidate
// hits are refused and recorded as crossing a surface that may let light
// through. Nothing is done in any other query.
void recordTransmitters(const RTCFilterFunctionNArguments* args);

// Geometry masks: every ray for intersect() carries all bits; occlusion rays
// carry only kShadowMask, which geometry with no_shadow lacks.
inline constexpr unsigned kCameraMask = 1u;
inline constexpr unsigned kShadowMask = 2u;
// The bit of a scene's one moving instance (AcceleratorState::swept). Two or
// more Embree culls by its own hierarchy over them: examples/cook.drt with two
// and three moving balls traced 5% and 7% slower with a bit each, and 25%
// faster with its one.
inline constexpr unsigned kSweptBit = 4u;

} // namespace drt::accel

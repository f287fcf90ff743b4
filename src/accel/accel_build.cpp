// Scene model -> Embree scenes. Analytic shapes become user-geometry
// primitives, boxes and meshes triangle geometry in level space, unions are
// flattened, other CSG operations become one primitive each, and every
// object with Motion gets its own sub-scene under a motion-blurred instance.
#include "accel/accel_impl.h"
#include "core/error.h"
#include "scene/light_through.h"

#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

// Planes have no bounds; Embree gets this large finite box instead. Embree
// drops primitives whose bounds exceed its FLT_LARGE (1.844e18) as invalid:
// with +-1e20 a plane silently vanished (measured), so stay below it.
constexpr double kUnbounded = 1e18;

std::string where(const Object& object) {
    if (!object.loc.valid()) return "";
    return "object at line " + std::to_string(object.loc.line) + ", column " + std::to_string(object.loc.column) +
           ": ";
}

[[noreturn]] void fail(const Object& object, const std::string& message) {
    throw RenderError(where(object) + message);
}

double determinant3(const Mat4& m) {
    const auto& a = m.m;
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

AnalyticShape prepare(const Object& object) {
    try {
        std::optional<AnalyticShape> shape = prepareShape(object.shape);
        // Every shape not traced as triangles needs an entry in prepareShape (accel/shapes.cpp).
        if (!shape) fail(object, "this shape has no intersection code");
        return *shape;
    } catch (const std::invalid_argument& e) {
        fail(object, e.what());
    }
}

// Meshes and boxes go to Embree as triangles (CSG is split into its members
// before this is asked); every other shape is traced by accel/shapes.cpp.
bool tracedAsTriangles(const Shape& shape) {
    return std::holds_alternative<Mesh>(shape) || std::holds_alternative<Box>(shape);
}

// Where a moving object is put (scene/motion.h): `placed` replaces
// object.transform (its rest pose, or its pose at one time), and
// `clipsTo`, if given, moves its clips from the rest pose to that time.
struct Placed {
    const Transform* placed = nullptr;
    const Transform* clipsTo = nullptr;
};

// The occlusion filter of a compact mesh's shared level in a scene with
// surfaces that let light through: an opaque query records the hits of a
// placement whose object may let light through (Instance::mayTransmit)
// instead of being blocked by them (QueryContext). A placement sits in the
// top level, so the context's instance is its id there.
void placementFilter(const RTCFilterFunctionNArguments* args) {
    if (!QueryContext::of(args->context).crossedTransmitter) return;
    const auto* state = static_cast<const AcceleratorState*>(args->geometryUserPtr);
    const unsigned id = args->context->instID[0];
    if (id < state->top.geometries.size() && state->instances[state->top.geometries[id].index].mayTransmit)
        recordTransmitters(args);
}

struct Builder {
    AcceleratorState& impl;

    // Whether an opaque query must record the object rather than be blocked by it.
    bool mayTransmit(const Object& object) const { return impl.transmitters && mayLetLightThrough(object); }

    // World (or world at time 0) -> level space: the frame shift, if any.
    Transform toLevel(const Transform& toWorld) const {
        return impl.shifted ? toWorld.then(Transform::translate(-impl.frameOrigin)) : toWorld;
    }

    void extendWorldBounds(const Vec3& lo, const Vec3& hi) {
        impl.lower = impl.bounded ? min(impl.lower, lo) : lo;
        impl.upper = impl.bounded ? max(impl.upper, hi) : hi;
        impl.bounded = true;
    }

    // Bounds of a level in level space, for the world bounds.
    struct LevelBounds {
        bool any = false;
        Vec3 lower, upper;
        void add(const Vec3& lo, const Vec3& hi) {
            lower = any ? min(lower, lo) : lo;
            upper = any ? max(upper, hi) : hi;
            any = true;
        }
    };

    // An object's transform into level space.
    static Transform placement(const Object& object, const Transform& parentToLevel, Placed where) {
        return (where.placed ? *where.placed : object.transform).then(parentToLevel);
    }

    // The clipped_by objects of `object` in level space (they live in the
    // object's parent space, a moving object's rest pose for a moving one).
    std::vector<CsgNode> clipNodes(const Object& object, const Transform& parentToLevel, Placed where) {
        std::vector<CsgNode> clips;
        if (object.clippedBy.empty()) return clips;
        const Transform clipToLevel = where.clipsTo ? where.clipsTo->then(parentToLevel) : parentToLevel;
        for (const Object& clip : object.clippedBy) {
            if (std::holds_alternative<Mesh>(clip.shape))
                fail(clip, "a mesh or triangle as a clipped_by object is not supported yet");
            clips.push_back(csgNode(clip, clipToLevel));
        }
        return clips;
    }

    CsgNode csgNode(const Object& object, const Transform& parentToLevel, Placed where = {}) {
        if (!object.motion.empty() && !where.placed)
            fail(object, "motion on an object inside merge, difference or intersection is not supported yet");
        CsgNode node;
        node.inverse = object.inverse;
        node.clips = clipNodes(object, parentToLevel, where);
        const Transform toLevel = placement(object, parentToLevel, where);
        if (const auto* csg = std::get_if<Csg>(&object.shape)) {
            if (csg->children.empty()) fail(object, "CSG with no children");
            node.leaf = false;
            node.op = csg->op;
            for (const Object& child : csg->children) node.children.push_back(csgNode(child, toLevel));
        } else if (std::holds_alternative<Mesh>(object.shape)) {
            fail(object, "meshes and triangles inside merge, difference or intersection are not supported yet");
        } else {
            node.shape = prepare(object);
            node.toLevel = toLevel;
            node.object = &object;
        }
        return node;
    }

    void addPrimitive(Level& level, LevelBounds& bounds, Primitive p) {
        if (p.bounded) {
            bounds.add(p.lower, p.upper);
        } else {
            p.lower = Vec3(-kUnbounded);
            p.upper = Vec3(kUnbounded);
        }
        p.identity = p.toLevel.isIdentity();
        p.plain = !p.csg && p.clips.empty();
        const double extent = p.bounded ? maxComponent(p.upper - p.lower) : 0;
        p.frameUnit = extent > 0 ? frameUnitFor(extent) : 0;
        level.primitives.push_back(std::move(p));
    }

    void addMesh(Level& level, LevelBounds& bounds, const Object& object, const Transform& toLevel, bool inverse,
                 bool noShadow, std::vector<CsgNode> clips = {}) {
        MeshRecord record;
        record.object = &object;
        record.inverse = inverse;
        record.mayTransmit = mayTransmit(object);
        record.clips = std::move(clips);
        const bool mirrored = determinant3(toLevel.matrix()) < 0;
        if (const auto* box = std::get_if<Box>(&object.shape)) {
            const Vec3 lo = min(box->corner1, box->corner2), hi = max(box->corner1, box->corner2);
            if (!isFinite(lo) || !isFinite(hi)) fail(object, "box corners must be finite");
            for (int c = 0; c < 8; ++c)
                record.vertices.push_back(toLevel.point({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y,
                                                         (c & 4) ? hi.z : lo.z}));
            // Corner c has bit 0 for x, bit 1 for y, bit 2 for z. Each face is two
            // triangles wound counter-clockwise seen from outside.
            static const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                            {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
            for (const auto& f : faces) {
                record.triangles.push_back({f[0], f[1], f[2]});
                record.triangles.push_back({f[0], f[2], f[3]});
            }
        } else if (const Mesh& compact = std::get<Mesh>(object.shape); compact.indexed) {
            copyIndexedMesh(record, object, compact, toLevel);
        } else {
            const Mesh& mesh = std::get<Mesh>(object.shape);
            const int vertexCount = static_cast<int>(mesh.vertices.size());
            for (const Vec3& v : mesh.vertices) {
                if (!isFinite(v)) fail(object, "mesh vertex is not finite");
                record.vertices.push_back(toLevel.point(v));
            }
            for (const auto& tri : mesh.triangles) {
                for (int i : tri)
                    if (i < 0 || i >= vertexCount) fail(object, "mesh triangle index out of range");
                record.triangles.push_back(tri);
            }
            if (!mesh.normals.empty()) {
                if (mesh.normalIndices.size() != mesh.triangles.size())
                    fail(object, "mesh needs one normal index triple per triangle");
                const int normalCount = static_cast<int>(mesh.normals.size());
                for (const auto& tri : mesh.normalIndices)
                    for (int i : tri)
                        if (i < 0 || i >= normalCount) fail(object, "mesh normal index out of range");
                for (const Vec3& n : mesh.normals) {
                    const Vec3 world = toLevel.normal(n);
                    const double len = length(world);
                    record.normals.push_back(len > 0 && std::isfinite(len) ? world / len : Vec3{});
                }
                record.normalIndices = mesh.normalIndices;
            }
        }
        if (record.triangles.empty()) return;
        // A mirroring transform reverses the winding; swap to keep the winding
        // normal on the transformed object-space side.
        if (mirrored) {
            for (auto& tri : record.triangles) std::swap(tri[1], tri[2]);
            for (auto& tri : record.normalIndices) std::swap(tri[1], tri[2]);
            record.swapped = true;
        }
        Vec3 lo(INFINITY), hi(-INFINITY);
        for (const Vec3& v : record.vertices) {
            lo = min(lo, v);
            hi = max(hi, v);
        }
        bounds.add(lo, hi);
        record.extent = maxComponent(hi - lo);
        attachMesh(impl.device.get(), level, std::move(record), noShadow);
        impl.device.throwIfFailed("adding a mesh");
    }

    void validate(const Object& object, const Mesh& mesh) {
        if (const std::string error = validateIndexedMesh(*mesh.indexed, mesh.textures.size()); !error.empty())
            fail(object, error);
    }

    // A compact mesh as a level-space copy (moving or clipped objects, which
    // cannot be instances of the shared level).
    void copyIndexedMesh(MeshRecord& record, const Object& object, const Mesh& mesh, const Transform& toLevel) {
        validate(object, mesh);
        const IndexedMesh& m = *mesh.indexed;
        record.indexed = mesh.indexed;
        record.vertices.reserve(m.positions.size());
        for (const Float3& v : m.positions) record.vertices.push_back(toLevel.point(v.toVec3()));
        const size_t count = m.triangleCount();
        record.triangles.reserve(count);
        for (size_t i = 0; i < count; ++i) {
            const auto tri = m.triangle(i);
            record.triangles.push_back({int(tri[0]), int(tri[1]), int(tri[2])});
        }
        if (m.normals.empty()) return;
        for (const Float3& n : m.normals) {
            const Vec3 level = toLevel.normal(n.toVec3());
            const double len = length(level);
            record.normals.push_back(len > 0 && std::isfinite(len) ? level / len : Vec3{});
        }
        record.normalIndices.reserve(count);
        for (size_t i = 0; i < count; ++i) {
            const auto tri = m.normalTriangle(i);
            record.normalIndices.push_back({int(tri[0]), int(tri[1]), int(tri[2])});
        }
    }

    // The shared level of a compact mesh, built on first use.
    const AcceleratorState::Prototype* prototype(const Object& object, const Mesh& mesh) {
        auto found = impl.prototypes.find(mesh.indexed.get());
        if (found != impl.prototypes.end()) return &found->second;
        validate(object, mesh);
        AcceleratorState::Prototype proto;
        if (!indexedMeshBounds(*mesh.indexed, proto.lower, proto.upper)) return nullptr;
        proto.level = std::make_shared<Level>();
        proto.level->scene = newScene();
        // In a scene with surfaces that let light through, any placement may be one.
        if (impl.transmitters) attachIndexedMesh(impl.device.get(), *proto.level, mesh.indexed, placementFilter, &impl);
        else attachIndexedMesh(impl.device.get(), *proto.level, mesh.indexed);
        impl.device.throwIfFailed("adding a mesh");
        rtcCommitScene(proto.level->scene);
        impl.device.throwIfFailed("building a mesh");
        return &impl.prototypes.emplace(mesh.indexed.get(), std::move(proto)).first->second;
    }

    // One placement of a compact mesh: an Embree instance of its shared level.
    void addMeshInstance(LevelBounds& bounds, const Object& object, const Transform& toLevel, bool inverse,
                         bool noShadow) {
        const Mesh& mesh = std::get<Mesh>(object.shape);
        const AcceleratorState::Prototype* proto = prototype(object, mesh);
        if (!proto) return; // no triangles
        Instance placed;
        placed.level = proto->level;
        placed.placed = impl.shifted ? toLevel.then(Transform::translate(impl.frameOrigin)) : toLevel;
        placed.object = &object;
        placed.inverse = inverse;
        placed.mayTransmit = mayTransmit(object);
        Vec3 lo = proto->lower, hi = proto->upper;
        transformBounds(toLevel, lo, hi);
        bounds.add(lo, hi);
        placed.frameUnit = frameUnitFor(maxComponent(hi - lo));
        RTCGeometry instance = rtcNewGeometry(impl.device.get(), RTC_GEOMETRY_TYPE_INSTANCE);
        impl.device.throwIfFailed("creating an instance");
        rtcSetGeometryInstancedScene(instance, proto->level->scene);
        float rows[12];
        const Mat4& m = toLevel.matrix();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) rows[4 * r + c] = float(m.m[r][c]);
        rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
        rtcSetGeometryMask(instance, noShadow ? kCameraMask : (kCameraMask | kShadowMask));
        rtcCommitGeometry(instance);
        const unsigned id = rtcAttachGeometry(impl.top.scene, instance);
        rtcReleaseGeometry(instance);
        impl.device.throwIfFailed("placing a mesh");
        if (impl.top.geometries.size() <= id) impl.top.geometries.resize(id + 1);
        impl.top.geometries[id] = {GeometryKind::Instance, impl.instances.size()};
        impl.instances.push_back(std::move(placed));
    }

    // `where`: see Placed. `parentClips`: the clipped_by objects of enclosing
    // unions, in level space.
    void addObject(Level& level, LevelBounds& bounds, const Object& object, const Transform& parentToLevel,
                   bool parentInverse, bool parentNoShadow, Placed where = {},
                   const std::vector<CsgNode>& parentClips = {}) {
        const Transform toLevel = placement(object, parentToLevel, where);
        const bool inverse = object.inverse != parentInverse;
        const bool noShadow = object.noShadow || parentNoShadow;
        std::vector<CsgNode> clips = parentClips;
        if (const auto* csg = std::get_if<Csg>(&object.shape)) {
            if (csg->op == Csg::Op::Union) {
                for (CsgNode& clip : clipNodes(object, parentToLevel, where)) clips.push_back(std::move(clip));
                for (const Object& child : csg->children) {
                    // Moving members were split off before (addPlaced).
                    if (!child.motion.empty()) fail(child, "motion inside a moving union is not supported here");
                    addObject(level, bounds, child, toLevel, inverse, noShadow, {}, clips);
                }
                return;
            }
            Primitive p;
            p.object = &object;
            p.noShadow = noShadow;
            p.mayTransmit = mayTransmit(object);
            // The tree's root carries the inherited inversion; leaves keep their own.
            p.csg = std::make_unique<CsgNode>(csgNode(object, parentToLevel, where));
            p.csg->inverse = inverse;
            p.csgPlan = planCsg(*p.csg);
            p.bounded = csgBounds(*p.csg, p.lower, p.upper);
            p.clips = std::move(clips);
            p.bounded = clipBounds(p.clips, p.bounded, p.lower, p.upper);
            addPrimitive(level, bounds, std::move(p));
            return;
        }
        for (CsgNode& clip : clipNodes(object, parentToLevel, where)) clips.push_back(std::move(clip));
        if (const Mesh* mesh = std::get_if<Mesh>(&object.shape);
            mesh && mesh->indexed && clips.empty() && &level == &impl.top) {
            addMeshInstance(bounds, object, toLevel, inverse, noShadow);
            return;
        }
        // A clipped box is traced as an analytic shape, so that its hits can be filtered.
        if (tracedAsTriangles(object.shape) && !(!clips.empty() && std::holds_alternative<Box>(object.shape))) {
            // Clipped meshes are filtered by Embree (embree_geometry.cpp), in the top level only.
            if (!clips.empty() && &level != &impl.top)
                fail(object, "clipped_by on a moving mesh or triangle is not supported yet");
            addMesh(level, bounds, object, toLevel, inverse, noShadow, std::move(clips));
            return;
        }
        Primitive p;
        p.shape = prepare(object);
        p.toLevel = toLevel;
        p.object = &object;
        p.inverse = inverse;
        p.noShadow = noShadow;
        p.mayTransmit = mayTransmit(object);
        p.bounded = shapeBounds(p.shape, p.lower, p.upper);
        if (p.bounded) transformBounds(toLevel, p.lower, p.upper);
        p.clips = std::move(clips);
        p.bounded = clipBounds(p.clips, p.bounded, p.lower, p.upper);
        addPrimitive(level, bounds, std::move(p));
    }

    RTCScene newScene() {
        RTCScene scene = rtcNewScene(impl.device.get());
        impl.device.throwIfFailed("creating a scene");
        return scene;
    }

    void finishLevel(Level& level) {
        attachPrimitives(impl.device.get(), level);
        impl.device.throwIfFailed("adding analytic shapes");
        rtcCommitScene(level.scene);
        impl.device.throwIfFailed("building the scene");
    }

    // A moving object at the one time every ray has, in double precision:
    // static geometry at placementAt(time). Composed as a static object whose
    // transform is that placement would be, so the two build bit for bit the same.
    void addObjectAtTime(Level& level, LevelBounds& bounds, const Object& object, const Transform& before,
                         const MotionChain& chain, bool parentInverse, bool parentNoShadow, double time) {
        const Transform placed = placementAt(before, chain, time);
        const std::optional<Mat4> restInverse = inverse(restPlacement(before, chain).matrix());
        if (!restInverse) fail(object, "the object's transform is singular");
        const Transform clipsTo = Transform::fromMatrix(*restInverse)->then(placed);
        addObject(level, bounds, object, toLevel(Transform()), parentInverse, parentNoShadow, {&placed, &clipsTo});
    }

    // The first moving instance's Embree id in the top level and its swept box
    // (AcceleratorState::swept), and how many moving instances there are.
    unsigned firstMovingId = 0;
    std::optional<AcceleratorState::SweptBox> firstMovingBox{};
    int movingInstances = 0;

    // The world box that the level's bounds (lower, upper) sweep over the
    // shutter (AcceleratorState::swept), as drt's callbacks place them (Instance::toWorld) and as
    // Embree's own single-precision interpolation does (its transform is what
    // places a mesh's triangles): the corners at 32 times per step of the
    // motion, the box grown by twice the farthest any corner moves between two
    // neighbouring times (a path between them stays within its length of
    // either end, and at 32 times per step of at most 90 degrees that length is
    // the chord's to within 0.1%), and by 1e-4 of the box's size and 1e-5 of
    // its distance from the origin for the rounding of the rays Embree is
    // given. False where the box is not finite.
    bool sweptBox(const Instance& moving, RTCGeometry instance, const Vec3& lower, const Vec3& upper, Vec3& lo,
                  Vec3& hi) const {
        const int samples = 32 * std::max(1, moving.motion->timeStepCount() - 1);
        const Vec3 shift = impl.shifted ? impl.frameOrigin : Vec3{};
        Vec3 previous[2][8];
        double chord = 0;
        lo = Vec3(INFINITY);
        hi = Vec3(-INFINITY);
        for (int k = 0; k <= samples; ++k) {
            const double t = double(k) / samples;
            const Transform toWorld = moving.toWorld(t);
            float rows[12];
            rtcGetGeometryTransform(instance, float(t), RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
            for (int c = 0; c < 8; ++c) {
                const Vec3 p{(c & 1) ? upper.x : lower.x, (c & 2) ? upper.y : lower.y, (c & 4) ? upper.z : lower.z};
                Vec3 embree; // Embree maps the level into the top level's frame: world minus `shift`
                for (int r = 0; r < 3; ++r)
                    embree[r] = double(rows[4 * r]) * p.x + double(rows[4 * r + 1]) * p.y +
                                double(rows[4 * r + 2]) * p.z + double(rows[4 * r + 3]) + shift[r];
                const Vec3 placed[2] = {toWorld.point(p), embree};
                for (int w = 0; w < 2; ++w) {
                    if (k > 0) chord = std::max(chord, length(placed[w] - previous[w][c]));
                    previous[w][c] = placed[w];
                    lo = min(lo, placed[w]);
                    hi = max(hi, placed[w]);
                }
            }
        }
        const double reach = std::max(maxComponent(abs(lo)), maxComponent(abs(hi)));
        const double margin = 2 * chord + 1e-4 * maxComponent(hi - lo) + 1e-5 * reach;
        lo = lo - Vec3(margin);
        hi = hi + Vec3(margin);
        return isFinite(lo) && isFinite(hi);
    }

    // Gives a scene's one moving instance its own mask bit, when its box is
    // finite (two or more are culled by Embree's own hierarchy over them).
    void maskTheOneMovingObject() {
        if (movingInstances != 1 || !firstMovingBox) return;
        RTCGeometry instance = rtcGetGeometry(impl.top.scene, firstMovingId);
        rtcSetGeometryMask(instance, kSweptBit);
        rtcCommitGeometry(instance);
        impl.swept = firstMovingBox;
        impl.device.throwIfFailed("masking the moving object");
    }

    void addMovingObject(const Object& object, const Transform& before, const MotionChain& chain,
                         bool parentInverse, bool parentNoShadow) {
        auto level = std::make_shared<Level>();
        level->scene = newScene();
        LevelBounds bounds;
        const Transform rest = restPlacement(before, chain);
        addObject(*level, bounds, object, toLevel(Transform()), parentInverse, parentNoShadow, {&rest, nullptr});
        finishLevel(*level);
        const Vec3 shift = impl.shifted ? impl.frameOrigin : Vec3{};
        std::optional<InstanceMotion> motion;
        try {
            motion.emplace(before, chain, bounds.any ? bounds.lower + shift : Vec3(1),
                           bounds.any ? bounds.upper + shift : Vec3(-1));
        } catch (const std::invalid_argument& e) {
            fail(object, e.what());
        }
        Instance moving;
        moving.level = std::move(level);
        moving.motion = std::move(motion);
        moving.shifted = impl.shifted;
        moving.frameOrigin = impl.frameOrigin;
        impl.anyMotion = true;
        RTCGeometry instance = rtcNewGeometry(impl.device.get(), RTC_GEOMETRY_TYPE_INSTANCE);
        impl.device.throwIfFailed("creating an instance");
        rtcSetGeometryInstancedScene(instance, moving.level->scene);
        const int steps = moving.motion->timeStepCount();
        rtcSetGeometryTimeStepCount(instance, static_cast<unsigned>(steps));
        const bool linear = moving.motion->translationOnly();
        for (int i = 0; i < steps; ++i) {
            if (linear) {
                float rows[12];
                moving.motion->stepRows(i, impl.frameOrigin, rows);
                rtcSetGeometryTransform(instance, static_cast<unsigned>(i), RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
                continue;
            }
            const RTCQuaternionDecomposition step = moving.motion->timeStep(i, impl.frameOrigin);
            rtcSetGeometryTransformQuaternion(instance, static_cast<unsigned>(i), &step);
        }
        // Shadow rays skip a no_shadow object at the instance.
        const bool noShadow = object.noShadow || parentNoShadow;
        rtcSetGeometryMask(instance, noShadow ? kCameraMask : (kCameraMask | kShadowMask));
        rtcCommitGeometry(instance);
        AcceleratorState::SweptBox box{{}, {}, !noShadow};
        const bool boxed = ++movingInstances == 1 && bounds.any &&
                           sweptBox(moving, instance, bounds.lower, bounds.upper, box.lower, box.upper);
        const unsigned id = rtcAttachGeometry(impl.top.scene, instance);
        rtcReleaseGeometry(instance);
        impl.device.throwIfFailed("adding a moving object");
        if (boxed) {
            firstMovingId = id;
            firstMovingBox = box;
        }
        if (bounds.any) {
            // The swept bounds, sampled at every step and between steps.
            const int samples = 4 * (steps - 1) + 4;
            for (int k = 0; k <= samples; ++k) {
                Vec3 lo = bounds.lower, hi = bounds.upper;
                transformBounds(moving.toWorld(double(k) / samples), lo, hi);
                extendWorldBounds(lo, hi);
            }
        }
        if (impl.top.geometries.size() <= id) impl.top.geometries.resize(id + 1);
        impl.top.geometries[id] = {GeometryKind::Instance, impl.instances.size()};
        impl.instances.push_back(std::move(moving));
    }

    // Whether a member of the union, or of a union inside it, has a motion of
    // its own (the union is then split into its members).
    static bool membersMove(const Csg& csg) {
        for (const Object& child : csg.children) {
            if (!child.motion.empty()) return true;
            const auto* inner = std::get_if<Csg>(&child.shape);
            if (inner && inner->op == Csg::Op::Union && membersMove(*inner)) return true;
        }
        return false;
    }

    static bool hasMovingMember(const Object& object) {
        const auto* csg = std::get_if<Csg>(&object.shape);
        return !object.motion.empty() || (csg && csg->op == Csg::Op::Union && membersMove(*csg));
    }

    // A top-level object, or a member of a union split because some member
    // moves: `outer` is the union's own placement over time (scene/motion.h),
    // the flags are the enclosing unions'.
    void addPlaced(LevelBounds& bounds, const Object& object, const Transform* outerBefore,
                   const MotionChain* outerChain, bool parentInverse, bool parentNoShadow) {
        const bool moving = hasMovingMember(object);
        if (!moving && !outerBefore) { // the common case: a still object
            addObject(impl.top, bounds, object, toLevel(Transform()), parentInverse, parentNoShadow);
            return;
        }
        Transform before = object.transform;
        MotionChain chain = object.motion;
        if (outerBefore) {
            if (!object.clippedBy.empty())
                fail(object, "clipped_by on a member of a union with moving members is not supported yet");
            appendPlacement(before, chain, *outerBefore, *outerChain);
        }
        const auto* csg = std::get_if<Csg>(&object.shape);
        if (csg && csg->op == Csg::Op::Union && membersMove(*csg)) {
            if (!object.clippedBy.empty())
                fail(object, "clipped_by on a union with moving members is not supported yet");
            for (const Object& child : csg->children)
                addPlaced(bounds, child, &before, &chain, parentInverse != object.inverse,
                          parentNoShadow || object.noShadow);
            return;
        }
        if (chain.empty()) addObject(impl.top, bounds, object, toLevel(Transform()), parentInverse, parentNoShadow, {&before});
        else if (impl.onlyTime)
            addObjectAtTime(impl.top, bounds, object, before, chain, parentInverse, parentNoShadow, *impl.onlyTime);
        else addMovingObject(object, before, chain, parentInverse, parentNoShadow);
    }
};

} // namespace

namespace {

void buildLevels(const Scene& scene, AcceleratorState& impl) {
    Builder builder{impl};
    impl.transmitters = anyMayLetLightThrough(scene.objects);
    impl.top.scene = builder.newScene();
    Builder::LevelBounds bounds;
    for (const Object& object : scene.objects) builder.addPlaced(bounds, object, nullptr, nullptr, false, false);
    if (bounds.any) {
        const Vec3 shift = impl.shifted ? impl.frameOrigin : Vec3{};
        builder.extendWorldBounds(bounds.lower + shift, bounds.upper + shift);
    }
    builder.maskTheOneMovingObject();
    builder.finishLevel(impl.top);
}

} // namespace

void buildScene(const Scene& scene, AcceleratorState& impl) {
    buildLevels(scene, impl);
    if (!impl.bounded) return;
    // Float coordinates lose absolute precision with distance from the origin:
    // a scene whose centre is farther away than its size is built again,
    // re-centred (accel.h "Frame"). Nearer scenes would gain at most a factor
    // of about 3 in precision and keep world coordinates.
    const Vec3 centre = 0.5 * (impl.lower + impl.upper);
    const double size = maxComponent(impl.upper - impl.lower);
    impl.sceneUnit = frameUnitFor(size);
    if (!(maxComponent(abs(centre)) > size)) return;
    impl.top.release();
    impl.instances.clear();
    impl.anyMotion = false;
    impl.swept.reset();
    impl.bounded = false;
    impl.shifted = true;
    impl.frameOrigin = centre;
    buildLevels(scene, impl);
}

double frameUnitFor(double extent) {
    if (!(extent > 0) || !std::isfinite(extent) || extent >= 1) return 1;
    int exponent = 0;
    std::frexp(extent, &exponent); // extent = m 2^exponent, m in [0.5, 1)
    return std::ldexp(1.0, exponent);
}

} // namespace drt::accel

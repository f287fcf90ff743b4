#include "accel/geometry_query.h"

#include "accel/accel.h"
#include "accel/shapes.h"

#include <cmath>
#include <list>
#include <memory>

namespace drt {

namespace {

// Crossings of the ray from `p` along a fixed direction with the object's
// surfaces: odd means inside (meshes, and any shape without an inside test).
bool insideByParity(const Object& object, const Vec3& p) {
    Scene scene;
    scene.objects.push_back(object);
    scene.objects.back().clippedBy.clear();
    scene.objects.back().inverse = false;
    const Accelerator accel(scene);
    // An irrational-looking direction, so the ray rarely grazes an edge.
    const Vec3 direction = normalize(Vec3(0.5773, 0.6123, 0.5402));
    Ray ray{p, direction};
    int crossings = 0;
    Hit hit;
    while (crossings < 100000 && accel.intersect(ray, hit)) {
        ++crossings;
        ray.origin = Accelerator::offsetOrigin(hit, direction);
        ray.tMin = 0;
    }
    return crossings % 2 == 1;
}

// POV-Ray's inside(): the object's own inside test, with CSG, `inverse` and
// clipped_by as the renderer counts them (accel/crossings.cpp).
bool insideObject(const Object& object, const Vec3& p) {
    bool inside = false;
    if (const Csg* csg = std::get_if<Csg>(&object.shape)) {
        const Vec3 local = object.transform.inversePoint(p);
        bool first = true;
        for (const Object& child : csg->children) {
            const bool c = insideObject(child, local);
            switch (csg->op) {
            case Csg::Op::Union:
            case Csg::Op::Merge: inside = first ? c : (inside || c); break;
            case Csg::Op::Intersection: inside = first ? c : (inside && c); break;
            case Csg::Op::Difference: inside = first ? c : (inside && !c); break;
            }
            first = false;
        }
    } else if (const std::optional<accel::AnalyticShape> shape = accel::prepareShape(object.shape)) {
        inside = accel::isSolidShape(*shape) && accel::insideShape(*shape, object.transform.inversePoint(p));
    } else {
        Object placed = object;
        inside = insideByParity(placed, p);
    }
    inside = inside != object.inverse;
    for (const Object& clip : object.clippedBy) inside = inside && insideObject(clip, p);
    return inside;
}

// Keeps what it built for the last few objects asked about (by identity):
// a scene that traces one terrain from a loop builds its accelerator once.
class AcceleratorQuery final : public SceneGeometryQuery {
public:
    std::optional<SurfaceHit> trace(const QueriedObject& object, const Vec3& origin, const Vec3& direction) override {
        Entry& entry = find(object);
        if (!entry.accel) entry.accel = std::make_unique<Accelerator>(*entry.scene);
        Hit hit;
        if (!entry.accel->intersect(Ray{origin, direction}, hit)) return std::nullopt;
        return SurfaceHit{hit.point, hit.geometricNormal};
    }
    bool inside(const QueriedObject& object, const Vec3& point) override {
        return insideObject(find(object).scene->objects.front(), point);
    }

private:
    struct Entry {
        std::shared_ptr<const void> identity;
        std::unique_ptr<Scene> scene; // the object alone; the accelerator refers to it
        std::unique_ptr<Accelerator> accel; // built at the first trace()
    };
    // How many objects' structures are kept (each may be a large mesh's BVH).
    static constexpr size_t kKept = 8;

    // The entry of `object`, most recently used first; an object without an
    // identity gets a fresh entry that the next question replaces.
    Entry& find(const QueriedObject& object) {
        if (object.identity) {
            for (auto it = recent_.begin(); it != recent_.end(); ++it)
                if (it->identity == object.identity) {
                    recent_.splice(recent_.begin(), recent_, it);
                    return recent_.front();
                }
        }
        if (!recent_.empty() && !recent_.front().identity) recent_.pop_front();
        Entry entry;
        entry.identity = object.identity;
        entry.scene = std::make_unique<Scene>();
        entry.scene->objects.push_back(object.make());
        recent_.push_front(std::move(entry));
        if (recent_.size() > kKept) recent_.pop_back();
        return recent_.front();
    }

    std::list<Entry> recent_;
};

} // namespace

std::unique_ptr<SceneGeometryQuery> makeGeometryQuery() { return std::make_unique<AcceleratorQuery>(); }

} // namespace drt

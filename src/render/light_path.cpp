#include "render/light_path.h"

#include <algorithm>

namespace drt {

namespace {

Vec3 mix(const Vec3& a, const Vec3& b, double s) { return (1 - s) * a + s * b; }

void setPose(Light& light, const LightKey& key) {
    light.position = key.position;
    light.pointAt = key.pointAt;
    if (light.area) {
        light.area->axis1 = key.axis1;
        light.area->axis2 = key.axis2;
    }
}

} // namespace

Light lightAt(const Light& light, double time) {
    Light out = light;
    out.motion.reset();
    if (!light.motion) return out;
    const double t = std::clamp(time, 0.0, 1.0);
    const std::vector<LightKey>& keys = light.motion->keys;
    if (keys.size() == 1 || (!keys.empty() && t <= keys.front().time)) {
        setPose(out, keys.front());
    } else if (!keys.empty() && t >= keys.back().time) {
        setPose(out, keys.back());
    } else if (!keys.empty()) {
        size_t i = 0;
        while (i + 2 < keys.size() && keys[i + 1].time <= t) ++i;
        const LightKey &a = keys[i], &b = keys[i + 1];
        const double s = (t - a.time) / (b.time - a.time);
        setPose(out, {t, mix(a.position, b.position, s), mix(a.pointAt, b.pointAt, s), mix(a.axis1, b.axis1, s),
                      mix(a.axis2, b.axis2, s)});
    }
    if (!light.motion->chain.empty()) {
        const Transform placement = placementAt(Transform(), light.motion->chain, t);
        out.position = placement.point(out.position);
        out.pointAt = placement.point(out.pointAt);
        if (out.area) {
            out.area->axis1 = placement.vector(out.area->axis1);
            out.area->axis2 = placement.vector(out.area->axis2);
        }
    }
    return out;
}

} // namespace drt

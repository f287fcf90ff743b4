#include "scene/blob.h"

#include <algorithm>

namespace drt {

bool blobBounds(const Blob& blob, Vec3& lower, Vec3& upper) {
    bool any = false;
    for (const BlobComponent& c : blob.components) {
        const Vec3 far = c.kind == BlobComponent::Kind::Cylinder ? c.end : c.center;
        const Vec3 lo = min(c.center, far) - Vec3(c.radius), hi = max(c.center, far) + Vec3(c.radius);
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
            const Vec3 q = c.transform.point(p);
            lower = any ? min(lower, q) : q;
            upper = any ? max(upper, q) : q;
            any = true;
        }
    }
    return any;
}

} // namespace drt

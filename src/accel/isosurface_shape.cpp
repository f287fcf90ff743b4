#include "accel/isosurface_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void require(bool ok, const char* message) {
    if (!ok) throw std::invalid_argument(message);
}

} // namespace

IsosurfaceGeometry::IsosurfaceGeometry(const Isosurface& iso) : iso_(iso) {
    require(iso.function != nullptr, "isosurface needs a function");
    require(iso.function->params.size() == 3 || iso.function->anyArity,
            "an isosurface's function takes 3 parameters (x, y, z)");
    require(std::isfinite(iso.maxGradient) && iso.maxGradient > 0, "isosurface max_gradient must be positive");
    require(std::isfinite(iso.accuracy) && iso.accuracy > 0, "isosurface accuracy must be positive");
    require(std::isfinite(iso.threshold), "isosurface threshold must be finite");
    if (iso.container == Isosurface::Container::Box) {
        require(finite(iso.corner1) && finite(iso.corner2), "isosurface container must be finite");
        lower_ = min(iso.corner1, iso.corner2);
        upper_ = max(iso.corner1, iso.corner2);
        require(lower_.x < upper_.x && lower_.y < upper_.y && lower_.z < upper_.z,
                "isosurface container box is empty");
    } else {
        require(finite(iso.center) && std::isfinite(iso.radius) && iso.radius > 0,
                "isosurface container sphere needs a positive radius");
        lower_ = iso.center - Vec3(iso.radius);
        upper_ = iso.center + Vec3(iso.radius);
    }
    const double extent = maxComponent(upper_ - lower_);
    step_ = std::max(1e-7 * extent, std::min(iso.accuracy * 0.1, 1e-4 * extent));
}

bool IsosurfaceGeometry::insideContainer(const Vec3& p) const {
    if (iso_.container == Isosurface::Container::Box)
        return p.x >= lower_.x && p.y >= lower_.y && p.z >= lower_.z && p.x <= upper_.x && p.y <= upper_.y &&
               p.z <= upper_.z;
    const Vec3 r = p - iso_.center;
    return dot(r, r) <= iso_.radius * iso_.radius;
}

bool IsosurfaceGeometry::containerSpan(const Vec3& o, const Vec3& d, double& t0, double& t1, Vec3& n0,
                                       Vec3& n1) const {
    if (iso_.container == Isosurface::Container::Box) {
        t0 = -INFINITY, t1 = INFINITY;
        for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] == 0) {
                if (o[axis] < lower_[axis] || o[axis] > upper_[axis]) return false;
                continue;
            }
            double a = (lower_[axis] - o[axis]) / d[axis], b = (upper_[axis] - o[axis]) / d[axis];
            Vec3 na(0.0), nb(0.0);
            na[axis] = -1, nb[axis] = 1;
            if (a > b) std::swap(a, b), std::swap(na, nb);
            if (a > t0) t0 = a, n0 = na;
            if (b < t1) t1 = b, n1 = nb;
        }
        return t0 < t1;
    }
    const Vec3 f = o - iso_.center;
    const double a = dot(d, d), b = dot(f, d);
    const Vec3 l = f - (b / a) * d;
    const double disc = a * (iso_.radius * iso_.radius - dot(l, l));
    if (!(disc > 0)) return false;
    const double q = -b - std::copysign(std::sqrt(disc), b);
    double r0 = q / a, r1 = q != 0 ? (dot(f, f) - iso_.radius * iso_.radius) / q : r0;
    if (r1 < r0) std::swap(r0, r1);
    t0 = r0, t1 = r1;
    n0 = o + t0 * d - iso_.center;
    n1 = o + t1 * d - iso_.center;
    return t0 < t1;
}

Vec3 IsosurfaceGeometry::gradient(const Vec3& p) const {
    const double h = step_;
    const Vec3 g((value(p + Vec3(h, 0, 0)) - value(p - Vec3(h, 0, 0))),
                 (value(p + Vec3(0, h, 0)) - value(p - Vec3(0, h, 0))),
                 (value(p + Vec3(0, 0, h)) - value(p - Vec3(0, 0, h))));
    return g / (2 * h);
}

void IsosurfaceGeometry::intersect(const Vec3& o, const Vec3& d, double tMin, double tMax, size_t limit,
                                   std::vector<Crossing>& out) const {
    out.clear();
    double t0, t1;
    Vec3 n0, n1;
    if (limit == 0 || !containerSpan(o, d, t0, t1, n0, n1)) return;
    const double speed = length(d); // object-space distance per unit of t
    if (!(speed > 0) || !std::isfinite(speed)) return;
    auto add = [&](double t, const Vec3& n) {
        if (t > tMin && t < tMax && out.size() < limit) out.push_back({t, n});
    };
    // The gradient, unless it contradicts the crossing's direction (then the ray's).
    auto surfaceNormal = [&](double t, bool entering) {
        const Vec3 g = gradient(o + t * d);
        const double along = dot(g, d);
        return finite(g) && (entering ? along < 0 : along > 0) ? g : (entering ? -d : d);
    };
    // The container's own surface where the inside reaches it (entry).
    double t = t0;
    double g = value(o + t * d);
    if (!iso_.open && g < 0) add(t0, n0);
    if (t1 <= tMin || t0 >= tMax) return;
    const double minStep = iso_.accuracy / speed;  // in t
    const double lipschitz = iso_.maxGradient * speed; // |dg/dt| at most
    const double refine = std::max(iso_.accuracy * 1e-4, 1e-12 * maxComponent(upper_ - lower_)) / speed;
    // Start no earlier than needed: the span before tMin can only hold crossings the caller does not want.
    if (tMin > t0) {
        t = tMin;
        g = value(o + t * d);
    }
    while (t < t1 && out.size() < limit) {
        const double step = std::max(std::fabs(g) / lipschitz, minStep);
        double next = std::min(t + step, t1);
        double gn = value(o + next * d);
        if ((g < 0) != (gn < 0)) {
            // A sign change in (t, next]: bisect.
            double a = t, b = next, ga = g;
            while (b - a > refine) {
                const double m = 0.5 * (a + b);
                const double gm = value(o + m * d);
                if ((gm < 0) == (ga < 0)) a = m, ga = gm;
                else b = m;
            }
            const double root = 0.5 * (a + b);
            add(root, surfaceNormal(root, gn < 0));
        }
        t = next, g = gn;
        if (t >= tMax) return;
    }
    if (!iso_.open && g < 0 && t >= t1) add(t1, n1);
}

} // namespace drt::accel

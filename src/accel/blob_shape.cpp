#include "accel/blob_shape.h"

#include "accel/line_cull.h"
#include "accel/polynomial.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drt::accel {

namespace {

bool positiveFinite(double v) { return std::isfinite(v) && v > 0; }

// A stretch of the line where one component piece is active: there
// (d/r)^2 = |w0 + (t - tRef) dir|^2 / r^2 with w0 the offset at tRef.
struct Piece {
    double t0, t1;   // active interval
    Vec3 w0, dir;    // offset and its rate, component space, at tRef
    double tRef;
    double invR2, strength;
};

// Adds the piece where |w0 + (t - tRef) dir| < r, clipped to [lo, hi]. The
// interval is found around the closest approach t* so that no cancellation
// occurs: q(t* + s) = |dir|^2 s^2 + |w*|^2.
void addPiece(std::vector<Piece>& pieces, const Vec3& w, const Vec3& dir, double tRef, double radius2,
              double strength, double lo, double hi) {
    const double a = dot(dir, dir);
    double t0 = lo, t1 = hi;
    if (a > 0) {
        const double sClosest = -dot(w, dir) / a;
        const Vec3 wClosest = w + sClosest * dir;
        const double gap = radius2 - dot(wClosest, wClosest);
        if (!(gap > 0)) return;
        const double half = std::sqrt(gap / a);
        t0 = std::max(lo, tRef + sClosest - half);
        t1 = std::min(hi, tRef + sClosest + half);
    } else if (!(dot(w, w) < radius2)) {
        return;
    }
    if (!(t0 < t1)) return;
    pieces.push_back({t0, t1, w, dir, tRef, 1 / radius2, strength});
}

// intersect's, field's and gradient's working lists, kept per thread
// (accel/thread_scratch.h).
struct BlobScratch {
    std::vector<Piece> pieces;
    std::vector<double> cuts;
    std::vector<int> lineComponents, pointComponents;
};

} // namespace

BlobGeometry::BlobGeometry(const Blob& blob, bool spatialIndex) : threshold_(blob.threshold) {
    if (blob.components.empty()) throw std::invalid_argument("blob needs at least one component");
    if (!positiveFinite(blob.threshold)) throw std::invalid_argument("blob threshold must be positive");
    for (const BlobComponent& b : blob.components) {
        if (!positiveFinite(b.radius)) throw std::invalid_argument("blob component radius must be positive");
        if (!std::isfinite(b.strength) || b.strength == 0)
            throw std::invalid_argument("blob component strength must be finite and non-zero");
        Component c;
        c.kind = b.kind;
        c.center = b.center;
        c.radius2 = b.radius * b.radius;
        c.strength = b.strength;
        c.toBlob = b.transform;
        c.transformed = !b.transform.isIdentity();
        if (b.kind == BlobComponent::Kind::Cylinder) {
            c.length = length(b.end - b.center);
            if (!positiveFinite(c.length)) throw std::invalid_argument("blob cylinder needs distinct finite ends");
            c.axis = (b.end - b.center) / c.length;
        }
        components_.push_back(c);
    }
    blobBounds(blob, lower_, upper_);
    if (spatialIndex) buildIndex();
}

namespace {
constexpr size_t kIndexedFrom = 16; // fewer components: test them all
} // namespace

void BlobGeometry::buildIndex() {
    if (components_.size() < kIndexedFrom) return;
    std::vector<int> indexed;
    for (size_t i = 0; i < components_.size(); ++i) {
        const Component& c = components_[i];
        const bool sphere = c.kind == BlobComponent::Kind::Sphere && !c.transformed;
        (sphere && isFinite(c.center) ? indexed : unindexed_).push_back(int(i));
    }
    if (indexed.size() < kIndexedFrom) { // mostly transformed or cylinders: nothing to gain
        unindexed_.clear();
        return;
    }
    std::vector<Vec3> lower(components_.size()), upper(components_.size()), centre(components_.size());
    smallestRadius_ = HUGE_VAL;
    for (int i : indexed) {
        const Component& c = components_[size_t(i)];
        const double radius = std::sqrt(c.radius2);
        smallestRadius_ = std::min(smallestRadius_, radius);
        lower[size_t(i)] = c.center - Vec3(radius);
        upper[size_t(i)] = c.center + Vec3(radius);
        centre[size_t(i)] = c.center;
        reach_ = std::max({reach_, maxComponent(abs(lower[size_t(i)])), maxComponent(abs(upper[size_t(i)]))});
    }
    index_.build(std::move(indexed), lower, upper, centre);
    reach_ += maxComponent(index_.nodes()[0].upper - index_.nodes()[0].lower);
}

namespace {

// Every component in a leaf whose box `overlaps` accepts, and the unindexed
// ones, in the components' order.
template <class Overlaps>
void gatherCandidates(const BoxHierarchy& index, const std::vector<int>& unindexed, Overlaps overlaps,
                      std::vector<int>& out) {
    out = unindexed;
    index.gather([&](int node) { return overlaps(index.nodes()[size_t(node)].lower, index.nodes()[size_t(node)].upper); },
                 out);
    std::sort(out.begin(), out.end());
}

} // namespace

// Skipping a sphere is exact: addPiece's gap r^2 - |w*|^2 (w* the closest
// approach) is rounded by about 1e-16 |w| r, and the field's q by 1e-16 |w|^2 /
// r^2, far below the margins here (1e-6 of the extent of origin and blob).
const int* BlobGeometry::lineCandidates(const Vec3& o, const Vec3& d, std::vector<int>& scratch,
                                       size_t& count) const {
    count = components_.size();
    const CullLine line = cullLine(o, d);
    if (index_.empty() || !line.usable) return nullptr;
    const double extent = line.originNorm + reach_;
    const double margin = 1e-6 * extent * (1 + extent / smallestRadius_);
    gatherCandidates(
        index_, unindexed_,
        [&](const Vec3& lower, const Vec3& upper) { return !lineMissesBox(line, lower, upper, margin); }, scratch);
    count = scratch.size();
    return scratch.data();
}

const int* BlobGeometry::pointCandidates(const Vec3& p, std::vector<int>& scratch, size_t& count) const {
    count = components_.size();
    if (index_.empty() || !isFinite(p)) return nullptr;
    const double margin = 1e-6 * (maxComponent(abs(p)) + reach_);
    const auto within = [&](const Vec3& lower, const Vec3& upper) {
        for (int axis = 0; axis < 3; ++axis)
            if (!(p[axis] >= lower[axis] - margin && p[axis] <= upper[axis] + margin)) return false;
        return true;
    };
    gatherCandidates(index_, unindexed_, within, scratch);
    count = scratch.size();
    return scratch.data();
}

Vec3 BlobGeometry::offsetFromCore(const Component& c, const Vec3& q) {
    const Vec3 w = q - c.center;
    if (c.kind == BlobComponent::Kind::Sphere) return w;
    const double h = std::clamp(dot(w, c.axis), 0.0, c.length);
    return w - h * c.axis;
}

// sum of strength (1 - d^2/r^2)^2 over the components with d < r.
double BlobGeometry::field(const Vec3& p) const {
    size_t count = 0;
    const int* candidates = pointCandidates(p, ThreadScratch<BlobScratch>::get().pointComponents, count);
    double sum = 0;
    for (size_t k = 0; k < count; ++k) {
        const Component& c = components_[candidates ? size_t(candidates[k]) : k];
        const Vec3 w = offsetFromCore(c, c.transformed ? c.toBlob.inversePoint(p) : p);
        const double q = dot(w, w) / c.radius2;
        if (q < 1) sum += c.strength * (1 - q) * (1 - q);
    }
    return sum;
}

// d/dp of strength (1 - |w|^2/r^2)^2 = -4 strength (1 - q) w / r^2 in
// component space; gradients go to blob space by the inverse transpose.
Vec3 BlobGeometry::gradient(const Vec3& p) const {
    size_t count = 0;
    const int* candidates = pointCandidates(p, ThreadScratch<BlobScratch>::get().pointComponents, count);
    Vec3 sum(0);
    for (size_t k = 0; k < count; ++k) {
        const Component& c = components_[candidates ? size_t(candidates[k]) : k];
        const Vec3 w = offsetFromCore(c, c.transformed ? c.toBlob.inversePoint(p) : p);
        const double q = dot(w, w) / c.radius2;
        if (q >= 1) continue;
        const Vec3 g = (-4 * c.strength * (1 - q) / c.radius2) * w;
        sum = sum + (c.transformed ? c.toBlob.normal(g) : g);
    }
    return sum;
}

std::unique_ptr<InstalledScratch> installBlobScratch() { return ThreadScratch<BlobScratch>::install(); }

void BlobGeometry::intersect(const Vec3& o, const Vec3& d, std::vector<Crossing>& out) const {
    out.clear();
    BlobScratch& scratch = ThreadScratch<BlobScratch>::get();
    std::vector<Piece>& pieces = scratch.pieces;
    std::vector<double>& cuts = scratch.cuts;
    pieces.clear();
    const double inf = HUGE_VAL;
    size_t count = 0;
    const int* candidates = lineCandidates(o, d, scratch.lineComponents, count);
    for (size_t k = 0; k < count; ++k) {
        const Component& c = components_[candidates ? size_t(candidates[k]) : k];
        const Vec3 oc = c.transformed ? c.toBlob.inversePoint(o) : o;
        const Vec3 dc = c.transformed ? c.toBlob.inverseVector(d) : d;
        const Vec3 w = oc - c.center; // offset from the centre at t = 0
        if (c.kind == BlobComponent::Kind::Sphere) {
            addPiece(pieces, w, dc, 0, c.radius2, c.strength, -inf, inf);
            continue;
        }
        // The projection on the axis, h(t) = h0 + t h1, picks the piece:
        // base end (h < 0), body (0 <= h <= length), apex end (h > length).
        const double h0 = dot(w, c.axis), h1 = dot(dc, c.axis);
        const Vec3 wApex = w - c.length * c.axis, wBody = w - h0 * c.axis, dBody = dc - h1 * c.axis;
        if (h1 == 0) {
            if (h0 < 0) addPiece(pieces, w, dc, 0, c.radius2, c.strength, -inf, inf);
            else if (h0 > c.length) addPiece(pieces, wApex, dc, 0, c.radius2, c.strength, -inf, inf);
            else addPiece(pieces, wBody, dBody, 0, c.radius2, c.strength, -inf, inf);
            continue;
        }
        const double tBase = -h0 / h1, tApex = (c.length - h0) / h1;
        if (h1 > 0) {
            addPiece(pieces, w, dc, 0, c.radius2, c.strength, -inf, tBase);
            addPiece(pieces, wBody, dBody, 0, c.radius2, c.strength, tBase, tApex);
            addPiece(pieces, wApex, dc, 0, c.radius2, c.strength, tApex, inf);
        } else {
            addPiece(pieces, wApex, dc, 0, c.radius2, c.strength, -inf, tApex);
            addPiece(pieces, wBody, dBody, 0, c.radius2, c.strength, tApex, tBase);
            addPiece(pieces, w, dc, 0, c.radius2, c.strength, tBase, inf);
        }
    }
    if (pieces.empty()) return;
    cuts.clear();
    for (const Piece& p : pieces) cuts.push_back(p.t0), cuts.push_back(p.t1);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    // Each cut's polynomial is rounded differently, so a crossing that lies
    // on a cut may show as a sign change across the cut only: the sign at the
    // end of one cut is carried to the start of the next (outside every
    // component the field minus the threshold is negative), which keeps the
    // count of crossings consistent with inside and outside.
    bool previousNegative = true;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double lo = cuts[i], hi = cuts[i + 1];
        const double mid = 0.5 * (lo + hi);
        // Sum of strength (1 - q(mid + s))^2 in powers of s, with
        // q = A s^2 + B s + C expanded about mid for accuracy.
        double poly[5] = {-threshold_, 0, 0, 0, 0};
        bool active = false;
        for (const Piece& p : pieces) {
            if (!(p.t0 <= mid && mid < p.t1)) continue;
            active = true;
            const Vec3 w = p.w0 + (mid - p.tRef) * p.dir;
            const double A = dot(p.dir, p.dir) * p.invR2, B = 2 * dot(w, p.dir) * p.invR2;
            const double C1 = 1 - dot(w, w) * p.invR2; // 1 - q(mid)
            // (C1 - B s - A s^2)^2
            poly[0] += p.strength * C1 * C1;
            poly[1] += p.strength * (-2 * C1 * B);
            poly[2] += p.strength * (B * B - 2 * C1 * A);
            poly[3] += p.strength * (2 * A * B);
            poly[4] += p.strength * (A * A);
        }
        const auto value = [&](double t) {
            double v = poly[4];
            for (int k = 3; k >= 0; --k) v = v * t + poly[k];
            return v;
        };
        const bool startNegative = !active || value(lo - mid) < 0;
        if (startNegative != previousNegative) out.push_back({lo, -1.0 * gradient(o + lo * d)});
        previousNegative = !active || value(hi - mid) < 0;
        if (!active) continue;
        double roots[5];
        const int n = polynomialRootsInInterval(poly, 4, lo - mid, hi - mid, roots);
        for (int k = 0; k < n; ++k) {
            const double t = std::max(mid + roots[k], out.empty() ? -HUGE_VAL : out.back().t); // sorted
            out.push_back({t, -1.0 * gradient(o + t * d)});
        }
    }
}

} // namespace drt::accel

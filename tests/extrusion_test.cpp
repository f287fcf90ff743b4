// The extrusion shape (prism, text): outlines from splines and TrueType glyphs
// (src/outline), ray crossings (accel/extrusion_shape.h) against closed forms
// and against the box, CSG inside/outside, and spawned rays.
#include "accel/accel.h"
#include "accel/extrusion_shape.h"
#include "accel/shapes.h"
#include "outline/prism_outline.h"
#include "outline/text_outline.h"
#include "test_support.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace drt {
namespace {

const std::string kTimes = std::string(kPovFontDir) + "/timrom.ttf";

double polygonArea(const std::vector<std::vector<Vec2>>& contours) {
    double area = 0;
    for (const auto& c : contours)
        for (size_t i = 0; i < c.size(); ++i) {
            const Vec2 a = c[i], b = c[(i + 1) % c.size()];
            area += 0.5 * (a.x * b.y - a.y * b.x);
        }
    return area;
}

double perimeter(const std::vector<std::vector<Vec2>>& contours) {
    double length = 0;
    for (const auto& c : contours)
        for (size_t i = 0; i < c.size(); ++i) {
            const Vec2 a = c[i], b = c[(i + 1) % c.size()];
            length += std::hypot(b.x - a.x, b.y - a.y);
        }
    return length;
}

Extrusion squarePrism(double h1, double h2, bool conic = false) {
    Extrusion e;
    e.prism = PrismSource{PrismSource::Spline::Linear, {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}};
    e.contours = prismContours(e.prism->spline, e.prism->points);
    e.height1 = h1;
    e.height2 = h2;
    e.conic = conic;
    return e;
}

Vec3 unit(const Vec3& v) { return v / length(v); }

// ------------------------------------------------------------ outlines

TEST(PrismOutline, LinearSubPolygonsCloseAtTheirFirstPoint) {
    // A square with a square hole: two sub-polygons, even-odd fill.
    const std::vector<Vec2> points = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {-2, -2},
                                      {-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    const auto contours = prismContours(PrismSource::Spline::Linear, points);
    ASSERT_EQ(contours.size(), 2u);
    EXPECT_EQ(contours[0].size(), 4u);
    EXPECT_EQ(contours[1].size(), 4u);
    Extrusion e;
    e.contours = contours;
    const accel::ExtrusionGeometry g(e);
    EXPECT_TRUE(g.filled({1.5, 0.3}));
    EXPECT_FALSE(g.filled({0.2, 0.3})); // the hole
    EXPECT_FALSE(g.filled({2.5, 0.3}));
}

TEST(PrismOutline, UnclosedLinearOutlineClosesItself) {
    const auto contours = prismContours(PrismSource::Spline::Linear, {{0, 0}, {1, 0}, {0, 1}});
    ASSERT_EQ(contours.size(), 1u);
    EXPECT_DOUBLE_EQ(polygonArea(contours), 0.5);
}

TEST(PrismOutline, TooFewPointsIsAnError) {
    EXPECT_THROW(prismContours(PrismSource::Spline::Cubic, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}),
                 std::invalid_argument);
    // Quadratic: the last sub-polygon never returns to its first on-curve point.
    EXPECT_THROW(prismContours(PrismSource::Spline::Quadratic, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}, {5, 5}}),
                 std::invalid_argument);
}

// Bezier circle (four quarter arcs, k = 4/3 (sqrt 2 - 1)): the flattened
// outline's area equals the curve's exact area (Green's theorem on the cubic
// polynomials, integrated by 20-point Gauss-Legendre per segment, exact for
// degree <= 39) to within perimeter * tolerance.
TEST(PrismOutline, BezierFlatteningStaysWithinTheStatedTolerance) {
    const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1);
    const std::vector<Vec2> quarter[4] = {{{1, 0}, {1, k}, {k, 1}, {0, 1}},
                                          {{0, 1}, {-k, 1}, {-1, k}, {-1, 0}},
                                          {{-1, 0}, {-1, -k}, {-k, -1}, {0, -1}},
                                          {{0, -1}, {k, -1}, {1, -k}, {1, 0}}};
    std::vector<Vec2> points;
    for (const auto& q : quarter) points.insert(points.end(), q.begin(), q.end());
    const auto contours = prismContours(PrismSource::Spline::Bezier, points);
    ASSERT_EQ(contours.size(), 1u);
    // Exact area: 1/2 closed integral of (x y' - y x') dt.
    auto bez = [](const std::vector<Vec2>& p, double t, bool derivative) {
        const double s = 1 - t;
        if (!derivative)
            return Vec2{s * s * s * p[0].x + 3 * s * s * t * p[1].x + 3 * s * t * t * p[2].x + t * t * t * p[3].x,
                        s * s * s * p[0].y + 3 * s * s * t * p[1].y + 3 * s * t * t * p[2].y + t * t * t * p[3].y};
        return Vec2{3 * s * s * (p[1].x - p[0].x) + 6 * s * t * (p[2].x - p[1].x) + 3 * t * t * (p[3].x - p[2].x),
                    3 * s * s * (p[1].y - p[0].y) + 6 * s * t * (p[2].y - p[1].y) + 3 * t * t * (p[3].y - p[2].y)};
    };
    double exact = 0;
    const int n = 2000; // midpoint rule is plenty: the integrand is a degree-5 polynomial
    for (const auto& q : quarter)
        for (int i = 0; i < n; ++i) {
            const double t = (i + 0.5) / n;
            const Vec2 p = bez(q, t, false), d = bez(q, t, true);
            exact += 0.5 * (p.x * d.y - p.y * d.x) / n;
        }
    const double tolerance = kPrismTolerance * 2; // the points span 2 units
    const double flat = polygonArea(contours);
    EXPECT_LT(flat, exact);
    EXPECT_LT(exact - flat, perimeter(contours) * tolerance);
    EXPECT_NEAR(exact, kPi, 1e-3); // the Bezier circle is within 2.7e-4 of the unit circle
}

// ------------------------------------------------------------ glyphs

// The exact area of a glyph's quadratic TrueType outline: the polygon of the
// segment ends plus, per conic segment, 2/3 of its control triangle.
double exactGlyphArea(char c) {
    FT_Library library;
    FT_Face face;
    EXPECT_EQ(FT_Init_FreeType(&library), 0);
    EXPECT_EQ(FT_New_Face(library, kTimes.c_str(), 0, &face), 0);
    EXPECT_EQ(FT_Load_Char(face, FT_ULong(c), FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING), 0);
    const FT_Outline& o = face->glyph->outline;
    double area = 0;
    int start = 0;
    for (int k = 0; k < o.n_contours; ++k) {
        const int end = o.contours[k];
        const int n = end - start + 1;
        auto pt = [&](int i) { return Vec2{double(o.points[start + i].x), double(o.points[start + i].y)}; };
        auto on = [&](int i) { return (o.tags[start + i] & 1) != 0; };
        // Walk from an on-curve point; two off-curve points imply an on-curve midpoint.
        int first = 0;
        while (!on(first)) ++first;
        Vec2 current = pt(first);
        for (int step = 1; step <= n; ++step) {
            const int i = (first + step) % n;
            if (on(i)) {
                area += 0.5 * (current.x * pt(i).y - current.y * pt(i).x);
                current = pt(i);
                continue;
            }
            const Vec2 control = pt(i);
            const int j = (i + 1) % n;
            const Vec2 next = on(j) ? pt(j) : Vec2{0.5 * (control.x + pt(j).x), 0.5 * (control.y + pt(j).y)};
            area += 0.5 * (current.x * next.y - current.y * next.x);
            area += 2.0 / 3.0 * 0.5 *
                    ((control.x - current.x) * (next.y - current.y) - (control.y - current.y) * (next.x - current.x));
            current = next;
            if (on(j)) ++step;
        }
        start = end + 1;
    }
    const double em = face->units_per_EM;
    FT_Done_Face(face);
    FT_Done_FreeType(library);
    return area / (em * em);
}

TEST(TextOutline, GlyphAreasMatchTheExactOutlineWithinTheTolerance) {
    for (char c : std::string("IlOo&")) {
        SCOPED_TRACE(std::string(1, c));
        const auto contours = textContours(kTimes, std::string(1, c), {0, 0});
        ASSERT_FALSE(contours.empty());
        // TrueType outer contours run clockwise: the signed area is negative.
        const double flat = -polygonArea(contours), exact = -exactGlyphArea(c);
        EXPECT_GT(exact, 0.01);
        EXPECT_LE(std::fabs(flat - exact), perimeter(contours) * kGlyphTolerance);
    }
}

TEST(TextOutline, FirstGlyphStartsAtZeroAndGlyphsFollowTheAdvances) {
    FT_Library library;
    FT_Face face;
    ASSERT_EQ(FT_Init_FreeType(&library), 0);
    ASSERT_EQ(FT_New_Face(library, kTimes.c_str(), 0, &face), 0);
    ASSERT_EQ(FT_Load_Char(face, 'H', FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING), 0);
    const double advance = double(face->glyph->metrics.horiAdvance) / face->units_per_EM;
    FT_Done_Face(face);
    FT_Done_FreeType(library);
    auto bounds = [](const std::vector<std::vector<Vec2>>& contours, Vec2& lo, Vec2& hi) {
        lo = {INFINITY, INFINITY};
        hi = {-INFINITY, -INFINITY};
        for (const auto& c : contours)
            for (const Vec2& p : c) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    };
    Vec2 lo1, hi1, lo3, hi3, loOff, hiOff;
    bounds(textContours(kTimes, "H", {0, 0}), lo1, hi1);
    bounds(textContours(kTimes, "HHH", {0, 0}), lo3, hi3);
    bounds(textContours(kTimes, "HHH", {0.1, 0.05}), loOff, hiOff);
    EXPECT_EQ(lo1.x, 0.0);
    EXPECT_EQ(lo1.y, 0.0); // 'H' sits on the baseline
    EXPECT_GT(hi1.y, 0.6); // and is a capital (cap height ~0.66 em in Times)
    EXPECT_LT(hi1.y, 0.7);
    // No kerning between H and H: each next H is one advance further.
    EXPECT_NEAR(hi3.x, hi1.x + 2 * advance, 1e-12);
    // The offset moves each next glyph by (0.1, 0.05) more.
    EXPECT_NEAR(hiOff.x - hi3.x, 0.2, 1e-12);
    EXPECT_NEAR(hiOff.y - hi3.y, 0.1, 1e-12);
}

TEST(TextOutline, KerningPullsAVTogether) {
    auto width = [](const std::string& s) {
        double hi = -INFINITY;
        for (const auto& c : textContours(kTimes, s, {0, 0}))
            for (const Vec2& p : c) hi = std::max(hi, p.x);
        return hi;
    };
    // 'AV' is kerned in Times (a negative pair value): narrower than 'AA'-style spacing predicts.
    const double av = width("AV"), a = width("A"), v = width("V");
    EXPECT_LT(av, a + v);
}

// UTF-8 text, and Latin-1 bytes (not valid UTF-8) read byte by byte.
TEST(TextOutline, Utf8AndLatin1Text) {
    // U+00A9 (copyright sign), which timrom.ttf has: a ring (two contours) around a C.
    const auto accented = textContours(kTimes, "\xC2\xA9", {0, 0});
    const auto latin1 = textContours(kTimes, "\xA9", {0, 0});
    EXPECT_EQ(accented.size(), 3u);
    ASSERT_EQ(latin1.size(), accented.size());
    for (size_t i = 0; i < latin1.size(); ++i) {
        ASSERT_EQ(latin1[i].size(), accented[i].size());
        for (size_t k = 0; k < latin1[i].size(); ++k) {
            EXPECT_EQ(latin1[i][k].x, accented[i][k].x);
            EXPECT_EQ(latin1[i][k].y, accented[i][k].y);
        }
    }
}

TEST(TextOutline, MissingOrBadFontIsAnError) {
    EXPECT_EQ(findFontFile("no-such-font.ttf", {kPovFontDir, "."}), "");
    EXPECT_EQ(findFontFile("timrom.ttf", {"/nonexistent", kPovFontDir}), kTimes);
    EXPECT_THROW(textContours("/etc/hostname", "a", {0, 0}), FontError);
}

// ------------------------------------------------------------ intersection

// A square linear prism is the box [-1,1] x [h1,h2] x [-1,1]: the same
// crossings (t and normal) on thousands of random lines, the same insides.
TEST(ExtrusionIntersect, SquarePrismEqualsTheBox) {
    const auto prism = *accel::prepareShape(squarePrism(-0.5, 0.75));
    const auto box = *accel::prepareShape(Box{{-1, -0.5, -1}, {1, 0.75, 1}});
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-2, 2);
    std::normal_distribution<double> g;
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 o{u(rng), u(rng), u(rng)};
        Vec3 d{g(rng), g(rng), g(rng)};
        if (i % 10 == 0) d = {0, 0, 0}, d[i % 3] = 1; // axis-aligned lines too
        accel::Crossing a[accel::kMaxCrossings], b[accel::kMaxCrossings];
        std::vector<accel::Crossing> many;
        const accel::Crossing* pa = nullptr;
        const int na = accel::allCrossings(prism, o, d, a, many, pa);
        const int nb = accel::intersectShape(box, o, d, b);
        // Lines through an edge or corner may count it on either face; skip the
        // measure-zero cases where the box itself reports a zero-length chord.
        if (nb == 2 && std::fabs(b[1].t - b[0].t) < 1e-12) continue;
        ASSERT_EQ(na, nb) << i;
        for (int k = 0; k < na; ++k) {
            EXPECT_NEAR(pa[k].t, b[k].t, 1e-12 * (1 + std::fabs(b[k].t)));
            const Vec3 na3 = unit(pa[k].normal), nb3 = unit(b[k].normal);
            EXPECT_NEAR(dot(na3, nb3), 1.0, 1e-12) << i;
        }
        hits += na > 0;
        const Vec3 p{u(rng), u(rng), u(rng)};
        EXPECT_EQ(accel::insideShape(prism, p), accel::insideShape(box, p));
    }
    EXPECT_GT(hits, 5000);
}

// Conic square prism between heights 0.5 and 1: the frustum |x|, |z| <= y.
TEST(ExtrusionIntersect, ConicSweepIsTheFrustum) {
    const auto s = *accel::prepareShape(squarePrism(0.5, 1, true));
    accel::Crossing c[accel::kMaxCrossings];
    // Along x at height 0.75: walls x = -0.75 and x = 0.75 with normals (-+1, -1, 0)/sqrt 2.
    int n = accel::intersectShape(s, {-3, 0.75, 0.1}, {1, 0, 0}, c);
    ASSERT_EQ(n, 2);
    EXPECT_NEAR(c[0].t, 3 - 0.75, 1e-12);
    EXPECT_NEAR(c[1].t, 3 + 0.75, 1e-12);
    EXPECT_NEAR(dot(unit(c[0].normal), unit(Vec3{-1, -1, 0})), 1, 1e-12);
    EXPECT_NEAR(dot(unit(c[1].normal), unit(Vec3{1, -1, 0})), 1, 1e-12);
    // Down the axis at (0.3, z=0.4): the top cap at y = 1 and the bottom at 0.5.
    n = accel::intersectShape(s, {0.3, 5, 0.4}, {0, -2, 0}, c);
    ASSERT_EQ(n, 2);
    EXPECT_NEAR(c[0].t, 2, 1e-12);
    EXPECT_NEAR(c[1].t, 2.25, 1e-12);
    EXPECT_EQ(unit(c[0].normal), Vec3(0, 1, 0));
    EXPECT_EQ(unit(c[1].normal), Vec3(0, -1, 0));
    // (0.7, 0.4) is outside the bottom cap (half-size 0.5) but inside the top one.
    n = accel::intersectShape(s, {0.7, 5, 0.4}, {0, -1, 0}, c);
    ASSERT_EQ(n, 2);
    EXPECT_NEAR(c[1].t, 5 - 0.7, 1e-12); // leaves through the wall x = y
    EXPECT_TRUE(accel::insideShape(s, {0.7, 0.8, 0.4}));
    EXPECT_FALSE(accel::insideShape(s, {0.7, 0.6, 0.4}));
}

TEST(ExtrusionIntersect, OpenPrismHasNoCapsAndNoInside) {
    Extrusion e = squarePrism(0, 1);
    e.open = true;
    const auto s = *accel::prepareShape(e);
    accel::Crossing c[accel::kMaxCrossings];
    EXPECT_EQ(accel::intersectShape(s, {0, 3, 0}, {0, -1, 0}, c), 0);
    EXPECT_EQ(accel::intersectShape(s, {-3, 0.5, 0}, {1, 0, 0}, c), 2);
    EXPECT_FALSE(accel::insideShape(s, {0, 0.5, 0}));
    EXPECT_FALSE(accel::isSolidShape(s));
}

TEST(ExtrusionIntersect, DegenerateExtrusionsAreRejected) {
    EXPECT_THROW(accel::prepareShape(squarePrism(1, 1)), std::invalid_argument);
    EXPECT_THROW(accel::prepareShape(squarePrism(-1, 1, true)), std::invalid_argument);
    Extrusion flat; // collinear points enclose nothing
    flat.contours = {{{0, 0}, {1, 1}, {2, 2}}};
    EXPECT_THROW(accel::prepareShape(flat), std::invalid_argument);
    Extrusion nan = squarePrism(0, 1);
    nan.contours[0][1].x = NAN;
    EXPECT_THROW(accel::prepareShape(nan), std::invalid_argument);
}

// A text of spaces has no contours: an empty shape, hit by nothing.
TEST(ExtrusionIntersect, EmptyOutlineIsAnEmptyShape) {
    TextSource source{"timrom.ttf", kTimes, "   ", {0, 0, 0}, {}, {}};
    const Extrusion e = makeTextExtrusion(source, 1);
    EXPECT_TRUE(e.contours.empty());
    EXPECT_EQ(e.text->boxLower.x, 0); // the spaces' origins: a box of zero height
    EXPECT_GT(e.text->boxUpper.x, 0);
    EXPECT_EQ(e.text->boxLower.y, e.text->boxUpper.y);
    const auto s = *accel::prepareShape(e);
    accel::Crossing c[accel::kMaxCrossings];
    EXPECT_EQ(accel::intersectShape(s, {0.2, 0.2, -3}, {0, 0, 1}, c), 0);
    EXPECT_FALSE(accel::insideShape(s, {0.2, 0.2, 0.5}));
}

// A text with many edges: every crossing along a line alternates between
// entering and leaving, and a line through a counter (the hole of 'o') leaves
// the letter there.
TEST(ExtrusionIntersect, TextCrossingsAlternateAndHolesAreEmpty) {
    TextSource source{"timrom.ttf", kTimes, "drt 80%", {0, 0, 0}, {}, {}};
    const auto s = *accel::prepareShape(makeTextExtrusion(source, 0.3));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ux(-0.5, 4), uy(-0.5, 1.2), uz(-1, 1);
    std::vector<accel::Crossing> many;
    accel::Crossing fixed[accel::kMaxCrossings];
    int lines = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 a{ux(rng), uy(rng), uz(rng)}, b{ux(rng), uy(rng), uz(rng)};
        const accel::Crossing* c = nullptr;
        const int n = accel::allCrossings(s, a, b - a, fixed, many, c);
        ASSERT_EQ(n % 2, 0) << i;
        for (int k = 0; k < n; ++k) {
            const bool entering = dot(c[k].normal, b - a) < 0;
            EXPECT_EQ(entering, k % 2 == 0) << i << " crossing " << k;
            // Just past a crossing: inside after entering, outside after leaving.
            const double next = k + 1 < n ? c[k + 1].t : c[k].t + 1;
            const Vec3 p = a + (0.5 * (c[k].t + next)) * (b - a);
            if (next - c[k].t > 1e-6) {
                EXPECT_EQ(accel::insideShape(s, p), entering) << i;
            }
        }
        lines += n > 0;
    }
    EXPECT_GT(lines, 1000);
}

// ------------------------------------------------------------ through Embree

Object object(Shape shape, Transform t = {}) {
    Object o;
    o.shape = std::move(shape);
    o.transform = t;
    return o;
}

TEST(ExtrusionAccel, DifferenceWithAPrismCutsTheHole) {
    // A box minus a square prism through it: a ray down the middle passes.
    Object csgObject;
    Csg csg;
    csg.op = Csg::Op::Difference;
    csg.children.push_back(object(Box{{-2, -1, -2}, {2, 1, 2}}));
    csg.children.push_back(object(squarePrism(-3, 3)));
    csgObject.shape = csg;
    Scene scene;
    scene.objects.push_back(csgObject);
    Accelerator accel(scene);
    Ray ray;
    Hit hit;
    ray.origin = {0.5, 5, 0.5};
    ray.direction = {0, -1, 0};
    EXPECT_FALSE(accel.intersect(ray, hit));
    ray.origin = {1.5, 5, 0.5};
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.t, 4, 1e-6);
    ray.origin = {-5, 0, 0.2};
    ray.direction = {1, 0, 0};
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.t, 3, 1e-6);
    ray.origin = Accelerator::offsetOrigin(hit, {1, 0, 0});
    ASSERT_TRUE(accel.intersect(ray, hit)); // leaves the box at the prism's wall x = -1
    EXPECT_NEAR(hit.point.x, -1, 1e-6);
    EXPECT_NEAR(dot(hit.geometricNormal, Vec3(1, 0, 0)), 1, 1e-9);
}

using test::randomUnitVector;

// Rays spawned from hits on text (non-convex, thin) and on a rotated conic
// prism, at several scales: a ray leaving a surface must not hit it again at
// its own spawn point.
TEST(ExtrusionAccel, SpawnedRaysDoNotReHitTheirSurface) {
    TextSource source{"timrom.ttf", kTimes, "Wg", {0, 0, 0}, {}, {}};
    const std::vector<Shape> shapes = {makeTextExtrusion(source, 0.2), squarePrism(0.5, 1, true)};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    int rays = 0, selfHits = 0;
    for (double scale : {1e-3, 1.0, 1e3})
        for (const Shape& shape : shapes) {
            const Transform t = Transform::rotate({10, 20, 30}).then(Transform::scale(Vec3(scale)));
            Scene scene;
            scene.objects.push_back(object(shape, t));
            Accelerator accel(scene);
            for (int i = 0; i < 1500; ++i) {
                const Vec3 target = t.point({u(rng) * 1.2, u(rng) * 0.7, u(rng) * 0.2});
                const Vec3 origin = target + randomUnitVector(rng) * (3 * scale);
                Ray ray;
                ray.origin = origin;
                ray.direction = target - origin;
                Hit hit;
                if (!accel.intersect(ray, hit)) continue;
                test::countSelfHits(accel, hit, origin, scale, rng, rays, selfHits);
            }
        }
    EXPECT_EQ(selfHits, 0) << "among " << rays;
    EXPECT_GT(rays, 5000);
}

} // namespace
} // namespace drt

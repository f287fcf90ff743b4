// The quadric primitives: sphere, plane, box, cylinder, cone, disc and torus.
//   sphere { centre, radius }          plane { normal, distance }
//   box { corner1, corner2 }           cylinder { base, cap, radius [open] }
//   cone { base, r1, cap, r2 [open] }  disc { centre, normal, radius [, hole] }
//   torus { major, minor }
// Commas are required in .drt files, optional in POV-Ray's. A value the
// renderer cannot draw (a zero radius, a zero axis) is an error in both.
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

#include <cmath>

namespace drt::lang {

using writer::number;
using writer::vector;

namespace {

double positive(Evaluator& e, const char* what) {
    const SourceLoc loc = e.peek().loc;
    const double r = e.floatExpr(what);
    if (!(r > 0)) {
        e.error(loc, std::string(what) + " must be positive" + e.got(r));
        return 1;
    }
    return r;
}

} // namespace

// ------------------------------------------------------------ sphere

template <>
const std::vector<std::string>& ShapeSyntax<Sphere>::keywords() {
    static const std::vector<std::string> w{"sphere"};
    return w;
}

template <>
void ShapeSyntax<Sphere>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Sphere s;
    s.center = e.vectorExpr("the centre <x, y, z>");
    e.comma("centre");
    s.radius = positive(e, "sphere radius");
    o.object.shape = s;
}

template <>
std::string ShapeSyntax<Sphere>::head(const Sphere& s, ShapeText&) {
    return "sphere { " + vector(s.center) + ", " + number(s.radius);
}

// ------------------------------------------------------------ plane

template <>
const std::vector<std::string>& ShapeSyntax<Plane>::keywords() {
    static const std::vector<std::string> w{"plane"};
    return w;
}

template <>
void ShapeSyntax<Plane>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Plane p;
    const SourceLoc loc = e.peek().loc;
    Vec3 n = e.vectorExpr("the normal <x, y, z>");
    e.comma("normal");
    double d = e.floatExpr("the distance");
    // POV-Ray normalises the normal and divides the distance by its length,
    // which keeps the plane dot(n, p) = d where it was: plane { <0, 2, 0>, 1 } is y = 0.5.
    const double len = length(n);
    if (!(len > 0)) {
        e.error(loc, "plane normal must not be a zero-length vector");
        n = {0, 1, 0};
    } else {
        n = n / len;
        d /= len;
    }
    p.normal = n;
    p.distance = d;
    o.object.shape = p;
}

template <>
std::string ShapeSyntax<Plane>::head(const Plane& p, ShapeText&) {
    // The reader divides both the normal and the distance by the normal's length.
    const Vec3 n = writer::unnormalised(p.normal);
    const double len = length(n);
    const double guess = p.distance * len;
    double d = guess;
    for (double c : {guess, std::nextafter(guess, INFINITY), std::nextafter(guess, -INFINITY)})
        if (c / len == p.distance) {
            d = c;
            break;
        }
    return "plane { " + vector(n) + ", " + number(d);
}

// ------------------------------------------------------------ box

template <>
const std::vector<std::string>& ShapeSyntax<Box>::keywords() {
    static const std::vector<std::string> w{"box"};
    return w;
}

template <>
void ShapeSyntax<Box>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Box b;
    b.corner1 = e.vectorExpr("a corner <x, y, z>");
    e.comma("first corner");
    b.corner2 = e.vectorExpr("a corner <x, y, z>");
    o.object.shape = b;
}

template <>
std::string ShapeSyntax<Box>::head(const Box& b, ShapeText&) {
    return "box { " + vector(b.corner1) + ", " + vector(b.corner2);
}

// ------------------------------------------------------------ cylinder

template <>
const std::vector<std::string>& ShapeSyntax<Cylinder>::keywords() {
    static const std::vector<std::string> w{"cylinder"};
    return w;
}

template <>
void ShapeSyntax<Cylinder>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Cylinder c;
    c.base = e.vectorExpr("the base point");
    e.comma("base point");
    const SourceLoc capLoc = e.peek().loc;
    c.cap = e.vectorExpr("the cap point");
    e.comma("cap point");
    c.radius = positive(e, "cylinder radius");
    if (c.base == c.cap) {
        e.error(capLoc, "cylinder base and cap are the same point (zero-length axis)");
        c.cap = c.base + Vec3(0, 1, 0);
    }
    o.object.shape = c;
}

template <>
std::string ShapeSyntax<Cylinder>::head(const Cylinder& c, ShapeText&) {
    return "cylinder { " + vector(c.base) + ", " + vector(c.cap) + ", " + number(c.radius) + (c.open ? " open" : "");
}

// ------------------------------------------------------------ cone

template <>
const std::vector<std::string>& ShapeSyntax<Cone>::keywords() {
    static const std::vector<std::string> w{"cone"};
    return w;
}

template <>
void ShapeSyntax<Cone>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Cone c;
    c.base = e.vectorExpr("the base point");
    e.comma("base point");
    SourceLoc loc = e.peek().loc;
    c.baseRadius = e.floatExpr("the base radius");
    if (c.baseRadius < 0) e.error(loc, "cone radius must not be negative" + e.got(c.baseRadius));
    e.comma("base radius");
    const SourceLoc capLoc = e.peek().loc;
    c.cap = e.vectorExpr("the cap point");
    e.comma("cap point");
    loc = e.peek().loc;
    c.capRadius = e.floatExpr("the cap radius");
    if (c.capRadius < 0) e.error(loc, "cone radius must not be negative" + e.got(c.capRadius));
    if (c.baseRadius <= 0 && c.capRadius <= 0) e.error(loc, "cone needs at least one positive radius");
    if (c.base == c.cap) {
        e.error(capLoc, "cone base and cap are the same point (zero-length axis)");
        c.cap = c.base + Vec3(0, 1, 0);
    }
    o.object.shape = c;
}

template <>
std::string ShapeSyntax<Cone>::head(const Cone& c, ShapeText&) {
    return "cone { " + vector(c.base) + ", " + number(c.baseRadius) + ", " + vector(c.cap) + ", " +
           number(c.capRadius) + (c.open ? " open" : "");
}

// ------------------------------------------------------------ disc

template <>
const std::vector<std::string>& ShapeSyntax<Disc>::keywords() {
    static const std::vector<std::string> w{"disc"};
    return w;
}

template <>
void ShapeSyntax<Disc>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Disc d;
    d.center = e.vectorExpr("the centre <x, y, z>");
    e.comma("centre");
    const SourceLoc loc = e.peek().loc;
    d.normal = e.vectorExpr("the normal <x, y, z>");
    if (!(length(d.normal) > 0)) {
        e.error(loc, "disc normal must not be a zero-length vector");
        d.normal = {0, 1, 0};
    }
    d.normal = normalize(d.normal);
    e.comma("normal");
    d.radius = positive(e, "disc radius");
    if (e.acceptSymbol(",")) {
        const SourceLoc holeLoc = e.peek().loc;
        d.holeRadius = e.floatExpr("the hole radius");
        if (d.holeRadius < 0) e.error(holeLoc, "disc hole radius must not be negative" + e.got(d.holeRadius));
    }
    o.object.shape = d;
}

template <>
std::string ShapeSyntax<Disc>::head(const Disc& d, ShapeText&) {
    return "disc { " + vector(d.center) + ", " + vector(writer::unnormalised(d.normal)) + ", " + number(d.radius) +
           (d.holeRadius != 0 ? ", " + number(d.holeRadius) : "");
}

// ------------------------------------------------------------ torus

template <>
const std::vector<std::string>& ShapeSyntax<Torus>::keywords() {
    static const std::vector<std::string> w{"torus"};
    return w;
}

template <>
void ShapeSyntax<Torus>::read(Evaluator& e, const Token&, ObjectValue& o) {
    Torus t;
    t.majorRadius = positive(e, "torus major radius");
    e.comma("major radius");
    t.minorRadius = positive(e, "torus minor radius");
    o.object.shape = t;
}

template <>
std::string ShapeSyntax<Torus>::head(const Torus& t, ShapeText&) {
    return "torus { " + number(t.majorRadius) + ", " + number(t.minorRadius);
}

} // namespace drt::lang

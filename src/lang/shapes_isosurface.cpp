// The isosurface (scene/isosurface.h), in both dialects:
//   isosurface { function { ... }
//                [contained_by { box { <c1>, <c2> } | sphere { <centre>, radius } }]
//                [threshold t] [accuracy a] [max_gradient g] [evaluate p0, p1, p2]
//                [open] [max_trace n | all_intersections] ... object modifiers }
// The function may also be a declared function's name (`function { F(x, y, z) }`
// is the same as POV-Ray's usual form). Defaults are POV-Ray's: the box
// <-1, -1, -1>, <1, 1, 1>, threshold 0, accuracy 0.001, max_gradient 1.1.
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"
#include "lang/writer_function.h"

#include <fmt/format.h>

namespace drt::lang {

using writer::number;
using writer::vector;

template <>
const std::vector<std::string>& ShapeSyntax<Isosurface>::keywords() {
    static const std::vector<std::string> w{"isosurface"};
    return w;
}

template <>
void ShapeSyntax<Isosurface>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    Isosurface iso;
    auto positive = [&](const char* what, double fallback) {
        const SourceLoc loc = e.peek().loc;
        const double v = e.floatExpr(what);
        if (v > 0 && std::isfinite(v)) return v;
        e.error(loc, std::string("isosurface ") + what + " must be positive" + e.got(v));
        return fallback;
    };
    for (;;) {
        const Token item = e.peek();
        if (item.isWord("function")) {
            e.next();
            iso.function = e.patternFunction(item);
        } else if (item.isWord("contained_by")) {
            e.next();
            const Token open = e.expectSymbol("{", "after 'contained_by'");
            Evaluator::BlockScope scope(e, "contained_by", item.loc);
            const Token shape = e.expectWord("'box' or 'sphere' in contained_by");
            if (shape.text != "box" && shape.text != "sphere")
                e.fail(shape.loc, "an isosurface is contained by a 'box' or a 'sphere', not '" + shape.text + "'");
            e.expectSymbol("{", "after '", shape.text, "'");
            if (shape.text == "box") {
                iso.container = Isosurface::Container::Box;
                iso.corner1 = e.vectorExpr("the box's first corner");
                e.comma("first corner");
                const SourceLoc loc = e.peek().loc;
                iso.corner2 = e.vectorExpr("the box's second corner");
                const Vec3 lo = min(iso.corner1, iso.corner2), hi = max(iso.corner1, iso.corner2);
                if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) {
                    e.error(loc, "the isosurface's container box is empty");
                    iso.corner1 = Vec3(-1), iso.corner2 = Vec3(1);
                }
            } else {
                iso.container = Isosurface::Container::Sphere;
                iso.center = e.vectorExpr("the sphere's centre");
                e.comma("centre");
                iso.radius = positive("container radius", 1);
            }
            e.expectSymbol("}", "to close the container's " + shape.text);
            e.expectSymbol("}", "to close 'contained_by'");
            (void)open;
        } else if (item.isWord("threshold")) {
            e.next();
            iso.threshold = e.floatExpr("the isosurface threshold");
        } else if (item.isWord("accuracy")) {
            e.next();
            iso.accuracy = positive("accuracy", 0.001);
        } else if (item.isWord("max_gradient")) {
            e.next();
            iso.maxGradient = positive("max_gradient", 1.1);
        } else if (item.isWord("evaluate")) {
            e.next();
            iso.evaluate = true;
            iso.evaluateParams.x = e.floatExpr("evaluate's first number");
            e.comma("number");
            iso.evaluateParams.y = e.floatExpr("evaluate's second number");
            e.comma("number");
            iso.evaluateParams.z = e.floatExpr("evaluate's third number");
            e.noteOnce("isosurface-evaluate", item.loc,
                       "'evaluate' is read but drt keeps max_gradient fixed (it steps by it everywhere)");
        } else if (item.isWord("open")) {
            e.next();
            iso.open = true;
        } else if (item.isWord("max_trace")) {
            e.next();
            iso.maxTrace = e.countExpr("max_trace", 1, 1e9);
        } else if (item.isWord("all_intersections")) {
            e.next();
            iso.maxTrace = 0;
        } else {
            break;
        }
    }
    if (!iso.function) e.fail(keyword.loc, "an isosurface needs a 'function { ... }'");
    o.object.shape = std::move(iso);
}

template <>
std::string ShapeSyntax<Isosurface>::head(const Isosurface& iso, ShapeText& out) {
    const std::string pad(size_t(out.indent + 1) * 2, ' ');
    std::string text = "isosurface { " + writer::functionHead(*iso.function) + "{ " +
                       writer::functionText(*iso.function, out.problems) + " }";
    text += "\n" + pad + "contained_by { ";
    if (iso.container == Isosurface::Container::Box)
        text += "box { " + vector(iso.corner1) + ", " + vector(iso.corner2) + " } }";
    else
        text += "sphere { " + vector(iso.center) + ", " + number(iso.radius) + " } }";
    text += "\n" + pad + "threshold " + number(iso.threshold) + " accuracy " + number(iso.accuracy) +
            " max_gradient " + number(iso.maxGradient);
    if (iso.evaluate)
        text += " evaluate " + number(iso.evaluateParams.x) + ", " + number(iso.evaluateParams.y) + ", " +
                number(iso.evaluateParams.z);
    if (iso.open) text += " open";
    if (iso.maxTrace == 0) text += " all_intersections";
    else if (iso.maxTrace != 1) text += " max_trace " + std::to_string(iso.maxTrace);
    return text;
}

} // namespace drt::lang

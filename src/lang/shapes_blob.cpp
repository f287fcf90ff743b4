// The blob (scene/blob.h):
//   blob { [threshold t]
//          sphere { <centre>, radius, [strength] s { transform } }
//          cylinder { <end1>, <end2>, radius, [strength] s { transform } }
//          component s, r, <centre>   (POV-Ray's old syntax for a sphere)
//          [sturm] [hierarchy [on | off]] ... object modifiers }
// Transforms inside a component move that component; a component's texture
// is read and ignored with a warning in POV-Ray scenes (drt textures the blob
// as one object).
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

namespace drt::lang {

using writer::number;
using writer::vector;

namespace {

BlobComponent component(Evaluator& e, const Token& keyword) {
    BlobComponent c;
    c.kind = keyword.text == "cylinder" ? BlobComponent::Kind::Cylinder : BlobComponent::Kind::Sphere;
    const Token open = e.expectSymbol("{", "after '", keyword.text, "'");
    Evaluator::DepthGuard guard(e, open.loc);
    c.center = e.vectorExpr(c.kind == BlobComponent::Kind::Sphere ? "the component's centre" : "the cylinder's first end");
    e.comma("point");
    if (c.kind == BlobComponent::Kind::Cylinder) {
        const SourceLoc loc = e.peek().loc;
        c.end = e.vectorExpr("the cylinder's second end");
        if (c.end == c.center) e.error(loc, "a blob cylinder needs two different end points");
        e.comma("second end");
    }
    const SourceLoc radiusLoc = e.peek().loc;
    c.radius = e.floatExpr("blob component radius");
    if (!(c.radius > 0)) {
        e.error(radiusLoc, "blob component radius must be positive" + e.got(c.radius));
        c.radius = 1;
    }
    e.comma("radius");
    e.acceptWord("strength");
    const SourceLoc strengthLoc = e.peek().loc;
    c.strength = e.floatExpr("the component's strength");
    if (c.strength == 0) e.refuse(strengthLoc, "a blob component's strength must not be 0");
    for (;;) {
        if (std::optional<Transform> t = e.transformItem()) {
            c.transform = c.transform.then(*t);
            continue;
        }
        const Token t = e.next();
        if (t.is("}")) break;
        if (!e.syntax().unsupportedIsError &&
            (t.isWord("texture") || t.isWord("pigment") || t.isWord("finish") || t.isWord("normal"))) {
            e.unsupported("blob-component-texture", t.loc,
                          "textures of blob components are ignored: the blob takes its own texture");
            if (t.isWord("texture")) e.texture(e.defaultTexture_);
            else if (t.isWord("pigment")) e.pigment(e.defaultTexture_.pigment);
            else if (t.isWord("finish")) e.finish(e.defaultTexture_.finish);
            else e.normalBlock(t.loc, std::nullopt);
            continue;
        }
        e.failExpected(t, "'}' to close the blob " + keyword.text);
    }
    return c;
}

} // namespace

template <>
const std::vector<std::string>& ShapeSyntax<Blob>::keywords() {
    static const std::vector<std::string> w{"blob"};
    return w;
}

template <>
void ShapeSyntax<Blob>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    Blob blob;
    for (;;) {
        const Token item = e.peek();
        if (item.isWord("threshold")) {
            e.next();
            const SourceLoc loc = e.peek().loc;
            blob.threshold = e.floatExpr("the blob threshold");
            if (!(blob.threshold > 0)) {
                e.error(loc, "the blob threshold must be positive" + e.got(blob.threshold));
                blob.threshold = 1;
            }
        } else if (item.isWord("sphere") || item.isWord("cylinder")) {
            e.next();
            e.countBuilt(item.loc, 1); // a #while can add components without end
            blob.components.push_back(component(e, item));
        } else if (item.isWord("component")) {
            e.next();
            e.countBuilt(item.loc, 1);
            BlobComponent c;
            c.strength = e.floatExpr("the component's strength");
            e.comma("strength");
            const SourceLoc radiusLoc = e.peek().loc;
            c.radius = e.floatExpr("blob component radius");
            if (!(c.radius > 0)) e.error(radiusLoc, "blob component radius must be positive" + e.got(c.radius));
            e.comma("radius");
            c.center = e.vectorExpr("the component's centre");
            blob.components.push_back(c);
        } else if (item.isWord("sturm")) {
            e.next();
            blob.sturm = e.optionalBool(true);
        } else if (item.isWord("hierarchy")) {
            e.next();
            blob.hierarchy = e.optionalBool(true);
        } else {
            break;
        }
    }
    if (blob.components.empty()) e.error(keyword.loc, "a blob needs at least one sphere or cylinder component");
    o.object.shape = std::move(blob);
}

template <>
std::string ShapeSyntax<Blob>::head(const Blob& b, ShapeText& out) {
    const std::string pad(size_t(out.indent + 1) * 2, ' ');
    std::string text = "blob { threshold " + number(b.threshold);
    for (const BlobComponent& c : b.components) {
        text += "\n" + pad;
        if (c.kind == BlobComponent::Kind::Sphere) text += "sphere { " + vector(c.center);
        else text += "cylinder { " + vector(c.center) + ", " + vector(c.end);
        text += ", " + number(c.radius) + ", strength " + number(c.strength);
        text += writer::formatSteps(writer::decompose(c.transform)) + " }";
    }
    if (b.sturm) text += "\n" + pad + "sturm";
    if (!b.hierarchy) text += "\n" + pad + "hierarchy off";
    return text;
}

} // namespace drt::lang

// The blob of the .drt language (POV-Ray's syntax):
//   blob { [threshold t]
//          sphere { <centre>, radius, [strength] s { transform } }
//          cylinder { <end1>, <end2>, radius, [strength] s { transform } } ...
//          [sturm] [hierarchy [on | off]] }
// `threshold`, components, `sturm` and `hierarchy` may come in any order
// before the object modifiers.
#include "lang/parser.h"

namespace drt {

namespace {

bool isBlobItemWord(const std::string& w) {
    return w == "threshold" || w == "sphere" || w == "cylinder" || w == "sturm" || w == "hierarchy";
}

} // namespace

BlobComponent Parser::blobComponent() {
    BlobComponent c;
    const Token keyword = current_;
    advance();
    c.kind = keyword.text == "cylinder" ? BlobComponent::Kind::Cylinder : BlobComponent::Kind::Sphere;
    const Token open = expect(TokenKind::LeftBrace, ("'{' after '" + keyword.text + "'").c_str());
    DepthGuard guard(*this, open.loc);
    c.center = vectorExpr(c.kind == BlobComponent::Kind::Sphere ? "the component's centre" : "the cylinder's first end");
    expect(TokenKind::Comma, "',' after the point");
    if (c.kind == BlobComponent::Kind::Cylinder) {
        const SourceLoc loc = current_.loc;
        c.end = vectorExpr("the cylinder's second end");
        if (c.end == c.center) error(loc, "a blob cylinder needs two different ends");
        expect(TokenKind::Comma, "',' after the second end");
    }
    c.radius = positiveRadius("blob component radius");
    expect(TokenKind::Comma, "',' after the radius");
    matchWord("strength");
    const SourceLoc strengthLoc = current_.loc;
    c.strength = floatExpr("the component's strength");
    if (c.strength == 0) error(strengthLoc, "a blob component's strength must not be 0");
    while (std::optional<Transform> t = transformItem()) c.transform = c.transform.then(*t);
    expect(TokenKind::RightBrace, ("'}' to close the blob " + keyword.text).c_str());
    return c;
}

void Parser::blobBody(const Token& keyword, ParsedObject& po) {
    Blob blob;
    while (check(TokenKind::Identifier) && isBlobItemWord(current_.text)) {
        const std::string w = current_.text;
        if (w == "threshold") {
            advance();
            const SourceLoc loc = current_.loc;
            blob.threshold = floatExpr("the blob threshold");
            if (!(blob.threshold > 0)) {
                error(loc, "the blob threshold must be positive");
                blob.threshold = 1;
            }
        } else if (w == "sphere" || w == "cylinder") {
            blob.components.push_back(blobComponent());
        } else if (w == "sturm") {
            advance();
            blob.sturm = true;
        } else { // hierarchy [on | off]
            advance();
            blob.hierarchy = true;
            if (matchWord("off")) blob.hierarchy = false;
            else matchWord("on");
        }
    }
    if (blob.components.empty()) error(keyword.loc, "a blob needs at least one sphere or cylinder component");
    po.object.shape = std::move(blob);
}

} // namespace drt

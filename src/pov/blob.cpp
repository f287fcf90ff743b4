// POV-Ray's blob, read into the scene model's Blob (scene/blob.h):
//   blob { [threshold t]
//          sphere { <c>, r, [strength] s [modifiers] }
//          cylinder { <a>, <b>, r, [strength] s [modifiers] }
//          component s, r, <c>   (the old syntax for a sphere)
//          ... object modifiers }
// Transforms inside a component move that component; its texture, pigment,
// finish and normal are read and ignored with a warning (drt textures the
// blob as one object). `sturm` and `hierarchy` are object modifiers
// (objects.cpp).
#include "pov/parser.h"

namespace drt::pov {

namespace {

bool isBlobItem(const Tok& t) {
    return t.isWord("threshold") || t.isWord("sphere") || t.isWord("cylinder") || t.isWord("component");
}

} // namespace

// After the blob's '{'.
Blob PovParser::blobShape(const Tok& keyword) {
    Blob blob;
    while (isBlobItem(peek())) {
        const Tok item = next();
        if (item.isWord("threshold")) {
            blob.threshold = floatExpr();
            if (!(blob.threshold > 0)) fail(item.loc, "blob threshold must be positive");
            continue;
        }
        BlobComponent c;
        if (item.isWord("component")) {
            c.strength = floatExpr();
            acceptSymbol(",");
            c.radius = floatExpr();
            acceptSymbol(",");
            c.center = vectorExpr();
        } else {
            expectSymbol("{", ("after blob '" + item.text + "'").c_str());
            c.kind = item.isWord("cylinder") ? BlobComponent::Kind::Cylinder : BlobComponent::Kind::Sphere;
            c.center = vectorExpr();
            acceptSymbol(",");
            if (c.kind == BlobComponent::Kind::Cylinder) {
                c.end = vectorExpr();
                acceptSymbol(",");
                if (c.end == c.center) fail(item.loc, "blob cylinder needs two different end points");
            }
            c.radius = floatExpr();
            acceptSymbol(",");
            if (peek().isWord("strength")) next();
            c.strength = floatExpr();
            for (;;) {
                if (std::optional<Transform> t = transformItem()) {
                    c.transform = c.transform.then(*t);
                    continue;
                }
                const Tok t = next();
                if (t.is("}")) break;
                if (t.isWord("texture") || t.isWord("pigment") || t.isWord("finish") || t.isWord("normal")) {
                    warnOnce("blob-component-texture", t.loc,
                             "textures of blob components are ignored: the blob takes its own texture");
                    if (t.isWord("texture")) texture(defaultTexture_);
                    else if (t.isWord("pigment")) pigment(defaultTexture_.pigment);
                    else if (t.isWord("finish")) finish(defaultTexture_.finish);
                    else normalBlock(t.loc);
                    continue;
                }
                failExpected(t, "a transform, texture or '}' in the blob " + item.text);
            }
        }
        if (!(c.radius > 0)) fail(item.loc, "blob component radius must be positive");
        blob.components.push_back(c);
    }
    if (blob.components.empty()) fail(keyword.loc, "blob needs at least one component");
    return blob;
}

} // namespace drt::pov

// The .drt text of a blob (see parser_blob.cpp): every number written so that
// it reads back exactly, component transforms as the readable steps that
// reproduce them (or a matrix).
#include "lang/writer_detail.h"

namespace drt::writer {

std::string blobText(const Blob& b, int indent) {
    const std::string pad(size_t(indent + 1) * 2, ' ');
    std::string text = "blob { threshold " + number(b.threshold);
    for (const BlobComponent& c : b.components) {
        text += "\n" + pad;
        if (c.kind == BlobComponent::Kind::Sphere) text += "sphere { " + vector(c.center);
        else text += "cylinder { " + vector(c.center) + ", " + vector(c.end);
        text += ", " + number(c.radius) + ", strength " + number(c.strength);
        text += formatSteps(decompose(c.transform)) + " }";
    }
    if (b.sturm) text += "\n" + pad + "sturm";
    if (!b.hierarchy) text += "\n" + pad + "hierarchy off";
    return text;
}

} // namespace drt::writer

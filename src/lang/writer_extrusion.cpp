// The .drt text of prism and text objects: written as their source (spline
// points, font and string), which the parser turns into the same outline.
#include "lang/writer_detail.h"
#include "outline/text_outline.h"

#include <filesystem>

namespace drt::writer {

namespace {

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else out += c;
    }
    return out + "\"";
}

// A font in POV-Ray's include folder is written by name (the .drt parser
// looks there too); any other by its absolute path.
std::string fontName(const TextSource& t) {
    namespace fs = std::filesystem;
    const fs::path path = fs::absolute(t.fontPath).lexically_normal();
    if (path.parent_path() == fs::path(kPovFontDir)) return path.filename().string();
    return path.string();
}

const char* splineWord(PrismSource::Spline s) {
    switch (s) {
    case PrismSource::Spline::Linear: return "linear_spline";
    case PrismSource::Spline::Quadratic: return "quadratic_spline";
    case PrismSource::Spline::Cubic: return "cubic_spline";
    case PrismSource::Spline::Bezier: return "bezier_spline";
    }
    return "linear_spline";
}

std::string point(Vec2 p) {
    std::string text = "<"; // appended piece by piece: GCC 12 warns (-Wrestrict) on "<" + string
    text += number(p.x);
    text += ", ";
    text += number(p.y);
    text += ">";
    return text;
}

} // namespace

std::string extrusionText(const Extrusion& e, int indent, std::set<std::string>& problems) {
    if (e.text) {
        std::string text = "text { font " + quoted(fontName(*e.text)) + " string " + quoted(e.text->string) +
                           " thickness " + number(e.height2);
        if (!(e.text->offset == Vec3(0))) text += " offset " + vector(e.text->offset);
        return text;
    }
    PrismSource source;
    if (e.prism) {
        source = *e.prism;
    } else {
        // An outline with no source: each contour as a closed linear sub-polygon.
        if (e.plane != Extrusion::Plane::XZ || e.fill != Extrusion::Fill::EvenOdd)
            problems.insert("an extrusion with no prism or text source (written as an even-odd prism)");
        for (const auto& contour : e.contours) {
            source.points.insert(source.points.end(), contour.begin(), contour.end());
            if (!contour.empty()) source.points.push_back(contour.front());
        }
    }
    std::string text = std::string("prism { ") + (e.conic ? "conic_sweep " : "") + splineWord(source.spline) + " " +
                       number(e.height1) + ", " + number(e.height2) + ", " + std::to_string(source.points.size());
    const std::string pad(size_t(indent + 1) * 2, ' ');
    for (size_t i = 0; i < source.points.size(); ++i)
        text += std::string(",") + (i % 6 == 0 ? "\n" + pad : " ") + point(source.points[i]);
    if (e.open) text += "\n" + pad + "open";
    return text;
}

} // namespace drt::writer

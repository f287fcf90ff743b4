// The .drt text of lathe and sor objects: their points as written.
#include "lang/writer_detail.h"

namespace drt::writer {

namespace {

const char* splineWord(Revolution::Spline s) {
    switch (s) {
    case Revolution::Spline::Linear: return "linear_spline";
    case Revolution::Spline::Quadratic: return "quadratic_spline";
    case Revolution::Spline::Cubic: return "cubic_spline";
    case Revolution::Spline::Bezier: return "bezier_spline";
    }
    return "linear_spline";
}

} // namespace

std::string revolutionText(const Revolution& r, int indent) {
    const bool sor = r.kind == Revolution::Kind::Sor;
    std::string text = sor ? "sor { " : std::string("lathe { ") + splineWord(r.spline) + " ";
    text += std::to_string(r.points.size());
    const std::string pad(size_t(indent + 1) * 2, ' ');
    for (size_t i = 0; i < r.points.size(); ++i) {
        text += i % 6 == 0 ? ",\n" + pad : ", ";
        text += "<";
        text += number(r.points[i].x);
        text += ", ";
        text += number(r.points[i].y);
        text += ">";
    }
    if (r.sturm) text += " sturm";
    if (sor && r.open) text += "\n" + pad + "open";
    return text;
}

} // namespace drt::writer

#include "outline/text_outline.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

namespace drt {

namespace fs = std::filesystem;

std::string findFontFile(const std::string& name, const std::vector<std::string>& dirs) {
    std::error_code ec;
    if (name.empty()) return "";
    if (fs::path(name).is_absolute()) return fs::is_regular_file(name, ec) ? name : "";
    for (const std::string& dir : dirs) {
        const fs::path candidate = fs::path(dir) / name;
        if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
    }
    if (!fs::path(name).has_extension()) return findFontFile(name + ".ttf", dirs);
    return "";
}

namespace {

// UTF-8, or byte by byte (Latin-1) when the text is not valid UTF-8.
std::vector<char32_t> decodeText(const std::string& s) {
    std::vector<char32_t> out;
    for (size_t i = 0; i < s.size();) {
        const unsigned char c = s[i];
        const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
        bool valid = extra >= 0 && i + extra < s.size();
        char32_t cp = valid ? (extra == 0 ? c : (c & (0x3F >> extra))) : 0;
        for (int k = 1; valid && k <= extra; ++k) {
            const unsigned char n = s[i + k];
            valid = (n >> 6) == 2;
            cp = (cp << 6) | (n & 0x3F);
        }
        if (!valid) {
            const auto* bytes = reinterpret_cast<const unsigned char*>(s.data());
            return std::vector<char32_t>(bytes, bytes + s.size());
        }
        out.push_back(cp);
        i += extra + 1;
    }
    return out;
}

// Collects a glyph outline as polylines in em units, placed at `origin`.
struct OutlineSink {
    std::vector<std::vector<Vec2>>* contours;
    double scale; // em per font unit
    Vec2 origin;
    double tolerance; // font units
    Vec2 last;        // font units
    bool open = false; // a contour is being collected

    Vec2 place(Vec2 p) const { return {origin.x + p.x * scale, origin.y + p.y * scale}; }
    static Vec2 point(const FT_Vector* v) { return {double(v->x), double(v->y)}; }
    int steps(double maxSecondDerivative) const {
        return std::clamp(int(std::ceil(std::sqrt(maxSecondDerivative / (8 * tolerance)))), 1, 1024);
    }
    void add(Vec2 p) {
        contours->back().push_back(place(p));
        last = p;
    }

    static int moveTo(const FT_Vector* to, void* user) {
        auto* self = static_cast<OutlineSink*>(user);
        self->finish();
        self->contours->emplace_back();
        self->open = true;
        self->add(point(to));
        return 0;
    }
    static int lineTo(const FT_Vector* to, void* user) {
        static_cast<OutlineSink*>(user)->add(point(to));
        return 0;
    }
    // Quadratic: P'' = 2 (p0 - 2 p1 + p2).
    static int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
        auto* self = static_cast<OutlineSink*>(user);
        const Vec2 p0 = self->last, p1 = point(control), p2 = point(to);
        const int n = self->steps(2 * std::hypot(p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y));
        for (int k = 1; k <= n; ++k) {
            const double t = double(k) / n, s = 1 - t;
            self->add({s * s * p0.x + 2 * s * t * p1.x + t * t * p2.x, s * s * p0.y + 2 * s * t * p1.y + t * t * p2.y});
        }
        return 0;
    }
    // Cubic: P'' = 6 ((1 - t)(p0 - 2 p1 + p2) + t (p1 - 2 p2 + p3)), largest at an end.
    static int cubicTo(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
        auto* self = static_cast<OutlineSink*>(user);
        const Vec2 p0 = self->last, p1 = point(c1), p2 = point(c2), p3 = point(to);
        const double m = 6 * std::max(std::hypot(p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y),
                                      std::hypot(p1.x - 2 * p2.x + p3.x, p1.y - 2 * p2.y + p3.y));
        const int n = self->steps(m);
        for (int k = 1; k <= n; ++k) {
            const double t = double(k) / n, s = 1 - t;
            const double a = s * s * s, b = 3 * s * s * t, c = 3 * s * t * t, d = t * t * t;
            self->add({a * p0.x + b * p1.x + c * p2.x + d * p3.x, a * p0.y + b * p1.y + c * p2.y + d * p3.y});
        }
        return 0;
    }
    // Drops the closing point that repeats the first, and contours without area.
    void finish() {
        if (!open) return;
        open = false;
        auto& c = contours->back();
        if (c.size() >= 2 && c.front().x == c.back().x && c.front().y == c.back().y) c.pop_back();
        if (c.size() < 3) contours->pop_back();
    }
};

struct FreeTypeLibrary {
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    ~FreeTypeLibrary() {
        if (face) FT_Done_Face(face);
        if (library) FT_Done_FreeType(library);
    }
};

FT_UInt glyphIndex(FT_Face face, char32_t c) {
    FT_UInt index = FT_Get_Char_Index(face, c);
    // Symbol fonts (Microsoft encoding 3, 0) map their characters at U+F000.
    if (index == 0 && c < 0x100) index = FT_Get_Char_Index(face, 0xF000 + c);
    return index;
}

} // namespace

std::vector<std::vector<Vec2>> textContours(const std::string& fontPath, const std::string& text, Vec2 offset,
                                            Vec2* boxLower, Vec2* boxUpper) {
    FreeTypeLibrary ft;
    if (FT_Init_FreeType(&ft.library)) throw FontError("cannot start FreeType");
    if (FT_New_Face(ft.library, fontPath.c_str(), 0, &ft.face))
        throw FontError("cannot read font '" + fontPath + "' (not a TrueType/OpenType font?)");
    FT_Face face = ft.face;
    if (!FT_IS_SCALABLE(face) || face->units_per_EM == 0) throw FontError("font '" + fontPath + "' has no outlines");
    if (FT_Select_Charmap(face, FT_ENCODING_UNICODE) && face->num_charmaps > 0) FT_Set_Charmap(face, face->charmaps[0]);
    const double scale = 1.0 / face->units_per_EM;
    const double minKern = -double(face->units_per_EM); // POV-Ray's floor on a kerning value

    std::vector<std::vector<Vec2>> contours;
    OutlineSink sink{&contours, scale, {}, kGlyphTolerance * face->units_per_EM, {}};
    FT_Outline_Funcs funcs{};
    funcs.move_to = &OutlineSink::moveTo;
    funcs.line_to = &OutlineSink::lineTo;
    funcs.conic_to = &OutlineSink::conicTo;
    funcs.cubic_to = &OutlineSink::cubicTo;

    Vec2 pen, boxLo, boxHi;
    FT_UInt previous = 0;
    bool firstGlyph = true;
    for (char32_t c : decodeText(text)) {
        const FT_UInt index = glyphIndex(face, c);
        if (FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
            throw FontError("cannot load a glyph from font '" + fontPath + "'");
        const FT_GlyphSlot slot = face->glyph;
        if (slot->format != FT_GLYPH_FORMAT_OUTLINE) throw FontError("font '" + fontPath + "' has no outlines");
        if (firstGlyph) {
            // The first glyph's outline starts at x = 0.
            FT_BBox box;
            FT_Outline_Get_CBox(&slot->outline, &box);
            pen.x = slot->outline.n_points > 0 ? -double(box.xMin) * scale : 0;
        } else if (FT_HAS_KERNING(face)) {
            FT_Vector kern{};
            if (!FT_Get_Kerning(face, previous, index, FT_KERNING_UNSCALED, &kern))
                pen.x += std::max(double(kern.x), minKern) * scale;
        }
        sink.origin = pen;
        FT_BBox box;
        FT_Outline_Get_CBox(&slot->outline, &box);
        if (slot->outline.n_points == 0) box = {0, 0, 0, 0};
        const Vec2 lo{pen.x + box.xMin * scale, pen.y + box.yMin * scale};
        const Vec2 hi{pen.x + box.xMax * scale, pen.y + box.yMax * scale};
        boxLo = firstGlyph ? lo : Vec2{std::min(boxLo.x, lo.x), std::min(boxLo.y, lo.y)};
        boxHi = firstGlyph ? hi : Vec2{std::max(boxHi.x, hi.x), std::max(boxHi.y, hi.y)};
        if (FT_Outline_Decompose(&slot->outline, &funcs, &sink))
            throw FontError("cannot read a glyph outline from font '" + fontPath + "'");
        sink.finish();
        pen.x += double(slot->metrics.horiAdvance) * scale + offset.x;
        pen.y += offset.y;
        previous = index;
        firstGlyph = false;
    }
    if (boxLower) *boxLower = boxLo;
    if (boxUpper) *boxUpper = boxHi;
    return contours;
}

Extrusion makeTextExtrusion(const TextSource& source, double thickness) {
    Extrusion e;
    e.text = source;
    e.contours = textContours(source.fontPath, source.string, {source.offset.x, source.offset.y},
                              &e.text->boxLower, &e.text->boxUpper);
    e.plane = Extrusion::Plane::XY;
    e.fill = Extrusion::Fill::NonZero;
    e.height1 = 0;
    e.height2 = thickness;
    return e;
}

} // namespace drt

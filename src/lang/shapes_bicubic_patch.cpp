// POV-Ray's bicubic_patch, in both dialects:
//   bicubic_patch { type 0|1 [flatness f] [u_steps m] [v_steps n]
//                   [uv_vectors <u,v>, <u,v>, <u,v>, <u,v>]
//                   <p1>, <p2>, ... <p16> modifiers... }
// read into a smooth triangle mesh (scene/bicubic_patch.h: 2^m x 2^n quads,
// normals from the surface's derivatives), which keeps the patch so that the
// writer can write it back as it was. `type` is required (POV-Ray's rule);
// steps go from 0 (POV-Ray's default: one quad) to kMaxBicubicPatchSteps.
#include "lang/mesh_syntax.h"
#include "lang/writer_detail.h"
#include "scene/bicubic_patch.h"

#include <fmt/format.h>

namespace drt::lang {

void readBicubicPatch(Evaluator& e, const Token& keyword, Mesh& m) {
    auto patch = std::make_shared<BicubicPatch>();
    bool typed = false;
    for (;;) {
        const Token t = e.peek();
        if (t.isWord("type")) {
            e.next();
            const SourceLoc at = e.peek().loc;
            const double type = [&] {
                FlagFor flag(e.countBeforeVector_); // `type 1 <0, 0, 0>`: the points follow
                return e.floatExpr("the bicubic_patch type");
            }();
            if (type != 0 && type != 1) e.fail(at, "the bicubic_patch type must be 0 or 1" + e.got(type));
            patch->type = int(type);
            typed = true;
        } else if (t.isWord("flatness")) {
            e.next();
            const SourceLoc at = e.peek().loc;
            {
                FlagFor flag(e.countBeforeVector_);
                patch->flatness = e.floatExpr("the bicubic_patch flatness");
            }
            if (!(patch->flatness >= 0)) e.refuse(at, "the bicubic_patch flatness must not be negative" + e.got(patch->flatness));
        } else if (t.isWord("u_steps") || t.isWord("v_steps")) {
            e.next();
            FlagFor flag(e.countBeforeVector_);
            const int steps = e.countExpr(t.isWord("u_steps") ? "u_steps" : "v_steps", 0, kMaxBicubicPatchSteps);
            (t.isWord("u_steps") ? patch->uSteps : patch->vSteps) = steps;
        } else if (t.isWord("uv_vectors")) {
            e.next();
            for (size_t k = 0; k < 4; ++k) {
                if (k > 0) e.comma("uv vector");
                const Vec3 uv = e.vectorExpr("a corner's uv vector <u, v>");
                patch->uvCorners[k] = {float(uv.x), float(uv.y)};
            }
        } else {
            break;
        }
        e.acceptSymbol(","); // POV-Ray's scenes write `u_steps 4 v_steps 4,` before the points
    }
    if (!typed) e.fail(keyword.loc, "bicubic_patch needs its 'type' (0 or 1) before the control points");
    for (size_t k = 0; k < 16; ++k) {
        if (k > 0) e.comma("control point");
        const std::string what = fmt::format("control point {} of the bicubic_patch's 16", k + 1);
        patch->points[k] = e.vectorExpr(what.c_str());
    }
    m.indexed = tessellateBicubicPatch(*patch);
    m.patch = std::move(patch);
}

std::string bicubicPatchHead(const Mesh& m, ShapeText& text) {
    const BicubicPatch& p = *m.patch;
    std::string out = fmt::format("bicubic_patch {{ type {} flatness {} u_steps {} v_steps {}", p.type,
                                  writer::number(p.flatness), p.uSteps, p.vSteps);
    const std::array<Float2, 4> unit = BicubicPatch{}.uvCorners;
    bool ownUvs = false;
    for (size_t k = 0; k < 4; ++k) ownUvs = ownUvs || p.uvCorners[k].u != unit[k].u || p.uvCorners[k].v != unit[k].v;
    if (ownUvs) {
        out += " uv_vectors";
        for (size_t k = 0; k < 4; ++k)
            out += fmt::format("{} <{}, {}>", k > 0 ? "," : "", writer::number(double(p.uvCorners[k].u)),
                               writer::number(double(p.uvCorners[k].v)));
    }
    const std::string pad(size_t(text.indent + 1) * 2, ' ');
    for (size_t row = 0; row < 4; ++row) {
        out += "\n" + pad;
        for (size_t i = 0; i < 4; ++i)
            out += writer::vector(p.points[4 * row + i]) + (row == 3 && i == 3 ? "" : i == 3 ? "," : ", ");
    }
    return out;
}

} // namespace drt::lang

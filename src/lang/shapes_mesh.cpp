// Triangle meshes:
//   triangle { a, b, c }    smooth_triangle { a, na, b, nb, c, nc }
//   mesh { triangle {...} smooth_triangle {...} ... }
//   mesh { file "model.obj" }  (OBJ, PLY, glTF 2.0; the file is read after parsing)
//   mesh2 { vertex_vectors { n, v... } [normal_vectors {...}] face_indices { n, <i,j,k>... } [normal_indices {...}] }
//   polygon { n, p1, ..., pn }   (triangulated as a fan: exact for convex outlines)
//   height_field { [type] "file" [smooth] [water_level w] }  (the image is read after parsing)
#include "lang/evaluator.h"
#include "lang/shape_syntax.h"
#include "lang/writer_detail.h"

#include <filesystem>
#include <fmt/format.h>

namespace drt::lang {

using writer::vector;

namespace {

// Sets a flag for one expression, cleared again even if it fails.
struct FlagFor {
    bool& flag;
    explicit FlagFor(bool& f) : flag(f) { flag = true; }
    ~FlagFor() { flag = false; }
};

void separator(Evaluator& e, const char* context) {
    if (e.syntax().requireCommas) e.expectSymbol(",", context);
    else e.acceptSymbol(",");
}

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 n = cross(b - a, c - a);
    return length(n) > 0 ? normalize(n) : n;
}

// One triangle's corners (and normals) into `mesh`. Normals are per triangle
// once any triangle has them: flat triangles in a mixed mesh get their face
// normal at all three corners.
void triangle(Evaluator& e, Mesh& mesh, bool smooth) {
    Vec3 corners[3], normals[3];
    for (int i = 0; i < 3; ++i) {
        if (i > 0) separator(e, "between triangle corners");
        corners[i] = e.vectorExpr("a triangle corner <x, y, z>");
        if (smooth) {
            separator(e, "after the corner");
            const SourceLoc loc = e.peek().loc;
            normals[i] = e.vectorExpr("a corner normal <x, y, z>");
            if (!(length(normals[i]) > 0)) {
                e.error(loc, "smooth_triangle normal must not be a zero-length vector");
                normals[i] = {0, 1, 0};
            }
        }
    }
    const int base = static_cast<int>(mesh.vertices.size());
    for (const Vec3& c : corners) mesh.vertices.push_back(c);
    mesh.triangles.push_back({base, base + 1, base + 2});
    const bool hadNormals = !mesh.normalIndices.empty();
    if (smooth && !hadNormals) {
        for (size_t t = 0; t + 1 < mesh.triangles.size(); ++t) {
            const auto& tri = mesh.triangles[t];
            const int ni = static_cast<int>(mesh.normals.size());
            mesh.normals.push_back(faceNormal(mesh.vertices[size_t(tri[0])], mesh.vertices[size_t(tri[1])],
                                              mesh.vertices[size_t(tri[2])]));
            mesh.normalIndices.push_back({ni, ni, ni});
        }
    }
    if (smooth || hadNormals) {
        const int ni = static_cast<int>(mesh.normals.size());
        if (smooth) {
            for (const Vec3& n : normals) mesh.normals.push_back(normalize(n));
            mesh.normalIndices.push_back({ni, ni + 1, ni + 2});
        } else {
            mesh.normals.push_back(faceNormal(corners[0], corners[1], corners[2]));
            mesh.normalIndices.push_back({ni, ni, ni});
        }
    }
}

// mesh { file "name" }: a model file found like an image (beside the file
// that names it, then beside the scene, then on the include path), whose
// triangles, normals, uvs and materials assets/model_load.cpp reads after
// parsing; its problems are reported at the file name.
void readModelFile(Evaluator& e, Mesh& m) {
    e.next(); // file
    const Token file = e.peek();
    if (e.syntax().kind == DialectKind::Drt && file.kind != TokenKind::String)
        e.failExpected(e.next(), "the model file name in quotes");
    const std::string name = e.stringExpr();
    const std::string path = e.findDataFile(name, false);
    if (path.empty()) e.fail(file.loc, "cannot find model file '" + name + "'");
    auto source = std::make_shared<MeshSource>();
    source->kind = MeshSource::Kind::ModelFile;
    source->path = path;
    source->loc = file.loc;
    m.source = std::move(source);
}

void readMesh(Evaluator& e, const Token& keyword, Mesh& m) {
    if (e.peek().isWord("file")) {
        readModelFile(e, m);
        return;
    }
    for (;;) {
        const Token t = e.peek();
        if (!(t.isWord("triangle") || t.isWord("smooth_triangle"))) break;
        e.next();
        const bool smooth = t.text == "smooth_triangle";
        e.expectSymbol("{", "after '" + t.text + "'");
        triangle(e, m, smooth);
        for (;;) {
            const Token s = e.next();
            if (s.is("}")) break;
            if (s.isWord("texture")) {
                e.unsupported("mesh-texture", s.loc, "per-triangle textures in a mesh are not supported; ignored");
                e.texture(Texture{});
            } else {
                e.failExpected(s, "'}' to close the triangle");
            }
        }
    }
    if (m.triangles.empty()) e.error(keyword.loc, "mesh has no triangles");
}

void readMesh2(Evaluator& e, const Token& keyword, Mesh& m) {
    // `{ n, item, ... }`: the count, then the items; `14 <-1, ...` is a count and a vector.
    auto count = [&](const char* what) {
        e.expectSymbol("{", "to open the list");
        const SourceLoc at = e.peek().loc;
        const double n = [&] {
            FlagFor flag(e.countBeforeVector_);
            return e.floatExpr("the number of items");
        }();
        if (std::isfinite(n) && n != std::floor(n) && e.syntax().strictValues)
            e.fail(at, "the number of items must be a whole number" + e.got(n));
        return e.countValue(n, at, what, 0, double(e.diags().limits().meshTriangles));
    };
    auto vectorList = [&](std::vector<Vec3>& out) {
        const int n = count("mesh2 vector count");
        for (int i = 0; i < n; ++i) {
            e.acceptSymbol(",");
            out.push_back(e.vectorExpr());
        }
        e.acceptSymbol(",");
        e.expectSymbol("}", "after the listed count of items");
    };
    auto indexList = [&](std::vector<std::array<int, 3>>& out, int maxIndex, const char* what) {
        const int n = count("mesh2 index count");
        const std::string indexName = std::string(what) + " index";
        for (int i = 0; i < n; ++i) {
            e.acceptSymbol(",");
            const SourceLoc at = e.peek().loc;
            const Vec3 v = e.vectorExpr();
            std::array<int, 3> tri{};
            for (int k = 0; k < 3; ++k)
                tri[size_t(k)] = e.countValue(v[k], at, indexName.c_str(), 0, double(maxIndex) - 1);
            out.push_back(tri);
            // Optional texture indices after a face.
            while (e.peekOperator().is(",")) {
                e.next();
                if (e.peek().is("<") || e.peek().is("}")) {
                    e.pushBack(Token{TokenKind::Symbol, ",", 0, at});
                    break;
                }
                e.floatExpr();
            }
        }
        e.acceptSymbol(",");
        e.expectSymbol("}", "after the listed count of items");
    };
    for (;;) {
        const Token t = e.peek();
        if (t.isWord("vertex_vectors")) e.next(), vectorList(m.vertices);
        else if (t.isWord("normal_vectors")) e.next(), vectorList(m.normals);
        else if (t.isWord("face_indices")) e.next(), indexList(m.triangles, int(m.vertices.size()), "vertex");
        else if (t.isWord("normal_indices")) e.next(), indexList(m.normalIndices, int(m.normals.size()), "normal");
        else if (t.isWord("uv_vectors") || t.isWord("uv_indices") || t.isWord("texture_list")) {
            e.next();
            if (t.text == "texture_list")
                e.unsupported("mesh-texture", t.loc, "per-triangle textures in a mesh are not supported; ignored");
            e.expectSymbol("{", "after '" + t.text + "'");
            e.skipBlock();
        } else {
            break;
        }
    }
    if (m.triangles.empty()) e.fail(keyword.loc, "mesh2 has no face_indices");
    if (!m.normals.empty() && m.normalIndices.empty()) {
        // Without normal_indices, normals pair with vertices one to one.
        if (m.normals.size() != m.vertices.size())
            e.fail(keyword.loc, "mesh2: normal_vectors needs normal_indices or one normal per vertex");
        m.normalIndices = m.triangles;
    }
    if (!m.normalIndices.empty() && m.normalIndices.size() != m.triangles.size())
        e.fail(keyword.loc, "mesh2: normal_indices and face_indices have different counts");
}

void readPolygon(Evaluator& e, const Token& keyword, Mesh& m) {
    const SourceLoc at = e.peek().loc;
    const double count = [&] {
        FlagFor flag(e.countBeforeVector_);
        return e.floatExpr("the number of points");
    }();
    const int points = e.countValue(count, at, "polygon point count", 0, double(e.diags().limits().meshTriangles));
    std::vector<Vec3> pts;
    for (int i = 0; i < points; ++i) {
        e.comma(i == 0 ? "number of points" : "point");
        pts.push_back(e.vectorExpr());
    }
    if (pts.size() >= 2 && pts.front() == pts.back()) pts.pop_back();
    e.warnOnce("polygon", keyword.loc, "polygon is triangulated as a fan (exact only for a convex outline)");
    m.vertices = pts;
    for (int i = 1; i + 1 < int(pts.size()); ++i) m.triangles.push_back({0, i, i + 1});
    if (m.triangles.empty()) e.fail(keyword.loc, "polygon needs at least 3 points");
}

// height_field: a mesh whose triangles come from the image after parsing
// (Mesh::source, assets/assets.h). Nothing for a function height field (not supported).
bool readHeightField(Evaluator& e, Mesh& m) {
    if (e.peek().isWord("function")) {
        e.unsupported("height_field-function", e.peek().loc,
                      "height_field { function ... } is not supported; the object is left out");
        e.next();
        e.floatExpr();
        e.acceptSymbol(",");
        e.floatExpr();
        e.expectSymbol("{", "after the function's resolution");
        e.skipBlock();
        while (e.peek().isWord("smooth") || e.peek().isWord("water_level") || e.peek().isWord("hierarchy")) {
            const Token w = e.next();
            if (!w.isWord("smooth")) e.floatExpr();
        }
        return false;
    }
    static const std::set<std::string> types = {"gif", "tga", "iff", "ppm", "pgm", "png",
                                                "jpeg", "tiff", "sys", "exr", "hdr", "pot"};
    if (e.peek().kind == TokenKind::Word && types.count(e.peek().text)) {
        const Token type = e.next();
        if (type.isWord("pot"))
            e.warnOnce("height_field-pot", type.loc,
                       "Fractint 'pot' files are read as plain GIF images, not as 16-bit heights (approximate)");
    }
    const SourceLoc fileLoc = e.peek().loc;
    const std::string name = e.stringExpr();
    const std::string path = e.findDataFile(name, true);
    if (path.empty()) e.fail(fileLoc, "cannot find image file '" + name + "'");
    auto source = std::make_shared<MeshSource>();
    source->kind = MeshSource::Kind::PovHeightField;
    source->path = path;
    source->loc = fileLoc;
    for (;;) {
        const Token t = e.peek();
        if (t.isWord("smooth")) e.next(), source->smooth = true;
        else if (t.isWord("water_level")) e.next(), source->waterLevel = e.floatExpr();
        else if (t.isWord("hierarchy")) e.next(), e.optionalBool(); // only POV-Ray's bounding
        else if (t.isWord("gamma") || t.isWord("premultiplied")) e.next(), e.floatExpr();
        else break;
    }
    m.source = std::move(source);
    return true;
}

} // namespace

const std::vector<std::string>& ShapeSyntax<Mesh>::keywords() {
    static const std::vector<std::string> w{"triangle", "smooth_triangle", "mesh", "mesh2", "polygon", "height_field"};
    return w;
}

void ShapeSyntax<Mesh>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    Mesh m;
    const std::string& w = keyword.text;
    if (w == "triangle" || w == "smooth_triangle") triangle(e, m, w == "smooth_triangle");
    else if (w == "mesh") readMesh(e, keyword, m);
    else if (w == "mesh2") readMesh2(e, keyword, m);
    else if (w == "polygon") readPolygon(e, keyword, m);
    else if (!readHeightField(e, m)) o.lightOnly = true; // left out
    o.object.shape = std::move(m);
}

std::string ShapeSyntax<Mesh>::head(const Mesh& m, ShapeText& text) {
    // A model file not read yet: its name, which reads back to the same mesh.
    if (m.source && m.source->kind == MeshSource::Kind::ModelFile)
        return "mesh { file " + writer::quoted(m.source->path);
    if (m.triangles.empty()) {
        text.problems.insert("a mesh with no triangles (left out)");
        return "";
    }
    const bool hasNormals = !m.normals.empty() && m.normalIndices.size() == m.triangles.size();
    auto triangleBody = [&](size_t t, bool& smooth) {
        const auto& tri = m.triangles[t];
        const Vec3 a = m.vertices[size_t(tri[0])], b = m.vertices[size_t(tri[1])], c = m.vertices[size_t(tri[2])];
        smooth = false;
        Vec3 n[3];
        if (hasNormals) {
            const Vec3 face = faceNormal(a, b, c);
            for (int k = 0; k < 3; ++k) {
                n[k] = m.normals[size_t(m.normalIndices[t][size_t(k)])];
                smooth = smooth || !(n[k] == face);
            }
        }
        if (!smooth) return vector(a) + ", " + vector(b) + ", " + vector(c);
        return vector(a) + ", " + vector(writer::unnormalised(n[0])) + ", " + vector(b) + ", " +
               vector(writer::unnormalised(n[1])) + ", " + vector(c) + ", " + vector(writer::unnormalised(n[2]));
    };
    bool smooth = false;
    if (m.triangles.size() == 1) {
        const std::string body = triangleBody(0, smooth);
        return std::string(smooth ? "smooth_triangle { " : "triangle { ") + body;
    }
    std::string out = "mesh {";
    const std::string pad(size_t(text.indent + 1) * 2, ' ');
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const std::string body = triangleBody(t, smooth);
        out += "\n" + pad + (smooth ? "smooth_triangle { " : "triangle { ") + body + " }";
    }
    return out;
}

} // namespace drt::lang

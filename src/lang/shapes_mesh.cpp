// Triangle meshes:
//   triangle { a, b, c }    smooth_triangle { a, na, b, nb, c, nc }
//   mesh { triangle {...} smooth_triangle {...} ... }  (shapes_mesh_indexed.cpp)
//   mesh { file "model.obj" }  (OBJ, PLY, glTF 2.0; the file is read after parsing)
//   mesh2 { vertex_vectors ... face_indices ... }  (shapes_mesh_indexed.cpp)
//   polygon { n, p1, ..., pn }   (triangulated as a fan: exact for convex outlines)
//   height_field { [type] "file" [smooth] [water_level w] }  (the image is read after parsing)
//   height_field { function W, H { ... } [smooth] [water_level w] }  (sampled now)
//   bicubic_patch { type t ... 16 points }  (tessellated now: shapes_bicubic_patch.cpp)
#include "lang/mesh_syntax.h"
#include "scene/height_field.h"
#include "lang/writer_detail.h"

#include <filesystem>
#include <fmt/format.h>

namespace drt::lang {

using writer::vector;

void meshSeparator(Evaluator& e, const char* context) {
    if (e.syntax().requireCommas) e.expectSymbol(",", context);
    else e.acceptSymbol(",");
}

TriangleCorners readTriangleCorners(Evaluator& e, bool smooth) {
    TriangleCorners c;
    for (int i = 0; i < 3; ++i) {
        if (i > 0) meshSeparator(e, "between triangle corners");
        c.corners[i] = e.vectorExpr("a triangle corner <x, y, z>");
        if (smooth) {
            meshSeparator(e, "after the corner");
            const SourceLoc loc = e.peek().loc;
            c.normals[i] = e.vectorExpr("a corner normal <x, y, z>");
            if (!(length(c.normals[i]) > 0)) {
                e.error(loc, "smooth_triangle normal must not be a zero-length vector");
                c.normals[i] = {0, 1, 0};
            }
            c.normals[i] = normalize(c.normals[i]);
        }
    }
    return c;
}

namespace {

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
    Vec3 n = cross(b - a, c - a);
    return length(n) > 0 ? normalize(n) : n;
}

// A lone triangle or smooth_triangle (outside a mesh).
void triangle(Evaluator& e, Mesh& mesh, bool smooth) {
    const TriangleCorners c = readTriangleCorners(e, smooth);
    mesh.vertices.assign(std::begin(c.corners), std::end(c.corners));
    mesh.triangles.push_back({0, 1, 2});
    if (smooth) {
        mesh.normals.assign(std::begin(c.normals), std::end(c.normals));
        mesh.normalIndices.push_back({0, 1, 2});
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
    readTriangleMesh(e, keyword, m);
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
// (Mesh::source, assets/assets.h), or from a function now:
//   height_field { function W, H { ... } [smooth] [water_level w] }
// samples the function of x, y (z = 0) on a W x H grid, as POV-Ray does: the
// vertex at x = i / (W - 1), z = j / (H - 1) has the height
// F(i / (W - 1), 1 - j / (H - 1), 0), clamped to [0, 1].
bool readHeightField(Evaluator& e, Mesh& m) {
    if (e.peek().isWord("function")) {
        const Token keyword = e.next();
        const int columns = e.countExpr("the height_field function's width", 2, 8192);
        e.comma("width");
        const int rows = e.countExpr("the height_field function's height", 2, 8192);
        const std::shared_ptr<const Function> f = e.patternFunction(keyword);
        bool smooth = false;
        double waterLevel = 0;
        for (;;) {
            const Token t = e.peek();
            if (t.isWord("smooth")) e.next(), smooth = true;
            else if (t.isWord("water_level")) e.next(), waterLevel = e.floatExpr();
            else if (t.isWord("hierarchy")) e.next(), e.optionalBool();
            else break;
        }
        std::vector<double> heights(size_t(columns) * size_t(rows));
        for (int j = 0; j < rows; ++j)
            for (int i = 0; i < columns; ++i) {
                const double v = f->at(Vec3(double(i) / (columns - 1), 1 - double(j) / (rows - 1), 0));
                heights[size_t(j) * size_t(columns) + size_t(i)] = std::clamp(v, 0.0, 1.0);
            }
        Mesh built = heightFieldMesh(heights, columns, rows, smooth, waterLevel);
        if (built.triangles.empty()) {
            e.warn(keyword.loc, "the height_field lies entirely below its water_level; it is left out");
            return false;
        }
        m = std::move(built);
        return true;
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

template <>
const std::vector<std::string>& ShapeSyntax<Mesh>::keywords() {
    static const std::vector<std::string> w{"triangle", "smooth_triangle", "mesh", "mesh2", "polygon", "height_field",
                                            "bicubic_patch"};
    return w;
}

template <>
void ShapeSyntax<Mesh>::read(Evaluator& e, const Token& keyword, ObjectValue& o) {
    const std::string& w = keyword.text;
    // mesh { Name modifiers }: a copy of a declared mesh, as in POV-Ray (the mesh_camera demos write it).
    if (w == "mesh" && e.peek().kind == TokenKind::Word) {
        const Cell declared = e.lookup(e.peek().text);
        if (declared && declared->kind == Value::Kind::Object && declared->object &&
            std::holds_alternative<Mesh>(declared->object->object.shape)) {
            const Token name = e.next();
            e.use(name.text);
            o = *declared->object;
            return;
        }
    }
    Mesh m;
    if (w == "triangle" || w == "smooth_triangle") triangle(e, m, w == "smooth_triangle");
    else if (w == "mesh") readMesh(e, keyword, m);
    else if (w == "mesh2") readMesh2(e, keyword, m);
    else if (w == "polygon") readPolygon(e, keyword, m);
    else if (w == "bicubic_patch") readBicubicPatch(e, keyword, m);
    else if (!readHeightField(e, m)) o.lightOnly = true; // left out
    o.object.shape = std::move(m);
}

template <>
std::string ShapeSyntax<Mesh>::head(const Mesh& m, ShapeText& text) {
    // A model file not read yet: its name, which reads back to the same mesh.
    if (m.source && m.source->kind == MeshSource::Kind::ModelFile)
        return "mesh { file " + writer::quoted(m.source->path);
    if (m.patch) return bicubicPatchHead(m, text);
    if (m.indexed) return indexedMeshHead(m, text);
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

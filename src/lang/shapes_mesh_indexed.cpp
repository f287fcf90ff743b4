// Meshes written in the scene, read into the compact mesh that model files
// use too (scene/indexed_mesh.h: float vertices, shared by every copy of
// the object, one Embree BVH for all of them):
//   mesh { triangle { a, b, c [uv_vectors uva, uvb, uvc] [texture {...}] }
//          smooth_triangle { a, na, b, nb, c, nc [uv_vectors ...] [texture {...}] } ... }
//   mesh2 { vertex_vectors { n, v... } [normal_vectors { n, v... }] [uv_vectors { n, <u, v>... }]
//           [texture_list { n, texture {...}... }]
//           face_indices { n, <i, j, k> [, t | , ta, tb, tc]... }
//           [normal_indices { n, <i, j, k>... }] [uv_indices { n, <i, j, k>... }] }
// with POV-Ray's meaning: a face's one texture index textures the whole face,
// three texture its corners (drt blends the corners' textures by barycentric
// weight); faces without one show the object's texture. Without
// normal_indices / uv_indices the normals / uvs are indexed like the
// vertices. A mesh triangle without uv_vectors has POV-Ray's uvs <0,0>,
// <1,0>, <1,1> when another triangle of the mesh has some (else the mesh has
// none).
//
// Speed: runs of items written as plain literals (triangles and
// smooth_triangles of literal vectors, list vectors, index triples and their
// texture indices) are read straight from the text by TokenStream's scans
// (lang/lexer.h), without tokens or the expression evaluator; anything else,
// and every list in a file a loop or a macro replays, goes through the
// evaluator. Both ways give the same mesh and the same messages
// (tests/mesh_literal_scan_test.cpp).
#include "lang/mesh_syntax.h"
#include "lang/writer_detail.h"
#include "scene/motion.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace drt::lang {

namespace {

Float2 toFloat2(const Vec3& v) {
    return {float(v.x), float(v.y)};
}

// The .drt text of a float, exact (it reads back to the same float).
// The shortest text that reads back to f: the reader takes a double and
// stores it as a float, so the float's own shortest form (0.001414, not the
// double 0.0014140000566840172) is exact, unless rounding twice (text to
// double to float) lands elsewhere, when the double's form is written.
std::string floatText(float f) {
    if (!std::isfinite(f) || f == 0) return writer::number(double(f));
    char buffer[32];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, f);
    double back = 0;
    const auto read = std::from_chars(buffer, written.ptr, back);
    if (read.ec == std::errc() && float(back) == f) return std::string(buffer, written.ptr);
    return writer::number(double(f));
}

// `triangle { a, b, c }` or `smooth_triangle { a, na, b, nb, c, nc }` whose
// vectors are plain literals, read straight from the text: its corners and
// unit normals, or false with nothing read (anything else, a zero normal
// included, goes the evaluator's way, which reports it).
bool literalTriangle(Evaluator& e, TokenStream& s, bool& smooth, TriangleCorners& c) {
    const TokenStream::Mark start = s.mark();
    const auto fail = [&] {
        s.reset(start);
        return false;
    };
    if (s.word("triangle"))
        smooth = false;
    else if (s.word("smooth_triangle"))
        smooth = true;
    else
        return false;
    if (!s.symbol('{'))
        return fail();
    const bool commas = e.syntax().requireCommas;
    LiteralVector v;
    for (int i = 0; i < (smooth ? 6 : 3); ++i) {
        if (i > 0 && !s.symbol(',') && commas)
            return fail();
        if (!s.vector(v))
            return fail();
        if (i % (smooth ? 2 : 1) == 0) {
            c.corners[smooth ? i / 2 : i] = v.xyz();
        } else {
            const Vec3 n = v.xyz();
            if (!(length(n) > 0))
                return fail();
            c.normals[i / 2] = normalize(n);
        }
    }
    const SourceLoc close = s.here();
    if (!s.symbol('}'))
        return fail();
    e.rawRead(close, "}");
    return true;
}

} // namespace

void readTriangleMesh(Evaluator& e, const Token& keyword, Mesh& m) {
    auto built = std::make_shared<IndexedMesh>();
    IndexedMesh& out = *built;
    // Made when the first triangle has one, with the earlier triangles'
    // defaults: normals (zero on flat triangles: the accelerator shades those
    // flat), uvs (POV-Ray's <0, 0>, <1, 0>, <1, 1>) and textures.
    std::vector<Float3> normals;
    std::vector<Float2> uvs;
    std::vector<uint32_t> textures;
    bool anySmooth = false, anyUv = false, anyTexture = false;
    const double limit = double(e.diags().limits().meshTriangles);
    static const Float2 kDefaultUv[3] = {{0, 0}, {1, 0}, {1, 1}};
    const auto add = [&](const TriangleCorners& c, bool smooth, const Float2* uv, uint32_t texture) {
        const uint32_t base = uint32_t(out.positions.size());
        for (int k = 0; k < 3; ++k) {
            out.positions.push_back(Float3::of(c.corners[k]));
            out.indices.push_back(base + uint32_t(k));
        }
        if (smooth && !anySmooth)
            normals.resize(base), anySmooth = true;
        if (anySmooth)
            for (int k = 0; k < 3; ++k)
                normals.push_back(smooth ? Float3::of(c.normals[k]) : Float3{});
        if (uv && !anyUv) {
            for (uint32_t t = 0; t < base / 3; ++t)
                uvs.insert(uvs.end(), std::begin(kDefaultUv), std::end(kDefaultUv));
            anyUv = true;
        }
        if (anyUv)
            uvs.insert(uvs.end(), uv ? uv : kDefaultUv, (uv ? uv : kDefaultUv) + 3);
        if (texture != kObjectTexture && !anyTexture)
            textures.assign(base, kObjectTexture), anyTexture = true;
        if (anyTexture)
            textures.insert(textures.end(), 3, texture);
    };
    // Triangles of plain literals are read from the text without tokens
    // while the keywords are no macro names and no loop runs (a triangle read
    // in a loop counts as an object: the evaluator's way counts it).
    const auto keywordsPlain = [&] { return !e.isMacro("triangle") && !e.isMacro("smooth_triangle"); };
    bool plain = keywordsPlain();
    const auto literal = [&] {
        if (!plain || double(out.triangleCount()) + 1 > limit || e.loopRunning())
            return false;
        TokenStream* s = e.rawStream();
        TriangleCorners c;
        bool smooth = false;
        if (!s || !literalTriangle(e, *s, smooth, c))
            return false;
        add(c, smooth, nullptr, kObjectTexture);
        return true;
    };
    for (;;) {
        if (literal())
            continue;
        // Directives before the triangle run, and it may be plain after all.
        const Token t = e.peek();
        if (!(t.isWord("triangle") || t.isWord("smooth_triangle")))
            break;
        if (literal())
            continue;
        e.next();
        if (double(out.triangleCount()) + 1 > limit)
            e.countValue(double(out.triangleCount()) + 1, t.loc, "mesh triangle count", 0, limit);
        if (e.loopRunning())
            e.countLoopTriangle(t.loc, keyword.loc);
        const bool smooth = t.text == "smooth_triangle";
        e.expectSymbol("{", "after '", t.text, "'");
        const TriangleCorners corners = readTriangleCorners(e, smooth);
        Float2 uv[3] = {{0, 0}, {1, 0}, {1, 1}};
        bool hasUv = false;
        uint32_t texture = kObjectTexture;
        for (;;) {
            const Token s = e.next();
            if (s.is("}"))
                break;
            if (s.isWord("uv_vectors")) {
                for (int k = 0; k < 3; ++k) {
                    if (k > 0)
                        meshSeparator(e, "between uv vectors");
                    uv[k] = toFloat2(e.vectorExpr("a uv vector <u, v>"));
                }
                hasUv = true;
            } else if (s.isWord("texture")) {
                m.textures.push_back(e.texture(Texture{}));
                texture = uint32_t(m.textures.size() - 1);
            } else {
                e.failExpected(s, "'uv_vectors', 'texture' or '}' to close the triangle");
            }
        }
        add(corners, smooth, hasUv ? uv : nullptr, texture);
        plain = keywordsPlain(); // a directive in the triangle may have declared one
    }
    if (out.indices.empty())
        e.error(keyword.loc, "mesh has no triangles");
    if (anySmooth)
        out.normals = std::move(normals);
    if (anyUv)
        out.uvs = std::move(uvs);
    if (anyTexture)
        out.faceTextures = std::move(textures);
    padForEmbree(out);
    m.indexed = std::move(built);
}

void readMesh2(Evaluator& e, const Token& keyword, Mesh& m) {
    auto built = std::make_shared<IndexedMesh>();
    IndexedMesh& out = *built;
    const double limit = double(e.diags().limits().meshTriangles);
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
        return e.countValue(n, at, what, 0, limit);
    };
    auto closeList = [&] {
        e.acceptSymbol(",");
        e.expectSymbol("}", "after the listed count of items");
    };
    // Runs of plain literal vectors `, <x, y, z>` are read from the text
    // without tokens, the rest by the evaluator.
    auto vectorList = [&](const char* what, auto add) {
        const int n = count(what);
        for (int i = 0; i < n; ++i) {
            if (TokenStream* s = e.rawStream()) {
                LiteralVector v;
                const int from = i;
                for (; i < n && s->item(v); ++i)
                    add(v.xyz());
                if (i > from)
                    e.rawRead(v.end, ">");
                if (i == n)
                    break;
            }
            e.acceptSymbol(",");
            add(e.vectorExpr());
        }
        closeList();
    };
    bool anyTexture = false;
    std::vector<uint32_t> textures; // 3 per face
    // Index triples, and after face_indices' triples their optional texture indices.
    auto indexList = [&](std::vector<uint32_t>& indices, size_t available, const char* what, bool faces) {
        const int n = count("mesh2 index count");
        const std::string indexName = std::string(what) + " index";
        // A face: its triple `v` (its '<' at `at`), checked, then (after
        // `own`, its texture indices, are read and checked) what they mean.
        std::vector<uint32_t> own;
        const auto triple = [&](const Vec3& v, SourceLoc at) {
            for (int k = 0; k < 3; ++k)
                indices.push_back(
                    uint32_t(e.countValue(v[k], at, indexName.c_str(), 0, double(available) - 1)));
        };
        const auto textureIndex = [&](double t, SourceLoc at) {
            own.push_back(uint32_t(e.countValue(t, at, "texture index", 0, double(m.textures.size()) - 1)));
        };
        const auto faceTextures = [&](SourceLoc at) {
            if (!faces)
                return;
            if (own.size() == 1)
                own.assign(3, own[0]);
            if (!own.empty() && own.size() != 3)
                e.fail(at, fmt::format("a face takes one texture index or three, not {}", own.size()));
            anyTexture = anyTexture || !own.empty();
            if (own.empty())
                own.assign(3, kObjectTexture);
            textures.insert(textures.end(), own.begin(), own.end());
        };
        for (int i = 0; i < n; ++i) {
            // Runs of plain literal triples `, <i, j, k>` and their texture
            // indices `, t`, from the text without tokens.
            if (TokenStream* s = e.rawStream()) {
                LiteralVector v;
                SourceLoc last;
                std::vector<std::pair<double, SourceLoc>> read;
                const int from = i;
                for (; i < n; ++i) {
                    const TokenStream::Mark at = s->mark();
                    if (!s->item(v))
                        break;
                    last = v.end;
                    read.clear();
                    // `, t`: a texture index unless a triple or the list's end follows the comma.
                    bool plain = true;
                    for (TokenStream::Mark before = s->mark(); s->symbol(','); before = s->mark()) {
                        const char c = s->peekChar();
                        if (c == '<' || c == '}') {
                            s->reset(before);
                            break;
                        }
                        double t = 0;
                        SourceLoc textureAt;
                        if (!faces || !s->number(t, textureAt)) {
                            plain = false;
                            break;
                        }
                        read.emplace_back(t, textureAt);
                        last = textureAt;
                    }
                    if (!plain) {
                        s->reset(at);
                        break;
                    }
                    triple(v.xyz(), v.loc);
                    own.clear();
                    for (const auto& [t, textureAt] : read)
                        textureIndex(t, textureAt);
                    faceTextures(v.loc);
                }
                if (i > from)
                    e.rawRead(last, ">");
                if (i == n)
                    break;
            }
            e.acceptSymbol(",");
            const SourceLoc at = e.peek().loc;
            triple(e.vectorExpr(), at);
            own.clear();
            while (e.peekOperator().is(",")) {
                Token comma = e.next();
                // The next face: '<', or a vector identifier (shapes.inc writes `F1+A, F2+A,`).
                const Token after = e.peek();
                const Cell named = after.kind == TokenKind::Word ? e.lookup(after.text) : nullptr;
                if (after.is("<") || after.is("}") || (named && named->kind == Value::Kind::Vector)) {
                    e.pushBack(std::move(comma));
                    break;
                }
                const SourceLoc textureAt = e.peek().loc;
                const double t = e.floatExpr("a texture index");
                if (!faces)
                    e.fail(textureAt,
                           std::string("texture indices follow face_indices only, not ") + what + " indices");
                textureIndex(t, textureAt);
            }
            faceTextures(at);
        }
        closeList();
    };
    for (;;) {
        const Token t = e.peek();
        if (t.isWord("vertex_vectors"))
            e.next(), vectorList("mesh2 vector count",
                                 [&](const Vec3& v) { out.positions.push_back(Float3::of(v)); });
        else if (t.isWord("normal_vectors"))
            e.next(), vectorList("mesh2 vector count",
                                 [&](const Vec3& v) { out.normals.push_back(Float3::of(v)); });
        else if (t.isWord("uv_vectors"))
            e.next(),
                vectorList("mesh2 vector count", [&](const Vec3& v) { out.uvs.push_back(toFloat2(v)); });
        else if (t.isWord("face_indices"))
            e.next(), indexList(out.indices, out.positions.size(), "vertex", true);
        else if (t.isWord("normal_indices"))
            e.next(), indexList(out.normalIndices, out.normals.size(), "normal", false);
        else if (t.isWord("uv_indices"))
            e.next(), indexList(out.uvIndices, out.uvs.size(), "uv", false);
        else if (t.isWord("texture_list")) {
            e.next();
            const int n = count("mesh2 texture count");
            for (int i = 0; i < n; ++i) {
                e.acceptSymbol(",");
                const Token word = e.next();
                if (!word.isWord("texture"))
                    e.failExpected(word, "'texture' in the texture_list");
                m.textures.push_back(e.texture(Texture{}));
            }
            closeList();
        } else {
            break;
        }
    }
    if (out.indices.empty())
        e.fail(keyword.loc, "mesh2 has no face_indices");
    if (!out.normals.empty() && out.normalIndices.empty() && out.normals.size() != out.positions.size())
        e.fail(keyword.loc, "mesh2: normal_vectors needs normal_indices or one normal per vertex");
    if (!out.normalIndices.empty() && out.normalIndices.size() != out.indices.size())
        e.fail(keyword.loc, "mesh2: normal_indices and face_indices have different counts");
    if (!out.uvs.empty() && out.uvIndices.empty() && out.uvs.size() != out.positions.size()) {
        // Without uv_indices the faces' vertex indices pick the uvs too.
        for (const uint32_t i : out.indices)
            if (i >= out.uvs.size())
                e.fail(keyword.loc,
                       fmt::format("mesh2: vertex index {} has no uv vector ({} uv_vectors and no "
                                   "uv_indices)",
                                   i, out.uvs.size()));
        out.uvIndices = out.indices;
    }
    if (!out.uvIndices.empty() && out.uvIndices.size() != out.indices.size())
        e.fail(keyword.loc, "mesh2: uv_indices and face_indices have different counts");
    if (anyTexture)
        out.faceTextures = std::move(textures);
    padForEmbree(out);
    m.indexed = std::move(built);
}

std::string indexedMeshHead(const Mesh& m, ShapeText& text) {
    const IndexedMesh& mesh = *m.indexed;
    if (mesh.indices.empty()) {
        text.problems.insert("a mesh with no triangles (left out)");
        return "";
    }
    const std::string pad(size_t(text.indent + 1) * 2, ' '), inner = pad + "  ";
    std::string out = "mesh2 {";
    const auto list = [&](const char* name, size_t n, const auto& item) {
        out += fmt::format("\n{}{} {{ {}", pad, name, n);
        for (size_t i = 0; i < n; ++i)
            out += fmt::format(",\n{}{}", inner, item(i));
        out += fmt::format("\n{}}}", pad);
    };
    const auto float3 = [](const Float3& v) {
        return fmt::format("<{}, {}, {}>", floatText(v.x), floatText(v.y), floatText(v.z));
    };
    const auto triple = [](const std::vector<uint32_t>& v, size_t t) {
        return fmt::format("<{}, {}, {}>", v[3 * t], v[3 * t + 1], v[3 * t + 2]);
    };
    list("vertex_vectors", mesh.positions.size(), [&](size_t i) { return float3(mesh.positions[i]); });
    if (!mesh.normals.empty())
        list("normal_vectors", mesh.normals.size(), [&](size_t i) { return float3(mesh.normals[i]); });
    if (!mesh.uvs.empty())
        list("uv_vectors", mesh.uvs.size(), [&](size_t i) {
            return fmt::format("<{}, {}>", floatText(mesh.uvs[i].u), floatText(mesh.uvs[i].v));
        });
    if (!m.textures.empty()) {
        // Written before the object's transforms, which move them as they move the object's texture.
        const std::vector<writer::Step> steps =
            text.object ? writer::decompose(restPlacement(text.object->transform, text.object->motion))
                        : std::vector<writer::Step>{};
        list("texture_list", m.textures.size(), [&](size_t i) {
            bool exact = true;
            const std::vector<std::string> blocks =
                writer::textureBlocks(m.textures[i], steps, exact, text.problems);
            if (blocks.size() > 1)
                text.problems.insert(
                    "a layered texture in a mesh's texture list (its upper layers left out)");
            return blocks.empty() ? std::string("texture { }") : blocks.front();
        });
    }
    list("face_indices", mesh.triangleCount(), [&](size_t t) {
        std::string face = triple(mesh.indices, t);
        if (mesh.faceTextures.empty())
            return face;
        const uint32_t* c = &mesh.faceTextures[3 * t];
        const bool objects = c[0] == kObjectTexture || c[1] == kObjectTexture || c[2] == kObjectTexture;
        if (objects && !(c[0] == c[1] && c[1] == c[2]))
            text.problems.insert(
                "a mesh face whose corners mix the object's texture with their own (the object's "
                "kept)");
        if (objects)
            return face;
        if (c[0] == c[1] && c[1] == c[2])
            return face + fmt::format(", {}", c[0]);
        return face + fmt::format(", {}, {}, {}", c[0], c[1], c[2]);
    });
    if (!mesh.normalIndices.empty())
        list("normal_indices", mesh.triangleCount(), [&](size_t t) { return triple(mesh.normalIndices, t); });
    if (!mesh.uvIndices.empty())
        list("uv_indices", mesh.triangleCount(), [&](size_t t) { return triple(mesh.uvIndices, t); });
    return out;
}

} // namespace drt::lang

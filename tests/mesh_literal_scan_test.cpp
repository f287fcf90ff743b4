// The fast way through text meshes: runs of plain literals in `mesh { triangle
// ... }` and mesh2 lists are read straight from the text (TokenStream's scans,
// lang/lexer.h) instead of token by token through the evaluator. These tests
// hold it to the evaluator's way: the same file read inside a one-pass #for
// loop (a loop in the file turns the fast way off, since a loop replays its
// tokens) must give bit for bit the same mesh and the same messages, for every
// way of writing a number, comments and blanks between, and lists that mix
// literals with expressions, directives and macros. The lexer's tokens made on
// demand are held to lex()'s, and the scans to what they may consume.
#include "lang/lexer.h"
#include "lang/load.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstring>
#include <string>

namespace drt {
namespace {

using lang::LiteralVector;
using lang::Token;
using lang::TokenKind;
using lang::TokenStream;

struct Parsed {
    std::optional<Scene> scene;
    std::string messages;
};

// Read from `name` in `dir` (a fresh folder when empty).
Parsed parse(const std::string& text, const std::string& name, std::string dir = "") {
    Diagnostics diags;
    if (dir.empty()) dir = test::tempDir();
    const std::string path = test::writeFile(dir + "/" + name, text);
    Parsed p;
    p.scene = loadSceneFile(path, diags);
    p.messages = diags.formatAll();
    return p;
}

// The same text inside `#for (Pass, 1, 1) ... #end` (on the first line, so
// later lines keep their numbers): read token by token.
std::string inALoop(const std::string& text) { return "#for (Pass, 1, 1) " + text + "\n#end\n"; }

template <class T> bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expectSameMeshes(const Scene& fast, const Scene& reference) {
    ASSERT_EQ(fast.objects.size(), reference.objects.size());
    for (size_t i = 0; i < fast.objects.size(); ++i) {
        const Mesh& a = std::get<Mesh>(fast.objects[i].shape);
        const Mesh& b = std::get<Mesh>(reference.objects[i].shape);
        ASSERT_TRUE(a.indexed && b.indexed);
        const IndexedMesh &x = *a.indexed, &y = *b.indexed;
        EXPECT_GT(x.triangleCount(), 0u);
        EXPECT_TRUE(sameBits(x.positions, y.positions)) << "object " << i;
        EXPECT_EQ(x.indices, y.indices) << "object " << i;
        EXPECT_TRUE(sameBits(x.normals, y.normals)) << "object " << i;
        EXPECT_EQ(x.normalIndices, y.normalIndices) << "object " << i;
        EXPECT_TRUE(sameBits(x.uvs, y.uvs)) << "object " << i;
        EXPECT_EQ(x.uvIndices, y.uvIndices) << "object " << i;
        EXPECT_EQ(x.faceTextures, y.faceTextures) << "object " << i;
        EXPECT_EQ(a.textures.size(), b.textures.size()) << "object " << i;
    }
}

// Numbers written every way the lexer reads them: shortest, fixed, exponent
// (e, E, signed), `.5`, `3.`, signs with and without a blank, and -0.
class Writer {
public:
    std::string number(double lo = -3, double hi = 3) {
        const double x = lo + (hi - lo) * unit();
        switch (next() % 9) {
        case 0: return fmt::format("{}", x);
        case 1: return fmt::format("{:.3f}", x);
        case 2: return fmt::format("{:e}", x);
        case 3: return fmt::format("{:.4E}", x);
        case 4: { // `.5`, `-.5`
            std::string s = fmt::format("{:.5f}", std::fabs(x) - std::floor(std::fabs(x)));
            return (x < 0 ? "-" : "") + s.substr(1);
        }
        case 5: return fmt::format("{}.", std::trunc(x) == 0 ? 0.0 : std::fabs(std::trunc(x))); // `3.`
        case 6: return fmt::format("+{}", std::fabs(x));
        case 7: return fmt::format("- {}", std::fabs(x));
        default: return next() % 4 == 0 ? "-0" : fmt::format("{:.6f}e+1", x / 10);
        }
    }
    std::string blank() {
        switch (next() % 8) {
        case 0: return "";
        case 1: return "\n    ";
        case 2: return " /* a comment /* nested */ */ ";
        case 3: return " // a line comment\n ";
        case 4: return "\t";
        case 5: return "\r\n";
        default: return " ";
        }
    }
    // With `nonZero`, its first component is 1.5 (a normal).
    std::string vector(int n = 3, bool nonZero = false) {
        std::string s = fmt::format("<{}", blank());
        for (int i = 0; i < n; ++i)
            s += fmt::format("{}{}{}", i ? fmt::format(",{}", blank()) : "", nonZero && i == 0 ? "1.5" : number(),
                             blank());
        return s + ">";
    }
    std::string index(uint32_t below) { return std::to_string(next() % below); }
    uint32_t next() {
        state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(state_ >> 33);
    }
    double unit() { return (next() & 0xFFFFFF) / double(0x1000000); }

private:
    uint64_t state_ = 12345;
};

std::string triangleMesh(Writer& w, int triangles, bool smooth, bool commas) {
    std::string s = "mesh {\n";
    for (int t = 0; t < triangles; ++t) {
        const bool thisSmooth = smooth && t % 3 != 1;
        s += thisSmooth ? "  smooth_triangle {" : "  triangle {";
        for (int k = 0; k < (thisSmooth ? 6 : 3); ++k) {
            if (k > 0) s += commas || w.next() % 2 ? "," : "";
            s += w.blank() + (thisSmooth && k % 2 ? w.vector(3, true) : w.vector());
        }
        s += w.blank() + "}\n";
    }
    return s + "  pigment { color rgb 1 }\n}\n";
}

std::string mesh2(Writer& w, int vertices, int faces) {
    std::string s = "mesh2 {\n  vertex_vectors { " + std::to_string(vertices);
    for (int i = 0; i < vertices; ++i) s += (w.next() % 5 ? ", " : " ") + w.blank() + w.vector();
    s += " }\n  normal_vectors { " + std::to_string(vertices);
    for (int i = 0; i < vertices; ++i) s += fmt::format(", {}", w.vector(3, true));
    s += " }\n  uv_vectors { " + std::to_string(vertices);
    for (int i = 0; i < vertices; ++i) s += fmt::format(", {}", w.vector(2));
    s += " }\n  texture_list { 3, texture { pigment { color rgb 1 } } texture { pigment { color rgb x } }"
         " texture { pigment { color rgb y } } }\n  face_indices { " + std::to_string(faces);
    const uint32_t n = uint32_t(vertices);
    for (int i = 0; i < faces; ++i) {
        s += ",\n    <" + w.index(n) + "," + w.blank() + w.index(n) + ", " + w.index(n) + ">";
        switch (w.next() % 4) { // no texture, one, or one per corner
        case 1: s += ", " + w.index(3); break;
        case 2: s += "," + w.blank() + w.index(3) + ", " + w.index(3) + "," + w.index(3); break;
        default: break;
        }
    }
    s += "\n  }\n  normal_indices { " + std::to_string(faces);
    for (int i = 0; i < faces; ++i) s += ", <" + w.index(n) + ", " + w.index(n) + ", " + w.index(n) + ">";
    s += " }\n  uv_indices { " + std::to_string(faces);
    for (int i = 0; i < faces; ++i) s += " <" + w.index(n) + ", " + w.index(n) + ", " + w.index(n) + ">";
    return s + " }\n}\n";
}

TEST(MeshLiteralScan, LiteralListsGiveTheEvaluatorsMeshBitForBit) {
    for (const char* name : {"m.drt", "m.pov"}) {
        const bool drt = std::string(name) == "m.drt";
        Writer w;
        std::string text = "camera { location <0, 0, -5> look_at <0, 0, 0> }\n";
        text += triangleMesh(w, 400, false, drt);
        text += triangleMesh(w, 400, true, drt);
        text += mesh2(w, 300, 500);
        const Parsed fast = parse(text, name), reference = parse(inALoop(text), name);
        ASSERT_TRUE(fast.scene) << fast.messages;
        ASSERT_TRUE(reference.scene) << reference.messages;
        EXPECT_EQ(fast.messages, reference.messages);
        expectSameMeshes(*fast.scene, *reference.scene);
        EXPECT_EQ(std::get<Mesh>(fast.scene->objects[0].shape).indexed->triangleCount(), 400u) << name;
    }
}

// Literals mixed with what only the evaluator reads: identifiers, arithmetic,
// a component, macro calls, directives between items, uv_vectors and a
// texture in a triangle, an expression as a texture index.
TEST(MeshLiteralScan, ListsMixingLiteralsWithExpressionsAndDirectives) {
    const std::string text = R"(#declare V = <1, 2, 3>;
#declare K = 2;
#macro Corner(X) <X, 0, 1> #end
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  triangle { V, <1, 0, 0> * 2, <0, 1, 0> + <1, 1, 1> }
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0>.x }
  #declare K = K + 1;
  triangle { Corner(K), <1, 0, 0>, <0, 1, 0> }
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0, 0>, <1, 0>, <1, 1> }
  #if (K = 3) triangle { <5, 5, 5>, <6, 5, 5>, <5, 6, 5> } #end
  smooth_triangle { <0, 0, 0>, <0, 0, -1>, <1, 0, 0>, -z, <0, 1, 0>, <0, 0, -K> texture { pigment { color rgb x } } }
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
}
mesh2 {
  vertex_vectors { 5, <0, 0, 0>, V, <1, 0, 0> * K, Corner(1),
    #declare K = 4;
    <K, 1, 1> }
  texture_list { 2, texture { pigment { color rgb 1 } } texture { pigment { color rgb x } } }
  face_indices { 4, <0, 1, 2>, K - 3, <1, 2, 3>, <2, 3, 4>, 0, 1, K - 3, <0, 2, 4> }
}
)";
    for (const char* name : {"x.drt", "x.pov"}) {
        const Parsed fast = parse(text, name), reference = parse(inALoop(text), name);
        ASSERT_TRUE(fast.scene) << fast.messages;
        ASSERT_TRUE(reference.scene) << reference.messages;
        expectSameMeshes(*fast.scene, *reference.scene);
        const IndexedMesh& m = *std::get<Mesh>(fast.scene->objects[0].shape).indexed;
        EXPECT_EQ(m.triangleCount(), 8u);
        EXPECT_EQ(m.positions[3 * 1].x, 1.0f); // V
        EXPECT_EQ(m.positions[3 * 3].x, 3.0f); // Corner(K) after K = K + 1
        EXPECT_EQ(m.positions[3 * 5].x, 5.0f); // the #if's triangle
        const IndexedMesh& m2 = *std::get<Mesh>(fast.scene->objects[1].shape).indexed;
        EXPECT_EQ(m2.positions[4].x, 4.0f);
        EXPECT_EQ(m2.faceTextures, (std::vector<uint32_t>{1, 1, 1, kObjectTexture, kObjectTexture, kObjectTexture,
                                                          0, 1, 1, kObjectTexture, kObjectTexture, kObjectTexture}));
    }
}

// An error met in a list the fast way is read gives the evaluator's message,
// place and caret.
TEST(MeshLiteralScan, ErrorsInLiteralListsAreTheEvaluatorsAtTheSamePlace) {
    const std::string v = "mesh2 {\n  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n";
    struct Case {
        std::string text, name, expected;
    };
    const Case cases[] = {
        {v + "  face_indices { 2, <0, 1, 2>, <0, 1, 3> }\n}\n", "a.pov", "a.pov:3:32: error: vertex index 3 is out of range (0 to 2)"},
        {v + "  face_indices { 2, <0, 1, 2>, 0, <0, 1, 2> }\n}\n", "b.pov", "b.pov:3:32: error: texture index 0 is out of range"},
        {v + "  face_indices { 1, <0, 1, 2.5e> }\n}\n", "c.drt", "c.drt:3:28: error: malformed number: exponent has no digits"},
        {v + "  face_indices { 2, <0, 1, 2> <0, -1, 1> }\n}\n", "d.drt",
         "d.drt:3:31: error: vertex index -1 is out of range (0 to 2)"},
        {"mesh {\n  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n  triangle { <0, 0, 0>, <1, 0, 0> <0, 1, 0> }\n}\n",
         "e.drt", "e.drt:3:35: error: expected ',' between triangle corners, found '<'"},
        {"mesh {\n  smooth_triangle { <0, 0, 0>, <0, 0, 0>, <1, 0, 0>, z, <0, 1, 0>, z }\n}\n", "f.pov",
         "f.pov:2:32: error: smooth_triangle normal must not be a zero-length vector"},
        {"mesh {\n  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> /* never closed\n}\n", "g.drt",
         "g.drt:2:46: error: unterminated comment"},
        {"mesh {\n  triangle { <0, 0, 0>, <1, 0, 1e999>, <0, 1, 0> }\n}\n", "h.pov",
         "h.pov:2:32: error: number '1e999' is out of range"},
    };
    for (const Case& c : cases) {
        const std::string dir = test::tempDir();
        const Parsed fast = parse(c.text, c.name, dir), reference = parse(inALoop(c.text), c.name, dir);
        EXPECT_FALSE(fast.scene) << c.name;
        EXPECT_NE(fast.messages.find(c.expected), std::string::npos) << c.name << "\n" << fast.messages;
        EXPECT_NE(fast.messages.find('^'), std::string::npos) << fast.messages;
        // The reference's first line differs (the #for); the first message is
        // on a later line in every case.
        const auto firstMessage = [](const std::string& m) { return m.substr(0, m.find("\n", m.find('^'))); };
        EXPECT_EQ(firstMessage(fast.messages), firstMessage(reference.messages)) << c.name;
    }
}

// Loops and macros replay their tokens by index: a mesh in a #while loop and
// one in a macro body called twice read the same as one written out.
TEST(MeshLiteralScan, MeshesInLoopsAndMacrosReplay) {
    const std::string text = R"(#declare I = 0;
#while (I < 2)
  mesh2 { vertex_vectors { 3, <0, 0, I>, <1, 0, I>, <0, 1, I> } face_indices { 1, <0, 1, 2> } }
  #declare I = I + 1;
#end
#macro M(Z) mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } triangle { <0, 0, Z>, <1, 0, Z>, <0, 1, Z> } } #end
object { M(5) }
object { M(6) }
)";
    const Parsed p = parse(text, "loop.drt");
    ASSERT_TRUE(p.scene) << p.messages;
    ASSERT_EQ(p.scene->objects.size(), 4u);
    const auto z = [&](size_t object, size_t vertex) {
        return std::get<Mesh>(p.scene->objects[object].shape).indexed->positions.at(vertex).z;
    };
    EXPECT_EQ(z(0, 0), 0.0f);
    EXPECT_EQ(z(1, 2), 1.0f);
    EXPECT_EQ(z(2, 3), 5.0f);
    EXPECT_EQ(z(3, 5), 6.0f);
}

// ------------------------------------------------------------ the lexer

TEST(TokenStream, TokensMadeOnDemandAreLexsTokens) {
    const std::string text = "#declare A = <1, -2.5e3, .5>; /* c */ sphere { A, 3. \"s\\n\" } // x\n 1e ab $";
    for (const bool strict : {true, false}) {
        const std::vector<Token> all = lang::lex(text, 7, strict);
        TokenStream stream(text, 7, strict);
        // Asked out of order, and past the end.
        EXPECT_EQ(stream[5].text, all[5].text);
        for (size_t i = 0; i < all.size() + 3; ++i) {
            const Token& t = stream[i];
            const Token& e = all[std::min(i, all.size() - 1)];
            EXPECT_EQ(t.kind, e.kind) << i;
            EXPECT_EQ(t.text, e.text) << i;
            EXPECT_EQ(t.number, e.number) << i;
            EXPECT_EQ(t.loc.line, e.loc.line) << i;
            EXPECT_EQ(t.loc.column, e.loc.column) << i;
            EXPECT_EQ(t.loc.file, 7) << i;
        }
    }
}

TEST(TokenStream, NumbersAreCorrectlyRounded) {
    const char* texts[] = {"0.1", "1.", ".5", "3.14159265358979323846", "1e308", "2.2250738585072014e-308",
                           "4.9e-324", "1e-400", "123456789012345678901234567890", "0.30000000000000004"};
    for (const char* s : texts) {
        const std::vector<Token> t = lang::lex(s, 0, true);
        ASSERT_EQ(t[0].kind, TokenKind::Number) << s;
        EXPECT_EQ(t[0].number, std::strtod(s, nullptr)) << s;
    }
    const std::vector<Token> big = lang::lex("1e999", 0, true);
    EXPECT_EQ(big[0].kind, TokenKind::Error);
    EXPECT_EQ(big[0].text, "number '1e999' is out of range");
}

TEST(TokenStream, ScansConsumeWhatTheyReadOrNothing) {
    TokenStream s("{ <1, -2, +.5e1> , <1,2>.x 7, 8> <3, 4, 5> * 2 <1, 2 ,3> # <= 9", 0, true);
    EXPECT_TRUE(s.symbol('{'));
    LiteralVector v;
    ASSERT_TRUE(s.vector(v));
    EXPECT_EQ(v.size, 3);
    EXPECT_EQ(v.v[0], 1.0);
    EXPECT_EQ(v.v[1], -2.0);
    EXPECT_EQ(v.v[2], 5.0);
    EXPECT_EQ(v.loc.column, 3);
    EXPECT_EQ(v.end.column, 16);
    EXPECT_TRUE(s.symbol(','));
    EXPECT_FALSE(s.vector(v)); // `.x` follows: an expression, left to the evaluator
    EXPECT_TRUE(s.symbol('<'));
    // Tokens go on from where the scans stopped, and can be given back.
    EXPECT_EQ(s[0].kind, TokenKind::Number);
    EXPECT_EQ(s[1].text, ",");
    EXPECT_TRUE(s.rewind(0));
    EXPECT_EQ(s.lexed(), 0u);
    double n = 0;
    SourceLoc at;
    EXPECT_TRUE(s.number(n, at)); // `1` before ','
    EXPECT_EQ(n, 1.0);
    EXPECT_EQ(at.column, 21);
    EXPECT_TRUE(s.symbol(','));
    EXPECT_FALSE(s.number(n, at)); // `2` before '>'
    EXPECT_EQ(s[0].number, 2.0);
    EXPECT_TRUE(s[1].is(">"));
    EXPECT_TRUE(s.symbol('.'));
    EXPECT_FALSE(s.word("xx"));
    EXPECT_TRUE(s.word("x"));
    EXPECT_FALSE(s.vector(v)); // no '<'
    EXPECT_TRUE(s.number(n, at));
    EXPECT_EQ(n, 7.0);
    EXPECT_TRUE(s.symbol(','));
    EXPECT_EQ(s.peekChar(), '8');
    EXPECT_FALSE(s.number(n, at)); // `8` before '>'
    EXPECT_EQ(s[2].number, 8.0);
    EXPECT_TRUE(s[3].is(">"));
    EXPECT_FALSE(s.vector(v)); // `<3, 4, 5>` is followed by `* 2`
    EXPECT_TRUE(s[4].is("<"));
    // Past `<3, 4, 5> * 2` token by token; the scans go on after the last token made.
    size_t i = 4;
    while (!(s[i].kind == TokenKind::Number && s[i].number == 2)) ASSERT_LT(++i, 14u);
    EXPECT_EQ(s.lexed(), i + 1);
    ASSERT_TRUE(s.vector(v)); // a directive follows
    EXPECT_EQ(v.size, 3);
    EXPECT_EQ(s.peekChar(), '#');
    EXPECT_FALSE(s.symbol('<'));
    EXPECT_FALSE(s.vector(v)); // `<=`
}

} // namespace
} // namespace drt

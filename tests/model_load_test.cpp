// Model files through assimp (assets/model_load.cpp): OBJ with materials,
// PLY in ASCII and binary, glTF 2.0, each written by the test; and the errors
// for missing, empty, truncated and malformed files, which name the file.
#include "accel/accel.h"
#include "assets/assets.h"
#include "scene/image_map.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>

namespace drt {
namespace {

// An object showing the model file at `path`, named at line 4, column 9.
Object modelObject(const std::string& path) {
    auto source = std::make_shared<MeshSource>();
    source->kind = MeshSource::Kind::ModelFile;
    source->path = path;
    source->loc = {0, 4, 9};
    Mesh mesh;
    mesh.source = source;
    Object o;
    o.shape = mesh;
    o.texture.edit().pigment.color = ColorFT{Color(0.5, 0.5, 0.5), 0, 0};
    o.texture.edit().finish.phong = 0.7;
    return o;
}

// resolveAssets on a scene of one model object; the diagnostics' text.
std::string load(Scene& scene) {
    Diagnostics diags;
    resolveAssets(scene, diags);
    std::string text;
    for (const Diagnostic& d : diags.all())
        text += d.message + "\n";
    return text;
}

const IndexedMesh& indexedOf(const Scene& scene, size_t i = 0) {
    return *std::get<Mesh>(scene.objects[i].shape).indexed;
}

// A unit square in x-y as two triangles with normals, uvs and a red material.
const char* kSquareObj = R"(mtllib square.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 -1
usemtl red
f 1/1/1 3/3/1 2/2/1
f 1/1/1 4/4/1 3/3/1
)";
const char* kSquareMtl = R"(newmtl red
Kd 0.9 0.1 0.05
)";

TEST(ModelFile, ObjWithMaterialNormalsAndUvs) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/square.obj", kSquareObj);
    test::writeFile(dir + "/square.mtl", kSquareMtl);
    Scene scene = test::sceneOf({modelObject(dir + "/square.obj")});
    EXPECT_EQ(load(scene), "");
    const IndexedMesh& m = indexedOf(scene);
    EXPECT_EQ(m.triangleCount(), 2u);
    EXPECT_EQ(m.positions.size(), 4u); // joined: one vertex per corner of the square
    ASSERT_EQ(m.normals.size(), m.positions.size());
    EXPECT_EQ(m.normals[0].z, -1.0f);
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    const Mesh& mesh = std::get<Mesh>(scene.objects[0].shape);
    ASSERT_EQ(mesh.textures.size(), 1u);
    EXPECT_NEAR(mesh.textures[0].pigment.color.rgb.r, 0.9, 1e-6);
    EXPECT_NEAR(mesh.textures[0].pigment.color.rgb.b, 0.05, 1e-6);
    EXPECT_EQ(mesh.textures[0].finish.phong, 0.7); // the object's finish stays
    ASSERT_EQ(m.faceTextures.size(), 6u);
    EXPECT_EQ(m.faceTextures[0], 0u);
    // A hit in the middle of the square: uv = position.
    const Accelerator accel(scene);
    Ray ray;
    ray.origin = {0.3, 0.6, -2};
    ray.direction = {0, 0, 1};
    Hit hit;
    ASSERT_TRUE(accel.intersect(ray, hit));
    EXPECT_NEAR(hit.uv.x, 0.3, 1e-6);
    EXPECT_NEAR(hit.uv.y, 0.6, 1e-6);
    EXPECT_EQ(hit.cornerTextures[0], &mesh.textures[0]);
}

TEST(ModelFile, ObjTextureMapBecomesAUvMappedImageMap) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/square.obj", kSquareObj);
    test::writeFile(dir + "/square.mtl", "newmtl red\nKd 1 1 1\nmap_Kd missing.png\n");
    Scene scene = test::sceneOf({modelObject(dir + "/square.obj")});
    const std::string errors = load(scene);
    // The map is read like any image_map: its absence is an error naming it.
    EXPECT_NE(errors.find("missing.png"), std::string::npos) << errors;
    const Mesh& mesh = std::get<Mesh>(scene.objects[0].shape);
    ASSERT_EQ(mesh.textures.size(), 1u);
    EXPECT_EQ(mesh.textures[0].pigment.pattern, PatternKind::ImageMap);
    EXPECT_TRUE(mesh.textures[0].pigment.uvMapping);
    EXPECT_EQ(mesh.textures[0].pigment.imageMap->path, dir + "/missing.png");
}

TEST(ModelFile, ObjWithoutMaterialsOrNormalsShowsTheObjectsTextureFlat) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n"); // a quad
    Scene scene = test::sceneOf({modelObject(dir + "/t.obj")});
    EXPECT_EQ(load(scene), "");
    const IndexedMesh& m = indexedOf(scene);
    EXPECT_EQ(m.triangleCount(), 2u); // triangulated
    EXPECT_TRUE(m.normals.empty());
    EXPECT_TRUE(m.faceTextures.empty());
    EXPECT_TRUE(std::get<Mesh>(scene.objects[0].shape).textures.empty());
}

std::string plyHeader(const char* format, int vertices, int faces) {
    return std::string("ply\nformat ") + format + " 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(ModelFile, PlyAsciiAndBinaryGiveTheSameMesh) {
    const std::string dir = test::tempDir();
    const float v[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    std::string ascii = plyHeader("ascii", 4, 2);
    for (const auto& p : v)
        ascii += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    ascii += "3 0 2 1\n3 0 3 2\n";
    test::writeFile(dir + "/a.ply", ascii);
    std::string binary = plyHeader("binary_little_endian", 4, 2);
    binary.append(reinterpret_cast<const char*>(v), sizeof v);
    const int32_t faces[2][3] = {{0, 2, 1}, {0, 3, 2}};
    for (const auto& face : faces) {
        binary.push_back(char(3));
        binary.append(reinterpret_cast<const char*>(face), sizeof face);
    }
    test::writeFile(dir + "/b.ply", binary);
    Scene scene = test::sceneOf({modelObject(dir + "/a.ply"), modelObject(dir + "/b.ply")});
    EXPECT_EQ(load(scene), "");
    const IndexedMesh &a = indexedOf(scene, 0), &b = indexedOf(scene, 1);
    ASSERT_EQ(a.triangleCount(), 2u);
    ASSERT_EQ(b.triangleCount(), 2u);
    Vec3 loA, hiA, loB, hiB;
    ASSERT_TRUE(indexedMeshBounds(a, loA, hiA));
    ASSERT_TRUE(indexedMeshBounds(b, loB, hiB));
    EXPECT_EQ(hiA, (Vec3{2, 1, 0}));
    EXPECT_EQ(hiB, (Vec3{2, 1, 0}));
    // PLY has no materials: the triangles show the object's texture.
    EXPECT_TRUE(std::get<Mesh>(scene.objects[0].shape).textures.empty());
    EXPECT_TRUE(a.faceTextures.empty());
}

std::string toBase64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t chunk = 0;
        for (size_t k = 0; k < 3; ++k)
            chunk = chunk << 8 | (k < n ? uint8_t(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k)
            out += k <= n ? alphabet[(chunk >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// glTF 2.0 with its buffer inline (base64): one triangle with a base colour.
TEST(ModelFile, GltfTriangleWithBaseColour) {
    // Three float3 positions (36 bytes) and three uint16 indices (6 bytes, padded to 8).
    float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint16_t indices[4] = {0, 1, 2, 0};
    std::string bytes(reinterpret_cast<const char*>(positions), sizeof positions);
    bytes.append(reinterpret_cast<const char*>(indices), sizeof indices);
    const std::string base64 = toBase64(bytes);
    const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"translation":[0,0,5]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
"materials":[{"name":"green","pbrMetallicRoughness":{"baseColorFactor":[0.1,0.8,0.2,1]}}],
"buffers":[{"byteLength":44,"uri":"data:application/octet-stream;base64,)" +
                             base64 + R"("}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]})";
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/t.gltf", gltf);
    Scene scene = test::sceneOf({modelObject(dir + "/t.gltf")});
    EXPECT_EQ(load(scene), "");
    const IndexedMesh& m = indexedOf(scene);
    ASSERT_EQ(m.triangleCount(), 1u);
    Vec3 lo, hi;
    ASSERT_TRUE(indexedMeshBounds(m, lo, hi));
    EXPECT_EQ(lo.z, 5); // the node's translation is baked in
    const Mesh& mesh = std::get<Mesh>(scene.objects[0].shape);
    ASSERT_EQ(mesh.textures.size(), 1u);
    EXPECT_NEAR(mesh.textures[0].pigment.color.rgb.g, 0.8, 1e-6);
}

TEST(ModelFile, CopiesOfOneModelShareOneMesh) {
    const std::string dir = test::tempDir();
    test::writeFile(dir + "/square.obj", kSquareObj);
    test::writeFile(dir + "/square.mtl", kSquareMtl);
    Object a = modelObject(dir + "/square.obj");
    Object b = a; // a declared model used twice shares its MeshSource
    b.transform = Transform::translate({5, 0, 0});
    b.texture.edit().finish.phong = 0.1;
    Scene scene = test::sceneOf({a, b});
    EXPECT_EQ(load(scene), "");
    EXPECT_EQ(&indexedOf(scene, 0), &indexedOf(scene, 1));
    EXPECT_EQ(std::get<Mesh>(scene.objects[1].shape).textures[0].finish.phong, 0.1); // each its own finish
    const Accelerator accel(scene);
    EXPECT_EQ(accel.meshStats().sharedMeshes, 1u);
    EXPECT_EQ(accel.meshStats().placements, 2u);
}

// Each bad file: the error is at the scene's place and names the file and the problem.
void expectLoadError(const std::string& path, const std::string& problem) {
    Scene scene = test::sceneOf({modelObject(path)});
    Diagnostics diags;
    EXPECT_FALSE(resolveAssets(scene, diags));
    ASSERT_EQ(diags.errorCount(), 1) << path;
    const Diagnostic& d = diags.all().front();
    EXPECT_EQ(d.loc.line, 4);
    EXPECT_EQ(d.loc.column, 9);
    EXPECT_NE(d.message.find(path), std::string::npos) << d.message;
    EXPECT_NE(d.message.find(problem), std::string::npos) << d.message;
    EXPECT_FALSE(std::get<Mesh>(scene.objects[0].shape).indexed);
}

TEST(ModelFile, MissingEmptyTruncatedAndMalformedFilesAreErrors) {
    const std::string dir = test::tempDir();
    expectLoadError(dir + "/nothing.obj", "no such file");
    expectLoadError(test::writeFile(dir + "/empty.obj", ""), "empty");
    std::string binary = plyHeader("binary_little_endian", 4, 2);
    binary.append(20, '\0'); // 20 of the 48 vertex bytes, no faces
    expectLoadError(test::writeFile(dir + "/truncated.ply", binary), "malformed or truncated");
    expectLoadError(
        test::writeFile(dir + "/bad.ply", "ply\nformat ascii 1.0\nelement vertex x\nend_header\n"),
        "malformed or truncated");
    expectLoadError(test::writeFile(dir + "/lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"), "no triangles");
    expectLoadError(test::writeFile(dir + "/bad.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [}"),
                    "malformed or truncated");
    expectLoadError(test::writeFile(dir + "/index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
                    "out of range");
}

} // namespace
} // namespace drt

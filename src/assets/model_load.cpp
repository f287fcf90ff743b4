// Model files (OBJ, PLY ASCII and binary, glTF 2.0) read through assimp into
// a compact mesh (scene/indexed_mesh.h).
//
// Why assimp: one Debian package (libassimp-dev) reads all three formats and
// many more, triangulates polygons, bakes the node hierarchy's transforms and
// reports malformed files as errors; tinyobjloader would have read OBJ alone.
//
// What is kept: positions; normals where the file has them (none: flat
// faces); the first UV channel; and per material its diffuse colour (glTF's
// base colour) and diffuse texture map. A material becomes a texture of the
// mesh (Mesh::textures): a copy of the object's texture whose pigment is the
// material's colour, or an image_map of its texture file, uv-mapped, planar,
// bilinear and repeating (as OBJ and glTF renderers show it). So the object's
// finish and normal apply to every material, and triangles of a file without
// materials show the object's texture.
#include "assets/loaders.h"
#include "core/limits.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace drt {

namespace {

// The pigment of one assimp material, or nothing when the file gives it no
// colour of its own (assimp's default material).
std::optional<Pigment> materialPigment(const aiMaterial& material, double workingGamma,
                                       const MeshSource& source, Diagnostics& diags) {
    // assimp gives a file without materials a default one (OBJ: "DefaultMaterial",
    // grey; PLY, which has no materials at all: a nameless white one).
    const std::string name = material.GetName().C_Str();
    std::string extension = std::filesystem::path(source.path).extension().string();
    for (char& c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    if (name == AI_DEFAULT_MATERIAL_NAME || (name.empty() && extension == ".ply"))
        return std::nullopt;
    aiString file;
    aiColor4D color(0.6f, 0.6f, 0.6f, 1.0f);
    const bool hasColor = material.Get(AI_MATKEY_BASE_COLOR, color) == AI_SUCCESS ||
                          material.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS;
    const bool hasMap = material.GetTexture(aiTextureType_BASE_COLOR, 0, &file) == AI_SUCCESS ||
                        material.GetTexture(aiTextureType_DIFFUSE, 0, &file) == AI_SUCCESS;
    Pigment pigment;
    if (hasMap && file.length > 0 && file.C_Str()[0] == '*') {
        diags.warning(source.loc, "'" + source.path +
                                      "': a texture embedded in the file is not supported; the "
                                      "material's colour is used");
    } else if (hasMap && file.length > 0) {
        auto map = std::make_shared<ImageMap>();
        map->file = file.C_Str();
        map->path = (std::filesystem::path(source.path).parent_path() / map->file).string();
        map->loc = source.loc;
        map->projection = ImageMap::Projection::Planar;
        map->interpolation = ImageMap::Interpolation::Bilinear;
        map->workingGamma = workingGamma;
        pigment.pattern = PatternKind::ImageMap;
        pigment.imageMap = std::move(map);
        pigment.uvMapping = true;
        return pigment;
    }
    if (!hasColor)
        return std::nullopt;
    pigment.color = ColorFT{Color(color.r, color.g, color.b), 0, std::clamp(1.0 - double(color.a), 0.0, 1.0)};
    return pigment;
}

// The vertices of one aiMesh with identical position, normal and uv (bit for
// bit) merged: remap[v] is vertex v's index among the distinct ones,
// firstOfEach[i] the first vertex of distinct vertex i.
struct WeldedVertices {
    std::vector<uint32_t> remap, firstOfEach;
};

WeldedVertices weld(const aiMesh& m, bool withNormals, bool withUvs) {
    // The bytes that make a vertex: position, then normal and uv when kept.
    const auto key = [&](uint32_t v, float(&k)[8]) {
        const aiVector3D& p = m.mVertices[v];
        const aiVector3D n = withNormals && m.HasNormals() ? m.mNormals[v] : aiVector3D(0, 0, 0);
        const aiVector3D t = withUvs && m.HasTextureCoords(0) ? m.mTextureCoords[0][v] : aiVector3D(0, 0, 0);
        const float values[8] = {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y};
        std::memcpy(k, values, sizeof values);
    };
    // Open addressing, linear probing, at most half full.
    size_t slots = 16;
    while (slots < 2 * size_t(m.mNumVertices))
        slots *= 2;
    constexpr uint32_t kEmpty = 0xFFFFFFFFu;
    std::vector<uint32_t> table(slots, kEmpty); // distinct-vertex index
    WeldedVertices out;
    out.remap.resize(m.mNumVertices);
    float k[8], other[8];
    for (uint32_t v = 0; v < m.mNumVertices; ++v) {
        key(v, k);
        uint64_t words[4], hash = 0;
        std::memcpy(words, k, sizeof k);
        for (const uint64_t w : words) // multiply-xorshift over the key's four 64-bit words
            hash = ((hash ^ w) * 0x9E3779B97F4A7C15ull) ^ (hash >> 29);
        hash ^= hash >> 32;
        for (size_t slot = hash & (slots - 1);; slot = (slot + 1) & (slots - 1)) {
            if (table[slot] == kEmpty) {
                table[slot] = uint32_t(out.firstOfEach.size());
                out.remap[v] = table[slot];
                out.firstOfEach.push_back(v);
                break;
            }
            key(out.firstOfEach[table[slot]], other);
            if (std::memcmp(k, other, sizeof k) == 0) {
                out.remap[v] = table[slot];
                break;
            }
        }
    }
    return out;
}

// True when every mesh of `scene` is shown by one node and every node's
// transform is the identity: the meshes as they are are the model.
bool placedAsIs(const aiScene& scene) {
    if (!scene.mRootNode)
        return false;
    std::vector<unsigned> uses(scene.mNumMeshes, 0);
    std::vector<const aiNode*> pending{scene.mRootNode};
    while (!pending.empty()) {
        const aiNode& node = *pending.back();
        pending.pop_back();
        if (!node.mTransformation.IsIdentity())
            return false;
        for (unsigned i = 0; i < node.mNumMeshes; ++i)
            if (node.mMeshes[i] >= uses.size() || ++uses[node.mMeshes[i]] > 1)
                return false;
        for (unsigned i = 0; i < node.mNumChildren; ++i)
            pending.push_back(node.mChildren[i]);
    }
    return std::all_of(uses.begin(), uses.end(), [](unsigned n) { return n == 1; });
}

// "" if the file can be read, else why not.
std::string unreadable(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return "no such file";
    if (std::filesystem::is_directory(path, ec))
        return "it is a directory";
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return "it cannot be opened";
    if (std::filesystem::file_size(path, ec) == 0)
        return "the file is empty";
    return "";
}

} // namespace

std::string loadModelFile(const MeshSource& source, double workingGamma, LoadedModel& model,
                          Diagnostics& diags) {
    const std::string prefix = "cannot read the model '" + source.path + "': ";
    if (const std::string why = unreadable(source.path); !why.empty())
        return prefix + why;
    Assimp::Importer importer;
    // Points and lines are dropped (a mesh is triangles); no normals are made
    // up (a file without them shows flat faces); UVs keep OpenGL's v-up
    // convention, the image map's.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // aiProcess_ValidateDataStructure stays, though it costs about a tenth of
    // reading a binary PLY: without it the truncated PLY of the tests reaches
    // the code below broken and crashes it.
    const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    // No aiProcess_JoinIdenticalVertices: weld() below does it for a fraction of the time and memory.
    const aiScene* scene = importer.ReadFile(source.path, flags);
    // The node transforms baked in, unless each mesh is placed once and as it
    // is (OBJ and PLY files always): then the step would only copy the meshes.
    if (scene && !placedAsIs(*scene))
        scene = importer.ApplyPostProcessing(aiProcess_PreTransformVertices);
    if (!scene) {
        const std::string why = importer.GetErrorString();
        // SortByPType removed every point and line: nothing was left.
        if (why.find("No meshes remaining") != std::string::npos)
            return prefix + "the file holds no triangles";
        return prefix + "the file is malformed or truncated" + (why.empty() ? "" : " (" + why + ")");
    }
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        return prefix + "the file is incomplete";

    // Which aiMeshes are triangles, and for each its vertices welded
    // (assimp's OBJ importer gives every corner of every face a vertex of its
    // own; assimp's JoinIdenticalVertices step costs seconds and hundreds of
    // bytes per triangle on a million triangles, this a fraction of both).
    bool anyNormals = false, anyUvs = false;
    size_t triangleTotal = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            continue;
        triangleTotal += m.mNumFaces;
        anyNormals = anyNormals || m.HasNormals();
        anyUvs = anyUvs || m.HasTextureCoords(0);
    }
    if (triangleTotal == 0)
        return prefix + "the file holds no triangles";
    if (triangleTotal >= kObjectTexture / 3)
        return prefix + "too many triangles";
    std::vector<WeldedVertices> welded(scene->mNumMeshes);
    size_t vertexTotal = 0;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        if (scene->mMeshes[i]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) {
            welded[i] = weld(*scene->mMeshes[i], anyNormals, anyUvs);
            vertexTotal += welded[i].firstOfEach.size();
        }
    }
    if (vertexTotal >= kObjectTexture)
        return prefix + "too many vertices";

    auto built = std::make_shared<IndexedMesh>();
    IndexedMesh& out = *built;
    out.positions.reserve(vertexTotal + 1); // + 1: padForEmbree
    out.indices.reserve(3 * triangleTotal);
    if (anyNormals)
        out.normals.reserve(vertexTotal);
    if (anyUvs)
        out.uvs.reserve(vertexTotal);

    std::map<unsigned, uint32_t> textureOfMaterial;
    std::vector<uint32_t> textureOfMesh(scene->mNumMeshes, kObjectTexture);
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || m.mMaterialIndex >= scene->mNumMaterials)
            continue;
        auto [it, fresh] = textureOfMaterial.try_emplace(m.mMaterialIndex, kObjectTexture);
        if (fresh) {
            if (auto pigment =
                    materialPigment(*scene->mMaterials[m.mMaterialIndex], workingGamma, source, diags)) {
                model.materials.push_back(std::move(*pigment));
                it->second = uint32_t(model.materials.size() - 1);
            }
        }
        textureOfMesh[i] = it->second;
    }
    const bool anyTexture = std::any_of(textureOfMesh.begin(), textureOfMesh.end(),
                                        [](uint32_t t) { return t != kObjectTexture; });
    if (anyTexture)
        out.faceTextures.reserve(3 * triangleTotal);
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh& m = *scene->mMeshes[i];
        if (!(m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            continue;
        const uint32_t base = uint32_t(out.positions.size());
        for (const uint32_t v : welded[i].firstOfEach) {
            const aiVector3D& p = m.mVertices[v];
            out.positions.push_back({p.x, p.y, p.z});
            if (anyNormals) {
                // A part without normals in a file with some gets zero normals:
                // the accelerator falls back to the flat face there.
                const aiVector3D n = m.HasNormals() ? m.mNormals[v] : aiVector3D(0, 0, 0);
                out.normals.push_back({n.x, n.y, n.z});
            }
            if (anyUvs) {
                const aiVector3D t = m.HasTextureCoords(0) ? m.mTextureCoords[0][v] : aiVector3D(0, 0, 0);
                out.uvs.push_back({t.x, t.y});
            }
        }
        const std::vector<uint32_t>& remap = welded[i].remap;
        std::vector<uint32_t>().swap(welded[i].firstOfEach);
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3)
                continue;
            for (int k = 0; k < 3; ++k)
                out.indices.push_back(base + remap[face.mIndices[k]]);
            if (anyTexture)
                out.faceTextures.insert(out.faceTextures.end(), 3, textureOfMesh[i]);
        }
        std::vector<uint32_t>().swap(welded[i].remap);
    }
    if (const std::string error = validateIndexedMesh(out, model.materials.size()); !error.empty())
        return prefix + error;
    padForEmbree(out);
    model.mesh = std::move(built);
    // assimp's copy is freed in many small blocks (an OBJ's faces, a few per
    // triangle); give the heap they leave back to the system.
    importer.FreeScene();
#ifdef __GLIBC__
    malloc_trim(0);
#endif
    return "";
}

void showModel(const LoadedModel& model, const Texture& objectTexture, Mesh& mesh) {
    mesh.indexed = model.mesh;
    mesh.textures.clear();
    for (const Pigment& pigment : model.materials) {
        Texture texture = objectTexture;
        texture.pigment = pigment;
        texture.map.clear();
        texture.layersAbove.clear();
        mesh.textures.push_back(std::move(texture));
    }
}

} // namespace drt

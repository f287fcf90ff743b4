#include "assets/assets.h"

#include "assets/loaders.h"
#include "scene/scene_walk.h"

#include <map>

namespace drt {

bool resolveAssets(Scene& scene, Diagnostics& diags) {
    const int errorsBefore = diags.errorCount();
    // Meshes first: a model file's materials may name image maps.
    // Copies of one model (a declared mesh used many times) share one
    // MeshSource: the file is read once and its triangles shared (instancing).
    // A model keeps its MeshSource beside the triangles, so that a scene
    // written back (drt convert) names the file instead of its triangles.
    std::map<const MeshSource*, LoadedModel> models;
    forEachObject(scene, [&](Object& object) {
        Mesh* mesh = std::get_if<Mesh>(&object.shape);
        if (!mesh || !mesh->source || mesh->indexed) return;
        const std::shared_ptr<const MeshSource> source = mesh->source;
        if (source->kind != MeshSource::Kind::ModelFile) {
            mesh->source.reset();
            if (const std::string error = loadMeshSource(*source, *mesh, diags); !error.empty())
                diags.error(source->loc, error);
            return;
        }
        auto [it, fresh] = models.try_emplace(source.get());
        if (fresh) {
            if (const std::string error = loadModelFile(*source, scene.global.assumedGamma, it->second, diags);
                !error.empty())
                diags.error(source->loc, error);
        }
        if (it->second.mesh) showModel(it->second, object.texture, *mesh);
    });
    // Pigments that share one ImageMap (a declared pigment used many times)
    // keep sharing the decoded copy.
    std::map<const ImageMap*, std::shared_ptr<const ImageMap>> decoded;
    forEachPigment(scene, [&](Pigment& pigment) {
        if (!pigment.imageMap || !pigment.imageMap->rgbt.empty()) return;
        auto [it, fresh] = decoded.try_emplace(pigment.imageMap.get());
        if (fresh) {
            auto map = std::make_shared<ImageMap>(*pigment.imageMap);
            if (const std::string error = loadImageMap(*map, diags); !error.empty()) diags.error(map->loc, error);
            it->second = std::move(map);
        }
        pigment.imageMap = it->second;
    });
    // df3 files, read once however many pigments and normals share one.
    std::map<const DensityFile*, std::shared_ptr<const DensityFile>> read;
    const auto resolveDensity = [&](std::shared_ptr<const DensityFile>& density) {
        if (!density || !density->values.empty()) return;
        auto [it, fresh] = read.try_emplace(density.get());
        if (fresh) {
            auto d = std::make_shared<DensityFile>(*density);
            if (const std::string error = loadDensityFile(*d, diags.limits()); !error.empty()) diags.error(d->loc, error);
            it->second = std::move(d);
        }
        density = it->second;
    };
    forEachPigment(scene, [&](Pigment& pigment) { resolveDensity(pigment.densityFile); });
    forEachNormal(scene, [&](Normal& normal) { resolveDensity(normal.densityFile); });
    return diags.errorCount() == errorsBefore;
}

bool assetsResolved(const Scene& scene) {
    bool resolved = true;
    forEachPigment(scene, [&](const Pigment& pigment) {
        if (pigment.imageMap && pigment.imageMap->rgbt.empty()) resolved = false;
        if (pigment.densityFile && pigment.densityFile->values.empty()) resolved = false;
    });
    forEachNormal(scene, [&](const Normal& normal) {
        if (normal.densityFile && normal.densityFile->values.empty()) resolved = false;
    });
    forEachObject(scene, [&](const Object& object) {
        if (const Mesh* mesh = std::get_if<Mesh>(&object.shape); mesh && mesh->source && !mesh->indexed)
            resolved = false;
    });
    return resolved;
}

} // namespace drt

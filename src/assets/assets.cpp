#include "assets/assets.h"

#include "assets/loaders.h"
#include "scene/scene_walk.h"

#include <map>

namespace drt {

bool resolveAssets(Scene& scene, Diagnostics& diags) {
    const int errorsBefore = diags.errorCount();
    // Pigments that share one ImageMap (a declared pigment used many times)
    // keep sharing the decoded copy.
    std::map<const ImageMap*, std::shared_ptr<const ImageMap>> decoded;
    forEachPigment(scene, [&](Pigment& pigment) {
        if (!pigment.imageMap || !pigment.imageMap->rgbt.empty()) return;
        auto [it, fresh] = decoded.try_emplace(pigment.imageMap.get());
        if (fresh) {
            auto map = std::make_shared<ImageMap>(*pigment.imageMap);
            if (const std::string error = loadImageMap(*map); !error.empty()) diags.error(map->loc, error);
            it->second = std::move(map);
        }
        pigment.imageMap = it->second;
    });
    forEachObject(scene, [&](Object& object) {
        Mesh* mesh = std::get_if<Mesh>(&object.shape);
        if (!mesh || !mesh->source) return;
        const MeshSource source = *mesh->source;
        if (const std::string error = loadMeshSource(source, *mesh, diags); !error.empty())
            diags.error(source.loc, error);
        mesh->source.reset();
    });
    return diags.errorCount() == errorsBefore;
}

bool assetsResolved(const Scene& scene) {
    bool resolved = true;
    forEachPigment(scene, [&](const Pigment& pigment) {
        if (pigment.imageMap && pigment.imageMap->rgbt.empty()) resolved = false;
    });
    forEachObject(scene, [&](const Object& object) {
        if (const Mesh* mesh = std::get_if<Mesh>(&object.shape); mesh && mesh->source) resolved = false;
    });
    return resolved;
}

} // namespace drt

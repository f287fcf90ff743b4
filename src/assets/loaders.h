// Private to src/assets: one decoder per kind of file.
#pragma once

#include "core/diagnostics.h"
#include "scene/density_file.h"
#include "scene/image_map.h"
#include "scene/scene.h"

#include <string>

namespace drt {

// Reads `map.path` and fills the texels, decoded with v^gamma when
// `map.gamma` > 0, else with the gamma the file states (a PNG gAMA chunk,
// a linear file), else from sRGB for integer files; float files (EXR, HDR)
// are linear. Alpha becomes transmit = 1 - alpha. A material_map's image and
// one with per-index amounts also get their palette indices (warnings, such as
// per-index amounts on an image without a palette, go to `diags`). Returns ""
// on success, else the reason.
std::string loadImageMap(ImageMap& map, Diagnostics& diags);

// Reads `d.path`, a df3 file, into the voxels (density_file_load.cpp);
// refuses a file whose voxels would take more than `limits.memoryMB`.
// Returns "" on success, else the reason, naming the file.
std::string loadDensityFile(DensityFile& d, const Limits& limits);

// Fills `mesh` from `source` (a height field); warnings go to `diags`.
// Returns "" on success, else the reason.
std::string loadMeshSource(const MeshSource& source, Mesh& mesh, Diagnostics& diags);

// A model file read once, however many objects show it: its triangles, and
// per material the pigment (a colour, or a uv-mapped image map) that
// IndexedMesh::faceTextures index.
struct LoadedModel {
    std::shared_ptr<const IndexedMesh> mesh;
    std::vector<Pigment> materials;
};

// Reads a model file (MeshSource::Kind::ModelFile; model_load.cpp). Image
// maps get `workingGamma` (the scene's assumed_gamma). Returns "" on
// success, else the reason, naming the file.
std::string loadModelFile(const MeshSource& source, double workingGamma, LoadedModel& model, Diagnostics& diags);

// Shows a loaded model in `mesh`: its triangles, and per material a copy of
// the object's texture with the material's pigment (Mesh::textures).
void showModel(const LoadedModel& model, const Texture& objectTexture, Mesh& mesh);

} // namespace drt

#include "pov/load.h"

#include "pov/parser.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {

std::optional<Scene> loadPovSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                      const PovOptions& options, const std::string& baseDir) {
    PovOptions effective = options;
    if (effective.includePaths.empty()) effective.includePaths = {baseDir, kPovStandardIncludeDir};
    const int id = diags.files().add(name, text);
    pov::PovParser parser(diags, effective);
    // POV-Ray's default camera: right <1.33,0,0> whatever the image size.
    parser.scene_.camera.right = Vec3(1.33, 0, 0);
    std::optional<Scene> scene = parser.run(id, baseDir);
    if (!scene) return std::nullopt;
    return scene;
}

std::optional<Scene> loadPovSceneFile(const std::string& path, Diagnostics& diags, const PovOptions& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diags.error(SourceLoc{}, "cannot read scene '" + path + "'");
        return std::nullopt;
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string dir = fs::path(path).parent_path().string();
    return loadPovSceneText(buffer.str(), path, diags, options, dir.empty() ? "." : dir);
}

} // namespace drt

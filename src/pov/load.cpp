#include "pov/load.h"

#include "lang/load.h"
#include "pov/parser.h"

#include <cctype>
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

bool isPovSceneFile(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".pov" || extension == ".inc";
}

std::optional<Scene> loadAnySceneFile(const std::string& path, Diagnostics& diags, const PovOptions& options) {
    return isPovSceneFile(path) ? loadPovSceneFile(path, diags, options) : loadSceneFile(path, diags);
}

} // namespace drt

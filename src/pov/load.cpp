#include "pov/load.h"

#include "pov/parser.h"

#include "core/source_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {

std::optional<Scene> loadPovSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                      const PovOptions& options, const std::string& baseDir) {
    PovOptions effective = options;
    if (effective.includePaths.empty()) effective.includePaths = {baseDir, kPovStandardIncludeDir};
    std::string withoutMark = text;
    stripByteOrderMark(withoutMark);
    const int id = diags.files().add(name, std::move(withoutMark));
    pov::PovParser parser(diags, effective);
    // POV-Ray's default camera: right <1.33,0,0> whatever the image size.
    parser.scene_.camera.right = Vec3(1.33, 0, 0);
    std::optional<Scene> scene = parser.run(id, baseDir);
    if (!scene) return std::nullopt;
    return scene;
}

std::optional<Scene> loadPovSceneFile(const std::string& path, Diagnostics& diags, const PovOptions& options) {
    std::string text;
    if (std::string problem = readSourceFile(path, -1, text); !problem.empty()) {
        diags.error(SourceLoc{}, "cannot read scene: " + problem);
        return std::nullopt;
    }
    std::string dir = fs::path(path).parent_path().string();
    return loadPovSceneText(text, path, diags, options, dir.empty() ? "." : dir);
}

} // namespace drt

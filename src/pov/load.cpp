#include "pov/load.h"

namespace drt {

namespace {

LoadOptions asPov(const PovOptions& options) {
    LoadOptions o = options;
    o.dialect = DialectKind::Pov;
    return o;
}

} // namespace

std::optional<Scene> loadPovSceneFile(const std::string& path, Diagnostics& diags, const PovOptions& options) {
    return loadScene(path, diags, asPov(options));
}

std::optional<Scene> loadPovSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                      const PovOptions& options, const std::string& baseDir) {
    return loadSceneText(text, name, diags, asPov(options), baseDir);
}

} // namespace drt

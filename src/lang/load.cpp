#include "lang/load.h"

#include "lang/evaluator.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {

namespace {

std::optional<std::string> readWholeFile(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

} // namespace

std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const LoadOptions& options, const std::string& baseDir) {
    LoadOptions effective = options;
    if (effective.includePaths.empty()) effective.includePaths = {baseDir, kPovStandardIncludeDir};
    const DialectKind dialect = options.dialect.value_or(dialectForPath(name));
    const int errorsBefore = diags.errorCount();
    const int fileId = diags.files().add(name, text);
    lang::Evaluator evaluator(diags, effective, dialect);
    std::optional<Scene> scene = evaluator.run(fileId, baseDir);
    if (diags.errorCount() > errorsBefore) return std::nullopt;
    return scene;
}

std::optional<Scene> loadScene(const std::string& path, Diagnostics& diags, const LoadOptions& options) {
    const std::optional<std::string> text = readWholeFile(path);
    if (!text) {
        diags.error(SourceLoc{}, "cannot read scene file '" + path + "'");
        return std::nullopt;
    }
    std::string dir = fs::path(path).parent_path().string();
    LoadOptions effective = options;
    if (!effective.dialect) effective.dialect = dialectForPath(path);
    return loadSceneText(*text, path, diags, effective, dir.empty() ? "." : dir);
}

std::optional<Scene> loadSceneFile(const std::string& path, Diagnostics& diags) { return loadScene(path, diags); }

std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const std::string& baseDir) {
    return loadSceneText(text, name, diags, LoadOptions{}, baseDir);
}

} // namespace drt

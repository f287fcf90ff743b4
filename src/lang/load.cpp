#include "lang/load.h"

#include "lang/evaluator.h"

#include "core/source_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace drt {

namespace {

// The scene in `text`, which the file table keeps (a scene read from a file
// is held once, not copied: a large mesh's text is most of the memory parsing takes).
std::optional<Scene> loadOwnedText(std::string text, const std::string& name, Diagnostics& diags,
                                   const LoadOptions& options, const std::string& baseDir) {
    LoadOptions effective = options;
    if (effective.includePaths.empty()) effective.includePaths = {baseDir, kPovStandardIncludeDir};
    const DialectKind dialect = options.dialect.value_or(dialectForPath(name));
    const int errorsBefore = diags.errorCount();
    stripByteOrderMark(text);
    const int fileId = diags.files().add(name, std::move(text));
    lang::Evaluator evaluator(diags, effective, dialect);
    std::optional<Scene> scene = evaluator.run(fileId, baseDir);
    if (diags.errorCount() > errorsBefore) return std::nullopt;
    return scene;
}

} // namespace

std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const LoadOptions& options, const std::string& baseDir) {
    return loadOwnedText(text, name, diags, options, baseDir);
}

std::optional<Scene> loadScene(const std::string& path, Diagnostics& diags, const LoadOptions& options) {
    std::string text;
    if (std::string problem = readSourceFile(path, -1, text); !problem.empty()) {
        diags.error(SourceLoc{}, "cannot read scene file: " + problem);
        return std::nullopt;
    }
    std::string dir = fs::path(path).parent_path().string();
    LoadOptions effective = options;
    if (!effective.dialect) effective.dialect = dialectForPath(path);
    return loadOwnedText(std::move(text), path, diags, effective, dir.empty() ? "." : dir);
}

std::optional<Scene> loadSceneFile(const std::string& path, Diagnostics& diags) { return loadScene(path, diags); }

std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const std::string& baseDir) {
    return loadSceneText(text, name, diags, LoadOptions{}, baseDir);
}

} // namespace drt

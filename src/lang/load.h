// The front end: scene text in either dialect -> scene model. One lexer and
// one evaluator read both `.drt` (drt's dialect, docs/language.md) and `.pov`
// (POV-Ray 3.7's scene language, docs/pov.md); the dialect follows the file's
// extension unless LoadOptions names it.
#pragma once

#include "core/diagnostics.h"
#include "lang/dialect.h"
#include "scene/frame_clock.h"
#include "scene/geometry_query.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace drt {

struct LoadOptions {
    // The dialect; none: from the file's extension (.pov, .inc, .mac: POV-Ray's).
    std::optional<DialectKind> dialect;
    // Folders searched by #include after the including file's own folder, in
    // order (POV-Ray's +L / Library_Path). When empty: the scene's folder,
    // then POV-Ray's standard include folder.
    std::vector<std::string> includePaths;
    // Warnings (unsupported features, approximations) become errors.
    bool strict = false;
    // image_width / image_height as the scene sees them; in the POV-Ray
    // dialect they are also the image size stored in Scene::render.
    int imageWidth = 320;
    int imageHeight = 240;
    // What `clock`, `frame_number` and the other animation identifiers read
    // (the same in both dialects).
    FrameClock frame;
    // The geometry behind trace() and inside() at parse time; without it they are errors.
    SceneGeometryQuery* geometry = nullptr;
};

// The folder of Debian's povray-includes package, the last default include path.
inline constexpr const char* kPovStandardIncludeDir = "/usr/share/povray-3.7/include";

// Reads and evaluates a scene file. Every problem is reported to `diags`
// (file:line:col, with the include chain); returns a scene only if there were
// no errors.
std::optional<Scene> loadScene(const std::string& path, Diagnostics& diags, const LoadOptions& options = {});

// The same for text in memory; `name` is the file name used in diagnostics
// (its extension picks the dialect unless options name one) and `baseDir` the
// folder #include resolves against first.
std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const LoadOptions& options, const std::string& baseDir = ".");

// The .drt dialect, whatever the file name.
std::optional<Scene> loadSceneFile(const std::string& path, Diagnostics& diags);
std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const std::string& baseDir = ".");

} // namespace drt

// The POV-Ray 3.7 front end: .pov scene text -> scene model (scene/scene.h).
// POV-Ray's scene description language is a macro language evaluated while it
// is parsed, so this front end is an evaluator, separate from src/lang. The
// supported subset, the mappings and the approximations are in docs/pov.md.
#pragma once

#include "core/diagnostics.h"
#include "scene/frame_clock.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace drt {

struct PovOptions {
    // Folders searched by #include after the including file's own folder, in
    // order (POV-Ray's +L / Library_Path). When empty, the default is the
    // scene's folder then /usr/share/povray-3.7/include.
    std::vector<std::string> includePaths;
    // Warnings (unsupported features, approximations) become errors.
    bool strict = false;
    // image_width / image_height seen by the scene, and the image size stored
    // in Scene::render.
    int imageWidth = 320;
    int imageHeight = 240;
    // What `clock`, `frame_number` and the other animation identifiers read.
    FrameClock frame;
};

// The folder of Debian's povray-includes package, the last default include path.
inline constexpr const char* kPovStandardIncludeDir = "/usr/share/povray-3.7/include";

// Reads and evaluates a .pov file. Every problem is reported to `diags`
// (file:line:col, with the include chain); returns a scene only if there were
// no errors.
std::optional<Scene> loadPovSceneFile(const std::string& path, Diagnostics& diags, const PovOptions& options = {});

// The same for text in memory; `name` is the file name used in diagnostics and
// `baseDir` the folder searched first by #include.
std::optional<Scene> loadPovSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                      const PovOptions& options = {}, const std::string& baseDir = ".");

} // namespace drt

// The .drt front end: scene text -> scene model.
#pragma once

#include "core/diagnostics.h"
#include "scene/frame_clock.h"
#include "scene/scene.h"

#include <optional>
#include <string>

namespace drt {

// Reads and parses a .drt file (resolving #include relative to the including
// file). Every problem is reported to `diags`; returns a scene only if there
// were no errors.
// `frame` is what the animation identifiers (`clock`, `frame_number`, ...) read.
std::optional<Scene> loadSceneFile(const std::string& path, Diagnostics& diags, const FrameClock& frame = {});

// The same for text in memory; `name` is the file name used in diagnostics and
// `baseDir` the folder #include resolves against.
std::optional<Scene> loadSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                   const std::string& baseDir = ".", const FrameClock& frame = {});

} // namespace drt

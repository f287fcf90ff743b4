// POV-Ray scenes: the front end (lang/load.h) in the POV-Ray dialect whatever
// the file name. The supported subset, the mappings and the approximations
// are in docs/pov.md.
#pragma once

#include "lang/load.h"

namespace drt {

// The options of a POV-Ray scene are the front end's (include path, strict,
// image size, clock, geometry).
using PovOptions = LoadOptions;

// Reads and evaluates a .pov file. Every problem is reported to `diags`
// (file:line:col, with the include chain); returns a scene only if there were
// no errors.
std::optional<Scene> loadPovSceneFile(const std::string& path, Diagnostics& diags, const PovOptions& options = {});

// The same for text in memory; `name` is the file name used in diagnostics and
// `baseDir` the folder searched first by #include.
std::optional<Scene> loadPovSceneText(const std::string& text, const std::string& name, Diagnostics& diags,
                                      const PovOptions& options = {}, const std::string& baseDir = ".");

} // namespace drt

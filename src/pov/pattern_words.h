// Pattern keywords of POV-Ray's SDL, shared by pigments and textures (textures.cpp).
#pragma once

#include "scene/scene.h"

#include <optional>
#include <set>
#include <string>

namespace drt::pov {

// Every POV-Ray pattern word drt reads but approximates or does not have.
const std::set<std::string>& noisePatterns();
// The noise patterns the scene model has (render/noise.h).
std::optional<PatternKind> noiseKind(const std::string& w);
// Pattern modifiers drt ignores, with a warning.
const std::set<std::string>& ignoredPatternModifiers();

} // namespace drt::pov

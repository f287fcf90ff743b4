// The .drt writer: scene model -> readable .drt text that loads back into the
// same scene model (the inverse of load.h). `drt convert` uses it to turn a
// POV-Ray scene into a .drt file; tests/writer_test.cpp checks the round trip.
//
// Numbers are written in their shortest form that reads back to the same
// double. Transforms are written as translate / rotate / scale when that
// sequence, composed as the parser composes it, gives back the same matrix
// (and inverse); otherwise as one `matrix`. Unions are written flattened into
// their members, as the .drt parser stores them anyway.
#pragma once

#include "core/diagnostics.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace drt {

struct WriterOptions {
    // Shown in the header comment ("converted from ..."); "" for none.
    std::string sourceName;
    // When set, each object and light gets a comment naming its source
    // location (file:line) in the original scene.
    const SourceFiles* sourceFiles = nullptr;
};

std::string writeDrtScene(const Scene& scene, const WriterOptions& options = {});

// What the .drt language cannot express in this scene, one line per kind
// (e.g. "difference (CSG) is written with POV-Ray syntax the .drt parser does
// not accept"). Empty when the written file is equivalent to the scene.
std::vector<std::string> drtInexpressible(const Scene& scene);

} // namespace drt

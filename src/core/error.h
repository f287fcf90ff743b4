// The error type of the stages after the front end: anything that goes wrong
// while resolving a scene's files, building the accelerator or rendering
// (e.g. an Embree error, an image size out of range). Front-end problems are
// located diagnostics instead (core/diagnostics.h).
#pragma once

#include <stdexcept>

namespace drt {

class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace drt

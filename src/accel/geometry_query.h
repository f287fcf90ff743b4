// The geometry a scene may ask about while it is read (POV-Ray's trace() and
// inside(), scene/geometry_query.h), answered with drt's own intersection code.
// The loader passes it to the front end, which never includes the accelerator.
#pragma once

#include "scene/geometry_query.h"

#include <memory>

namespace drt {

std::unique_ptr<SceneGeometryQuery> makeGeometryQuery();

} // namespace drt

// Gives the function evaluator (scene/function.h) the renderer's noise and
// pattern code. Runs when the program starts (render/pigment.cpp links it in);
// calling it again does nothing.
#pragma once

#include "scene/function.h"

namespace drt {

bool installFunctionHooks();

} // namespace drt

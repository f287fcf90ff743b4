// What an animated scene sees of its frame: POV-Ray's clock identifiers, the
// same in the .drt and POV-Ray dialects.
//
//   clock          the frame's clock value (initial_clock .. final_clock)
//   clock_delta    the clock's step from one frame to the next (1 for a still image)
//   clock_on       1 while rendering an animation, else 0
//   frame_number   the frame's number (initial_frame .. final_frame; 0 for a still image)
//   initial_frame, final_frame, initial_clock, final_clock   the animation's range
//
// Within a frame, scene time t in [0, 1] (scene/motion.h) is clock + t * clock_delta:
// with the camera's shutter open, a scene whose text reads `clock` is evaluated
// again at clock values over the shutter to find how it moves (docs/effects.md).
#pragma once

#include <optional>
#include <string>

namespace drt {

struct FrameClock {
    double clock = 0;
    double clockDelta = 1;
    bool clockOn = false;
    int frameNumber = 0;
    int initialFrame = 1;
    int finalFrame = 1;
    double initialClock = 0;
    double finalClock = 1;
};

// The value of a clock identifier (the names above), or nothing for any other name.
std::optional<double> frameClockValue(const FrameClock& frame, const std::string& name);

} // namespace drt

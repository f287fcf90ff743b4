#include "scene/frame_clock.h"

namespace drt {

std::optional<double> frameClockValue(const FrameClock& frame, const std::string& name) {
    if (name == "clock") return frame.clock;
    if (name == "clock_delta") return frame.clockDelta;
    if (name == "clock_on") return frame.clockOn ? 1.0 : 0.0;
    if (name == "frame_number") return double(frame.frameNumber);
    if (name == "initial_frame") return double(frame.initialFrame);
    if (name == "final_frame") return double(frame.finalFrame);
    if (name == "initial_clock") return frame.initialClock;
    if (name == "final_clock") return frame.finalClock;
    return std::nullopt;
}

} // namespace drt

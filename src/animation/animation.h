// Animation: frames over a clock range, each rendered on its own, and motion
// blur from a scene's own clock dependence.
//
// Frames: POV-Ray's animation options. Frame f of initial_frame..final_frame
// sees
//   clock = initial_clock + (final_clock - initial_clock) (f - initial_frame) / n,
//   n = final_frame - initial_frame (final_frame - initial_frame + 1 with
//   Cyclic_Animation, so the last frame stops one step short of final_clock),
//   clock_delta = (final_clock - initial_clock) / n,
// and only subset_start..subset_end of them are rendered. A frame shares
// nothing with the others but the scene text: it is evaluated, moved and
// rendered alone, so it is bit-identical to rendering that frame by itself.
//
// Motion from the clock: scene time t in [0, 1] of a frame is the clock
// clock + t clock_delta (scene/frame_clock.h). When the camera's shutter is
// open and the scene's text read `clock`, the scene is evaluated again at
// clock values spread over the shutter (3, then 5, 9, 17 or 33, until the
// midpoints agree with the path through the others: clock_motion.cpp) and the
// evaluations are merged: the frame's objects, lights and camera become the
// ones evaluated at the shutter's opening, moving along the paths the others
// trace. Objects and lights are paired by identity: the place in the scene
// text where they were made, and their order among those made there.
#pragma once

#include "core/diagnostics.h"
#include "render/render.h"
#include "scene/frame_clock.h"
#include "scene/scene.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace drt {

struct Animation {
    int initialFrame = 1;
    int finalFrame = 1;
    double initialClock = 0;
    double finalClock = 1;
    std::optional<int> subsetStart; // POV-Ray's Subset_Start_Frame / Subset_End_Frame
    std::optional<int> subsetEnd;
    bool cyclic = false; // Cyclic_Animation
};

// The clock frame `frame` sees (clock_on set).
FrameClock frameClockOf(const Animation& animation, int frame);
// The frames rendered: initial..final narrowed to the subset.
int firstRenderedFrame(const Animation& animation);
int lastRenderedFrame(const Animation& animation);
// An error message for an animation that cannot be rendered (final before
// initial, an empty subset, non-finite clocks), or empty.
std::string animationProblem(const Animation& animation);

// The output file of one frame: a printf-style pattern (`out_%04d.png`, `%d`)
// takes the frame number; otherwise, as POV-Ray, the number is put before the
// extension, zero-padded to the digits of the final frame.
std::string frameFileName(const std::string& pattern, int frame, int finalFrame);
// True if the pattern holds one integer conversion (%d, %0Nd) and no other.
bool isFramePattern(const std::string& pattern);

// Evaluates the scene text as seen at one frame clock (front end, then the
// files the scene names); reports to `diagnostics`, returns nothing on error.
using SceneEvaluator = std::function<std::optional<Scene>(const FrameClock& frame, Diagnostics& diagnostics)>;

struct FrameOptions {
    // Overrides the camera's shutter: open at the frame's clock, close after
    // this fraction of the frame interval (0: no motion blur).
    std::optional<double> shutter;
};

// What evaluateFrame did, for the command line's report.
struct FrameReport {
    int evaluations = 1;           // the scene was evaluated this many times
    int objectsFromClock = 0;      // objects given a path from the clock
    int lightsFromClock = 0;
    bool cameraFromClock = false;
    std::vector<std::string> unpaired; // what could not be paired (held still), "line:column: why"
};

// The scene of one frame, moving over its shutter (see above). Problems in
// evaluations other than the first are reported as errors too.
std::optional<Scene> evaluateFrame(const SceneEvaluator& evaluate, const FrameClock& frame,
                                   const FrameOptions& options, Diagnostics& diagnostics,
                                   FrameReport* report = nullptr);

// Frame `frame` of an animation, rendered: evaluateFrame, then the scene's
// settings overlaid by `overrides` (scene/scene.h overlaySettings), then
// render(). Throws RenderError; returns nothing (with `diagnostics` filled)
// when the scene has errors. For callers that render frames elsewhere (one
// rank per frame range): each frame needs only the evaluator and this call.
std::optional<RenderResult> renderFrame(const SceneEvaluator& evaluate, const Animation& animation, int frame,
                                        const FrameOptions& options, const RenderSettings& overrides,
                                        Diagnostics& diagnostics, FrameReport* report = nullptr);

} // namespace drt

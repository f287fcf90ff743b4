#include "animation/animation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace drt {

FrameClock frameClockOf(const Animation& a, int frame) {
    FrameClock f;
    f.clockOn = true;
    f.frameNumber = frame;
    f.initialFrame = a.initialFrame;
    f.finalFrame = a.finalFrame;
    f.initialClock = a.initialClock;
    f.finalClock = a.finalClock;
    const int steps = a.finalFrame - a.initialFrame + (a.cyclic ? 1 : 0);
    if (steps <= 0) {
        f.clock = a.initialClock;
        f.clockDelta = 1;
        return f;
    }
    // The same arithmetic for every frame, so a frame's clock does not depend
    // on how the range was split.
    f.clock = a.initialClock + (a.finalClock - a.initialClock) * double(frame - a.initialFrame) / double(steps);
    f.clockDelta = (a.finalClock - a.initialClock) / double(steps);
    return f;
}

int firstRenderedFrame(const Animation& a) { return std::max(a.initialFrame, a.subsetStart.value_or(a.initialFrame)); }
int lastRenderedFrame(const Animation& a) { return std::min(a.finalFrame, a.subsetEnd.value_or(a.finalFrame)); }

std::string animationProblem(const Animation& a) {
    if (a.finalFrame < a.initialFrame)
        return "the final frame (" + std::to_string(a.finalFrame) + ") is before the initial frame (" +
               std::to_string(a.initialFrame) + ")";
    if (!std::isfinite(a.initialClock) || !std::isfinite(a.finalClock)) return "the clock range must be finite";
    if (firstRenderedFrame(a) > lastRenderedFrame(a))
        return "the subset of frames " + std::to_string(a.subsetStart.value_or(a.initialFrame)) + ".." +
               std::to_string(a.subsetEnd.value_or(a.finalFrame)) + " holds no frame of " +
               std::to_string(a.initialFrame) + ".." + std::to_string(a.finalFrame);
    return "";
}

namespace {

// The position and length of the one integer conversion in a pattern, if any.
bool findConversion(const std::string& pattern, size_t& start, size_t& length) {
    int found = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        size_t j = i + 1;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
        if (j >= pattern.size() || pattern[j] != 'd') return false;
        if (j - i - 1 > 2) return false; // a width of at most 99
        start = i;
        length = j - i + 1;
        ++found;
        i = j;
    }
    return found == 1;
}

} // namespace

bool isFramePattern(const std::string& pattern) {
    size_t start = 0, length = 0;
    return findConversion(pattern, start, length);
}

std::string frameFileName(const std::string& pattern, int frame, int finalFrame) {
    size_t start = 0, length = 0;
    std::string out;
    if (findConversion(pattern, start, length)) {
        char number[128];
        std::snprintf(number, sizeof number, pattern.substr(start, length).c_str(), frame);
        out = pattern.substr(0, start) + number + pattern.substr(start + length);
        // %% stands for one %.
        std::string unescaped;
        for (size_t i = 0; i < out.size(); ++i) {
            unescaped += out[i];
            if (out[i] == '%' && i + 1 < out.size() && out[i + 1] == '%') ++i;
        }
        return unescaped;
    }
    const int digits = static_cast<int>(std::to_string(std::max(std::abs(finalFrame), std::abs(frame))).size());
    char number[64];
    std::snprintf(number, sizeof number, "%0*d", digits, frame);
    const size_t slash = pattern.find_last_of('/');
    const size_t dot = pattern.find_last_of('.');
    const size_t at = dot != std::string::npos && (slash == std::string::npos || dot > slash) ? dot : pattern.size();
    return pattern.substr(0, at) + number + pattern.substr(at);
}

std::optional<RenderResult> renderFrame(const SceneEvaluator& evaluate, const Animation& animation, int frame,
                                        const FrameOptions& options, const RenderSettings& overrides,
                                        Diagnostics& diagnostics, FrameReport* report) {
    const std::optional<Scene> scene = evaluateFrame(evaluate, frameClockOf(animation, frame), options, diagnostics, report);
    if (!scene || diagnostics.hasErrors()) return std::nullopt;
    return render(*scene, resolveRenderOptions(overlaySettings(scene->render, overrides)));
}

} // namespace drt

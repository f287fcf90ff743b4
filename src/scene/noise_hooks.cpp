#include "scene/noise_hooks.h"

#include <mutex>

namespace drt {

namespace {
std::mutex gMutex;
NoiseHooks gHooks;
} // namespace

void setNoiseHooks(const NoiseHooks& hooks) {
    const std::lock_guard<std::mutex> lock(gMutex);
    gHooks = hooks;
}

NoiseHooks noiseHooks() {
    const std::lock_guard<std::mutex> lock(gMutex);
    return gHooks;
}

} // namespace drt

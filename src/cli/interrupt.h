// SIGINT and SIGTERM while drt renders: the first asks the render to stop
// (it saves the finished tiles and a checkpoint), the second ends the process
// at once, removing the temporary files being written (core/temporary_files.h)
// so that no half-written file is left.
#pragma once

#include <atomic>

namespace drt::cli {

// Installs the handlers for its lifetime (one at a time), restoring the previous ones after.
class InterruptHandler {
public:
    InterruptHandler();
    ~InterruptHandler();
    InterruptHandler(const InterruptHandler&) = delete;
    InterruptHandler& operator=(const InterruptHandler&) = delete;

    // Set by the first signal.
    const std::atomic<bool>* flag() const;
    bool interrupted() const { return flag()->load(); }
    // The first signal's number, 0 if none came.
    int signal() const;
    // The exit status that says so: 128 + the signal (130 for SIGINT, 143 for SIGTERM).
    int exitStatus() const { return 128 + signal(); }

    // While one lives, nothing is rendered yet (the scene is read, the
    // accelerator built: minutes for a scene that traces at parse time), so
    // the first signal quits at once instead of waiting for tiles to save.
    class NothingToSave {
    public:
        NothingToSave();
        ~NothingToSave();
        NothingToSave(const NothingToSave&) = delete;
        NothingToSave& operator=(const NothingToSave&) = delete;
    };
};

} // namespace drt::cli

// Per-thread scratch buffers (the vectors a ray query or a shading point
// reuses so that it allocates nothing once warm), without thread_local
// destructors in render threads.
//
// Why: a thread_local with a destructor registers it on its first use in each
// thread (__cxa_thread_atexit), and glibc takes the dynamic loader's lock to
// do so, the lock dlopen holds for its whole load. A render loads the image
// module in the background once its first tile is done (about half a second
// of symbol binding), so a render thread that first shaded a point, crossed a
// CSG or walked a texture's layers during that load waited for all of it: on
// `camera/focalblur.pov`, whose first tiles are sky, every render thread did.
//
// So a render thread installs its buffers for the render's length
// (InstalledScratch, made by each file's installer and gathered by
// Integrator::installThreadBuffers); they are plain heap objects found through a
// thread_local pointer, which has no destructor to register. A thread that
// installed none (a test, the front end's trace()) gets a thread_local of its
// own, as before.
#pragma once

#include <memory>
#include <vector>

namespace drt {

// One file's buffers installed for the calling thread while this lives.
class InstalledScratch {
public:
    virtual ~InstalledScratch() = default;
};

// Several files' buffers installed together. Each restores only its own
// type's pointer, so the order they are uninstalled in does not matter.
using InstalledScratchSet = std::vector<std::unique_ptr<InstalledScratch>>;

template <class T> class ThreadScratch {
public:
    // The calling thread's buffers: the installed ones, else its own.
    static T& get() {
        if (T* installed = installed_) return *installed;
        thread_local T own; // registers a destructor: never in a render thread
        return own;
    }

    // Installs fresh buffers for the calling thread until the result is
    // destroyed (on the same thread), then restores what was there.
    static std::unique_ptr<InstalledScratch> install() { return std::make_unique<Installed>(); }

private:
    struct Installed final : InstalledScratch {
        Installed() : previous(installed_) { installed_ = &buffers; }
        ~Installed() override { installed_ = previous; }
        T buffers;
        T* previous;
    };
    // A pointer: constant-initialised, nothing to destroy, nothing registered.
    static inline thread_local T* installed_ = nullptr;
};

} // namespace drt

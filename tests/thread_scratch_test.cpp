// Render threads and the dynamic loader's lock (accel/thread_scratch.h). drt
// loads its image module in the background while a render runs, and dlopen
// holds the loader's lock for the whole load; a render thread that registered
// a thread_local's destructor then (its first CSG, shading point, layered
// texture or medium) waited for all of it. These tests hold the lock with a
// module whose constructor blocks (tests/support/loader_gate_module.cpp) and
// render on fresh threads meanwhile.
#include "accel/thread_scratch.h"
#include "lang/load.h"
#include "render/render.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <fmt/format.h>
#include <poll.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace drt {
namespace {

using namespace std::chrono_literals;

// A bound for waits that only keeps a failing run from hanging.
constexpr auto kPatience = 120s;

std::string gateModulePath() {
    return (fs::read_symlink("/proc/self/exe").parent_path() / "libdrt_test_loader_gate.so").string();
}

// While alive (until release()), another thread is inside dlopen, in the
// gate module's constructor: the dynamic loader's lock is held.
class LoaderLockHeld {
public:
    LoaderLockHeld() {
        if (!fs::exists(gateModulePath()) || pipe(entered_) != 0 || pipe(release_) != 0) return;
        setenv("DRT_TEST_LOADER_GATE_FDS", fmt::format("{},{}", entered_[1], release_[0]).c_str(), 1);
        loader_ = std::thread([this] { handle_ = dlopen(gateModulePath().c_str(), RTLD_NOW | RTLD_LOCAL); });
        pollfd entered{entered_[0], POLLIN, 0};
        char byte = 0;
        held_ = poll(&entered, 1, int(std::chrono::milliseconds(kPatience).count())) == 1 &&
                read(entered_[0], &byte, 1) == 1;
    }
    ~LoaderLockHeld() {
        release();
        if (handle_) dlclose(handle_);
        unsetenv("DRT_TEST_LOADER_GATE_FDS");
        for (int fd : {entered_[0], entered_[1], release_[0], release_[1]})
            if (fd >= 0) close(fd);
    }
    bool held() const { return held_; }
    void release() {
        if (!loader_.joinable()) return;
        const char byte = 1;
        while (write(release_[1], &byte, 1) < 0 && errno == EINTR) {
        }
        loader_.join();
    }

private:
    int entered_[2] = {-1, -1}, release_[2] = {-1, -1};
    std::thread loader_;
    void* handle_ = nullptr;
    bool held_ = false;
};

// Runs `work` on a fresh thread while the loader's lock is held; true if it
// finished before the lock was released (after `patience` at most).
template <class Work>
bool finishesWhileTheLoaderLockIsHeld(Work work, std::chrono::milliseconds patience = kPatience) {
    LoaderLockHeld lock;
    EXPECT_TRUE(lock.held()) << "the gate module " << gateModulePath() << " did not take the loader's lock";
    if (!lock.held()) return false;
    std::atomic<bool> done{false};
    std::thread worker([&] {
        work();
        done = true;
    });
    const auto deadline = std::chrono::steady_clock::now() + patience;
    while (!done && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(5ms);
    const bool finished = done;
    lock.release();
    worker.join();
    return finished;
}

// The gate works: a thread_local with a destructor, first used on a fresh
// thread, waits for the lock (what render threads did before), here for as
// long as the test holds it.
TEST(ThreadScratch, AThreadLocalsFirstUseWaitsForTheLoaderLock) {
    struct Counted {
        std::vector<int> values;
    };
    EXPECT_FALSE(finishesWhileTheLoaderLockIsHeld(
        [] {
            thread_local Counted counted;
            counted.values.push_back(1);
        },
        2s));
}

// The buffers found through ThreadScratch: the installed ones while installed,
// the thread's own otherwise, and installations nest.
TEST(ThreadScratch, InstalledBuffersAreFoundUntilUninstalled) {
    struct Buffers {
        std::vector<int> values;
    };
    std::thread([] {
        Buffers& own = ThreadScratch<Buffers>::get();
        {
            const auto outer = ThreadScratch<Buffers>::install();
            Buffers& installed = ThreadScratch<Buffers>::get();
            EXPECT_NE(&installed, &own);
            {
                const auto inner = ThreadScratch<Buffers>::install();
                EXPECT_NE(&ThreadScratch<Buffers>::get(), &installed);
            }
            EXPECT_EQ(&ThreadScratch<Buffers>::get(), &installed);
        }
        EXPECT_EQ(&ThreadScratch<Buffers>::get(), &own);
    }).join();
}

// Every buffer a render uses: CSG and listed crossings (blob, lathe, sor,
// prism, text, polynomials), media, layered textures, area lights' shadow
// rays, glossy and translucent rays, motion blur.
TEST(ThreadScratch, ARenderOnAFreshThreadDoesNotWaitForTheLoaderLock) {
    std::vector<Scene> scenes;
    for (const char* name : {"blob", "lathe_and_sor", "text_and_prism", "algebraic_surfaces", "media",
                             "layered_textures", "soft_shadows", "cook", "clipped_by"}) {
        Diagnostics diagnostics;
        std::optional<Scene> scene = loadSceneFile(test::sourcePath(fmt::format("examples/{}.drt", name)), diagnostics);
        ASSERT_TRUE(scene && !diagnostics.hasErrors()) << name << ": " << diagnostics.formatAll();
        scenes.push_back(test::withAssets(std::move(*scene)));
    }
    uint64_t rays = 0;
    const auto renderAll = [&] {
        for (const Scene& scene : scenes) {
            RenderOptions options = resolveRenderOptions(scene.render);
            options.width = 24;
            options.height = 18;
            options.samplesPerPixel = 2;
            options.threads = 1; // the calling thread renders
            const RenderResult result = render(scene, options);
            rays += result.stats.cameraRays + result.stats.shadowRays + result.stats.secondaryRays;
        }
    };
    // Once per process, Embree's first device starts TBB, which dlopens a
    // library: done here first, as a render has done by its first finished
    // tile, when drt starts loading its module.
    std::thread(renderAll).join();
    EXPECT_TRUE(finishesWhileTheLoaderLockIsHeld(renderAll)) << "a render thread waited for the dynamic loader's lock";
    EXPECT_GT(rays, 0u);
}

} // namespace
} // namespace drt

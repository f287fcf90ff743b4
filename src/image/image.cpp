// The image I/O entry points. Every image goes through OpenImageIO, in the
// module libdrt_oiio.so (image/oiio/), loaded once, on the first call
// (image/image_io_module.h says why); the file handling around it stays here:
// writes go to a temporary file (registered for removal on a signal) renamed
// over the real one when complete. The module is $DRT_OIIO_MODULE if that is
// set (and then nothing else is tried); else it is looked for beside the
// executable, in ../lib/drt beside it (an installed drt), and in the build
// tree it was built in.
#include "image/image.h"
#include "image/image_io_module.h"
#include "image/image_process.h"

#include "core/limits.h"
#include "core/modules.h"
#include "core/temporary_files.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <mutex>
#include <condition_variable>
#include <thread>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace drt {

namespace {

// The build tree's path comes from CMake (DRT_OIIO_MODULE_BUILD_PATH).
constexpr ModuleSpec kImageIoSpec{kImageIoModuleFile, kImageIoModuleSymbol, "DRT_OIIO_MODULE",
                                  DRT_OIIO_MODULE_BUILD_PATH, "drt's OpenImageIO module"};

} // namespace

const LoadedModule<ImageIoModule>& imageIoInThisProcess() {
    return moduleOnce<ImageIoModule>(kImageIoSpec, kImageIoModuleVersion);
}

namespace {

// The module: in the image process if one was started (image/image_process.h),
// else in this one.
const LoadedModule<ImageIoModule>& imageIo() {
    if (const LoadedModule<ImageIoModule>* remote = imageIoProcessModule()) return *remote;
    return imageIoInThisProcess();
}

// The background load of loadImageIoInBackground(), joined when the process ends.
struct BackgroundLoad {
    std::thread thread;
    ~BackgroundLoad() {
        if (thread.joinable()) thread.join();
    }
};

// Whether a background load runs, for imageIoLoading and waitForImageIoLoad.
struct LoadProgress {
    std::mutex mutex;
    std::condition_variable ended;
    std::atomic<bool> running{false};
};
LoadProgress& loadProgress() {
    static LoadProgress progress;
    return progress;
}

// Formats that every OpenImageIO build writes (its core plugins): an output
// with one of these extensions is accepted without asking the module, which
// may still be loading. Any other extension is asked of the module.
bool coreFormat(const std::string& extension) {
    static const char* const kCore[] = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr", ".hdr"};
    for (const char* core : kCore)
        if (extension == core) return true;
    return false;
}

// A name for the temporary file beside `path`, unique within this machine
// (pid) and this process (counter). It keeps no extension: the writer is
// chosen from the real path.
fs::path temporaryPath(const fs::path& path) {
    static std::atomic<unsigned> counter{0};
    return path.parent_path() / fmt::format(".{}.tmp-{}-{}", path.filename().string(), ::getpid(), counter++);
}

fs::path folderOf(const std::string& path) {
    fs::path folder = fs::path(path).parent_path();
    return folder.empty() ? fs::path(".") : folder;
}

} // namespace

std::string checkWritable(const std::string& path) {
    if (path.empty())
        return "no output file given";
    if (fs::path(path).filename().empty())
        return "'" + path + "' names a folder, not a file";
    if (coreFormat(lowerExtension(path))) {
        // Whether the module loads is known only once it has; a missing file is known now.
        if (std::string missing = moduleFilesMissing(kImageIoSpec); !missing.empty()) return missing;
    } else {
        const LoadedModule<ImageIoModule>& io = imageIo();
        if (!io.table)
            return io.error;
        if (!io.table->hasWriter(path))
            return "cannot write '" + path + "': unknown image format '" + lowerExtension(path) +
                   "' (use .png, .jpg, .tif, .exr or .hdr)";
    }
    const fs::path folder = folderOf(path);
    std::error_code ec;
    if (!fs::exists(folder, ec))
        return "cannot write '" + path + "': folder '" + folder.string() + "' does not exist";
    if (!fs::is_directory(folder, ec))
        return "cannot write '" + path + "': '" + folder.string() + "' is not a folder";
    if (fs::is_directory(path, ec))
        return "cannot write '" + path + "': it is a folder";
    // access() is not enough (root passes it everywhere, read-only mounts do
    // not show in the mode bits): create and remove a probe file instead.
    const fs::path probe = temporaryPath(fs::path(path));
    const TemporaryFile registered(probe.string()); // removed if a signal ends the process
    {
        std::ofstream out(probe, std::ios::binary);
        if (!out) {
            const int error = errno;
            return "cannot write '" + path + "': " + std::strerror(error != 0 ? error : EACCES);
        }
    }
    fs::remove(probe, ec);
    return "";
}

void loadImageIoInBackground() {
    if (imageIoProcessStarted()) return; // it loads there, begun when it started
    static BackgroundLoad background;
    static std::once_flag once;
    std::call_once(once, [] {
        LoadProgress& progress = loadProgress();
        progress.running = true;
        background.thread = std::thread([&progress] {
            imageIo();
            {
                const std::lock_guard<std::mutex> lock(progress.mutex);
                progress.running = false;
            }
            progress.ended.notify_all();
        });
    });
}

bool imageIoLoading() { return imageIoProcessStarted() ? imageIoProcessLoading() : loadProgress().running.load(); }

void waitForImageIoLoad() {
    if (imageIoProcessModule()) return; // waited for the image process's load
    LoadProgress& progress = loadProgress();
    std::unique_lock<std::mutex> lock(progress.mutex);
    progress.ended.wait(lock, [&progress] { return !progress.running.load(); });
}

std::string writeImage(const std::string& path, const Image& image, const Metadata& metadata) {
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0 ||
        image.pixels.size() != size_t(image.width) * image.height * image.channels)
        return "cannot write '" + path + "': the image is empty or malformed";
    const LoadedModule<ImageIoModule>& io = imageIo();
    if (!io.table)
        return io.error;
    if (!io.table->hasWriter(path))
        return "cannot write '" + path + "': unknown image format '" + lowerExtension(path) + "'";
    const fs::path temporary = temporaryPath(fs::path(path));
    const TemporaryFile registered(temporary.string()); // removed if a signal ends the process
    std::error_code ec;
    auto fail = [&](const std::string& reason) {
        fs::remove(temporary, ec);
        return "cannot write '" + path + "': " + reason;
    };
    if (std::string problem = io.table->writeFile(temporary.string(), path, image, metadata);
        !problem.empty())
        return fail(problem);
    fs::rename(temporary, path, ec);
    if (ec)
        return fail(ec.message());
    return "";
}

namespace {

ReadBudget readBudget() {
    const Limits& limits = defaultLimits();
    return {uint64_t(limits.imageMemoryMB), limitHint(limits, &Limits::imageMemoryMB)};
}

} // namespace

std::string readImage(const std::string& path, Image& image, Metadata* metadata) {
    const LoadedModule<ImageIoModule>& io = imageIo();
    return io.table ? io.table->readImage(path, image, metadata, readBudget()) : io.error;
}

std::string readImageEncoded(const std::string& path, Image& image, ImageFileInfo& info) {
    const LoadedModule<ImageIoModule>& io = imageIo();
    return io.table ? io.table->readImageEncoded(path, image, info, readBudget()) : io.error;
}

} // namespace drt

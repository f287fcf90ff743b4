// The image I/O entry points: each forwards to the OpenImageIO module,
// loaded once, on the first call (image/image_io_module.h says why). The
// module is $DRT_OIIO_MODULE if that is set (and then nothing else is tried);
// else it is looked for beside the executable, in ../lib/drt beside it (an
// installed drt), and in the build tree it was built in.
#include "image/image.h"
#include "image/image_io_module.h"

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <vector>

namespace fs = std::filesystem;

namespace drt {

namespace {

struct LoadedModule {
    const ImageIoModule* module = nullptr;
    std::string error; // why there is none
};

std::vector<std::string> moduleCandidates() {
    if (const char* given = std::getenv("DRT_OIIO_MODULE"); given && *given)
        return {given};
    std::vector<std::string> candidates;
    std::error_code ec;
    const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back((executable.parent_path() / kImageIoModuleFile).string());
        candidates.push_back(
            (executable.parent_path().parent_path() / "lib" / "drt" / kImageIoModuleFile).string());
    }
#ifdef DRT_OIIO_MODULE_BUILD_PATH
    candidates.push_back(DRT_OIIO_MODULE_BUILD_PATH);
#endif
    return candidates;
}

LoadedModule load() {
    LoadedModule loaded;
    std::string tried;
    for (const std::string& path : moduleCandidates()) {
        std::error_code ec;
        if (!fs::exists(path, ec)) {
            tried += "\n  " + path + ": no such file";
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            tried += "\n  " + path + ": " + (why ? why : "cannot be loaded");
            continue;
        }
        using Entry = const ImageIoModule* (*)();
        const auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageIoModuleSymbol));
        const ImageIoModule* module = entry ? entry() : nullptr;
        if (!module || module->version != kImageIoModuleVersion) {
            tried += "\n  " + path + ": not a module of this drt build";
            dlclose(handle);
            continue;
        }
        loaded.module = module; // stays loaded until the process ends
        return loaded;
    }
    loaded.error = std::string("cannot load drt's OpenImageIO module ") + kImageIoModuleFile + ":" + tried;
    return loaded;
}

const LoadedModule& imageIo() {
    static const LoadedModule loaded = load(); // thread-safe, once
    return loaded;
}

} // namespace

std::string checkWritable(const std::string& path) {
    const LoadedModule& io = imageIo();
    return io.module ? io.module->checkWritable(path) : io.error;
}

std::string writeImage(const std::string& path, const Image& image, const Metadata& metadata) {
    const LoadedModule& io = imageIo();
    return io.module ? io.module->writeImage(path, image, metadata) : io.error;
}

std::string readImage(const std::string& path, Image& image, Metadata* metadata) {
    const LoadedModule& io = imageIo();
    return io.module ? io.module->readImage(path, image, metadata) : io.error;
}

std::string readImageEncoded(const std::string& path, Image& image, ImageFileInfo& info) {
    const LoadedModule& io = imageIo();
    return io.module ? io.module->readImageEncoded(path, image, info) : io.error;
}

} // namespace drt

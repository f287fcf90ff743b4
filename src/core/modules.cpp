#include "core/modules.h"

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace drt {

namespace {

// Where the module is looked for (core/modules.h), in order.
std::vector<std::string> moduleCandidates(const ModuleSpec& spec) {
    if (const char* given = std::getenv(spec.environment); given && *given) return {given};
    std::vector<std::string> candidates;
    std::error_code ec;
    const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back((executable.parent_path() / spec.file).string());
        candidates.push_back((executable.parent_path().parent_path() / "lib" / "drt" / spec.file).string());
    }
    if (spec.buildPath && *spec.buildPath) candidates.push_back(spec.buildPath);
    return candidates;
}

std::string cannotLoad(const ModuleSpec& spec, const std::string& tried) {
    return std::string("cannot load ") + spec.description + " " + spec.file + ":" + tried;
}

} // namespace

std::string moduleFilesMissing(const ModuleSpec& spec) {
    std::string listed;
    for (const std::string& path : moduleCandidates(spec)) {
        std::error_code ec;
        if (fs::exists(path, ec)) return "";
        listed += "\n  " + path + ": no such file";
    }
    return cannotLoad(spec, listed);
}

const void* loadModule(const ModuleSpec& spec, int version, const void* (*call)(void* entry), std::string& error) {
    std::string tried;
    for (const std::string& path : moduleCandidates(spec)) {
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
        void* const entry = dlsym(handle, spec.symbol);
        const void* table = entry ? call(entry) : nullptr;
        if (!table || *static_cast<const int*>(table) != version) {
            tried += "\n  " + path + ": not a module of this drt build";
            dlclose(handle);
            continue;
        }
        return table; // stays loaded until the process ends
    }
    error = cannotLoad(spec, tried);
    return nullptr;
}

} // namespace drt

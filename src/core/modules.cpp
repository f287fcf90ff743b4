#include "core/modules.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
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

// Preloading (core/modules.h): each library of `module`'s preload list
// loaded on its own, dependencies first. A line that does not load is
// skipped: the module's own dlopen loads that library as it always did.
void preloadLibraries(const std::string& module) {
    std::FILE* list = std::fopen((module + kPreloadSuffix).c_str(), "r");
    if (!list) return;
    char line[4096];
    while (std::fgets(line, sizeof line, list)) {
        line[std::strcspn(line, "\r\n")] = '\0';
        if (line[0] == '\0' || line[0] == '#' || std::strchr(line, '/')) continue; // sonames only
        dlopen(line, RTLD_NOW | RTLD_LOCAL); // stays loaded, as the module's libraries do
    }
    std::fclose(list);
    dlerror(); // a skipped library's reason is not the module's
}

std::string cannotLoad(const ModuleSpec& spec, const std::string& tried) {
    return std::string("cannot load ") + spec.description + " " + spec.file + ":" + tried;
}

} // namespace

std::string findModuleFile(const ModuleSpec& spec) {
    for (const std::string& path : moduleCandidates(spec)) {
        std::error_code ec;
        if (fs::is_regular_file(path, ec)) return path;
    }
    return "";
}

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
        preloadLibraries(path);
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

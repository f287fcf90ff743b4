// drt_module_preload MODULE OUTPUT: writes the order in which drt preloads a
// module's libraries (core/modules.h, "Preloading"), one soname a line,
// every library after all of its own dependencies.
//
// A build step, run once the module is linked. It loads MODULE with dlopen as
// drt does, so the libraries are the ones the dynamic loader really picks,
// then walks the loader's list of loaded objects and each one's DT_NEEDED
// entries from its dynamic section, and writes their dependency closure in
// post order (a depth-first walk from the module; MODULE itself left out).
// Exit status 0 and OUTPUT replaced whole, or non-zero with a message and
// OUTPUT untouched.
#include "image/oiio/loaded_library.h"

#include <cstdio>
#include <dlfcn.h>
#include <map>
#include <set>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s MODULE OUTPUT\n", argv[0]);
        return 2;
    }
    void* handle = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        std::fprintf(stderr, "%s: cannot load %s: %s\n", argv[0], argv[1], dlerror());
        return 1;
    }
    link_map* module = nullptr;
    if (dlinfo(handle, RTLD_DI_LINKMAP, &module) != 0 || !module) {
        std::fprintf(stderr, "%s: no link map for %s\n", argv[0], argv[1]);
        return 1;
    }
    // Every object of the namespace, found by soname and by file name.
    link_map* first = module;
    while (first->l_prev) first = first->l_prev;
    std::map<std::string, const link_map*> byName;
    std::map<const link_map*, drt::LoadedLibrary> described;
    for (const link_map* map = first; map; map = map->l_next) {
        if (!map->l_name || !*map->l_name) continue; // the executable, the vDSO
        const drt::LoadedLibrary& loaded = described[map] = drt::describeLoadedLibrary(map);
        byName.emplace(loaded.soname, map);
        byName.emplace(drt::fileNameOf(map->l_name), map);
    }
    // Post order from the module, iteratively (closures run to hundreds).
    std::vector<std::string> order;
    std::set<const link_map*> seen{module};
    struct Frame {
        const link_map* map;
        size_t next;
    };
    std::vector<Frame> stack{{module, 0}};
    while (!stack.empty()) {
        Frame& top = stack.back();
        const std::vector<std::string>& needed = described[top.map].needed;
        if (top.next < needed.size()) {
            const auto found = byName.find(needed[top.next++]);
            if (found != byName.end() && seen.insert(found->second).second) stack.push_back({found->second, 0});
            continue;
        }
        if (top.map != module) order.push_back(described[top.map].soname);
        stack.pop_back();
    }
    const std::string output = argv[2], temporary = output + ".tmp";
    std::FILE* file = std::fopen(temporary.c_str(), "w");
    if (!file) {
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], temporary.c_str());
        return 1;
    }
    bool written = true;
    for (const std::string& soname : order) written = written && std::fprintf(file, "%s\n", soname.c_str()) > 0;
    written = std::fclose(file) == 0 && written;
    if (!written || std::rename(temporary.c_str(), output.c_str()) != 0) {
        std::remove(temporary.c_str());
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], output.c_str());
        return 1;
    }
    return 0;
}

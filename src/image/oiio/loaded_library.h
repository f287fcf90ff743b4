// What a library the dynamic loader has loaded says of itself: its soname and
// the sonames it needs, read from its dynamic section in memory (for
// drt_module_preload, preload_order_main.cpp, and its test).
#pragma once

#include <cstring>
#include <elf.h>
#include <link.h>
#include <string>
#include <vector>

namespace drt {

struct LoadedLibrary {
    std::string soname;              // DT_SONAME, or the file name if it has none
    std::vector<std::string> needed; // DT_NEEDED, in order
};

inline std::string fileNameOf(const char* path) {
    const char* slash = std::strrchr(path, '/');
    return slash ? slash + 1 : path;
}

inline LoadedLibrary describeLoadedLibrary(const link_map* map) {
    // The loader keeps a loaded object's dynamic section with its addresses
    // relocated on most targets and unrelocated on a few: an address below
    // the object's load base is taken as relative to it.
    const auto address = [map](ElfW(Addr) value) {
        return reinterpret_cast<const char*>(value < map->l_addr ? map->l_addr + value : value);
    };
    LoadedLibrary library;
    library.soname = fileNameOf(map->l_name);
    const char* strings = nullptr;
    std::vector<ElfW(Xword)> needed;
    const ElfW(Xword)* soname = nullptr;
    for (const ElfW(Dyn)* d = map->l_ld; d && d->d_tag != DT_NULL; ++d) {
        if (d->d_tag == DT_STRTAB) strings = address(d->d_un.d_ptr);
        else if (d->d_tag == DT_NEEDED) needed.push_back(d->d_un.d_val);
        else if (d->d_tag == DT_SONAME) soname = &d->d_un.d_val;
    }
    if (!strings) return library;
    if (soname) library.soname = strings + *soname;
    for (const ElfW(Xword) offset : needed) library.needed.emplace_back(strings + offset);
    return library;
}

} // namespace drt

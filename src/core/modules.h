// drt's own modules: the parts of drt whose libraries would cost every drt
// process that linked them, built as shared libraries that drt loads with
// dlopen when one is first needed (image/image_io_module.h: OpenImageIO;
// bench/chart_module.h: cairo). A module exports one extern "C" function
// returning its table of entry points, whose first member is an int version:
// a module from another build is refused.
#pragma once

#include <cstddef>
#include <string>
#include <type_traits>

namespace drt {

struct ModuleSpec {
    const char* file;        // the module's file name, e.g. "libdrt_oiio.so"
    const char* symbol;      // its entry: extern "C" const Table* symbol()
    const char* environment; // a variable that, when set, names the one file to load
    const char* buildPath;   // where the build tree put it ("" if not known)
    const char* description; // for messages, e.g. "drt's OpenImageIO module"
};

// A module is looked for, in order: at $environment alone if it is set; else
// beside the executable, in ../lib/drt beside it (an installed drt), and in
// the build tree.

// Preloading. Before a candidate FILE is loaded, the libraries named in
// FILE.preload (one soname a line, each after its own dependencies; written
// at build time by drt_module_preload, src/image/oiio/preload_order_main.cpp)
// are loaded one by one, each as a dlopen of its own. The dynamic loader
// resolves a library's symbols through the executable's libraries and then
// that library's own dependencies, so each library is searched early for its
// own symbols rather than after the hundreds loaded before it in the module's
// breadth-first order: Debian's OpenImageIO module loads in about a tenth
// less CPU time (docs/performance.md, "The fixed cost of a render"). The same
// libraries load and their constructors run dependencies first as before; a
// C++ inline function or type information defined in several of them may be
// taken from another of its identical copies. A line that does not load (a
// library missing its own dependencies, a list from another system) is
// skipped and the module's dlopen loads it as before; no list, no preloading.
inline constexpr const char* kPreloadSuffix = ".preload";

// The first candidate that is a file, "" if none is (the files drt runs as
// programs are looked for so too: image/image_wire.h).
std::string findModuleFile(const ModuleSpec& spec);

// "" when a candidate file exists; else why none can be loaded.
std::string moduleFilesMissing(const ModuleSpec& spec);

// The table of the first candidate that loads, exports the entry and whose
// table's version (its leading int) is `version`; it stays loaded. Null if
// none does, with `error` saying why, candidate by candidate. `call` calls the
// entry found at a symbol's address as the function it is (loadModuleTable).
const void* loadModule(const ModuleSpec& spec, int version, const void* (*call)(void* entry), std::string& error);

// A module's table, or null and why there is none.
template <class Table>
struct LoadedModule {
    const Table* table = nullptr;
    std::string error;
};

// loadModule for a table type whose leading member is `int version`.
template <class Table>
const Table* loadModuleTable(const ModuleSpec& spec, int version, std::string& error) {
    static_assert(std::is_standard_layout_v<Table> && offsetof(Table, version) == 0,
                  "loadModule reads a table's version as its leading int");
    const auto call = [](void* entry) -> const void* { return reinterpret_cast<const Table* (*)()>(entry)(); };
    return static_cast<const Table*>(loadModule(spec, version, call, error));
}

// The module of `spec` loaded on the first call, once for the process
// (thread-safe; one module per table type).
template <class Table>
const LoadedModule<Table>& moduleOnce(const ModuleSpec& spec, int version) {
    static const LoadedModule<Table> loaded = [&spec, version] {
        LoadedModule<Table> result;
        result.table = loadModuleTable<Table>(spec, version, result.error);
        return result;
    }();
    return loaded;
}

} // namespace drt

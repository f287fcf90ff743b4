// Preloading a module's libraries (core/modules.h, "Preloading"): the list the
// build writes beside the OpenImageIO module, and what loadModule does with a
// list.
#include "core/modules.h"
#include "image/image_io_module.h"
#include "image/oiio/loaded_library.h"
#include "test_support.h"

#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace drt {
namespace {

fs::path buildFolder() { return fs::read_symlink("/proc/self/exe").parent_path().parent_path(); }

std::vector<std::string> readLines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The list holds the module's whole dependency closure, each library after
// every library it needs (so each loads with its own dependencies already
// there and searched first).
TEST(ModulePreload, TheListPutsEveryLibraryAfterTheLibrariesItNeeds) {
    const fs::path module = buildFolder() / kImageIoModuleFile;
    const std::vector<std::string> list = readLines(module.string() + kPreloadSuffix);
    ASSERT_GT(list.size(), 10u) << module;
    void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(handle, nullptr) << dlerror();
    std::map<std::string, size_t> position;
    for (size_t i = 0; i < list.size(); ++i) {
        EXPECT_EQ(list[i].find('/'), std::string::npos) << list[i]; // sonames, found as the loader finds them
        EXPECT_TRUE(position.emplace(list[i], i).second) << list[i] << " listed twice";
    }
    // Every library listed is loaded with the module, and needs only libraries listed before it.
    std::set<std::string> closure;
    for (size_t i = 0; i < list.size(); ++i) {
        void* library = dlopen(list[i].c_str(), RTLD_NOW | RTLD_NOLOAD);
        ASSERT_NE(library, nullptr) << list[i] << " is not loaded with the module";
        link_map* map = nullptr;
        ASSERT_EQ(dlinfo(library, RTLD_DI_LINKMAP, &map), 0);
        const LoadedLibrary described = describeLoadedLibrary(map);
        EXPECT_EQ(described.soname, list[i]);
        for (const std::string& needed : described.needed) {
            const auto found = position.find(needed);
            ASSERT_NE(found, position.end()) << list[i] << " needs " << needed << ", which is not listed";
            EXPECT_LT(found->second, i) << list[i] << " needs " << needed << ", listed after it";
        }
        dlclose(library);
    }
    // And the module's own dependencies are all listed: the list is the closure.
    link_map* map = nullptr;
    ASSERT_EQ(dlinfo(handle, RTLD_DI_LINKMAP, &map), 0);
    const LoadedLibrary own = describeLoadedLibrary(map);
    ASSERT_FALSE(own.needed.empty());
    for (const std::string& needed : own.needed) EXPECT_TRUE(position.count(needed)) << needed;
    bool hasOpenImageIo = false;
    for (const std::string& name : list) hasOpenImageIo |= name.rfind("libOpenImageIO.so.", 0) == 0;
    EXPECT_TRUE(hasOpenImageIo);
    dlclose(handle);
}

// loadModule loads the listed libraries before the module; a line that does
// not load is skipped, and the module loads as without the list.
TEST(ModulePreload, ListedLibrariesLoadFirstAndALineThatDoesNotLoadIsSkipped) {
    // A library the module does not need and nothing in the tests loads: it is
    // loaded only because the list names it (GMP's floating point, which the
    // compiler itself needs, so it is on every machine that builds drt).
    const char* const unrelated = "libmpfr.so.6";
    ASSERT_EQ(dlopen(unrelated, RTLD_LAZY | RTLD_NOLOAD), nullptr) << "already loaded: pick another library";
    const std::string dir = test::tempDir();
    const std::string copy = dir + "/" + kImageIoModuleFile;
    fs::copy_file(buildFolder() / kImageIoModuleFile, copy);
    test::writeFile(copy + kPreloadSuffix, std::string("# not a library\nlibno-such-library.so.9\n\n/") + unrelated +
                                               "\n" + unrelated + "\n");
    const ModuleSpec spec{kImageIoModuleFile, kImageIoModuleSymbol, "DRT_TEST_PRELOAD_MODULE", "",
                          "the preloading test's module"};
    setenv("DRT_TEST_PRELOAD_MODULE", copy.c_str(), 1);
    std::string error;
    const ImageIoModule* table = loadModuleTable<ImageIoModule>(spec, kImageIoModuleVersion, error);
    unsetenv("DRT_TEST_PRELOAD_MODULE");
    ASSERT_NE(table, nullptr) << error;
    EXPECT_TRUE(table->hasWriter("x.exr"));
    EXPECT_NE(dlopen(unrelated, RTLD_LAZY | RTLD_NOLOAD), nullptr) << "the listed library was not loaded";
    EXPECT_EQ(dlerror(), nullptr); // the skipped lines left no error behind
}

} // namespace
} // namespace drt

// Every input the fuzzers found a problem with (tests/fuzz/regressions/<harness>/)
// runs through its harness again here, in every build: it must finish without
// a crash (and, in the sanitizer build, without a sanitizer report). The cases
// that need a particular message or exit code have their own tests besides.
#include "fuzz/fuzz_support.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> reproducers(const std::string& harness) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(drt::test::sourcePath("tests/fuzz/regressions")) / harness;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().filename() != "README") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

void replay(const std::string& harness, int (*function)(const uint8_t*, size_t)) {
    for (const fs::path& file : reproducers(harness)) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        const std::string bytes = buffer.str();
        EXPECT_EQ(function(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), 0);
    }
}

} // namespace

TEST(FuzzRegressions, DrtFrontEnd) { replay("drt", drt::fuzz::fuzzDrtFrontEnd); }
TEST(FuzzRegressions, PovFrontEnd) { replay("pov", drt::fuzz::fuzzPovFrontEnd); }
TEST(FuzzRegressions, Render) { replay("render", drt::fuzz::fuzzRender); }

// The folders hold at least the seeds kept there, so the replay cannot pass by
// finding nothing.
TEST(FuzzRegressions, EveryHarnessHasReproducers) {
    for (const char* harness : {"drt", "pov", "render"})
        EXPECT_FALSE(reproducers(harness).empty()) << harness;
}

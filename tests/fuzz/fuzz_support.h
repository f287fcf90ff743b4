// Helpers shared by the libFuzzer harnesses. Each harness is a function that
// the fuzzer binaries call through LLVMFuzzerTestOneInput (DRT_FUZZ_ENTRY_POINT,
// only in the DRT_FUZZ build) and that the unit tests call on every saved
// reproducer (tests/fuzz_regressions_test.cpp), in every build.
#pragma once

#include "core/diagnostics.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace drt::fuzz {

int fuzzDrtFrontEnd(const uint8_t* data, size_t size);
int fuzzPovFrontEnd(const uint8_t* data, size_t size);
int fuzzRender(const uint8_t* data, size_t size);

inline std::string text(const uint8_t* data, size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// The folder #include resolves against: the working directory, as for a scene
// named on the command line in the current folder.
inline const char* includeDir() { return "."; }

// The limits a harness reads with: the defaults cut so that an input which
// fills one (a #while that never ends and adds an object per pass) reaches its
// located error within seconds under the sanitizers, not within the fuzzer's
// 10 s timeout: under the sanitizers and libFuzzer's comparison tracing a loop
// pass that builds an object costs about 1 ms (in a release build 27 us), so
// 50,000 of them took minutes.
// The default limits' endings are unit-tested (hardening_*_test).
inline Diagnostics fuzzDiagnostics() {
    Diagnostics diagnostics;
    Limits limits = diagnostics.limits();
    limits.objects = 1'000;
    limits.loopIterations = 5'000;
    limits.passesAndCalls = 50'000; // all loops and macro calls of a read: nested loops, recursion
    limits.arrayElements = 20'000;
    limits.meshTriangles = 20'000;
    limits.memoryMB = 1536;
    diagnostics.setLimits(limits);
    return diagnostics;
}

// Formats every diagnostic (quoting source lines, placing carets) so that the
// diagnostics code is fuzzed too.
inline void formatEveryDiagnostic(const Diagnostics& diagnostics) {
    volatile size_t length = diagnostics.formatAll().size();
    (void)length;
}

} // namespace drt::fuzz

#ifdef DRT_FUZZ_MAIN
#define DRT_FUZZ_ENTRY_POINT(function)                                                                          \
    extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return drt::fuzz::function(data, size); }
#else
#define DRT_FUZZ_ENTRY_POINT(function)
#endif

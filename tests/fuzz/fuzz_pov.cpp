// libFuzzer harness: POV-Ray scene text -> the POV-Ray front end (directives,
// macros, loops, functions, the standard include files) -> scene model.
#include "fuzz_support.h"
#include "pov/load.h"

int drt::fuzz::fuzzPovFrontEnd(const uint8_t* data, size_t size) {
    drt::Diagnostics diagnostics = drt::fuzz::fuzzDiagnostics();
    drt::PovOptions options;
    options.imageWidth = 8;
    options.imageHeight = 6;
    drt::loadPovSceneText(drt::fuzz::text(data, size), "fuzz.pov", diagnostics, options, drt::fuzz::includeDir());
    drt::fuzz::formatEveryDiagnostic(diagnostics);
    return 0;
}

DRT_FUZZ_ENTRY_POINT(fuzzPovFrontEnd)

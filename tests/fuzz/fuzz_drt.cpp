// libFuzzer harness: .drt scene text -> the .drt front end (lexer, parser,
// expression evaluator, #include, #declare) -> scene model. Any input must end
// in a scene or in located errors: no crash, no hang, no unbounded memory.
#include "fuzz_support.h"
#include "lang/load.h"

int drt::fuzz::fuzzDrtFrontEnd(const uint8_t* data, size_t size) {
    drt::Diagnostics diagnostics = drt::fuzz::fuzzDiagnostics();
    drt::loadSceneText(drt::fuzz::text(data, size), "fuzz.drt", diagnostics, drt::fuzz::includeDir());
    drt::fuzz::formatEveryDiagnostic(diagnostics);
    return 0;
}

DRT_FUZZ_ENTRY_POINT(fuzzDrtFrontEnd)

// drt_perf time-to-error: how much sooner one drt reaches the image error
// another drt reaches at a given sample count, on one drt scene (by default
// examples/cook.drt, every distribution effect at once, and its 16 samples per
// pixel). Each drt renders the scene at several sample counts, repetitions
// interleaved, every render timed as a whole process; relMSE is measured
// against one converged reference (the mean of independent renders by the
// first drt, its own noise taken out). The target is the median relMSE of the
// `target` drt at `targetSpp`; each drt's time to it is read off its best
// curve (bench/equal_error.h). It also tables the shadow rays each drt traces
// per camera sample, and checks that every drt converges to the reference
// (bench/agreement.h). See docs/performance.md.
#pragma once

#include "perf.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace drt::perf {

struct TimeToErrorOptions {
    std::string outputDir;
    std::vector<DrtBinary> drt; // the first renders the reference
    std::string scene;          // "": examples/cook.drt
    std::string target;         // label of the drt whose error at targetSpp is the target; "": the last
    int targetSpp = 16;
    std::vector<int> spp = {2, 4, 8, 16, 32, 64};
    int referenceSpp = 256; // per reference render; at least 4 renders, at most 16
    int threads = 2;
    int repetitions = 0; // 0: 3
};

// Writes time-to-error.csv and time-to-error.md into outputDir; the table also
// goes to `log`. Returns the exit status (0 done).
int runTimeToError(const TimeToErrorOptions& options, std::ostream& log);

} // namespace drt::perf

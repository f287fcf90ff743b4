// "The benchmark that decides it": drt against POV-Ray 3.7 at equal error.
// Each renderer renders each scene at several settings, each setting several
// times; every render is timed as a whole process (start-up, parsing, bounding
// or BVH build, tracing and writing the file: what a user waits for) on the
// same thread count, and its relMSE is measured against that renderer's own
// converged reference. The time each needs for a target relMSE is read off
// its best curve (bench/equal_error.h); the two references are compared for
// bias (bench/agreement.h). See docs/performance.md.
#pragma once

#include "perf.h"

#include <functional>
#include <string>
#include <vector>

namespace drt::perf {

// Rewrites a POV-Ray scene's text (a knob the scene file holds). Throws
// std::runtime_error if the scene lacks what the edit changes.
using SceneEdit = std::function<std::string(const std::string&)>;

// `blur_samples N` becomes `blur_samples count` (with `exact`, also `variance 0`).
SceneEdit blurSamples(int count, bool exact);
// Every area light's grid gets about `factor` times the intervals per axis,
// its axes rescaled so that the jittered grid covers the same rectangle.
SceneEdit scaleAreaGrids(double factor);

struct PovSetting {
    std::string name;               // for tables: "blur_samples 37, +A0.3"
    SceneEdit edit;                 // applied to a copy of the scene
    std::vector<std::string> flags; // command-line knobs: anti-aliasing
};

struct VersusScene {
    std::string name; // "focalblur"
    std::string file; // below POV-Ray's examples folder
    std::vector<PovSetting> povSettings, quickPovSettings;
    // POV-Ray's converged reference, and the same at half the budget: their
    // difference tells how far from converged the reference still is.
    PovSetting povReference, povReferenceHalf, quickPovReference, quickPovReferenceHalf;
    std::vector<int> drtSpp, quickDrtSpp;
    // drt's reference: the mean of renders (seeds apart) of this many samples
    // per pixel each, at least 4 of them, until its noise is a tenth of the
    // smallest target (at most 16; quick: 8).
    int drtReferenceSpp = 0, quickDrtReferenceSpp = 0;
};

std::vector<VersusScene> versusScenes();

struct VersusOptions {
    std::string outputDir;
    std::vector<DrtBinary> drt;      // the first one renders drt's reference
    std::vector<std::string> scenes; // empty: all
    int repetitions = 0;             // 0: 3
    int threads = 2;
    int width = 320, height = 240;
    bool quick = false;
    std::string povExamples = kPovExamples;
    std::vector<double> targets = {1e-4, 3e-5};
};

// Runs the benchmark; writes results.csv, summary.md and one chart per scene
// into outputDir, progress to `log`. Returns the exit status (0 done).
int runVersusPovray(const VersusOptions& options, std::ostream& log);

} // namespace drt::perf

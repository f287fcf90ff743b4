// drt_perf pov-scenes: POV-Ray's shipped sample scenes rendered as a user
// runs them, by POV-Ray 3.7 (+A0.3) and by each drt (16 samples per pixel),
// both at 160x120 on 2 threads, timed as whole processes.
//
// Which scenes: every .pov file under POV-Ray's examples folder that the first
// drt accepts (`drt check` in the scene's folder), ordered by the FNV-1a hash
// of its path below that folder (a fixed shuffle across the folders), then
// taken in that order, skipping any that a program fails to render, until
// `count` have rendered in every program. POV-Ray's own benchmark scene
// (advanced/benchmark/benchmark.pov) comes first when drt accepts it. The
// scenes used are written to scenes.txt; `--scenes-file` replays such a list.
#pragma once

#include "perf.h"

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace drt::perf {

struct PovScenesOptions {
    std::string outputDir;
    std::vector<DrtBinary> drt;
    int count = 40;
    int repetitions = 0; // 0: 1
    int width = 160, height = 120, spp = 16, threads = 2;
    double timeoutSeconds = 900; // a render running longer counts as failed
    std::string scenesFile;      // one path per line, relative to povExamples: use exactly these
    std::string povExamples = kPovExamples;
};

// The FNV-1a 64-bit hash of a text: the order scenes are taken in.
uint64_t fnv1a64(const std::string& text);
// `paths` ordered as the scene rule says (benchmark first, then by hash).
std::vector<std::string> orderScenes(std::vector<std::string> paths);

int runPovScenes(const PovScenesOptions& options, std::ostream& log);

} // namespace drt::perf

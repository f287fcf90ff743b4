// drt_perf startup: the fixed costs of drt's commands against POV-Ray's
// (`--version`, `drt check`, a 32x24 render of a tiny scene both read), and
// where drt's go (shared libraries mapped, the dynamic loader's statistics).
#pragma once

#include "perf.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace drt::perf {

struct StartupOptions {
    std::string outputDir;
    std::vector<DrtBinary> drt;
    int repetitions = 0; // 0: 10
};

// Writes startup.csv and startup.md into outputDir; the table also goes to `log`.
int runStartup(const StartupOptions& options, std::ostream& log);

} // namespace drt::perf

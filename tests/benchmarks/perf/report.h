// drt_perf report: every instrument in one run, for the tables of
// docs/performance.md: start-up, the ray rate against raw Embree, the time to
// an equal error on examples/cook.drt and drt against POV-Ray 3.7 at equal
// error, each into its own subfolder, then report.md with all their tables.
#pragma once

#include "perf.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace drt::perf {

struct ReportOptions {
    std::string outputDir;
    std::vector<DrtBinary> drt; // e.g. after=build/drt, before=an older drt
    bool quick = false;         // every instrument in its lighter form
    bool povray = true;         // false: skip drt against POV-Ray (the longest part)
};

int runReport(const ReportOptions& options, std::ostream& log);

} // namespace drt::perf

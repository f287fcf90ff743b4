// The seam between drt and cairo: `drt bench` draws its charts with cairo,
// which with its ~14 libraries (pixman, fontconfig, X11, xcb, ...) is not
// linked into drt but lives in the module libdrt_charts.so
// (src/bench/cairo/), loaded when the first chart is written
// (core/modules.h). Every library a process has linked is searched before
// the image module's own for each of its ~170,000 symbols, so linked into drt
// cairo's libraries cost every render about 11 ms of the image module's load
// (docs/performance.md, "The fixed cost of a render").
#pragma once

#include "bench/chart.h"

#include <string>

namespace drt::bench {

// Bumped whenever this table or bench/chart.h's Chart changes.
inline constexpr int kChartModuleVersion = 1;

struct ChartModule {
    int version;
    // writeChart (bench/chart.h), drawn with cairo.
    std::string (*writeChart)(const Chart& chart, const std::string& basePath);
};

inline constexpr const char* kChartModuleFile = "libdrt_charts.so";
inline constexpr const char* kChartModuleSymbol = "drt_chart_module";

} // namespace drt::bench

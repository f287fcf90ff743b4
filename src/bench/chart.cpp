// writeChart through the chart module (bench/chart_module.h), loaded on the
// first chart: $DRT_CHARTS_MODULE if set, else beside the executable, in
// ../lib/drt beside it, or in the build tree (core/modules.h).
#include "bench/chart.h"
#include "bench/chart_module.h"

#include "core/modules.h"


namespace drt::bench {

namespace {

// The build tree's path comes from CMake (DRT_CHARTS_MODULE_BUILD_PATH).
constexpr ModuleSpec kChartSpec{kChartModuleFile, kChartModuleSymbol, "DRT_CHARTS_MODULE",
                                DRT_CHARTS_MODULE_BUILD_PATH, "drt's chart module"};

const LoadedModule<ChartModule>& charts() { return moduleOnce<ChartModule>(kChartSpec, kChartModuleVersion); }

} // namespace

std::string chartsUnavailable() {
    const LoadedModule<ChartModule>& loaded = charts();
    return loaded.table ? "" : loaded.error;
}

std::string writeChart(const Chart& chart, const std::string& basePath) {
    const LoadedModule<ChartModule>& loaded = charts();
    return loaded.table ? loaded.table->writeChart(chart, basePath) : loaded.error;
}

} // namespace drt::bench

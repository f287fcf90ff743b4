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

struct LoadedCharts {
    const ChartModule* module = nullptr;
    std::string error;
};

const LoadedCharts& charts() {
    static const LoadedCharts loaded = [] { // thread-safe, once
        LoadedCharts result;
        result.module = loadModuleTable<ChartModule>(kChartSpec, kChartModuleVersion, result.error);
        return result;
    }();
    return loaded;
}

} // namespace

std::string chartsUnavailable() { return charts().module ? "" : charts().error; }

std::string writeChart(const Chart& chart, const std::string& basePath) {
    const LoadedCharts& loaded = charts();
    return loaded.module ? loaded.module->writeChart(chart, basePath) : loaded.error;
}

} // namespace drt::bench

// Log-log line charts for `drt bench`, drawn once with cairo and written as
// both SVG (for documents) and PNG (for quick viewing): one routine, two
// surfaces.
#pragma once

#include <string>
#include <vector>

namespace drt::bench {

struct ChartPoint {
    double x = 0;
    double y = 0;    // the median over seeds
    double low = 0;  // interquartile bar: first quartile (<= 0: no bar)
    double high = 0; // third quartile
};

struct ChartSeries {
    std::string name; // legend entry
    std::vector<ChartPoint> points;
    bool connected = true; // false: markers only (e.g. every setting of a renderer, not a curve)
};

// A labelled horizontal line (e.g. a target error), dotted, across the plot.
struct ChartLevel {
    double y = 0;
    std::string label;
};

struct Chart {
    std::string title;
    std::string subtitle; // e.g. the scene and image size
    std::string xLabel;
    std::string yLabel;
    std::vector<ChartSeries> series;
    // A dashed guide line y ~ x^guideSlope through the middle of the data
    // (e.g. -1: an unbiased estimator's error x time is constant).
    bool guide = false;
    double guideSlope = -1;
    std::string guideLabel;
    // Points of the Pareto front in data coordinates, by increasing x; drawn
    // as a staircase under the markers, with rings on its points.
    std::vector<ChartPoint> paretoFront;
    std::vector<ChartLevel> levels;
    int width = 760;
    int height = 500;
};

// Writes `basePath`.svg and `basePath`.png (each through a temporary file
// renamed when complete). Returns "" on success, else the reason.
std::string writeChart(const Chart& chart, const std::string& basePath);

// "" if charts can be drawn (the chart module loads: bench/chart_module.h),
// else why not; asked before a bench renders anything.
std::string chartsUnavailable();

} // namespace drt::bench

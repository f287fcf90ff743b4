// The chart module libdrt_charts.so (bench/chart_module.h): charts drawn with
// cairo, which drt itself does not link.
//
// Chart layout: title and subtitle on top, the plot area on the left with
// decade ticks (minor ticks at 2..9 x 10^k, labelled too when the axis spans
// two decades or less), the legend on the right outside the data. Colours are
// the Okabe-Ito palette, distinguishable with the common colour-vision
// deficiencies; each series also has its own marker shape.
#include "bench/chart.h"
#include "bench/chart_module.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <limits>

namespace drt::bench {

namespace {

struct Rgb {
    double r, g, b;
};
constexpr Rgb kPalette[] = {{0.000, 0.447, 0.698}, {0.835, 0.369, 0.000}, {0.000, 0.620, 0.451},
                            {0.800, 0.475, 0.655}, {0.902, 0.624, 0.000}, {0.337, 0.706, 0.914},
                            {0.000, 0.000, 0.000}, {0.549, 0.337, 0.294}, {0.498, 0.498, 0.498}};
constexpr int kPaletteSize = int(std::size(kPalette));
constexpr const char* kFont = "DejaVu Sans";

// The data range of one axis in log10 units, widened to whole decades.
struct LogAxis {
    double lo = 0, hi = 1; // log10 of the ends
    double toPixel(double value, double p0, double p1) const {
        return p0 + (std::log10(value) - lo) / (hi - lo) * (p1 - p0);
    }
};

LogAxis decadeAxis(double minValue, double maxValue) {
    if (!(minValue > 0) || !std::isfinite(minValue) || !(maxValue >= minValue)) return {0, 1};
    LogAxis axis{std::floor(std::log10(minValue)), std::ceil(std::log10(maxValue))};
    if (axis.hi <= axis.lo) axis.hi = axis.lo + 1;
    return axis;
}

struct Frame { // the plot area in device units
    double left, top, right, bottom;
};

void setColor(cairo_t* cr, const Rgb& c, double alpha = 1) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

double textWidth(cairo_t* cr, const std::string& text) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
}

void showText(cairo_t* cr, double x, double y, const std::string& text) {
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, text.c_str());
}

// "10" with a raised exponent, centred on x (anchor 0) or right-aligned (anchor 1).
void drawPowerOfTen(cairo_t* cr, double x, double y, int exponent, double anchor) {
    const std::string base = "10", power = std::to_string(exponent);
    cairo_set_font_size(cr, 12);
    const double baseWidth = textWidth(cr, base);
    cairo_set_font_size(cr, 9);
    const double powerWidth = textWidth(cr, power);
    const double start = x - (anchor == 0 ? (baseWidth + powerWidth) / 2 : baseWidth + powerWidth);
    cairo_set_font_size(cr, 12);
    showText(cr, start, y, base);
    cairo_set_font_size(cr, 9);
    showText(cr, start + baseWidth, y - 6, power);
}

void drawMarker(cairo_t* cr, int shape, double x, double y, double r) {
    switch (shape % 5) {
    case 0: cairo_arc(cr, x, y, r, 0, 2 * M_PI); break;
    case 1: cairo_rectangle(cr, x - r * 0.85, y - r * 0.85, 1.7 * r, 1.7 * r); break;
    case 2:
        cairo_move_to(cr, x, y - r * 1.15);
        cairo_line_to(cr, x + r, y + r * 0.75);
        cairo_line_to(cr, x - r, y + r * 0.75);
        cairo_close_path(cr);
        break;
    case 3:
        cairo_move_to(cr, x, y - r * 1.2);
        cairo_line_to(cr, x + r, y);
        cairo_line_to(cr, x, y + r * 1.2);
        cairo_line_to(cr, x - r, y);
        cairo_close_path(cr);
        break;
    default:
        cairo_move_to(cr, x, y + r * 1.15);
        cairo_line_to(cr, x + r, y - r * 0.75);
        cairo_line_to(cr, x - r, y - r * 0.75);
        cairo_close_path(cr);
        break;
    }
}

// Ticks, grid lines and labels of one log axis.
void drawAxisTicks(cairo_t* cr, const LogAxis& axis, const Frame& f, bool horizontal) {
    const bool labelMinor = axis.hi - axis.lo <= 2;
    const bool drawMinor = axis.hi - axis.lo <= 8;
    for (int decade = int(axis.lo); decade <= int(axis.hi); ++decade) {
        for (int m = 1; m <= 9; ++m) {
            if (m > 1 && (!drawMinor || decade == int(axis.hi))) break;
            const double value = m * std::pow(10.0, decade);
            const double p = horizontal ? axis.toPixel(value, f.left, f.right) : axis.toPixel(value, f.bottom, f.top);
            cairo_set_source_rgb(cr, m == 1 ? 0.86 : 0.94, m == 1 ? 0.86 : 0.94, m == 1 ? 0.86 : 0.94);
            cairo_set_line_width(cr, 1);
            if (horizontal) cairo_move_to(cr, p, f.top), cairo_line_to(cr, p, f.bottom);
            else cairo_move_to(cr, f.left, p), cairo_line_to(cr, f.right, p);
            cairo_stroke(cr);
            const double tick = m == 1 ? 6 : 3;
            cairo_set_source_rgb(cr, 0, 0, 0);
            if (horizontal) cairo_move_to(cr, p, f.bottom), cairo_line_to(cr, p, f.bottom + tick);
            else cairo_move_to(cr, f.left - tick, p), cairo_line_to(cr, f.left, p);
            cairo_stroke(cr);
            if (m == 1) {
                if (horizontal) drawPowerOfTen(cr, p, f.bottom + 22, decade, 0);
                else drawPowerOfTen(cr, f.left - 9, p + 5, decade, 1);
            } else if (labelMinor && (m == 2 || m == 5)) {
                cairo_set_font_size(cr, 10);
                cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
                const std::string label = std::to_string(m);
                if (horizontal) showText(cr, p - textWidth(cr, label) / 2, f.bottom + 18, label);
                else showText(cr, f.left - 9 - textWidth(cr, label), p + 4, label);
            }
        }
    }
}

void drawChart(cairo_t* cr, const Chart& chart) {
    const double width = chart.width, height = chart.height;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

    double minX = std::numeric_limits<double>::infinity(), maxX = 0;
    double minY = std::numeric_limits<double>::infinity(), maxY = 0;
    for (const ChartSeries& s : chart.series) {
        for (const ChartPoint& p : s.points) {
            if (!(p.x > 0 && p.y > 0) || !std::isfinite(p.x + p.y)) continue;
            minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
            minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
            if (p.low > 0 && std::isfinite(p.low)) minY = std::min(minY, p.low);
            if (p.high > 0 && std::isfinite(p.high)) maxY = std::max(maxY, p.high);
        }
    }
    for (const ChartLevel& level : chart.levels)
        if (level.y > 0 && std::isfinite(level.y)) minY = std::min(minY, level.y), maxY = std::max(maxY, level.y);
    const LogAxis ax = decadeAxis(minX, maxX), ay = decadeAxis(minY, maxY);

    // Legend width decides the plot width.
    cairo_set_font_size(cr, 11.5);
    double legendWidth = 0;
    for (const ChartSeries& s : chart.series) legendWidth = std::max(legendWidth, textWidth(cr, s.name));
    if (!chart.paretoFront.empty()) legendWidth = std::max(legendWidth, textWidth(cr, "Pareto front"));
    if (chart.guide) legendWidth = std::max(legendWidth, textWidth(cr, chart.guideLabel));
    legendWidth += 44;
    const Frame f{78, 62, width - legendWidth - 24, height - 58};

    // Title and axis labels.
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 15);
    showText(cr, f.left, 24, chart.title);
    cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 11);
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    showText(cr, f.left, 43, chart.subtitle);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 12.5);
    showText(cr, (f.left + f.right - textWidth(cr, chart.xLabel)) / 2, height - 14, chart.xLabel);
    cairo_save(cr);
    cairo_translate(cr, 20, (f.top + f.bottom + textWidth(cr, chart.yLabel)) / 2);
    cairo_rotate(cr, -M_PI / 2);
    showText(cr, 0, 0, chart.yLabel);
    cairo_restore(cr);

    drawAxisTicks(cr, ax, f, true);
    drawAxisTicks(cr, ay, f, false);

    const auto px = [&](double x) { return ax.toPixel(x, f.left, f.right); };
    const auto py = [&](double y) { return ay.toPixel(y, f.bottom, f.top); };
    cairo_save(cr);
    cairo_rectangle(cr, f.left, f.top, f.right - f.left, f.bottom - f.top);
    cairo_clip(cr);

    // Slope guide through the geometric centre of the data.
    if (chart.guide && maxX > 0) {
        const double cx = std::sqrt(minX * maxX), cy = std::sqrt(minY * maxY);
        const double x0 = std::pow(10.0, ax.lo), x1 = std::pow(10.0, ax.hi);
        cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
        cairo_set_line_width(cr, 1.3);
        const double dashes[] = {6, 4};
        cairo_set_dash(cr, dashes, 2, 0);
        cairo_move_to(cr, px(x0), py(cy * std::pow(x0 / cx, chart.guideSlope)));
        cairo_line_to(cr, px(x1), py(cy * std::pow(x1 / cx, chart.guideSlope)));
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
    }

    // Target levels: dotted lines, labelled at the right end.
    for (const ChartLevel& level : chart.levels) {
        if (!(level.y > 0) || !std::isfinite(level.y)) continue;
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        cairo_set_line_width(cr, 1);
        const double dots[] = {2, 3};
        cairo_set_dash(cr, dots, 2, 0);
        cairo_move_to(cr, f.left, py(level.y)), cairo_line_to(cr, f.right, py(level.y));
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        cairo_set_font_size(cr, 10.5);
        showText(cr, f.right - textWidth(cr, level.label) - 4, py(level.y) - 4, level.label);
    }

    // Pareto front: a staircase (the best error reachable within each budget).
    if (!chart.paretoFront.empty()) {
        cairo_set_source_rgba(cr, 0.2, 0.2, 0.2, 0.22);
        cairo_set_line_width(cr, 7);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        const std::vector<ChartPoint>& front = chart.paretoFront;
        cairo_move_to(cr, px(front[0].x), py(front[0].y));
        for (size_t i = 1; i < front.size(); ++i) {
            cairo_line_to(cr, px(front[i].x), py(front[i - 1].y));
            cairo_line_to(cr, px(front[i].x), py(front[i].y));
        }
        cairo_line_to(cr, f.right, py(front.back().y));
        cairo_stroke(cr);
    }

    // Series: interquartile bars, the line through the medians, markers.
    for (size_t si = 0; si < chart.series.size(); ++si) {
        const ChartSeries& s = chart.series[si];
        const Rgb& color = kPalette[si % kPaletteSize];
        std::vector<ChartPoint> points;
        for (const ChartPoint& p : s.points)
            if (p.x > 0 && p.y > 0 && std::isfinite(p.x + p.y)) points.push_back(p);
        std::sort(points.begin(), points.end(), [](const ChartPoint& a, const ChartPoint& b) { return a.x < b.x; });
        setColor(cr, color, 0.8);
        cairo_set_line_width(cr, 1.2);
        for (const ChartPoint& p : points) {
            if (!(p.low > 0 && p.high >= p.low)) continue;
            cairo_move_to(cr, px(p.x), py(p.low)), cairo_line_to(cr, px(p.x), py(p.high));
            cairo_move_to(cr, px(p.x) - 3, py(p.low)), cairo_line_to(cr, px(p.x) + 3, py(p.low));
            cairo_move_to(cr, px(p.x) - 3, py(p.high)), cairo_line_to(cr, px(p.x) + 3, py(p.high));
            cairo_stroke(cr);
        }
        setColor(cr, color);
        cairo_set_line_width(cr, 1.8);
        for (size_t i = 0; s.connected && i < points.size(); ++i) {
            if (i == 0) cairo_move_to(cr, px(points[i].x), py(points[i].y));
            else cairo_line_to(cr, px(points[i].x), py(points[i].y));
        }
        cairo_stroke(cr);
        for (const ChartPoint& p : points) {
            drawMarker(cr, int(si), px(p.x), py(p.y), 3.6);
            setColor(cr, color);
            cairo_fill_preserve(cr);
            cairo_set_source_rgb(cr, 1, 1, 1);
            cairo_set_line_width(cr, 0.8);
            cairo_stroke(cr);
            setColor(cr, color);
        }
    }
    for (const ChartPoint& p : chart.paretoFront) {
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_set_line_width(cr, 1.2);
        cairo_new_sub_path(cr);
        cairo_arc(cr, px(p.x), py(p.y), 7, 0, 2 * M_PI);
        cairo_stroke(cr);
    }
    cairo_restore(cr);

    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, f.left, f.top, f.right - f.left, f.bottom - f.top);
    cairo_stroke(cr);

    // Legend.
    double ly = f.top + 14;
    const double lx = f.right + 18;
    cairo_set_font_size(cr, 11.5);
    for (size_t si = 0; si < chart.series.size(); ++si) {
        const Rgb& color = kPalette[si % kPaletteSize];
        setColor(cr, color);
        cairo_set_line_width(cr, 1.8);
        if (chart.series[si].connected) cairo_move_to(cr, lx, ly - 4), cairo_line_to(cr, lx + 26, ly - 4);
        cairo_stroke(cr);
        drawMarker(cr, int(si), lx + 13, ly - 4, 3.6);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        showText(cr, lx + 34, ly, chart.series[si].name);
        ly += 19;
    }
    if (chart.guide) {
        cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
        cairo_set_line_width(cr, 1.3);
        const double dashes[] = {6, 4};
        cairo_set_dash(cr, dashes, 2, 0);
        cairo_move_to(cr, lx, ly - 4), cairo_line_to(cr, lx + 26, ly - 4);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        cairo_set_source_rgb(cr, 0, 0, 0);
        showText(cr, lx + 34, ly, chart.guideLabel);
        ly += 19;
    }
    if (!chart.paretoFront.empty()) {
        cairo_set_source_rgba(cr, 0.2, 0.2, 0.2, 0.22);
        cairo_set_line_width(cr, 7);
        cairo_move_to(cr, lx, ly - 4), cairo_line_to(cr, lx + 26, ly - 4);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_set_line_width(cr, 1.2);
        cairo_new_sub_path(cr);
        cairo_arc(cr, lx + 13, ly - 4, 6, 0, 2 * M_PI);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        showText(cr, lx + 34, ly, "Pareto front");
    }
}

std::string statusText(cairo_status_t status) { return cairo_status_to_string(status); }

// Renames `temporary` over `path`, removing it on failure.
std::string moveInto(const std::string& temporary, const std::string& path) {
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        return fmt::format("cannot write '{}': {}", path, ec.message());
    }
    return "";
}

std::string drawAndWrite(const Chart& chart, const std::string& basePath) {
    const std::string svgPath = basePath + ".svg", pngPath = basePath + ".png";
    const std::string svgTemporary = svgPath + ".tmp", pngTemporary = pngPath + ".tmp";

    cairo_surface_t* svg = cairo_svg_surface_create(svgTemporary.c_str(), chart.width, chart.height);
    cairo_t* cr = cairo_create(svg);
    drawChart(cr, chart);
    cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(svg);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(svg);
    cairo_surface_destroy(svg);
    if (status != CAIRO_STATUS_SUCCESS) {
        std::error_code ec;
        std::filesystem::remove(svgTemporary, ec);
        return fmt::format("cannot write '{}': {}", svgPath, statusText(status));
    }
    if (std::string problem = moveInto(svgTemporary, svgPath); !problem.empty()) return problem;

    cairo_surface_t* png = cairo_image_surface_create(CAIRO_FORMAT_RGB24, chart.width, chart.height);
    cr = cairo_create(png);
    drawChart(cr, chart);
    status = cairo_status(cr);
    cairo_destroy(cr);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_write_to_png(png, pngTemporary.c_str());
    cairo_surface_destroy(png);
    if (status != CAIRO_STATUS_SUCCESS) {
        std::error_code ec;
        std::filesystem::remove(pngTemporary, ec);
        return fmt::format("cannot write '{}': {}", pngPath, statusText(status));
    }
    return moveInto(pngTemporary, pngPath);
}

} // namespace

} // namespace drt::bench

extern "C" const drt::bench::ChartModule* drt_chart_module() {
    static const drt::bench::ChartModule module = {drt::bench::kChartModuleVersion, &drt::bench::drawAndWrite};
    return &module;
}

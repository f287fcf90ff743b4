// The three scenes of the drt-against-POV-Ray benchmark and the settings each
// renderer is measured at. POV-Ray gets the knobs it has: focal blur samples,
// the area-light grid, and its adaptive anti-aliasing (threshold +A, depth +R).
// drt gets one knob: samples per pixel.
#include "versus.h"

#include <cmath>
#include <fmt/format.h>
#include <regex>
#include <stdexcept>

namespace drt::perf {

// `blur_samples N` becomes `blur_samples count`; with `exact`, also
// `variance 0`, which makes POV-Ray take exactly that many samples instead of
// stopping early once a pixel's variance looks small.
SceneEdit blurSamples(int count, bool exact) {
    return [count, exact](const std::string& text) {
        static const std::regex pattern(R"(blur_samples\s+[0-9]+)");
        if (!std::regex_search(text, pattern))
            throw std::runtime_error("no blur_samples in the scene");
        return std::regex_replace(text, pattern,
                                  fmt::format("blur_samples {}{}", count, exact ? " variance 0" : ""));
    };
}

// Every `area_light <a>, <b>, n1, n2` gets about `factor` times as many grid
// intervals per axis (at least 2 points). POV-Ray's jittered grid covers n/(n-1)
// times the written axis (points edge to edge, each jittered by half a cell),
// so each axis is rescaled to keep the covered rectangle, hence the converged
// image, the same.
SceneEdit scaleAreaGrids(double factor) {
    return [factor](const std::string& text) {
        static const std::regex pattern(
            R"(area_light\s*(<[^>]*>)\s*,\s*(<[^>]*>)\s*,\s*([0-9]+)\s*,\s*([0-9]+))");
        std::string out;
        auto begin = std::sregex_iterator(text.begin(), text.end(), pattern);
        if (begin == std::sregex_iterator())
            throw std::runtime_error("no area_light in the scene");
        size_t last = 0;
        for (auto it = begin; it != std::sregex_iterator(); ++it) {
            const std::smatch& m = *it;
            const auto rescaled = [&](int n, double& scale) {
                const int m2 = std::max(2, int(std::lround((n - 1) * factor)) + 1);
                scale = n > 1 ? (double(n) / (n - 1)) * (double(m2 - 1) / m2) : 1.0;
                return n > 1 ? m2 : n;
            };
            double s1 = 1, s2 = 1;
            const int n1 = rescaled(std::stoi(m[3]), s1), n2 = rescaled(std::stoi(m[4]), s2);
            out += text.substr(last, size_t(m.position(0)) - last);
            out += fmt::format("area_light {}*{:.9g}, {}*{:.9g}, {}, {}", m[1].str(), s1, m[2].str(), s2, n1,
                               n2);
            last = size_t(m.position(0) + m.length(0));
        }
        return out + text.substr(last);
    };
}

namespace {

SceneEdit asWritten() {
    return [](const std::string& text) { return text; };
}

PovSetting pov(std::string name, SceneEdit edit, std::vector<std::string> flags) {
    return PovSetting{std::move(name), std::move(edit), std::move(flags)};
}

VersusScene focalBlur() {
    VersusScene s;
    s.name = "focalblur";
    s.file = "camera/focalblur.pov";
    // The scene asks for 120 blur samples at POV-Ray's default confidence,
    // which stops a pixel early once its samples agree: fast, but it leaves an
    // error floor. `variance 0` takes every sample. Anti-aliasing on top of
    // focal blur (whose samples already cover the pixel) costs more than it
    // gains, so only a few settings keep +A0.3.
    for (int samples : {19, 37, 80, 160, 320})
        s.povSettings.push_back(
            pov(fmt::format("blur_samples {}, -A", samples), blurSamples(samples, false), {"-A"}));
    for (int samples : {19, 37, 80, 160, 320, 640})
        s.povSettings.push_back(
            pov(fmt::format("blur_samples {} variance 0, -A", samples), blurSamples(samples, true), {"-A"}));
    for (int samples : {37, 120, 320})
        s.povSettings.push_back(
            pov(fmt::format("blur_samples {}, +A0.3", samples), blurSamples(samples, false), {"+A0.3"}));
    s.quickPovSettings = {s.povSettings[1], s.povSettings[3], s.povSettings[6], s.povSettings[7],
                          s.povSettings[8], s.povSettings[9], s.povSettings[12]};
    s.povReference = pov("blur_samples 3000 variance 0, -A", blurSamples(3000, true), {"-A"});
    s.povReferenceHalf = pov("blur_samples 1500 variance 0, -A", blurSamples(1500, true), {"-A"});
    s.quickPovReference = pov("blur_samples 800 variance 0, -A", blurSamples(800, true), {"-A"});
    s.quickPovReferenceHalf = pov("blur_samples 400 variance 0, -A", blurSamples(400, true), {"-A"});
    s.drtSpp = {2, 4, 8, 16, 32, 64, 128, 256};
    s.quickDrtSpp = {4, 16, 64, 256};
    s.drtReferenceSpp = 128;
    s.quickDrtReferenceSpp = 64;
    return s;
}

// arealit1 (grids 3x3, 5x5, 17x17) and arealit2 (three 17x17 grids of three
// sizes) share their knobs: grid factor x anti-aliasing.
VersusScene areaLights(const std::string& name) {
    VersusScene s;
    s.name = name;
    s.file = "lights/" + name + ".pov";
    const std::vector<std::pair<std::string, std::vector<std::string>>> antialiasing = {
        {"-A", {"-A"}},
        {"+A0.3", {"+A0.3"}},
        {"+A0.1", {"+A0.1"}},
        {"+A0.0 +R3", {"+A0.0", "+R3"}},
        {"+A0.0 +R5", {"+A0.0", "+R5"}},
    };
    for (double factor : {0.5, 1.0, 2.0}) {
        for (const auto& [aa, flags] : antialiasing) {
            const std::string grid = factor == 1.0 ? "grids as written" : fmt::format("grids x{:g}", factor);
            s.povSettings.push_back(pov(fmt::format("{}, {}", grid, aa),
                                        factor == 1.0 ? asWritten() : scaleAreaGrids(factor), flags));
        }
    }
    s.quickPovSettings = {s.povSettings[6], s.povSettings[7], s.povSettings[8], s.povSettings[11],
                          s.povSettings[12]};
    s.povReference = pov("grids as written, +A0.0 +R8", asWritten(), {"+A0.0", "+R8"});
    s.povReferenceHalf = pov("grids as written, +A0.0 +R6", asWritten(), {"+A0.0", "+R6"});
    s.quickPovReference = pov("grids as written, +A0.0 +R6", asWritten(), {"+A0.0", "+R6"});
    s.quickPovReferenceHalf = pov("grids as written, +A0.0 +R4", asWritten(), {"+A0.0", "+R4"});
    s.drtSpp = {1, 2, 4, 8, 16, 32, 64, 128, 256};
    s.quickDrtSpp = {1, 4, 16, 64, 256};
    // Renders of 8 spp left the quick reference's own noise at 1.5e-4, above
    // both targets (it is subtracted from every relMSE, so the figures near
    // 3e-5 were mostly that correction).
    s.drtReferenceSpp = 128;
    s.quickDrtReferenceSpp = 64;
    return s;
}

} // namespace

std::vector<VersusScene> versusScenes() {
    return {focalBlur(), areaLights("arealit1"), areaLights("arealit2")};
}

} // namespace drt::perf

// `drt render` and `drt check`: scene file -> diagnostics -> (render -> image
// files). The render itself (processes, interruption, checkpoints) is in
// cli/render_run.cpp.
#include "cli/commands.h"
#include "assets/assets.h"

#include "cli/paths.h"
#include "cli/progress.h"
#include "accel/geometry_query.h"
#include "cli/render_parts.h"
#include "distributed/checkpoint.h"
#include "lang/load.h"
#include "render/scene_warnings.h"
#include "sampling/filter.h"
#include "render/camera.h"
#include "sampling/sampler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>

namespace fs = std::filesystem;

namespace drt::cli {

namespace {

// A NUL byte in the first 4 KiB: an image or other binary file given by
// mistake, which would otherwise produce thousands of lexer errors.
bool looksBinary(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char buffer[4096];
    in.read(buffer, sizeof buffer);
    return std::find(buffer, buffer + in.gcount(), '\0') != buffer + in.gcount();
}

} // namespace

// The front end for `path` as a function of the frame's clock: one front end
// for both dialects, then the files the scene names. The scene sees the image
// size it will be rendered at.
SceneEvaluator sceneEvaluator(const std::string& path, const PovCliOptions& pov, const RenderSettings& overrides) {
    return [path, pov, overrides](const FrameClock& frame, Diagnostics& diagnostics) -> std::optional<Scene> {
        LoadOptions options;
        if (!pov.dialect.empty()) options.dialect = dialectNamed(pov.dialect);
        options.strict = pov.strict;
        options.frame = frame;
        if (!pov.includePaths.empty()) {
            const std::string dir = fs::path(path).parent_path().string();
            options.includePaths.push_back(dir.empty() ? "." : dir);
            options.includePaths.insert(options.includePaths.end(), pov.includePaths.begin(), pov.includePaths.end());
            options.includePaths.push_back(kPovStandardIncludeDir);
        }
        if (overrides.width) options.imageWidth = *overrides.width;
        if (overrides.height) options.imageHeight = *overrides.height;
        const std::unique_ptr<SceneGeometryQuery> geometry = makeGeometryQuery();
        options.geometry = geometry.get();
        std::optional<Scene> scene = drt::loadScene(path, diagnostics, options);
        if (scene && !diagnostics.hasErrors()) resolveAssets(*scene, diagnostics);
        return scene;
    };
}

// At one frame's clock, moving over its shutter (animation.h evaluateFrame).
int loadScene(const std::string& path, std::ostream& err, std::optional<Scene>& scene, const PovCliOptions& pov,
              const RenderSettings& overrides, std::string* sceneSha1, const FrameClock& frame,
              const FrameOptions& frameOptions, FrameReport* report) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec) || !std::ifstream(path)) {
        err << fmt::format("drt: cannot read scene '{}': {}\n", path,
                           fs::exists(path, ec) ? "not a readable file" : "no such file");
        return kIoError;
    }
    if (looksBinary(path)) {
        err << fmt::format("drt: {}: not a scene file (it holds binary data)\n", path);
        return kSceneError;
    }
    Diagnostics diagnostics;
    scene = evaluateFrame(sceneEvaluator(path, pov, overrides), frame, frameOptions, diagnostics, report);
    if (sceneSha1) // the scene text read (the evaluations over the shutter read the same files)
        *sceneSha1 = sceneTextSha1(diagnostics.files());
    if (scene && !diagnostics.hasErrors()) {
        // The camera's problems (sky or up along the view, ...) are found by
        // check too, and reported at the camera.
        const RenderOptions size = resolveRenderOptions(overlaySettings(scene->render, overrides));
        try {
            resolveCamera(scene->camera, size.width, size.height);
        } catch (const RenderError& e) {
            diagnostics.error(scene->camera.loc, e.what());
        }
    }
    err << diagnostics.formatAll();
    if (scene && !diagnostics.hasErrors()) {
        // Apart from the front end's diagnostics, so that --strict does not make them errors.
        Diagnostics sceneWarnings(diagnostics.sharedFiles());
        warnAboutScene(*scene, path, sceneWarnings);
        err << sceneWarnings.formatAll();
    }
    if (diagnostics.hasErrors() || !scene) {
        err << fmt::format("drt: {}: {} error{}\n", path, diagnostics.errorCount(),
                           diagnostics.errorCount() == 1 ? "" : "s");
        return kSceneError;
    }
    return kSuccess;
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

namespace {

// No NaN or Inf may reach a file: replace them by 0 and count the pixels.
uint64_t clearNonFinite(Image& image) {
    uint64_t pixels = 0;
    for (size_t p = 0; p < image.pixels.size(); p += size_t(image.channels)) {
        bool bad = false;
        for (int c = 0; c < image.channels; ++c) {
            float& v = image.pixels[p + size_t(c)];
            if (!std::isfinite(v))
                v = 0, bad = true;
        }
        pixels += bad;
    }
    return pixels;
}

// The samples-per-pixel image: raw counts for a float file, else scaled so
// that the largest count is white.
Image sampleCountImage(const Image& counts, bool raw) {
    Image out = counts;
    if (raw) return out;
    float most = 0;
    for (float v : out.pixels) most = std::max(most, v);
    if (most > 0)
        for (float& v : out.pixels) v /= most;
    return out;
}

std::string millions(uint64_t n) {
    return fmt::format("{:.2f}M", double(n) / 1e6);
}

} // namespace

Metadata renderMetadata(const RenderCommand& command, const RenderOptions& options, const RenderIdentity& identity,
                        const RunRecord& record, const RenderStats& stats, uint64_t nonFinitePixels) {
    Provenance p = renderProvenance(command.scene, record.sceneSha1, options, record.filter);
    p.identify("drt:effects", describeEffects(stats.effects));
    p.identify("drt:samples_taken", std::to_string(stats.pixelSamples));
    if (options.adaptive)
        p.identify("drt:spp_range", fmt::format("{}-{}", stats.minPixelSamples, stats.maxPixelSamples));
    p.identify("drt:nonfinite_samples", std::to_string(stats.nonFiniteSamples));
    p.identify("drt:nonfinite_pixels", std::to_string(nonFinitePixels));
    // What crops are merged and checkpoints resumed by: the same for every run.
    Metadata identityEntries;
    addIdentity(identityEntries, identity, options.crop, options.width, options.height);
    for (const auto& [key, value] : identityEntries)
        p.identify(key, value);
    recordRun(p, options, stats, command.commandLine, record.started);
    return p.metadata(command.reproducible);
}

int runCheck(const std::string& scenePath, std::ostream& out, std::ostream& err) {
    return runCheck(scenePath, PovCliOptions{}, out, err);
}

int runCheck(const std::string& scenePath, const PovCliOptions& pov, std::ostream& out, std::ostream& err) {
    std::optional<Scene> scene;
    if (int status = loadScene(scenePath, err, scene, pov); status != kSuccess)
        return status;
    out << fmt::format("{}: ok ({} objects, {} lights)\n", scenePath, scene->objects.size(),
                       scene->lights.size());
    return kSuccess;
}

int checkOutputs(const RenderCommand& command, std::ostream& err) {
    if (std::string problem = checkWritable(command.output); !problem.empty()) {
        err << "drt: " << problem << "\n";
        return kIoError;
    }
    if (!command.varianceOutput.empty()) {
        if (lowerExtension(command.varianceOutput) != ".exr") {
            err << fmt::format("drt: the variance image '{}' must be an .exr file (it holds linear floats)\n",
                               command.varianceOutput);
            return kUsageError;
        }
        if (std::string problem = checkWritable(command.varianceOutput); !problem.empty()) {
            err << "drt: " << problem << "\n";
            return kIoError;
        }
    }
    if (!command.sppImageOutput.empty()) {
        if (std::string problem = checkWritable(command.sppImageOutput); !problem.empty()) {
            err << "drt: " << problem << "\n";
            return kIoError;
        }
    }
    if (!command.statsOutput.empty()) {
        const fs::path folder = fs::absolute(command.statsOutput).parent_path();
        std::error_code ec;
        if (!fs::is_directory(folder, ec)) {
            err << fmt::format("drt: cannot write '{}': the folder '{}' does not exist\n", command.statsOutput,
                               folder.string());
            return kIoError;
        }
    }
    return kSuccess;
}

std::string writeStatsJson(const RenderCommand& command, const RenderOptions& options, const RenderResult& result,
                           const RenderTimes& times) {
    const RenderStats& s = result.stats;
    const double traceSeconds = s.renderSeconds > 0 ? s.renderSeconds : times.renderSeconds;
    const nlohmann::json stats = {
        {"scene", command.scene},
        {"output", command.output},
        {"width", result.color.width},
        {"height", result.color.height},
        {"spp", options.samplesPerPixel},
        {"adaptive", options.adaptive},
        {"threads", options.threads},
        {"pixel_samples", s.pixelSamples},
        {"load_seconds", times.loadSeconds},
        {"build_seconds", s.buildSeconds},
        {"trace_seconds", traceSeconds},
        {"trace_cpu_seconds", s.traceCpuSeconds},
        {"render_seconds", times.renderSeconds},
        {"total_seconds", times.totalSeconds},
        {"camera_rays", s.cameraRays},
        {"shadow_rays", s.shadowRays},
        {"secondary_rays", s.secondaryRays},
        {"total_rays", s.totalRays()},
        {"mrays_per_second", traceSeconds > 0 ? double(s.totalRays()) / traceSeconds / 1e6 : 0.0},
        {"nonfinite_samples", s.nonFiniteSamples},
        {"untraceable_rays", s.untraceableRays},
    };
    const std::string temporary = command.statsOutput + ".tmp";
    {
        std::ofstream file(temporary);
        file << stats.dump(2) << "\n";
        if (!file.flush()) return fmt::format("cannot write '{}'", command.statsOutput);
    }
    std::error_code ec;
    fs::rename(temporary, command.statsOutput, ec);
    return ec ? fmt::format("cannot write '{}': {}", command.statsOutput, ec.message()) : "";
}

int writeOutputs(const RenderCommand& command, const RenderOptions& options, const RenderIdentity& identity,
                 const RunRecord& record, RenderResult& result, uint64_t& nonFinitePixels, std::ostream& err) {
    nonFinitePixels = clearNonFinite(result.color);
    const Metadata metadata = renderMetadata(command, options, identity, record, result.stats, nonFinitePixels);
    if (std::string problem = writeImage(command.output, result.color, metadata); !problem.empty()) {
        err << "drt: " << problem << "\n";
        return kIoError;
    }
    if (!command.varianceOutput.empty()) {
        clearNonFinite(result.variance);
        Metadata varianceMetadata = metadata;
        varianceMetadata.emplace_back("drt:content", "variance of the mean");
        if (std::string problem = writeImage(command.varianceOutput, result.variance, varianceMetadata);
            !problem.empty()) {
            err << "drt: " << problem << "\n";
            return kIoError;
        }
    }
    if (!command.sppImageOutput.empty()) {
        Metadata sppMetadata = metadata;
        Image counts = sampleCountImage(result.sampleCount, lowerExtension(command.sppImageOutput) == ".exr");
        sppMetadata.emplace_back("drt:content", "samples per pixel");
        if (std::string problem = writeImage(command.sppImageOutput, counts, sppMetadata); !problem.empty()) {
            err << "drt: " << problem << "\n";
            return kIoError;
        }
    }
    // The render is complete: a checkpoint left by an earlier, interrupted run is stale.
    std::error_code ec;
    fs::remove(checkpointPathFor(command.output), ec);
    return kSuccess;
}

void printSummary(const RenderCommand& command, const RenderOptions& options, const RenderResult& result,
                  uint64_t nonFinitePixels, double seconds, std::ostream& err) {
    const RenderStats& s = result.stats;
    const double traceSeconds = s.renderSeconds > 0 ? s.renderSeconds : seconds;
    const double pixels = double(result.color.width) * result.color.height;
    const std::string spp =
        options.adaptive ? fmt::format("{}-{} spp (mean {:.1f}, adaptive)", s.minPixelSamples, s.maxPixelSamples,
                                       double(s.pixelSamples) / pixels)
                         : fmt::format("{} spp", options.samplesPerPixel);
    err << fmt::format("drt: {} {}x{}{} at {} in {} (build {}, trace {}): {} samples, {:.2f} Mrays/s "
                       "(camera {}, shadow {}, secondary {}), {} NaN/Inf samples; effects: {}\n",
                       command.output, result.color.width, result.color.height,
                       options.crop ? fmt::format(" (crop {} of {}x{})", formatWindow(*options.crop), options.width,
                                                  options.height)
                                    : "",
                       spp, formatDuration(seconds), formatDuration(s.buildSeconds), formatDuration(traceSeconds),
                       millions(s.pixelSamples), traceSeconds > 0 ? double(s.totalRays()) / traceSeconds / 1e6 : 0.0,
                       millions(s.cameraRays), millions(s.shadowRays), millions(s.secondaryRays),
                       s.nonFiniteSamples + nonFinitePixels, describeEffects(s.effects));
}

} // namespace drt::cli

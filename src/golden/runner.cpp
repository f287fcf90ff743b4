// The golden-test runner: find the tests in a folder, render each scene with
// its sidecar's settings, and compare with (or, with --update, rewrite) its
// golden images. Scenes run concurrently as oneTBB tasks; each render also
// spreads its tiles over the cores, and TBB shares the threads between them.
#include "golden/golden.h"

#include "animation/animation.h"
#include "assets/assets.h"
#include "accel/geometry_query.h"
#include "lang/load.h"
#include "render/provenance.h"
#include "render/render.h"
#include "sampling/filter.h"
#include "sampling/sampler.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <fmt/format.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace drt::golden {

const char* outcomeName(Outcome outcome) {
    switch (outcome) {
    case Outcome::Pass:
        return "PASS";
    case Outcome::Fail:
        return "FAIL";
    case Outcome::Missing:
        return "MISSING";
    case Outcome::Error:
        return "ERROR";
    case Outcome::Updated:
        return "UPDATED";
    }
    return "?";
}

namespace {

constexpr const char* kSidecarSuffix = ".golden.json";

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The scene of a test without a "scene" key: NAME.drt, else NAME.pov.
GoldenCase makeCase(const fs::path& folder, const std::string& name, bool hasSidecar, const std::string& sceneExtension) {
    GoldenCase c;
    c.name = name;
    c.sidecarPath = hasSidecar ? (folder / (name + kSidecarSuffix)).string() : "";
    c.scenePath = (folder / (name + sceneExtension)).string();
    c.exrPath = (folder / (name + ".golden.exr")).string();
    c.pngPath = (folder / (name + ".golden.png")).string();
    c.variancePath = (folder / (name + ".golden.var.exr")).string();
    c.previewPath = (folder / (name + ".preview.png")).string();
    return c;
}

bool exists(const std::string& path) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

// A private scratch folder for format round trips, removed with the object.
class ScratchFolder {
  public:
    ScratchFolder() {
        static std::atomic<int> counter{0};
        std::error_code ec;
        path_ = fs::temp_directory_path(ec) / fmt::format("drt-golden-scratch-{}-{}", ::getpid(), counter++);
        fs::create_directories(path_, ec);
    }
    ~ScratchFolder() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

  private:
    fs::path path_;
};

// The candidate as the golden's file format stores it: written and read back
// through the one image I/O path (an 8-bit PNG quantises and sRGB-encodes).
std::string roundTrip(const Image& image, const std::string& goldenPath, const ScratchFolder& scratch,
                      const std::string& name, Image& stored) {
    const std::string path = scratch.file(name + ".candidate" + fs::path(goldenPath).extension().string());
    if (std::string problem = writeImage(path, image); !problem.empty())
        return problem;
    return readImage(path, stored);
}

bool allFinite(const Image& image) {
    for (float v : image.pixels)
        if (!std::isfinite(v))
            return false;
    return true;
}

bool bitIdentical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// Everything a case needs before rendering. Returns false with `result` set
// to the outcome if it cannot go on.
struct Prepared {
    GoldenSettings settings;
    Scene scene;
    RenderOptions options;
    std::string scenePath, sceneSha1;
};

bool prepare(const GoldenCase& c, bool update, Prepared& p, CaseResult& result) {
    if (c.sidecarPath.empty() && !update) {
        result.outcome = Outcome::Missing;
        result.message =
            fmt::format("no {}{} (create the golden with drt test --update)", c.name, kSidecarSuffix);
        return false;
    }
    if (!c.sidecarPath.empty()) {
        if (std::string problem = readSettings(c.sidecarPath, p.settings); !problem.empty()) {
            result.message = problem;
            return false;
        }
    }
    result.policy = p.settings.policy;
    result.settings = p.settings;
    result.format = p.settings.format;
    const std::string scenePath =
        p.settings.scene.empty()
            ? c.scenePath
            : (fs::path(c.sidecarPath).parent_path() / p.settings.scene).lexically_normal().string();
    result.scenePath = scenePath;
    if (!exists(scenePath)) {
        result.message = fmt::format("{}: no such scene file", scenePath);
        return false;
    }
    // Either dialect, by the extension; the scene sees the image size it is
    // rendered at (image_width, image_height) and the geometry (trace,
    // inside). The still frame `drt render` gives: clock 0, and with the
    // shutter open a scene that reads `clock` moves as its clock says
    // (animation/animation.h).
    const SceneEvaluator evaluate = [&scenePath, &p](const FrameClock& frame, Diagnostics& d) {
        LoadOptions load;
        load.imageWidth = p.settings.width.value_or(load.imageWidth);
        load.imageHeight = p.settings.height.value_or(load.imageHeight);
        load.frame = frame;
        const std::unique_ptr<SceneGeometryQuery> geometry = makeGeometryQuery();
        load.geometry = geometry.get();
        std::optional<Scene> evaluated = loadScene(scenePath, d, load);
        if (evaluated && !d.hasErrors()) resolveAssets(*evaluated, d);
        return evaluated;
    };
    Diagnostics diagnostics;
    std::optional<Scene> scene = evaluateFrame(evaluate, FrameClock{}, {}, diagnostics);
    p.scenePath = scenePath;
    p.sceneSha1 = sceneTextSha1(diagnostics.files());
    if (diagnostics.hasErrors() || !scene) {
        result.message = fmt::format("{}: the scene has {} error{}", scenePath, diagnostics.errorCount(),
                                     diagnostics.errorCount() == 1 ? "" : "s");
        result.details = diagnostics.formatAll();
        return false;
    }
    p.scene = std::move(*scene);
    RenderSettings overrides;
    overrides.width = p.settings.width;
    overrides.height = p.settings.height;
    overrides.samplesPerPixel = p.settings.samplesPerPixel;
    overrides.seed = p.settings.seed;
    overrides.sampler = p.settings.sampler;
    overrides.threads = p.settings.threads;
    p.options = resolveRenderOptions(overlaySettings(p.scene.render, overrides));
    return true;
}

// Reproducible metadata (no run details), so rewriting an unchanged golden
// leaves its file byte for byte the same.
Metadata goldenMetadata(const GoldenCase& c, const Prepared& p, const RenderOptions& o) {
    Provenance provenance =
        renderProvenance(p.scenePath, p.sceneSha1, o, p.scene.render.filter.value_or(defaultFilterName()));
    provenance.identify("drt:golden", c.name);
    provenance.identify("drt:policy", policyName(p.settings.policy));
    return provenance.metadata(true);
}

// --update: render the golden (at reference_spp for a statistical one) and
// write the images and a complete sidecar.
void updateCase(const GoldenCase& c, Prepared& p, CaseResult& result) {
    GoldenSettings& s = p.settings;
    // Freeze every setting in the sidecar, so a later change of the scene's
    // render block shows up as a failure rather than a silently different test.
    s.width = p.options.width;
    s.height = p.options.height;
    s.samplesPerPixel = p.options.samplesPerPixel;
    s.seed = p.options.seed;
    s.sampler = p.options.sampler.empty() ? defaultSamplerName() : p.options.sampler;
    RenderOptions options = p.options;
    if (s.policy == Policy::Statistical) {
        s.referenceSamplesPerPixel = options.samplesPerPixel =
            s.referenceSamplesPerPixel.value_or(64 * p.options.samplesPerPixel);
        s.referenceSeed = options.seed = s.referenceSeed.value_or(p.options.seed + 1);
    }
    RenderResult rendered = render(p.scene, options);
    if (!allFinite(rendered.color) || !allFinite(rendered.variance)) {
        result.message = "the render has NaN or Inf pixels: not writing a golden";
        return;
    }
    const Metadata metadata = goldenMetadata(c, p, options);
    std::vector<std::string> written;
    const bool png = s.format != "exr";
    const bool exr = s.format != "png";
    for (const auto& [wanted, path] : {std::pair{exr, c.exrPath}, std::pair{png, c.pngPath}}) {
        if (!wanted)
            continue;
        if (std::string problem = writeImage(path, rendered.color, metadata); !problem.empty()) {
            result.message = problem;
            return;
        }
        written.push_back(fs::path(path).filename().string());
    }
    if (!png) {
        // An 8-bit view of the EXR golden for code review (a PNG golden is its own view).
        Metadata previewMetadata = metadata;
        previewMetadata.emplace_back("drt:content", "preview of " + fs::path(c.exrPath).filename().string());
        if (std::string problem = writeImage(c.previewPath, rendered.color, previewMetadata); !problem.empty()) {
            result.message = problem;
            return;
        }
        written.push_back(fs::path(c.previewPath).filename().string());
    }
    if (s.policy == Policy::Statistical) {
        Metadata varianceMetadata = metadata;
        varianceMetadata.emplace_back("drt:content", "variance of the mean");
        if (std::string problem = writeImage(c.variancePath, rendered.variance, varianceMetadata);
            !problem.empty()) {
            result.message = problem;
            return;
        }
        written.push_back(fs::path(c.variancePath).filename().string());
    }
    const std::string sidecar =
        c.sidecarPath.empty() ? (fs::path(c.scenePath).parent_path() / (c.name + kSidecarSuffix)).string()
                              : c.sidecarPath;
    if (std::string problem = writeSettings(sidecar, s); !problem.empty()) {
        result.message = problem;
        return;
    }
    if (c.sidecarPath.empty())
        written.push_back(fs::path(sidecar).filename().string());
    result.outcome = Outcome::Updated;
    std::string files;
    for (const std::string& f : written)
        files += (files.empty() ? "" : ", ") + f;
    result.message = fmt::format("wrote {} ({}x{}, {} spp, seed {})", files, options.width, options.height,
                                 options.samplesPerPixel, options.seed);
}

// Sets the outcome from a comparison.
void judge(const CompareResult& comparison, bool exactZeroTolerance, bool identical, CaseResult& result) {
    result.comparison = comparison;
    if (comparison.status == CompareStatus::SizeMismatch || comparison.status == CompareStatus::Fail) {
        result.outcome = Outcome::Fail;
        result.message = comparison.message;
    } else if (exactZeroTolerance && !identical) {
        // Equal values with different bits: +0 against -0.
        result.outcome = Outcome::Fail;
        result.message = "pixels are equal in value but not bit-identical (signed zeros)";
    } else {
        result.outcome = Outcome::Pass;
        result.message = comparison.status == CompareStatus::Warn ? comparison.message : "";
    }
}

void compareExact(const GoldenCase& c, const Prepared& p, const Image& candidate, CaseResult& result) {
    const GoldenSettings& s = p.settings;
    CompareOptions options;
    options.failThreshold = options.warnThreshold = s.failThreshold;
    options.failPercent = options.warnPercent = s.failPercent;
    const bool zeroTolerance = s.failThreshold == 0 && s.failPercent == 0;
    ScratchFolder scratch;
    // Every golden format the sidecar names must match; the first failure is kept.
    for (const std::string& path : {c.exrPath, c.pngPath}) {
        if ((path == c.exrPath && s.format == "png") || (path == c.pngPath && s.format == "exr"))
            continue;
        Image golden, stored;
        if (std::string problem = readImage(path, golden); !problem.empty()) {
            result.outcome = Outcome::Error;
            result.message = problem;
            return;
        }
        if (std::string problem = roundTrip(candidate, path, scratch, c.name, stored); !problem.empty()) {
            result.outcome = Outcome::Error;
            result.message = problem;
            return;
        }
        const CompareResult comparison = compareImages(stored, golden, options);
        judge(comparison, zeroTolerance, bitIdentical(stored, golden), result);
        if (result.outcome != Outcome::Pass) {
            result.message = fmt::format("{}: {}", fs::path(path).filename().string(), result.message);
            result.candidate = std::move(stored);
            result.golden = std::move(golden);
            return;
        }
    }
}

void compareStatistical(const GoldenCase& c, const Prepared& p, RenderResult& rendered, CaseResult& result) {
    Image golden, goldenVariance;
    for (auto [path, image] : {std::pair{&c.exrPath, &golden}, std::pair{&c.variancePath, &goldenVariance}}) {
        if (std::string problem = readImage(*path, *image); !problem.empty()) {
            result.outcome = Outcome::Error;
            result.message = problem;
            return;
        }
    }
    CompareOptions options;
    options.alpha = p.settings.alpha;
    options.tileSize = p.settings.tileSize;
    // The candidate's own variance estimate is poor at low spp, and 0 where its
    // few samples all agreed although the golden's many found rare events (a
    // far edge seen through the lens). The per-sample variance of a pixel is a
    // property of the scene, estimated far better by the golden:
    // sigma^2 = Var_golden * N_golden, so Var_candidate >= sigma^2 / N_candidate.
    // (A stratified sampler's true variance is lower still: conservative.)
    const double scale =
        double(p.settings.referenceSamplesPerPixel.value_or(64 * p.options.samplesPerPixel)) /
        double(p.options.samplesPerPixel);
    if (goldenVariance.pixels.size() == rendered.variance.pixels.size())
        for (size_t i = 0; i < goldenVariance.pixels.size(); ++i)
            rendered.variance.pixels[i] =
                std::fmax(rendered.variance.pixels[i], float(goldenVariance.pixels[i] * scale));
    VarianceImages variance;
    variance.reference = &goldenVariance;
    variance.candidate = &rendered.variance;
    const CompareResult comparison = compareImages(rendered.color, golden, options, variance);
    judge(comparison, false, false, result);
    if (result.outcome != Outcome::Pass) {
        result.candidate = std::move(rendered.color);
        result.candidateVariance = std::move(rendered.variance);
        result.golden = std::move(golden);
        result.goldenVariance = std::move(goldenVariance);
    }
}

CaseResult runCase(const GoldenCase& c, bool update) {
    const auto start = std::chrono::steady_clock::now();
    CaseResult result;
    result.name = c.name;
    result.outcome = Outcome::Error;
    Prepared p;
    try {
        if (prepare(c, update, p, result)) {
            const bool isExact = p.settings.policy == Policy::Exact;
            const std::string format = p.settings.format;
            const bool haveGolden = (format == "png" || exists(c.exrPath)) &&
                                    (format == "exr" || exists(c.pngPath)) &&
                                    (isExact || exists(c.variancePath));
            if (update) {
                updateCase(c, p, result);
            } else if (!haveGolden) {
                result.outcome = Outcome::Missing;
                const std::string images = format == "both" ? c.name + ".golden.exr and .png"
                                           : isExact        ? c.name + ".golden." + format
                                                            : c.name + ".golden.exr and .golden.var.exr";
                result.message = fmt::format("no {} (create it with drt test --update)", images);
            } else {
                RenderResult rendered = render(p.scene, p.options);
                if (isExact)
                    compareExact(c, p, rendered.color, result);
                else
                    compareStatistical(c, p, rendered, result);
            }
        }
    } catch (const std::exception& e) {
        result.outcome = Outcome::Error;
        result.message = fmt::format("render failed: {}", e.what());
    }
    if (const std::string& view = result.format == "exr" ? c.previewPath : c.pngPath; exists(view))
        result.previewPath = view;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace

std::string discoverCases(const std::string& folder, std::vector<GoldenCase>& cases) {
    cases.clear();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return fmt::format("{}: not a folder", folder);
    std::vector<std::string> sidecars;
    std::map<std::string, std::string> scenes; // name -> extension (.drt preferred over .pov)
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (!it->is_regular_file(ec))
            continue;
        if (endsWith(file, kSidecarSuffix)) {
            sidecars.push_back(file.substr(0, file.size() - std::strlen(kSidecarSuffix)));
        } else {
            for (const char* extension : {".drt", ".pov"})
                if (endsWith(file, extension)) {
                    std::string& known = scenes[file.substr(0, file.size() - 4)];
                    if (known.empty() || std::string(extension) == ".drt")
                        known = extension;
                }
        }
    }
    if (ec)
        return fmt::format("{}: cannot list the folder: {}", folder, ec.message());
    for (const std::string& name : sidecars)
        cases.push_back(makeCase(folder, name, true, scenes.count(name) ? scenes[name] : ".drt"));
    for (const auto& [name, extension] : scenes)
        if (std::find(sidecars.begin(), sidecars.end(), name) == sidecars.end())
            cases.push_back(makeCase(folder, name, false, extension));
    std::sort(cases.begin(), cases.end(),
              [](const GoldenCase& a, const GoldenCase& b) { return a.name < b.name; });
    return "";
}

RunSummary runGoldenTests(const std::string& folder, const RunOptions& options, std::string& error) {
    const auto start = std::chrono::steady_clock::now();
    RunSummary summary;
    summary.folder = folder;
    std::vector<GoldenCase> cases;
    error = discoverCases(folder, cases);
    if (!error.empty())
        return summary;
    if (!options.only.empty()) {
        for (const std::string& name : options.only)
            if (std::none_of(cases.begin(), cases.end(),
                             [&](const GoldenCase& c) { return c.name == name; })) {
                error = fmt::format("{}: no test named '{}'", folder, name);
                return summary;
            }
        std::erase_if(cases, [&](const GoldenCase& c) {
            return std::find(options.only.begin(), options.only.end(), c.name) == options.only.end();
        });
    }
    summary.cases.resize(cases.size());
    tbb::parallel_for(size_t(0), cases.size(), [&](size_t i) {
        summary.cases[i] = runCase(cases[i], options.update);
        if (options.onCaseDone)
            options.onCaseDone(summary.cases[i]);
    });
    for (const CaseResult& r : summary.cases) {
        switch (r.outcome) {
        case Outcome::Pass:
            ++summary.passed;
            break;
        case Outcome::Fail:
            ++summary.failed;
            break;
        case Outcome::Missing:
            ++summary.missing;
            break;
        case Outcome::Error:
            ++summary.errors;
            break;
        case Outcome::Updated:
            ++summary.updated;
            break;
        }
    }
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

} // namespace drt::golden

// The runner of the drt-against-POV-Ray benchmark (versus.h): references,
// interleaved timed renders, then the tables and charts (versus_report.cpp).
#include "versus.h"

#include "bench/agreement.h"
#include "bench/reference.h"
#include "compare/compare.h"
#include "image/image.h"
#include "versus_report.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <sys/stat.h>

namespace fs = std::filesystem;

namespace drt::perf {

namespace {

// drt's reference is the mean of at least 4 and at most 16 renders; it stops
// once its own noise is a tenth of the smallest target.
constexpr int kDrtReferenceMinParts = 4, kDrtReferenceMaxParts = 16;
constexpr uint64_t kDrtReferenceSeed = 1001;

struct Context {
    const VersusOptions& options;
    std::ostream& log;
    fs::path references, work;
};

// What identifies a binary's build: its path, size and modification time.
std::string binaryIdentity(const std::string& path) {
    struct stat s {};
    if (stat(path.c_str(), &s) != 0)
        return path;
    return fmt::format("{} {} {}", path, s.st_size, s.st_mtim.tv_sec);
}

// A cached reference is reused when its sidecar records the same identity.
bool cached(const fs::path& image, const std::string& identity) {
    std::error_code ec;
    if (!fs::exists(image, ec))
        return false;
    try {
        const nlohmann::json sidecar = nlohmann::json::parse(readTextFile(image.string() + ".json"));
        return sidecar.at("identity") == identity;
    } catch (const nlohmann::json::exception&) {
        return false;
    }
}

void recordIdentity(const fs::path& image, const std::string& identity, double seconds, int parts = 1) {
    writeTextFile(image.string() + ".json",
                  nlohmann::json{{"identity", identity}, {"seconds", seconds}, {"parts", parts}}.dump(2));
}

std::vector<std::string> povArguments(const Context& c, const std::string& scene, const std::string& output,
                                      const PovSetting& setting, const std::string& sceneFolder) {
    std::vector<std::string> args = {"+I" + scene,
                                     "+O" + output,
                                     "+FE", // OpenEXR: linear half floats, not clipped (8-bit PNG would be)
                                     fmt::format("+W{}", c.options.width),
                                     fmt::format("+H{}", c.options.height),
                                     "-D",
                                     fmt::format("+WT{}", c.options.threads),
                                     "+L" + sceneFolder};
    args.insert(args.end(), setting.flags.begin(), setting.flags.end());
    return args;
}

// Writes the setting's copy of the scene into the work folder; returns its file name.
std::string writeSceneCopy(const Context& c, const std::string& text, const PovSetting& setting,
                           const std::string& stem) {
    const std::string name = stem + ".pov";
    writeTextFile((c.work / name).string(), setting.edit(text));
    return name;
}

// POV-Ray's reference for one setting (rendered once, cached).
Image povReferenceImage(const Context& c, const VersusScene& scene, const std::string& text,
                        const PovSetting& setting, const std::string& stem, const std::string& sceneFolder) {
    const fs::path image = c.references / (stem + ".exr");
    const std::string identity =
        fmt::format("{} | {} | {} | {}x{} | {} threads", povrayVersion(), scene.file, setting.name,
                    c.options.width, c.options.height, c.options.threads);
    if (cached(image, identity)) {
        c.log << fmt::format("versus: {}: reusing {}\n", scene.name, image.string());
        return readImageOrThrow(image.string());
    }
    c.log << fmt::format("versus: {}: POV-Ray reference ({})...\n", scene.name, setting.name);
    const std::string file = writeSceneCopy(c, text, setting, stem);
    const PovRender run =
        runPovray(povArguments(c, file, fs::absolute(image).string(), setting, sceneFolder), c.work.string());
    if (!run.process.succeeded())
        throw std::runtime_error(
            fmt::format("POV-Ray failed on {}:\n{}", file, lastLines(run.process.output)));
    recordIdentity(image, identity, run.process.wallSeconds);
    c.log << fmt::format("versus: {}: POV-Ray reference done in {:.1f} s\n", scene.name,
                         run.process.wallSeconds);
    return readImageOrThrow(image.string());
}

// drt's reference: the mean of independent renders (seeds apart) and the
// variance of that mean from their spread (bench/reference.h).
bench::AveragedImage drtReferenceImage(const Context& c, const VersusScene& scene,
                                       const std::string& scenePath, int spp, int& partsUsed) {
    const double noiseGoal = *std::min_element(c.options.targets.begin(), c.options.targets.end()) / 10;
    const DrtBinary& drt = c.options.drt.front();
    const fs::path image = c.references / (scene.name + "-drt.exr");
    const fs::path variance = c.references / (scene.name + "-drt.variance.exr");
    const std::string identity = fmt::format(
        "{} | {} | {}x{} | parts of {} spp, noise <= {:.1e} | seeds from {}", binaryIdentity(drt.path),
        scene.file, c.options.width, c.options.height, spp, noiseGoal, kDrtReferenceSeed);
    if (cached(image, identity) && fs::exists(variance)) {
        c.log << fmt::format("versus: {}: reusing {}\n", scene.name, image.string());
        try {
            partsUsed = nlohmann::json::parse(readTextFile(image.string() + ".json")).at("parts");
        } catch (const nlohmann::json::exception&) {
        }
        return {readImageOrThrow(image.string()), readImageOrThrow(variance.string())};
    }
    c.log << fmt::format(
        "versus: {}: drt reference ({}, renders of {} spp until its noise is below {:.1e})...\n", scene.name,
        drt.label, spp, noiseGoal);
    std::vector<Image> parts;
    double seconds = 0;
    const int maxParts = c.options.quick ? kDrtReferenceMaxParts / 2 : kDrtReferenceMaxParts;
    for (int k = 0; k < maxParts; ++k) {
        const std::string part = (c.work / fmt::format("{}-drt-reference-{}.exr", scene.name, k)).string();
        const DrtRender run = runDrtRender(drt, scenePath, part,
                                           {"--width", std::to_string(c.options.width), "--height",
                                            std::to_string(c.options.height), "--spp", std::to_string(spp),
                                            "--threads", std::to_string(c.options.threads), "--seed",
                                            std::to_string(kDrtReferenceSeed + uint64_t(k)), "--quiet"},
                                           c.work.string());
        if (!run.process.succeeded())
            throw std::runtime_error(
                fmt::format("drt failed on {}:\n{}", scenePath, lastLines(run.process.output)));
        parts.push_back(readImageOrThrow(part));
        seconds += run.process.wallSeconds;
        fs::remove(part);
        if (parts.size() >= size_t(kDrtReferenceMinParts)) {
            const bench::AveragedImage sofar = bench::averageImages(parts);
            const double noise = bench::referenceNoise(sofar.mean, sofar.varianceOfMean);
            c.log << fmt::format("versus: {}: drt reference of {} x {} spp: noise {:.2e}\n", scene.name,
                                 parts.size(), spp, noise);
            if (noise <= noiseGoal)
                break;
        }
    }
    bench::AveragedImage reference = bench::averageImages(parts);
    const Metadata metadata = {{"drt:versus_reference", identity}};
    for (const auto& [path, picture] :
         {std::pair{image, &reference.mean}, std::pair{variance, &reference.varianceOfMean}})
        if (std::string problem = writeImage(path.string(), *picture, metadata); !problem.empty())
            throw std::runtime_error(problem);
    partsUsed = int(parts.size());
    recordIdentity(image, identity, seconds, partsUsed);
    c.log << fmt::format("versus: {}: drt reference done in {:.1f} s\n", scene.name, seconds);
    return reference;
}

double relMse(const std::string& candidatePath, const Image& reference) {
    Image candidate;
    if (!readImage(candidatePath, candidate).empty())
        return NAN;
    if (candidate.width != reference.width || candidate.height != reference.height)
        return NAN;
    return compareImages(candidate, reference).relMse;
}

// One timed render of either renderer, in the interleaved order.
struct Job {
    bool povray = false;
    size_t drtIndex = 0; // which drt binary
    size_t setting = 0;  // index into the settings (POV-Ray) or the spp list (drt)
};

SceneResult runScene(const Context& c, const VersusScene& scene) {
    const std::string scenePath = (fs::path(c.options.povExamples) / scene.file).string();
    const std::string sceneFolder = fs::path(scenePath).parent_path().string();
    const std::string text = readTextFile(scenePath);
    if (text.empty())
        throw std::runtime_error(fmt::format("cannot read '{}'", scenePath));
    const bool quick = c.options.quick;
    const std::vector<PovSetting>& povSettings = quick ? scene.quickPovSettings : scene.povSettings;
    const std::vector<int>& spps = quick ? scene.quickDrtSpp : scene.drtSpp;

    SceneResult result;
    result.scene = scene.name;
    result.povReferenceSetting = (quick ? scene.quickPovReference : scene.povReference).name;
    result.povReferenceHalfSetting = (quick ? scene.quickPovReferenceHalf : scene.povReferenceHalf).name;
    const Image povReference =
        povReferenceImage(c, scene, text, quick ? scene.quickPovReference : scene.povReference,
                          scene.name + "-povray", sceneFolder);
    const Image povHalf =
        povReferenceImage(c, scene, text, quick ? scene.quickPovReferenceHalf : scene.povReferenceHalf,
                          scene.name + "-povray-half", sceneFolder);
    const int referenceSpp = quick ? scene.quickDrtReferenceSpp : scene.drtReferenceSpp;
    int parts = 0;
    const bench::AveragedImage drtReference = drtReferenceImage(c, scene, scenePath, referenceSpp, parts);
    result.drtReferenceSetting =
        fmt::format("{} x {} spp by {}", parts, referenceSpp, c.options.drt.front().label);
    result.drtReferenceNoise = bench::referenceNoise(drtReference.mean, drtReference.varianceOfMean);
    result.povReferenceSelfError = compareImages(povHalf, povReference).relMse;
    result.agreement = bench::compareReferences(drtReference.mean, povReference);

    for (size_t i = 0; i < povSettings.size(); ++i)
        writeSceneCopy(c, text, povSettings[i], fmt::format("{}-setting-{}", scene.name, i));

    // Interleaved: every repetition walks all settings of all renderers in
    // turn, so a change of machine load hits each renderer alike.
    std::vector<Job> jobs;
    for (size_t i = 0; i < std::max(povSettings.size(), spps.size()); ++i) {
        if (i < povSettings.size())
            jobs.push_back({true, 0, i});
        for (size_t d = 0; d < c.options.drt.size() && i < spps.size(); ++d)
            jobs.push_back({false, d, i});
    }
    const int repetitions = c.options.repetitions > 0 ? c.options.repetitions : 3;
    // A drt binary stops climbing its spp list (for every repetition) once a
    // render in the first repetition is well below the smallest target (the
    // curve already brackets every target) or took longer than the budget
    // (the next count would take about twice as long): CPU time, a budget per
    // thread, since on a shared machine the wall time of a render says more
    // about the other programs than about it.
    const double enough = *std::min_element(c.options.targets.begin(), c.options.targets.end()) / 3;
    const double budgetSeconds = quick ? 20 : 60;
    std::vector<size_t> sppLimit(c.options.drt.size(), spps.size());
    const std::string candidate = (c.work / (scene.name + "-candidate.exr")).string();
    for (int rep = 1; rep <= repetitions; ++rep) {
        for (const Job& job : jobs) {
            RunRow row;
            row.scene = scene.name;
            row.repetition = rep;
            fs::remove(candidate);
            if (job.povray) {
                const PovSetting& setting = povSettings[job.setting];
                row.renderer = "POV-Ray";
                row.setting = setting.name;
                const PovRender run =
                    runPovray(povArguments(c, fmt::format("{}-setting-{}.pov", scene.name, job.setting),
                                           candidate, setting, sceneFolder),
                              c.work.string());
                row.process = run.process;
                row.reportedSeconds = run.reportedSeconds();
                row.relMseRaw = run.process.succeeded() ? relMse(candidate, povReference) : NAN;
                row.relMse = row.relMseRaw;
            } else {
                if (job.setting >= sppLimit[job.drtIndex])
                    continue;
                const DrtBinary& drt = c.options.drt[job.drtIndex];
                row.renderer = "drt " + drt.label;
                row.setting = fmt::format("{} spp", spps[job.setting]);
                row.spp = spps[job.setting];
                std::vector<std::string> args = {"--width", std::to_string(c.options.width), "--height",
                                                 std::to_string(c.options.height)};
                const std::vector<std::string> samples = drtSampleArgs(drt, spps[job.setting]);
                args.insert(args.end(), samples.begin(), samples.end());
                args.insert(args.end(),
                            {"--threads", std::to_string(c.options.threads), "--seed", std::to_string(rep)});
                const DrtRender run = runDrtRender(drt, scenePath, candidate, args, c.work.string());
                row.process = run.process;
                row.reportedSeconds = run.reported && run.loadSeconds >= 0
                                          ? run.loadSeconds + run.renderSeconds()
                                      : run.reported ? run.renderSeconds()
                                                     : -1;
                row.reportedIncludesParse = run.loadSeconds >= 0;
                row.relMseRaw = run.process.succeeded() ? relMse(candidate, drtReference.mean) : NAN;
                // E[relMSE against a noisy reference] = relMSE + the reference's noise: take it out.
                row.relMse = row.relMseRaw - result.drtReferenceNoise;
            }
            if (!row.process.succeeded())
                c.log << fmt::format("versus: {} {} ({}) failed:\n{}\n", scene.name, row.renderer,
                                     row.setting, lastLines(row.process.output));
            c.log << fmt::format(
                "versus: {} rep {}/{}: {:<12} {:<32} {:6.2f} s wall {:6.2f} s cpu  relMSE {:.3e}\n",
                scene.name, rep, repetitions, row.renderer, row.setting, row.process.wallSeconds,
                row.process.cpuSeconds(), row.relMse);
            if (!job.povray && rep == 1 &&
                (row.relMse < enough || row.process.cpuSeconds() > budgetSeconds * c.options.threads ||
                 !row.process.succeeded())) {
                sppLimit[job.drtIndex] = job.setting + 1;
                c.log << fmt::format("versus: {}: {} stops at {} (relMSE {:.2e}, {:.1f} s)\n", scene.name,
                                     row.renderer, row.setting, row.relMse, row.process.wallSeconds);
            }
            result.rows.push_back(std::move(row));
        }
    }
    fs::remove(candidate);
    return result;
}

} // namespace

int runVersusPovray(const VersusOptions& options, std::ostream& log) {
    if (options.drt.empty()) {
        log << "versus: no drt binary given\n";
        return 2;
    }
    if (povrayVersion().empty()) {
        log << "versus: POV-Ray is not installed (apt-get install povray povray-examples povray-includes)\n";
        return 3;
    }
    Context c{options, log, fs::path(options.outputDir) / "references", fs::path(options.outputDir) / "work"};
    std::error_code ec;
    fs::create_directories(c.references, ec);
    fs::create_directories(c.work, ec);
    if (ec) {
        log << fmt::format("versus: cannot create '{}': {}\n", options.outputDir, ec.message());
        return 3;
    }
    VersusReport report;
    report.options = options;
    report.machine = machineDescription();
    report.povray = povrayVersion();
    report.loadBefore = loadAverage();
    try {
        for (const VersusScene& scene : versusScenes()) {
            if (!options.scenes.empty() &&
                std::find(options.scenes.begin(), options.scenes.end(), scene.name) == options.scenes.end())
                continue;
            report.scenes.push_back(runScene(c, scene));
        }
        report.loadAfter = loadAverage();
        writeVersusReport(report, options.outputDir);
    } catch (const std::exception& e) {
        log << fmt::format("versus: {}\n", e.what());
        return 1;
    }
    log << fmt::format("versus: wrote {}/summary.md\n", options.outputDir);
    return 0;
}

} // namespace drt::perf

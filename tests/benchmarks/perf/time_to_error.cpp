// drt_perf time-to-error (time_to_error.h): the sweep, the reference, the table.
#include "time_to_error.h"

#include "bench/agreement.h"
#include "bench/equal_error.h"
#include "bench/reference.h"
#include "bench/stats.h"
#include "compare/compare.h"
#include "image/image.h"
#include "versus_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <ostream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace drt::perf {

namespace {

constexpr int kReferenceMinParts = 4, kReferenceMaxParts = 16;
constexpr uint64_t kReferenceSeed = 1001; // candidates use seeds 1, 2, ...

struct Render {
    size_t drt = 0;
    int spp = 0, repetition = 0;
    std::string image;
    DrtRender run;
    double relMse = NAN; // against the reference, its noise taken out
};

// The median relMSE at each spp of one drt, and its best curve on wall or CPU time.
std::vector<bench::SettingPoint> points(const std::vector<Render>& renders, size_t drt, bool cpu) {
    std::map<int, std::pair<std::vector<double>, std::vector<double>>> bySpp;
    for (const Render& r : renders)
        if (r.drt == drt && r.run.process.succeeded()) {
            bySpp[r.spp].first.push_back(cpu ? r.run.process.cpuSeconds() : r.run.process.wallSeconds);
            bySpp[r.spp].second.push_back(r.relMse);
        }
    std::vector<bench::SettingPoint> out;
    for (const auto& [spp, values] : bySpp)
        out.push_back(bench::medianPoint(fmt::format("{} spp", spp), values.first, values.second));
    return out;
}

double medianOf(const std::vector<Render>& renders, size_t drt, int spp, double (*value)(const Render&)) {
    std::vector<double> values;
    for (const Render& r : renders)
        if (r.drt == drt && r.spp == spp && r.run.process.succeeded())
            values.push_back(value(r));
    return bench::median(values);
}

double targetOf(const std::vector<Render>& renders, size_t targetDrt, int targetSpp) {
    return medianOf(renders, targetDrt, targetSpp, [](const Render& r) { return r.relMse; });
}

void measure(std::vector<Render>& renders, const bench::AveragedImage& reference, double noise) {
    for (Render& r : renders) {
        if (!r.run.process.succeeded())
            continue;
        const Image candidate = readImageOrThrow(r.image);
        r.relMse = compareImages(candidate, reference.mean).relMse - noise;
    }
}

} // namespace

int runTimeToError(const TimeToErrorOptions& o, std::ostream& log) {
    if (o.drt.empty()) {
        log << "time-to-error: no drt binary given\n";
        return 2;
    }
    size_t targetDrt = o.drt.size() - 1;
    if (!o.target.empty()) {
        const auto it =
            std::find_if(o.drt.begin(), o.drt.end(), [&](const DrtBinary& d) { return d.label == o.target; });
        if (it == o.drt.end()) {
            log << fmt::format("time-to-error: no --drt labelled '{}'\n", o.target);
            return 2;
        }
        targetDrt = size_t(it - o.drt.begin());
    }
    std::vector<int> spps = o.spp;
    if (std::find(spps.begin(), spps.end(), o.targetSpp) == spps.end())
        spps.push_back(o.targetSpp);
    std::sort(spps.begin(), spps.end());
    const std::string scene =
        fs::absolute(o.scene.empty() ? std::string(DRT_SOURCE_DIR) + "/examples/cook.drt" : o.scene).string();
    const fs::path work = fs::path(o.outputDir) / "work";
    std::error_code ec;
    fs::create_directories(work, ec);
    if (ec) {
        log << fmt::format("time-to-error: cannot create '{}': {}\n", work.string(), ec.message());
        return 3;
    }
    const int repetitions = o.repetitions > 0 ? o.repetitions : 3;
    const std::vector<std::string> threads = {"--threads", std::to_string(o.threads)};

    try {
        // The timed renders, interleaved: each repetition walks every spp of every drt.
        std::vector<Render> renders;
        for (int rep = 1; rep <= repetitions; ++rep)
            for (int spp : spps)
                for (size_t d = 0; d < o.drt.size(); ++d) {
                    Render r{d,
                             spp,
                             rep,
                             (work / fmt::format("{}-{}spp-{}.exr", o.drt[d].label, spp, rep)).string(),
                             {}};
                    std::vector<std::string> args = drtSampleArgs(o.drt[d], spp);
                    args.insert(args.end(), {"--seed", std::to_string(rep)});
                    args.insert(args.end(), threads.begin(), threads.end());
                    r.run = runDrtRender(o.drt[d], scene, r.image, args, work.string());
                    if (!r.run.process.succeeded())
                        throw std::runtime_error(fmt::format("drt {} failed on {}:\n{}", o.drt[d].label,
                                                             scene, lastLines(r.run.process.output)));
                    log << fmt::format(
                        "time-to-error: rep {}/{} drt {:<8} {:4} spp {:7.2f} s wall {:7.2f} s cpu\n", rep,
                        repetitions, o.drt[d].label, spp, r.run.process.wallSeconds,
                        r.run.process.cpuSeconds());
                    renders.push_back(std::move(r));
                }

        // The reference: renders by the first drt until its noise is a tenth of the target.
        std::vector<Image> parts;
        bench::AveragedImage reference;
        double noise = 0, target = NAN;
        for (int k = 0; k < kReferenceMaxParts; ++k) {
            const std::string part = (work / fmt::format("reference-{}.exr", k)).string();
            std::vector<std::string> args = {"--spp", std::to_string(o.referenceSpp), "--seed",
                                             std::to_string(kReferenceSeed + uint64_t(k)), "--quiet"};
            args.insert(args.end(), threads.begin(), threads.end());
            const DrtRender run = runDrtRender(o.drt.front(), scene, part, args, work.string());
            if (!run.process.succeeded())
                throw std::runtime_error(fmt::format("drt {} failed on {}:\n{}", o.drt.front().label, scene,
                                                     lastLines(run.process.output)));
            parts.push_back(readImageOrThrow(part));
            fs::remove(part, ec);
            if (parts.size() < size_t(kReferenceMinParts))
                continue;
            reference = bench::averageImages(parts);
            noise = bench::referenceNoise(reference.mean, reference.varianceOfMean);
            measure(renders, reference, noise);
            target = targetOf(renders, targetDrt, o.targetSpp);
            log << fmt::format("time-to-error: reference of {} x {} spp: noise {:.2e}, target {:.2e}\n",
                               parts.size(), o.referenceSpp, noise, target);
            if (noise <= target / 10)
                break;
        }

        // Tables.
        Csv csv;
        csv.header = {"drt",          "spp",         "repetition",  "wall_seconds",   "cpu_seconds",
                      "peak_rss_mib", "camera_rays", "shadow_rays", "secondary_rays", "relmse"};
        for (const Render& r : renders)
            csv.rows.push_back({o.drt[r.drt].label, std::to_string(r.spp), std::to_string(r.repetition),
                                fmt::format("{:.4f}", r.run.process.wallSeconds),
                                fmt::format("{:.4f}", r.run.process.cpuSeconds()),
                                fmt::format("{:.1f}", r.run.process.peakRssMiB),
                                std::to_string(r.run.cameraRays), std::to_string(r.run.shadowRays),
                                std::to_string(r.run.secondaryRays), fmt::format("{:.4e}", r.relMse)});

        const std::string targetLabel = o.drt[targetDrt].label;
        std::string md = fmt::format(
            "# Time to an equal error on `{}`\n\n- Machine: {}; load average {} at the end.\n- {} threads; "
            "medians of {} runs, interleaved; time = the whole `drt render` process (wall, and CPU = user + "
            "system).\n- Target: relMSE {:.3e}, the median of drt {} at {} spp.\n- Reference: the mean of {} "
            "renders of {} spp by drt {} (its noise {:.2e}, taken out of every relMSE).\n\n",
            fs::path(scene).filename().string(), machineDescription(), loadAverage(), o.threads, repetitions,
            target, targetLabel, o.targetSpp, parts.size(), o.referenceSpp, o.drt.front().label, noise);
        for (const DrtBinary& d : o.drt)
            if (d.adaptive)
                md += fmt::format("- drt {} samples adaptively: its \"N spp\" is `--adaptive --adaptive-error "
                                  "{}/sqrt(N) --min-spp {} --max-spp {}`.\n\n",
                                  d.label, d.adaptiveScale, d.adaptiveMinSpp, d.adaptiveMaxSpp);
        for (const DrtBinary& d : o.drt)
            if (d.lightSamples != 1)
                md += fmt::format("- drt {} renders with `--light-samples {}`.\n\n", d.label, d.lightSamples);
        md += "| drt | time to the target (wall) | (CPU) | speed-up over " + targetLabel +
              " (wall) | (CPU) | shadow rays per camera sample | secondary rays per camera sample |\n"
              "|---|---|---|---|---|---|---|\n";
        const bench::TimeToError targetWall = bench::timeToReach(points(renders, targetDrt, false), target);
        const bench::TimeToError targetCpu = bench::timeToReach(points(renders, targetDrt, true), target);
        for (size_t d = 0; d < o.drt.size(); ++d) {
            const bench::TimeToError wall = bench::timeToReach(points(renders, d, false), target);
            const bench::TimeToError cpu = bench::timeToReach(points(renders, d, true), target);
            const auto perSample = [&](auto rays) { return medianOf(renders, d, o.targetSpp, rays); };
            const double shadow = perSample([](const Render& r) {
                return double(r.run.shadowRays) / double(std::max<uint64_t>(1, r.run.cameraRays));
            });
            const double secondary = perSample([](const Render& r) {
                return double(r.run.secondaryRays) / double(std::max<uint64_t>(1, r.run.cameraRays));
            });
            md += fmt::format("| {} | {} | {} | {} | {} | {:.2f} | {:.2f} |\n", o.drt[d].label,
                              bench::formatTime(wall), bench::formatTime(cpu),
                              bench::formatRatio(bench::speedRatio(targetWall, wall)),
                              bench::formatRatio(bench::speedRatio(targetCpu, cpu)), shadow, secondary);
        }
        md += "\nEvery sample count (medians):\n\n| drt | spp | wall s | CPU s | relMSE "
              "|\n|---|---|---|---|---|\n";
        for (size_t d = 0; d < o.drt.size(); ++d)
            for (int spp : spps)
                md += fmt::format(
                    "| {} | {} | {:.2f} | {:.2f} | {:.3e} |\n", o.drt[d].label, spp,
                    medianOf(renders, d, spp, [](const Render& r) { return r.run.process.wallSeconds; }),
                    medianOf(renders, d, spp, [](const Render& r) { return r.run.process.cpuSeconds(); }),
                    medianOf(renders, d, spp, [](const Render& r) { return r.relMse; }));

        // Does every drt converge to the reference? The mean of its renders at its largest spp.
        md += "\nDoes each drt converge to the reference (the mean of its renders at " +
              std::to_string(spps.back()) + " spp against it)?\n\n";
        for (size_t d = 0; d < o.drt.size(); ++d) {
            std::vector<Image> own;
            for (const Render& r : renders)
                if (r.drt == d && r.spp == spps.back())
                    own.push_back(readImageOrThrow(r.image));
            const bench::AveragedImage mean = bench::averageImages(own);
            md += "- " +
                  bench::formatAgreement(bench::compareReferences(mean.mean, reference.mean),
                                         "drt " + o.drt[d].label, "the reference") +
                  "\n";
        }
        for (const Render& r : renders)
            fs::remove(r.image, ec);
        writeTextFile((fs::path(o.outputDir) / "time-to-error.csv").string(), csv.text());
        writeTextFile((fs::path(o.outputDir) / "time-to-error.md").string(), md);
        log << md;
    } catch (const std::exception& e) {
        log << fmt::format("time-to-error: {}\n", e.what());
        return 1;
    }
    return 0;
}

} // namespace drt::perf

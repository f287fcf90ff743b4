// drt_perf rays: drt's ray rate as a fraction of raw Embree's on the same
// geometry and ray mix (rays.h).
#include "rays.h"

#include "bench/stats.h"
#include "rays_embree.h"
#include "rays_scene.h"

#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <ostream>

namespace fs = std::filesystem;

namespace drt::perf {

namespace {

const char* mixName(RayMix mix) {
    return mix == RayMix::CameraOnly ? "camera rays" : "camera + shadow rays";
}

struct Measurement {
    std::vector<double> rates;               // Mrays/s, one per repetition
    std::vector<double> cpuRates;            // Mrays per second of the tracing threads' CPU, times the threads
    uint64_t cameraRays = 0, shadowRays = 0; // of the last repetition
};

std::string key(const std::string& scene, RayMix mix, const std::string& program) {
    return scene + "|" + mixName(mix) + "|" + program;
}

} // namespace

int runRays(const RaysOptions& o, std::ostream& log) {
    const fs::path work = fs::path(o.outputDir) / "work";
    std::error_code ec;
    fs::create_directories(work, ec);
    if (ec) {
        log << fmt::format("rays: cannot create '{}': {}\n", work.string(), ec.message());
        return 3;
    }
    const int repetitions = o.repetitions > 0 ? o.repetitions : 5;
    const std::vector<RayWidth> widths = {RayWidth::Single, RayWidth::Packet8, RayWidth::Packet16};
    const std::vector<RayMix> mixes = {RayMix::CameraOnly, RayMix::CameraAndShadow};
    std::map<std::string, Measurement> results;
    Csv csv;
    csv.header = {"scene",       "rays",        "program", "repetition",      "camera_rays",
                  "shadow_rays", "seconds",     "cpu_seconds", "mrays_per_second", "mrays_per_thread_cpu_second"};
    // Rays over the tracing threads' CPU time shared out to the threads: what
    // the tracing would do with the cores to itself (-1 if not known).
    const int threads = o.threads;
    const auto cpuRate = [threads](uint64_t rays, double cpuSeconds) {
        return cpuSeconds > 0 ? double(rays) / (cpuSeconds / threads) / 1e6 : -1.0;
    };
    std::vector<std::string> sceneNames;

    for (const std::string& name : o.scenes) {
        const RaysScene scene = name == "mesh" ? meshScene(o.triangles) : spheresScene();
        sceneNames.push_back(name);
        log << fmt::format("rays: {}: building ({} spheres, {} triangles)...\n", name, scene.spheres.size(),
                           scene.triangles.size());
        const RawEmbreeScene raw(scene);
        std::map<RayMix, std::string> files;
        for (RayMix mix : mixes) {
            files[mix] = (work / (name + (mix == RayMix::CameraOnly ? "-camera" : "-shadow") +
                                  drtSceneExtension(scene)))
                             .string();
            writeTextFile(files[mix], drtSceneText(scene, mix == RayMix::CameraAndShadow));
        }
        // Interleaved: each repetition measures every program once.
        for (int rep = 1; rep <= repetitions; ++rep) {
            for (RayMix mix : mixes) {
                for (RayWidth width : widths) {
                    const RawRate rate = raw.trace(mix, width, o.width, o.height, o.spp, o.threads);
                    const std::string program = std::string("Embree ") + rayWidthName(width);
                    Measurement& m = results[key(name, mix, program)];
                    m.rates.push_back(rate.mraysPerSecond());
                    const double perCpu = cpuRate(rate.cameraRays + rate.shadowRays, rate.cpuSeconds);
                    m.cpuRates.push_back(perCpu);
                    m.cameraRays = rate.cameraRays, m.shadowRays = rate.shadowRays;
                    csv.rows.push_back({name, mixName(mix), program, std::to_string(rep),
                                        std::to_string(rate.cameraRays), std::to_string(rate.shadowRays),
                                        fmt::format("{:.4f}", rate.seconds), fmt::format("{:.4f}", rate.cpuSeconds),
                                        fmt::format("{:.3f}", rate.mraysPerSecond()), fmt::format("{:.3f}", perCpu)});
                }
                for (const DrtBinary& drt : o.drt) {
                    const std::string output = (work / (name + "-drt.exr")).string();
                    const DrtRender run = runDrtRender(
                        drt, files[mix], output,
                        {"--width", std::to_string(o.width), "--height", std::to_string(o.height), "--spp",
                         std::to_string(o.spp), "--threads", std::to_string(o.threads)},
                        work.string());
                    if (!run.process.succeeded() || !run.reported) {
                        log << fmt::format("rays: drt {} failed on {}:\n{}\n", drt.label, files[mix],
                                           run.process.output);
                        return 1;
                    }
                    const std::string program = "drt " + drt.label;
                    Measurement& m = results[key(name, mix, program)];
                    m.rates.push_back(run.mraysPerSecond);
                    const double perCpu =
                        cpuRate(run.cameraRays + run.shadowRays + run.secondaryRays, run.traceCpuSeconds);
                    m.cpuRates.push_back(perCpu);
                    m.cameraRays = run.cameraRays, m.shadowRays = run.shadowRays;
                    csv.rows.push_back({name, mixName(mix), program, std::to_string(rep),
                                        std::to_string(run.cameraRays), std::to_string(run.shadowRays),
                                        fmt::format("{:.4f}", run.traceSeconds),
                                        fmt::format("{:.4f}", run.traceCpuSeconds),
                                        fmt::format("{:.3f}", run.mraysPerSecond), fmt::format("{:.3f}", perCpu)});
                }
                log << fmt::format("rays: {} {} rep {}/{} done\n", name, mixName(mix), rep, repetitions);
            }
        }
    }

    // The table: medians, and each drt as a fraction of raw single rays and of the best packet.
    std::string md =
        fmt::format("# drt's ray rate against raw Embree\n\n- Machine: {}.\n- {}x{}, {} samples per "
                    "pixel, {} threads, median of {} runs, interleaved.\n- Mrays/s = rays traced / "
                    "tracing seconds (drt: `--stats` trace time: sampling, shading and film "
                    "included; BVH build and parsing excluded for both).\n\n",
                    machineDescription(), o.width, o.height, o.spp, o.threads, repetitions);
    // The median rate of a program (-1 if it has none), per wall second or per
    // second of its tracing threads' CPU; and a row's first five cells.
    const auto medianRate = [&](const std::string& name, RayMix mix, const std::string& program, bool perCpu) {
        const auto it = results.find(key(name, mix, program));
        if (it == results.end()) return -1.0;
        return bench::median(perCpu ? it->second.cpuRates : it->second.rates);
    };
    const auto embreeCells = [&](const std::string& name, RayMix mix, bool perCpu) {
        return fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.1f} |", name, mixName(mix),
                           medianRate(name, mix, "Embree single", perCpu),
                           medianRate(name, mix, "Embree packet 8", perCpu),
                           medianRate(name, mix, "Embree packet 16", perCpu));
    };
    // A table's header: the Embree columns, `drtColumns` per drt (a format of its
    // label, `width` cells), then `last` if not empty.
    const auto header = [&](const char* drtColumns, int width, const std::string& last) {
        std::string h = "| scene | rays | Embree single | Embree packet 8 | Embree packet 16 |";
        for (const DrtBinary& drt : o.drt)
            h += fmt::format(fmt::runtime(drtColumns), drt.label);
        h += last.empty() ? "" : " " + last + " |";
        h += "\n|---|---|---|---|---|";
        for (size_t i = 0; i < o.drt.size() * size_t(width) + (last.empty() ? 0 : 1); ++i)
            h += "---|";
        return h + "\n";
    };
    md += header(" drt {0} | {0} / single | {0} / best packet |", 3, "shadow rays per camera ray (Embree / drt)");
    for (const std::string& name : sceneNames)
        for (RayMix mix : mixes) {
            const double single = medianRate(name, mix, "Embree single", false);
            const double best = std::max(medianRate(name, mix, "Embree packet 8", false),
                                         medianRate(name, mix, "Embree packet 16", false));
            md += embreeCells(name, mix, false);
            for (const DrtBinary& drt : o.drt) {
                const double d = medianRate(name, mix, "drt " + drt.label, false);
                md += fmt::format(" {:.2f} | {:.0f}% | {:.0f}% |", d, 100 * d / single, 100 * d / best);
            }
            const Measurement& rawSingle = results[key(name, mix, "Embree single")];
            const Measurement& first = results[key(name, mix, "drt " + o.drt.front().label)];
            md += fmt::format(" {:.3f} / {:.3f} |\n",
                              double(rawSingle.shadowRays) / double(rawSingle.cameraRays),
                              first.cameraRays ? double(first.shadowRays) / double(first.cameraRays) : 0.0);
        }
    md += "\nThe last column checks that both traced the same ray mix: the share of camera rays that hit a "
          "surface facing the light (drt counts to 0.01M in its summary line when it has no `--stats`).\n";

    // The same per second of the tracing threads' CPU: a render loads the image
    // module on another thread while it traces, which raw Embree never does.
    md += "\n## Per CPU second of the tracing threads\n\nRays / (the tracing threads' CPU seconds / threads): "
          "what each traces with the cores to itself. drt's figure leaves out the CPU that the image module's "
          "load (in a process of its own, or a thread where drt loads it itself) takes from the same cores (a "
          "drt without `trace_cpu_seconds` in its `--stats` shows -).\n\n" +
          header(" drt {0} | {0} / single |", 2, "");
    for (const std::string& name : sceneNames)
        for (RayMix mix : mixes) {
            const double single = medianRate(name, mix, "Embree single", true);
            md += embreeCells(name, mix, true);
            for (const DrtBinary& drt : o.drt) {
                const double d = medianRate(name, mix, "drt " + drt.label, true);
                md += d > 0 && single > 0 ? fmt::format(" {:.2f} | {:.0f}% |", d, 100 * d / single) : " - | - |";
            }
            md += "\n";
        }
    writeTextFile((fs::path(o.outputDir) / "rays.csv").string(), csv.text());
    writeTextFile((fs::path(o.outputDir) / "rays.md").string(), md);
    log << md;
    return 0;
}

} // namespace drt::perf

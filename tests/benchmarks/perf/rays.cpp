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
    csv.header = {"scene",       "rays",        "program", "repetition",
                  "camera_rays", "shadow_rays", "seconds", "mrays_per_second"};
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
                    m.cameraRays = rate.cameraRays, m.shadowRays = rate.shadowRays;
                    csv.rows.push_back({name, mixName(mix), program, std::to_string(rep),
                                        std::to_string(rate.cameraRays), std::to_string(rate.shadowRays),
                                        fmt::format("{:.4f}", rate.seconds),
                                        fmt::format("{:.3f}", rate.mraysPerSecond())});
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
                    m.cameraRays = run.cameraRays, m.shadowRays = run.shadowRays;
                    csv.rows.push_back({name, mixName(mix), program, std::to_string(rep),
                                        std::to_string(run.cameraRays), std::to_string(run.shadowRays),
                                        fmt::format("{:.4f}", run.traceSeconds),
                                        fmt::format("{:.3f}", run.mraysPerSecond)});
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
    md += "| scene | rays | Embree single | Embree packet 8 | Embree packet 16 |";
    for (const DrtBinary& drt : o.drt)
        md += fmt::format(" drt {0} | {0} / single | {0} / best packet |", drt.label);
    md += " shadow rays per camera ray (Embree / drt) |\n|---|---|---|---|---|";
    for (size_t i = 0; i < o.drt.size(); ++i)
        md += "---|---|---|";
    md += "---|\n";
    for (const std::string& name : sceneNames)
        for (RayMix mix : mixes) {
            const auto rate = [&](const std::string& program) {
                auto it = results.find(key(name, mix, program));
                return it == results.end() ? 0.0 : bench::median(it->second.rates);
            };
            const double single = rate("Embree single");
            const double best = std::max(rate("Embree packet 8"), rate("Embree packet 16"));
            md += fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.1f} |", name, mixName(mix), single,
                              rate("Embree packet 8"), rate("Embree packet 16"));
            std::string ratios;
            for (const DrtBinary& drt : o.drt) {
                const double d = rate("drt " + drt.label);
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
    writeTextFile((fs::path(o.outputDir) / "rays.csv").string(), csv.text());
    writeTextFile((fs::path(o.outputDir) / "rays.md").string(), md);
    log << md;
    return 0;
}

} // namespace drt::perf

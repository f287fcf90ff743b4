// drt_perf: the performance instruments of docs/performance.md, one
// subcommand each. Run from the build folder; `drt_perf SUBCOMMAND --help`.
#include "pov_scenes.h"
#include "rays.h"
#include "report.h"
#include "startup.h"
#include "time_to_error.h"
#include "versus.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <iostream>
#include <stdexcept>

namespace {

// --drt LABEL=PATH (repeatable); none: the drt built beside this tool.
std::vector<std::string> adaptiveTexts; // --drt-adaptive of versus-povray and time-to-error
std::vector<std::string> lightSampleTexts; // --drt-light-samples of the same

std::vector<drt::perf::DrtBinary> drtBinaries(const std::vector<std::string>& texts) {
    std::vector<drt::perf::DrtBinary> binaries;
    for (const std::string& text : texts)
        binaries.push_back(drt::perf::parseDrtBinary(text));
    if (binaries.empty())
        binaries.push_back(drt::perf::builtDrt());
    for (const std::string& text : adaptiveTexts)
        drt::perf::markAdaptive(binaries, text);
    for (const std::string& text : lightSampleTexts)
        drt::perf::markLightSamples(binaries, text);
    return binaries;
}

constexpr const char* kLightSamplesHelp =
    "LABEL=K: that --drt renders with --light-samples K (repeatable); give the same PATH twice under two labels "
    "to compare";

constexpr const char* kAdaptiveHelp =
    "LABEL[=MIN,MAX[,SCALE]]: measure that --drt with adaptive sampling (repeatable): a sweep step of N spp "
    "renders --adaptive --adaptive-error SCALE/sqrt(N) --min-spp MIN --max-spp MAX (default 4,1024,0.05); give "
    "the same PATH twice under two labels to compare fixed and adaptive sampling";

} // namespace

int main(int argc, char** argv) {
    CLI::App app("drt's performance instruments (docs/performance.md)");
    app.require_subcommand(1);
    std::vector<std::string> drtTexts;

    drt::perf::VersusOptions versus;
    CLI::App* versusCommand = app.add_subcommand(
        "versus-povray", "drt against POV-Ray 3.7 at equal relMSE on focalblur, arealit1 and arealit2");
    versusCommand->add_option("-o,--output", versus.outputDir, "Output folder (created if missing)")
        ->required();
    versusCommand->add_option("--drt", drtTexts,
                              "LABEL=PATH of a drt to measure (repeatable; the first renders "
                              "drt's reference; default: the drt built here)");
    versusCommand
        ->add_option("--scenes", versus.scenes, "Scenes, comma-separated (focalblur,arealit1,arealit2)")
        ->delimiter(',');
    versusCommand->add_option("--repetitions", versus.repetitions, "Runs of every setting (default 3)")
        ->check(CLI::Range(1, 100));
    versusCommand->add_option("--threads", versus.threads, "Threads for both renderers")
        ->check(CLI::Range(1, 256));
    versusCommand->add_option("--pov-examples", versus.povExamples, "POV-Ray's sample scene folder");
    versusCommand->add_option("--drt-adaptive", adaptiveTexts, kAdaptiveHelp);
    versusCommand->add_option("--drt-light-samples", lightSampleTexts, kLightSamplesHelp);
    versusCommand->add_flag("--quick", versus.quick, "Fewer settings and lighter references (a few minutes)");

    drt::perf::RaysOptions rays;
    bool raysQuick = false;
    CLI::App* raysCommand = app.add_subcommand(
        "rays", "drt's ray rate as a fraction of raw Embree's (single rays and packets) on the same scenes");
    raysCommand->add_option("-o,--output", rays.outputDir, "Output folder (created if missing)")->required();
    raysCommand->add_option("--drt", drtTexts, "LABEL=PATH of a drt to measure (repeatable)");
    raysCommand->add_option("--scenes", rays.scenes, "Scenes, comma-separated (spheres,mesh)")
        ->delimiter(',')
        ->check(CLI::IsMember({"spheres", "mesh"}));
    raysCommand->add_option("--width", rays.width, "Image width")->check(CLI::Range(4, 1 << 15));
    raysCommand->add_option("--height", rays.height, "Image height")->check(CLI::Range(4, 1 << 15));
    raysCommand->add_option("--spp", rays.spp, "Samples per pixel")->check(CLI::Range(1, 1 << 16));
    raysCommand->add_option("--threads", rays.threads, "Threads for both")->check(CLI::Range(1, 256));
    raysCommand->add_option("--repetitions", rays.repetitions, "Runs of everything (default 5)")
        ->check(CLI::Range(1, 100));
    raysCommand->add_option("--triangles", rays.triangles, "Triangles of the mesh")
        ->check(CLI::Range(8, 1 << 26));
    raysCommand->add_flag("--quick", raysQuick, "4 samples per pixel, 3 runs");

    drt::perf::StartupOptions startup;
    CLI::App* startupCommand =
        app.add_subcommand("startup", "Start-up costs: --version, check, a tiny render; drt against POV-Ray");
    startupCommand->add_option("-o,--output", startup.outputDir, "Output folder (created if missing)")
        ->required();
    startupCommand->add_option("--drt", drtTexts, "LABEL=PATH of a drt to measure (repeatable)");
    startupCommand->add_option("--repetitions", startup.repetitions, "Runs of every command (default 10)")
        ->check(CLI::Range(1, 1000));

    drt::perf::PovScenesOptions scenes;
    bool scenesQuick = false;
    CLI::App* scenesCommand = app.add_subcommand(
        "pov-scenes",
        "POV-Ray's sample scenes as a user runs them: POV-Ray +A0.3 against drt at 16 spp, 160x120");
    scenesCommand->add_option("-o,--output", scenes.outputDir, "Output folder (created if missing)")
        ->required();
    scenesCommand->add_option("--drt", drtTexts,
                              "LABEL=PATH of a drt to measure (repeatable; the first picks "
                              "the scenes)");
    scenesCommand->add_option("--count", scenes.count, "Scenes (default 40)")->check(CLI::Range(1, 1000));
    scenesCommand->add_option("--repetitions", scenes.repetitions, "Runs of every render (default 1)")
        ->check(CLI::Range(1, 100));
    scenesCommand->add_option("--scenes-file", scenes.scenesFile,
                              "Render exactly these scenes (e.g. a scenes.txt)");
    scenesCommand
        ->add_option("--timeout", scenes.timeoutSeconds, "Seconds after which a render counts as failed")
        ->check(CLI::PositiveNumber);
    scenesCommand->add_option("--pov-examples", scenes.povExamples, "POV-Ray's sample scene folder");
    scenesCommand->add_flag("--quick", scenesQuick, "10 scenes");

    drt::perf::TimeToErrorOptions timeToError;
    CLI::App* timeCommand = app.add_subcommand(
        "time-to-error",
        "How much sooner each drt reaches the error one drt reaches at N spp (examples/cook.drt)");
    timeCommand->add_option("-o,--output", timeToError.outputDir, "Output folder (created if missing)")
        ->required();
    timeCommand->add_option("--drt", drtTexts,
                            "LABEL=PATH of a drt to measure (repeatable; the first renders the reference)");
    timeCommand->add_option("--drt-adaptive", adaptiveTexts, kAdaptiveHelp);
    timeCommand->add_option("--drt-light-samples", lightSampleTexts, kLightSamplesHelp);
    timeCommand->add_option("--scene", timeToError.scene, "A drt scene (default examples/cook.drt)");
    timeCommand->add_option("--target", timeToError.target,
                            "Label of the drt whose error at --target-spp is the target (default: the last)");
    timeCommand
        ->add_option("--target-spp", timeToError.targetSpp, "Samples per pixel of the target (default 16)")
        ->check(CLI::Range(1, 1 << 16));
    timeCommand->add_option("--spp", timeToError.spp, "Sample counts measured, comma-separated")
        ->delimiter(',')
        ->check(CLI::Range(1, 1 << 16));
    timeCommand
        ->add_option("--reference-spp", timeToError.referenceSpp, "Samples per pixel of a reference render")
        ->check(CLI::Range(1, 1 << 20));
    timeCommand->add_option("--threads", timeToError.threads, "Threads")->check(CLI::Range(1, 256));
    timeCommand->add_option("--repetitions", timeToError.repetitions, "Runs of every render (default 3)")
        ->check(CLI::Range(1, 100));

    drt::perf::ReportOptions report;
    bool reportNoPovray = false;
    CLI::App* reportCommand = app.add_subcommand(
        "report", "Every instrument in one run (startup, rays, time-to-error, versus-povray) and report.md");
    reportCommand->add_option("-o,--output", report.outputDir, "Output folder (created if missing)")
        ->required();
    reportCommand->add_option("--drt", drtTexts, "LABEL=PATH of a drt to measure (repeatable)");
    reportCommand->add_flag("--quick", report.quick, "Every instrument in its lighter form");
    reportCommand->add_flag("--no-povray", reportNoPovray,
                            "Leave out drt against POV-Ray (the longest part)");

    CLI11_PARSE(app, argc, argv);
    try {
        if (versusCommand->parsed()) {
            versus.drt = drtBinaries(drtTexts);
            return drt::perf::runVersusPovray(versus, std::cerr);
        }
        if (scenesCommand->parsed()) {
            scenes.drt = drtBinaries(drtTexts);
            if (scenesQuick)
                scenes.count = std::min(scenes.count, 10);
            return drt::perf::runPovScenes(scenes, std::cerr);
        }
        if (startupCommand->parsed()) {
            startup.drt = drtBinaries(drtTexts);
            return drt::perf::runStartup(startup, std::cerr);
        }
        if (timeCommand->parsed()) {
            timeToError.drt = drtBinaries(drtTexts);
            return drt::perf::runTimeToError(timeToError, std::cerr);
        }
        if (reportCommand->parsed()) {
            report.drt = drtBinaries(drtTexts);
            report.povray = !reportNoPovray;
            return drt::perf::runReport(report, std::cerr);
        }
        if (raysCommand->parsed()) {
            rays.drt = drtBinaries(drtTexts);
            if (raysQuick) {
                rays.spp = std::min(rays.spp, 4);
                if (rays.repetitions == 0)
                    rays.repetitions = 3;
            }
            return drt::perf::runRays(rays, std::cerr);
        }
    } catch (const std::invalid_argument& e) {
        std::cerr << "drt_perf: " << e.what() << "\n";
        return 2;
    }
    return 0;
}

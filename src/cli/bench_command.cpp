// `drt bench`: the command-line face of bench/bench.h.
#include "cli/commands.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <ostream>

namespace drt::cli {

CLI::App* addBenchSubcommand(CLI::App& app, BenchCommand& c) {
    bench::BenchOptions& o = c.options;
    CLI::App* bench = app.add_subcommand(
        "bench", "Chart speed against accuracy: render a scene with each method, sample count and seed, measure "
                 "the error against a reference, write results.csv, charts and summary.md");
    bench->add_option("scene", o.scenePath, "Scene file (.drt or .pov)")->required();
    bench->add_option("-o,--output", o.outputDir, "Output folder (created if missing)")->required();
    bench->add_option("--spp", c.sppList, "Samples per pixel, comma-separated (default 1,4,16,64,256)");
    bench->add_option("--seeds", o.seeds, "Seeds per configuration (default 3)")->check(CLI::Range(1, 1000));
    bench->add_option("--methods", o.methods, "Methods to run, comma-separated (default: all that apply)")
        ->delimiter(',')
        ->check(CLI::IsMember(bench::benchMethodNames()));
    CLI::Option* reference =
        bench->add_option("--reference", o.referencePath,
                          "Reference image (.exr) for the scene as written; <stem>.variance.exr beside it is used");
    bench
        ->add_option("--reference-spp", o.referenceSpp,
                     "Samples per pixel of the references the bench renders (default 16 x the largest --spp)")
        ->check(CLI::Range(1, 1 << 24))
        ->excludes(reference);
    bench->add_option("--width", o.width, "Image width (default 96, quick 48)")->check(CLI::Range(1, 1 << 16));
    bench->add_option("--height", o.height, "Image height (default: the scene's aspect)")
        ->check(CLI::Range(1, 1 << 16));
    bench->add_option("--threads", o.threads, "Worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
    bench->add_flag("--quick", o.quick, "A run under a minute: 48 wide, spp 1,4,16, one seed, 256-spp reference");
    return bench;
}

int runBenchCommand(const BenchCommand& command, std::ostream& out, std::ostream& err) {
    bench::BenchOptions options = command.options;
    if (!command.sppList.empty()) {
        try {
            options.spp = bench::parseSppList(command.sppList);
        } catch (const std::invalid_argument& e) {
            err << fmt::format("drt bench: --spp: {}\n", e.what());
            return kUsageError;
        }
    }
    try {
        const bench::BenchReport report = bench::runBench(options, err);
        out << fmt::format("{}/summary.md\n", options.outputDir);
        (void)report;
    } catch (const bench::BenchError& e) {
        err << fmt::format("drt bench: {}\n", e.what());
        return e.ioError ? kIoError : kSceneError;
    }
    return kSuccess;
}

} // namespace drt::cli

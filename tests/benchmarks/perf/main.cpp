// drt_perf: the performance instruments of docs/performance.md, one
// subcommand each. Run from the build folder; `drt_perf SUBCOMMAND --help`.
#include "versus.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <iostream>
#include <stdexcept>

namespace {

// --drt LABEL=PATH (repeatable); none: the drt built beside this tool.
std::vector<drt::perf::DrtBinary> drtBinaries(const std::vector<std::string>& texts) {
    std::vector<drt::perf::DrtBinary> binaries;
    for (const std::string& text : texts)
        binaries.push_back(drt::perf::parseDrtBinary(text));
    if (binaries.empty())
        binaries.push_back(drt::perf::builtDrt());
    return binaries;
}

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
    versusCommand->add_flag("--quick", versus.quick, "Fewer settings and lighter references (a few minutes)");

    CLI11_PARSE(app, argc, argv);
    try {
        if (versusCommand->parsed()) {
            versus.drt = drtBinaries(drtTexts);
            return drt::perf::runVersusPovray(versus, std::cerr);
        }
    } catch (const std::invalid_argument& e) {
        std::cerr << "drt_perf: " << e.what() << "\n";
        return 2;
    }
    return 0;
}

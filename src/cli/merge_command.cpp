// `drt merge PARTS... -o OUT`: crop renders -> one image (distributed/crop_merge.h).
#include "cli/commands.h"

#include "cli/render_parts.h"
#include "distributed/crop_merge.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <ostream>

namespace drt::cli {

namespace {

void recordMergeCommand(Metadata& metadata, const std::string& commandLine) {
    std::erase_if(metadata, [](const auto& entry) { return entry.first == "drt:command_line"; });
    if (!commandLine.empty()) metadata.emplace_back("drt:command_line", commandLine);
}

} // namespace

int runMerge(const MergeCommand& command, std::ostream& out, std::ostream& err) {
    for (const std::string& output : {command.output, command.varianceOutput, command.sppImageOutput}) {
        if (output.empty()) continue;
        if (std::string problem = checkWritable(output); !problem.empty()) {
            err << "drt merge: " << problem << "\n";
            return kIoError;
        }
    }
    MergedImages merged;
    bool unreadable = false;
    if (std::string problem = mergeCrops(command.parts, merged, unreadable); !problem.empty()) {
        err << "drt merge: " << (unreadable ? "" : "refused: ") << problem << "\n";
        return unreadable ? kIoError : kSceneError;
    }
    // Each kind of part present goes to its output, and each output named needs its parts.
    std::string variancePath, sppPath;
    for (size_t i = 0; i < merged.others.size(); ++i) {
        const bool variance = merged.otherKinds[i] == PartContent::Variance;
        const std::string& path = variance ? command.varianceOutput : command.sppImageOutput;
        if (path.empty()) {
            err << fmt::format("drt merge: the parts include {} images: name their output with {}\n",
                               variance ? "variance" : "samples-per-pixel", variance ? "--variance" : "--spp-image");
            return kUsageError;
        }
        (variance ? variancePath : sppPath) = path;
    }
    for (const auto& [given, found, name] : {std::tuple{command.varianceOutput, variancePath, "variance"},
                                             std::tuple{command.sppImageOutput, sppPath, "samples-per-pixel"}})
        if (!given.empty() && found.empty()) {
            err << fmt::format("drt merge: '{}' is to hold the {} image, but no part is one\n", given, name);
            return kUsageError;
        }
    // The parts' provenance stays (scene hash, seed, settings, summed counts); the
    // command line is this merge's, not the first part's.
    recordMergeCommand(merged.colorMetadata, command.commandLine);
    for (Metadata& metadata : merged.otherMetadata) recordMergeCommand(metadata, command.commandLine);
    if (std::string problem = writeImage(command.output, merged.color, merged.colorMetadata); !problem.empty()) {
        err << "drt merge: " << problem << "\n";
        return kIoError;
    }
    for (size_t i = 0; i < merged.others.size(); ++i) {
        const std::string& path =
            merged.otherKinds[i] == PartContent::Variance ? command.varianceOutput : command.sppImageOutput;
        if (std::string problem = writeImage(path, merged.others[i], merged.otherMetadata[i]); !problem.empty()) {
            err << "drt merge: " << problem << "\n";
            return kIoError;
        }
    }
    out << fmt::format("drt merge: {} parts -> {} ({}x{})\n", merged.parts, command.output, merged.color.width,
                       merged.color.height);
    return kSuccess;
}

CLI::App* addMergeSubcommand(CLI::App& app, MergeCommand& command) {
    CLI::App* merge = app.add_subcommand(
        "merge", "Assemble crop renders (drt render --crop) into one image (exit 0 merged, 1 the parts do not "
                 "form one image of one render, 2 usage error, 3 I/O error)");
    merge->add_option("parts", command.parts, "Crop images (and their variance / spp images)")->required();
    merge->add_option("-o,--output", command.output, "The merged image")->required();
    merge->add_option("--variance", command.varianceOutput, "Where the merged variance parts go (.exr)");
    merge->add_option("--spp-image", command.sppImageOutput, "Where the merged samples-per-pixel parts go");
    return merge;
}

} // namespace drt::cli

// `drt compare CANDIDATE REFERENCE`: read, compare (compare/compare.h), report.
#include "cli/commands.h"
#include "cli/paths.h"

#include <fmt/format.h>
#include <ostream>

namespace drt::cli {

namespace {

int report(const CompareCommand& command, const CompareResult& result, std::ostream& out, std::ostream& err) {
    if (command.json) {
        out << formatCompareJson(result, command.candidate, command.reference);
    } else {
        if (result.status == CompareStatus::FileError || result.status == CompareStatus::SizeMismatch)
            err << "drt compare: " << result.message << "\n";
        else
            out << fmt::format("drt compare: {} against {}\n", command.candidate, command.reference)
                << formatCompareText(result);
    }
    return static_cast<int>(result.status);
}

int fileError(const CompareCommand& command, std::string message, std::ostream& out, std::ostream& err) {
    CompareResult result;
    result.status = CompareStatus::FileError;
    result.message = std::move(message);
    return report(command, result, out, err);
}

} // namespace

int runCompare(const CompareCommand& command, std::ostream& out, std::ostream& err) {
    if (std::string clash = outputClash({{"the candidate", command.candidate},
                                         {"the reference", command.reference},
                                         {"--variance", command.referenceVariance},
                                         {"--candidate-variance", command.candidateVariance}},
                                        {{"--diff", command.diffOutput}, {"--zmap", command.zmapOutput}});
        !clash.empty()) {
        err << "drt compare: " << clash << "\n";
        return kUsageError;
    }
    Image candidate, reference, referenceVariance, candidateVariance;
    VarianceImages variance;
    if (std::string problem = readImage(command.candidate, candidate); !problem.empty())
        return fileError(command, problem, out, err);
    if (std::string problem = readImage(command.reference, reference); !problem.empty())
        return fileError(command, problem, out, err);
    if (!command.referenceVariance.empty()) {
        if (std::string problem = readImage(command.referenceVariance, referenceVariance); !problem.empty())
            return fileError(command, problem, out, err);
        variance.reference = &referenceVariance;
    }
    if (!command.candidateVariance.empty()) {
        if (std::string problem = readImage(command.candidateVariance, candidateVariance); !problem.empty())
            return fileError(command, problem, out, err);
        variance.candidate = &candidateVariance;
    }

    CompareResult result = compareImages(candidate, reference, command.options, variance);
    if (result.status != CompareStatus::SizeMismatch) {
        if (!command.diffOutput.empty()) {
            if (std::string problem =
                    writeImage(command.diffOutput, errorHeatmap(candidate, reference, command.diffScale));
                !problem.empty())
                return fileError(command, problem, out, err);
        }
        if (!command.zmapOutput.empty()) {
            if (std::string problem =
                    writeImage(command.zmapOutput, zScoreMap(candidate, reference, variance));
                !problem.empty())
                return fileError(command, problem, out, err);
        }
    }
    return report(command, result, out, err);
}

} // namespace drt::cli

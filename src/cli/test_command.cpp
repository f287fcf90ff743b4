// `drt test DIR`: run the golden tests in a folder (golden/golden.h) and print
// one line per test, the figures of each failure, and a summary; optionally
// the HTML report, JUnit XML and JSON.
#include "cli/commands.h"

#include "golden/golden.h"

#include <filesystem>
#include <fmt/format.h>
#include <ostream>

namespace fs = std::filesystem;

namespace drt::cli {

namespace {

// A report file must go into an existing folder: checked before the (possibly
// long) run rather than after it.
std::string checkReportPath(const std::string& option, const std::string& path) {
    if (path.empty())
        return "";
    std::error_code ec;
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec))
        return fmt::format("{} {}: folder '{}' does not exist", option, path, folder.string());
    if (fs::is_directory(path, ec))
        return fmt::format("{} {}: it is a folder", option, path);
    return "";
}

} // namespace

int runTest(const TestCommand& command, std::ostream& out, std::ostream& err) {
    for (const auto& [option, path] : {std::pair{"--junit", command.junitFile}, std::pair{"--json", command.jsonFile}})
        if (std::string problem = checkReportPath(option, path); !problem.empty()) {
            err << "drt test: " << problem << "\n";
            return kIoError;
        }
    golden::RunOptions options;
    options.update = command.update;
    options.only = command.only;
    std::string error;
    const golden::RunSummary summary = golden::runGoldenTests(command.folder, options, error);
    if (!error.empty()) {
        err << "drt test: " << error << "\n";
        return kIoError;
    }

    for (const golden::CaseResult& r : summary.cases) {
        out << fmt::format("{:<8} {:<24} {:<12} {:6.2f} s{}{}\n", golden::outcomeName(r.outcome), r.name,
                           golden::policyName(r.policy), r.seconds, r.message.empty() ? "" : "  ", r.message);
        if (r.outcome == golden::Outcome::Fail)
            if (const std::string figures = golden::failureFigures(r); !figures.empty())
                out << "         " << figures << "\n";
        if (!r.details.empty())
            out << r.details;
    }
    if (command.update)
        out << fmt::format("drt test {}: {} tests, {} updated, {} errors in {:.1f} s\n", command.folder,
                           summary.cases.size(), summary.updated, summary.errors, summary.seconds);
    else
        out << fmt::format("drt test {}: {} tests, {} passed, {} failed, {} missing, {} errors in {:.1f} s\n",
                           command.folder, summary.cases.size(), summary.passed, summary.failed,
                           summary.missing, summary.errors, summary.seconds);

    int status = summary.allPassed() ? kSuccess : kSceneError;
    auto writeReport = [&](const std::string& path, const std::string& text) {
        if (path.empty())
            return;
        if (std::string problem = golden::writeTextFile(path, text); !problem.empty()) {
            err << "drt test: " << problem << "\n";
            status = kIoError;
        }
    };
    writeReport(command.junitFile, golden::junitReport(summary));
    writeReport(command.jsonFile, golden::jsonReport(summary));
    if (!command.reportDir.empty() && !command.update) {
        if (std::string problem = golden::writeReport(command.reportDir, summary); !problem.empty()) {
            err << "drt test: " << problem << "\n";
            return kIoError;
        }
        out << fmt::format("report: {}/index.html\n", command.reportDir);
    }
    return status;
}

} // namespace drt::cli

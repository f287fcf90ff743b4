// `drt test DIR`: run the golden tests in a folder (golden/golden.h) and print
// one line per test, the figures of each failure, and a summary.
#include "cli/commands.h"

#include "golden/golden.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <ostream>

namespace drt::cli {

namespace {

// The figures a reader needs to judge a failed comparison, on one line.
std::string failureFigures(const CompareResult& r) {
    std::string line =
        fmt::format("RMSE {:.3g}, bias {:+.3g}, max error {:.3g} at ({}, {}), NaN/Inf pixels {}", r.rmse,
                    r.meanSignedError, r.maxError, r.maxErrorX, r.maxErrorY, r.nonFinitePixels);
    if (r.statistical) {
        double worst = 0;
        for (double z : r.globalZ)
            if (std::fabs(z) > std::fabs(worst))
                worst = z;
        line += fmt::format("; global z {:+.2f} (limit {:.2f}), {} of {} tiles fail (limit {:.2f})", worst,
                            r.globalZThreshold, r.failingTiles, r.tileTests, r.tileZThreshold);
    } else {
        line += fmt::format("; {} pixels differ", r.failingPixels);
    }
    return line;
}

} // namespace

int runTest(const TestCommand& command, std::ostream& out, std::ostream& err) {
    const auto start = std::chrono::steady_clock::now();
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
        if (r.outcome == golden::Outcome::Fail && r.comparison)
            out << "         " << failureFigures(*r.comparison) << "\n";
        if (!r.details.empty())
            out << r.details;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (command.update)
        out << fmt::format("drt test {}: {} tests, {} updated, {} errors in {:.1f} s\n", command.folder,
                           summary.cases.size(), summary.updated, summary.errors, seconds);
    else
        out << fmt::format("drt test {}: {} tests, {} passed, {} failed, {} missing, {} errors in {:.1f} s\n",
                           command.folder, summary.cases.size(), summary.passed, summary.failed,
                           summary.missing, summary.errors, seconds);

    if (!command.reportDir.empty() && !command.update) {
        if (std::string problem = golden::writeReport(command.reportDir, summary); !problem.empty()) {
            err << "drt test: " << problem << "\n";
            return kIoError;
        }
        out << fmt::format("report: {}/index.html\n", command.reportDir);
    }
    return summary.allPassed() ? kSuccess : kSceneError;
}

} // namespace drt::cli

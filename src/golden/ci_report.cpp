// Results of `drt test` for CI systems: the one-line figures of a failure,
// JUnit XML (`--junit FILE`) and JSON (`--json FILE`).
//
// The JUnit file follows the Ant JUnit task's format, the one GitLab, Jenkins
// and GitHub's test reporters read: <testsuites> (no attributes) holding one <testsuite> (with
// package, id, name, timestamp without a zone, hostname, tests, failures,
// errors, skipped, time, then <properties>, the <testcase>s, <system-out> and
// <system-err>, all present even when empty); each <testcase> has name,
// classname and time and at most one <failure> or <error> child, whose
// `message` is the one-line reason and whose text holds the figures.
#include "golden/golden.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace drt::golden {

namespace {

// The channel whose global z is largest in magnitude.
int worstGlobalZChannel(const CompareResult& r) {
    int worst = 0;
    for (size_t c = 1; c < r.globalZ.size(); ++c)
        if (std::fabs(r.globalZ[c]) > std::fabs(r.globalZ[size_t(worst)]))
            worst = int(c);
    return worst;
}

} // namespace

std::string failureFigures(const CaseResult& result) {
    if (!result.comparison)
        return "";
    const CompareResult& r = *result.comparison;
    std::string line = fmt::format("RMSE {:.3g}, bias {:+.3g}, max error {:.3g} at ({}, {}) {}, NaN/Inf pixels {}",
                                   r.rmse, r.meanSignedError, r.maxError, r.maxErrorX, r.maxErrorY,
                                   channelName(r.maxErrorChannel), r.nonFinitePixels);
    if (r.statistical) {
        const int c = worstGlobalZChannel(r);
        line += fmt::format("; global z {} {:+.2f} (limit {:.2f}), {} of {} tiles fail (limit {:.2f})", channelName(c),
                            r.globalZ.empty() ? 0.0 : r.globalZ[size_t(c)], r.globalZThreshold, r.failingTiles,
                            r.tileTests, r.tileZThreshold);
    } else if (result.settings.failThreshold > 0) {
        line += fmt::format("; {} pixels differ by more than {:g} (allowed: {:g}%)", r.failingPixels,
                            result.settings.failThreshold, result.settings.failPercent);
    } else {
        line += fmt::format("; {} pixels differ", r.failingPixels);
    }
    return line;
}

std::string escapeMarkup(const std::string& text) {
    std::string out;
    for (char ch : text) {
        switch (ch) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        case '\n':
        case '\t':
            out += ch;
            break;
        default:
            if (static_cast<unsigned char>(ch) >= 0x20)
                out += ch;
        }
    }
    return out;
}

namespace {

// An attribute on one line: a newline in an attribute value is normalised to a
// space by XML parsers anyway.
std::string xmlAttribute(const std::string& text) {
    std::string flat = text;
    for (char& ch : flat)
        if (ch == '\n' || ch == '\t')
            ch = ' ';
    return escapeMarkup(flat);
}

std::string hostName() {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0')
        return "localhost";
    return name;
}

std::string localTimestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &local);
    return text;
}

// The testsuite's name: the folder as given, without a trailing slash ("."
// becomes the folder's own name).
std::string suiteName(const std::string& folder) {
    fs::path path = fs::path(folder).lexically_normal();
    if (path.filename().empty())
        path = path.parent_path();
    if (path.empty() || path == ".") {
        std::error_code ec;
        path = fs::current_path(ec).filename();
    }
    return path.empty() ? "." : path.string();
}

} // namespace

std::string junitReport(const RunSummary& summary) {
    const std::string suite = suiteName(summary.folder);
    std::string cases;
    for (const CaseResult& r : summary.cases) {
        cases += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.3f}\"", xmlAttribute(r.name),
                             xmlAttribute(suite), r.seconds);
        const bool failure = r.outcome == Outcome::Fail || r.outcome == Outcome::Missing;
        const bool error = r.outcome == Outcome::Error;
        if (!failure && !error) {
            cases += "/>\n";
            continue;
        }
        std::string text = fmt::format("{} ({} policy): {}\n", outcomeName(r.outcome), policyName(r.policy), r.message);
        if (const std::string figures = failureFigures(r); !figures.empty())
            text += figures + "\n";
        if (!r.scenePath.empty())
            text += "scene: " + r.scenePath + "\n";
        text += r.details;
        const char* element = failure ? "failure" : "error";
        cases += fmt::format(">\n      <{0} message=\"{1}\" type=\"{2}\">{3}</{0}>\n    </testcase>\n", element,
                             xmlAttribute(r.message), outcomeName(r.outcome), escapeMarkup(text));
    }
    const int failures = summary.failed + summary.missing;
    const std::string out = fmt::format(
        "drt test {}: {} tests, {} passed, {} failed, {} missing, {} errors, {} updated\n", suite,
        summary.cases.size(), summary.passed, summary.failed, summary.missing, summary.errors, summary.updated);
    return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                       "<testsuites>\n"
                       "  <testsuite package=\"drt\" id=\"0\" name=\"{0}\" timestamp=\"{6}\" hostname=\"{7}\" "
                       "tests=\"{2}\" failures=\"{3}\" errors=\"{4}\" skipped=\"0\" time=\"{5:.3f}\">\n"
                       "    <properties>\n"
                       "      <property name=\"drt.version\" value=\"{8}\"/>\n"
                       "      <property name=\"folder\" value=\"{0}\"/>\n"
                       "    </properties>\n"
                       "{1}"
                       "    <system-out>{9}</system-out>\n"
                       "    <system-err></system-err>\n"
                       "  </testsuite>\n"
                       "</testsuites>\n",
                       xmlAttribute(suite), cases, summary.cases.size(), failures, summary.errors, summary.seconds,
                       localTimestamp(), xmlAttribute(hostName()), DRT_VERSION, escapeMarkup(out));
}

namespace {

// JSON has no Inf or NaN: they become null.
json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json figuresJson(const CaseResult& result) {
    const CompareResult& r = *result.comparison;
    json f = {
        {"width", r.width},
        {"height", r.height},
        {"channels", r.channels},
        {"nonfinite_pixels", r.nonFinitePixels},
        {"rmse", number(r.rmse)},
        {"relmse", number(r.relMse)},
        {"bias", number(r.meanSignedError)},
        {"mean_absolute_error", number(r.meanAbsoluteError)},
        {"max_error", {{"value", number(r.maxError)},
                       {"x", r.maxErrorX},
                       {"y", r.maxErrorY},
                       {"channel", channelName(r.maxErrorChannel)}}},
        {"psnr_db", number(r.psnr)}, // null: identical
    };
    if (r.statistical) {
        json z = json::object();
        for (size_t c = 0; c < r.globalZ.size(); ++c)
            z[channelName(int(c))] = number(r.globalZ[c]);
        f["alpha"] = result.settings.alpha;
        f["global_z"] = z;
        f["global_z_limit"] = number(r.globalZThreshold);
        f["tiles"] = r.tileTests;
        f["failing_tiles"] = r.failingTiles;
        f["tile_z_limit"] = number(r.tileZThreshold);
        f["worst_tile"] = {{"x", r.worstTile.x0},
                           {"y", r.worstTile.y0},
                           {"channel", channelName(r.worstTile.channel)},
                           {"z", number(r.worstTile.z)},
                           {"mean_error", number(r.worstTile.meanError)}};
    } else {
        f["fail"] = result.settings.failThreshold;
        f["fail_percent"] = result.settings.failPercent;
        f["differing_pixels"] = r.failingPixels;
    }
    return f;
}

} // namespace

std::string jsonReport(const RunSummary& summary) {
    json cases = json::array();
    for (const CaseResult& r : summary.cases) {
        json c = {{"name", r.name},
                  {"outcome", outcomeName(r.outcome)},
                  {"policy", policyName(r.policy)},
                  {"scene", r.scenePath},
                  {"seconds", r.seconds},
                  {"message", r.message}};
        if (!r.details.empty())
            c["details"] = r.details;
        if (r.comparison)
            c["figures"] = figuresJson(r);
        cases.push_back(std::move(c));
    }
    const json report = {{"drt_version", DRT_VERSION},
                         {"folder", summary.folder},
                         {"tests", summary.cases.size()},
                         {"passed", summary.passed},
                         {"failed", summary.failed},
                         {"missing", summary.missing},
                         {"errors", summary.errors},
                         {"updated", summary.updated},
                         {"all_passed", summary.allPassed()},
                         {"seconds", summary.seconds},
                         {"cases", cases}};
    return report.dump(2) + "\n";
}

std::string writeTextFile(const std::string& path, const std::string& text) {
    const fs::path target(path);
    const fs::path temporary =
        target.parent_path() / fmt::format(".{}.tmp-{}", target.filename().string(), ::getpid());
    std::error_code ec;
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        if (!out) {
            fs::remove(temporary, ec);
            return fmt::format("cannot write '{}'", path);
        }
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return fmt::format("cannot write '{}': {}", path, ec.message());
    }
    return "";
}

} // namespace drt::golden

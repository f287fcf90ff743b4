// drt_perf report (report.h): runs the instruments one after another (each
// interleaves its own programs) and gathers their tables.
#include "report.h"

#include "rays.h"
#include "startup.h"
#include "time_to_error.h"
#include "versus.h"
#include "versus_report.h"

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fmt/format.h>
#include <ostream>
#include <sys/stat.h>
#include <vector>

namespace fs = std::filesystem;

namespace drt::perf {

namespace {

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    return text;
}

std::string modified(const std::string& path) {
    struct stat s {};
    if (stat(path.c_str(), &s) != 0)
        return "?";
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&s.st_mtim.tv_sec));
    return text;
}

// A section's tables, its headings one level down.
std::string section(const fs::path& file) {
    std::string text = readTextFile(file.string());
    if (text.empty())
        return fmt::format("(no {})\n", file.filename().string());
    std::string out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        end = end == std::string::npos ? text.size() : end + 1;
        const std::string line = text.substr(start, end - start);
        out += (line.rfind('#', 0) == 0 ? "#" : "") + line;
        start = end;
    }
    return out;
}

} // namespace

int runReport(const ReportOptions& o, std::ostream& log) {
    const fs::path root = o.outputDir;
    std::error_code ec;
    fs::create_directories(root, ec);
    if (ec) {
        log << fmt::format("report: cannot create '{}': {}\n", root.string(), ec.message());
        return 3;
    }
    int status = 0;
    const auto step = [&](const char* name, int result) {
        if (result != 0) {
            log << fmt::format("report: {} ended with status {}\n", name, result);
            status = status ? status : result;
        }
    };
    const std::string started = utcNow(), loadBefore = loadAverage();

    StartupOptions startup;
    startup.outputDir = (root / "startup").string();
    startup.drt = o.drt;
    step("startup", runStartup(startup, log));

    RaysOptions rays;
    rays.outputDir = (root / "rays").string();
    rays.drt = o.drt;
    if (o.quick) { // the spheres only, at the full sample count (the figure the goal is stated for)
        rays.repetitions = 3;
        rays.scenes = {"spheres"};
    }
    step("rays", runRays(rays, log));

    TimeToErrorOptions cook;
    cook.outputDir = (root / "time-to-error").string();
    cook.drt = o.drt;
    if (o.quick) {
        cook.spp = {4, 16, 64};
        cook.referenceSpp = 128;
    }
    step("time-to-error", runTimeToError(cook, log));

    if (o.povray) {
        VersusOptions versus;
        versus.outputDir = (root / "versus-povray").string();
        versus.drt = o.drt;
        versus.quick = o.quick;
        step("versus-povray", runVersusPovray(versus, log));
    }

    std::string md = fmt::format("# drt performance report\n\n- Machine: {}.\n- From {} to {}; load average "
                                 "{} at the start, {} at the end.\n- Programs:\n",
                                 machineDescription(), started, utcNow(), loadBefore, loadAverage());
    for (const DrtBinary& drt : o.drt)
        md += fmt::format("  - drt {}: `{}` (built {})\n", drt.label, drt.path, modified(drt.path));
    if (const std::string pov = povrayVersion(); !pov.empty())
        md += fmt::format("  - {}\n", pov);
    std::vector<fs::path> sections = {root / "startup" / "startup.md", root / "rays" / "rays.md",
                                      root / "time-to-error" / "time-to-error.md"};
    if (o.povray)
        sections.push_back(root / "versus-povray" / "summary.md");
    for (const fs::path& file : sections)
        md += fmt::format("\n{}", section(file));
    writeTextFile((root / "report.md").string(), md);
    log << fmt::format("report: wrote {}\n", (root / "report.md").string());
    return status;
}

} // namespace drt::perf

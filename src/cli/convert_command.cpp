// `drt convert`: a POV-Ray scene -> an equivalent .drt file, through the POV
// front end (pov/load.h) and the .drt writer (lang/writer.h).
//
// `drt convert --report DIR` converts every .pov under DIR and sorts the
// scenes into clean / with warnings / failed. Each scene runs in a child
// process with a time limit, so a scene that loops forever or crashes the
// front end is reported as such and the report carries on. A scene counts as
// clean when it loads without an unsupported-feature warning, the .drt text
// expresses all of it and loads back, and the result renders (small, 1 spp).
#include "accel/geometry_query.h"
#include "cli/commands.h"
#include "cli/paths.h"
#include "core/temporary_files.h"
#include "assets/assets.h"

#include "lang/load.h"
#include "lang/writer.h"
#include "pov/load.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <ostream>
#include <regex>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace drt::cli {

namespace {

// `geometry` answers trace() and inside() while the scene is read, as for a
// render: the converted scene holds the values they gave.
PovOptions povOptions(const PovCliOptions& cli, SceneGeometryQuery* geometry) {
    PovOptions options;
    options.includePaths = cli.includePaths;
    options.strict = cli.strict;
    options.geometry = geometry;
    return options;
}

// Warnings that do not mean a feature is missing: the scene's own #warning
// and behaviour that matches POV-Ray (the front end says "(as POV-Ray)").
bool isInformational(const std::string& message) {
    return message.rfind("#warning", 0) == 0 || message.find("(as POV-Ray)") != std::string::npos;
}

// A short name for the kind of a warning: the message up to its first ';'.
std::string warningKind(const std::string& message) {
    std::string kind = message.substr(0, message.find(';'));
    if (kind.size() > 90)
        kind = kind.substr(0, 87) + "...";
    return kind;
}

// "file:line:col: message" without the source line and caret.
std::string oneLine(const Diagnostics& diags, const Diagnostic& d) {
    std::string where;
    if (d.loc.valid() && d.loc.file < diags.files().count())
        where = fmt::format("{}:{}:{}: ", fs::path(diags.files().path(d.loc.file)).filename().string(),
                            d.loc.line, d.loc.column);
    return where + d.message;
}

std::string firstError(const Diagnostics& diags) {
    for (const Diagnostic& d : diags.all())
        if (d.severity == Severity::Error)
            return oneLine(diags, d);
    return "unknown error";
}

// Writes `text` to a temporary file beside `path`, then renames it over `path`.
std::string writeTextFile(const std::string& path, const std::string& text) {
    const fs::path target(path);
    const fs::path temp =
        target.parent_path() / (".~" + target.filename().string() + "." + std::to_string(::getpid()));
    const TemporaryFile registered(temp.string()); // removed if a signal ends the process
    {
        std::ofstream out(temp, std::ios::binary);
        if (!out)
            return fmt::format("cannot write '{}': {}", path, std::strerror(errno));
        out << text;
        out.flush();
        if (!out) {
            std::error_code ec;
            fs::remove(temp, ec);
            return fmt::format("cannot write '{}': write failed", path);
        }
    }
    std::error_code ec;
    fs::rename(temp, target, ec);
    if (ec) {
        fs::remove(temp, ec);
        return fmt::format("cannot write '{}': {}", path, ec.message());
    }
    return "";
}

int convertOne(const ConvertCommand& command, std::ostream& out, std::ostream& err) {
    std::error_code ec;
    if (!fs::is_regular_file(command.scene, ec)) {
        err << fmt::format("drt: cannot read scene '{}': {}\n", command.scene,
                           fs::exists(command.scene, ec) ? "not a readable file" : "no such file");
        return kIoError;
    }
    if (command.output.empty()) {
        err << "drt convert: give the output file with -o scene.drt\n";
        return kUsageError;
    }
    if (std::string clash = outputClash({{"the scene", command.scene}}, {{"-o", command.output}}); !clash.empty()) {
        err << "drt convert: " << clash << "\n";
        return kUsageError;
    }
    Diagnostics diags;
    const std::unique_ptr<SceneGeometryQuery> geometry = makeGeometryQuery();
    std::optional<Scene> scene = loadPovSceneFile(command.scene, diags, povOptions(command.pov, geometry.get()));
    if (scene && !diags.hasErrors()) resolveAssets(*scene, diags);
    err << diags.formatAll();
    if (diags.hasErrors() || !scene) {
        err << fmt::format("drt: {}: {} error{}\n", command.scene, diags.errorCount(),
                           diags.errorCount() == 1 ? "" : "s");
        return kSceneError;
    }
    WriterOptions options;
    options.sourceName = fs::path(command.scene).filename().string();
    options.sourceFiles = &diags.files();
    const std::string text = writeDrtScene(*scene, options);
    const std::vector<std::string> problems = drtInexpressible(*scene);
    for (const std::string& p : problems)
        err << fmt::format("drt: {}: warning: .drt cannot express {}\n", command.output, p);

    // The written text must load back (it always does unless .drt lacks a construct).
    Diagnostics again;
    const std::string dir = fs::path(command.output).parent_path().string();
    const bool loads =
        loadSceneText(text, command.output, again, dir.empty() ? "." : dir).has_value() && !again.hasErrors();
    if (std::string problem = writeTextFile(command.output, text); !problem.empty()) {
        err << "drt: " << problem << "\n";
        return kIoError;
    }
    if (!loads) {
        err << fmt::format("drt: {}: written, but drt cannot load it back: {}\n", command.output,
                           firstError(again));
        return kSceneError;
    }
    out << fmt::format("drt: {} -> {} ({} objects, {} lights, {} warning{})\n", command.scene, command.output,
                       scene->objects.size(), scene->lights.size(), diags.warningCount(),
                       diags.warningCount() == 1 ? "" : "s");
    return kSuccess;
}

} // namespace

ConversionCheck checkConversion(const std::string& povPath, const PovCliOptions& pov, int width, int height) {
    ConversionCheck check;
    try {
        Diagnostics diags;
        const std::unique_ptr<SceneGeometryQuery> geometry = makeGeometryQuery();
        std::optional<Scene> scene = loadPovSceneFile(povPath, diags, povOptions(pov, geometry.get()));
        if (scene && !diags.hasErrors()) resolveAssets(*scene, diags);
        for (const Diagnostic& d : diags.all()) {
            if (d.severity != Severity::Warning)
                continue;
            (isInformational(d.message) ? check.notes : check.unsupported).push_back(warningKind(d.message));
        }
        if (diags.hasErrors() || !scene) {
            check.outcome = ConversionCheck::Outcome::Failed;
            check.reason = "load: " + firstError(diags);
            return check;
        }
        for (const std::string& p : drtInexpressible(*scene))
            check.unsupported.push_back(".drt cannot express " + p);
        const std::string text = writeDrtScene(*scene);
        Scene toRender = *scene;
        if (check.unsupported.empty()) {
            // Clean means the .drt file itself loads and renders.
            Diagnostics again;
            std::optional<Scene> reloaded = loadSceneText(text, "converted.drt", again);
            if (reloaded && !again.hasErrors()) resolveAssets(*reloaded, again);
            if (!reloaded || again.hasErrors()) {
                check.outcome = ConversionCheck::Outcome::Failed;
                check.reason = "the written .drt does not load: " + firstError(again);
                return check;
            }
            toRender = *reloaded;
        }
        RenderOptions options = resolveRenderOptions(toRender.render);
        options.width = width;
        options.height = height;
        options.samplesPerPixel = 1;
        options.adaptive = false;
        options.threads = 1;
        render(toRender, options);
        check.outcome =
            check.unsupported.empty() ? ConversionCheck::Outcome::Clean : ConversionCheck::Outcome::Warnings;
    } catch (const std::exception& e) {
        check.outcome = ConversionCheck::Outcome::Failed;
        check.reason = std::string("render: ") + e.what();
    } catch (...) {
        check.outcome = ConversionCheck::Outcome::Failed;
        check.reason = "unknown exception";
    }
    auto unique = [](std::vector<std::string>& v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
    };
    unique(check.unsupported);
    unique(check.notes);
    return check;
}

namespace {

// The result travels from the child over a pipe as tab-free lines:
// the outcome, the reason, then "u " / "n " lines of warning kinds.
std::string serialize(const ConversionCheck& c) {
    auto clean = [](std::string s) {
        std::replace(s.begin(), s.end(), '\n', ' ');
        return s.substr(0, 600);
    };
    std::string text = std::to_string(int(c.outcome)) + "\n" + clean(c.reason) + "\n";
    for (const auto& k : c.unsupported)
        text += "u " + clean(k) + "\n";
    for (const auto& k : c.notes)
        text += "n " + clean(k) + "\n";
    return text.substr(0, 16000); // well under a pipe's buffer
}

ConversionCheck deserialize(const std::string& text) {
    ConversionCheck c;
    size_t pos = 0;
    int lineNumber = 0;
    while (pos < text.size()) {
        const size_t end = std::min(text.find('\n', pos), text.size());
        const std::string line = text.substr(pos, end - pos);
        if (lineNumber == 0)
            c.outcome = ConversionCheck::Outcome(std::clamp(std::atoi(line.c_str()), 0, 2));
        else if (lineNumber == 1)
            c.reason = line;
        else if (line.rfind("u ", 0) == 0)
            c.unsupported.push_back(line.substr(2));
        else if (line.rfind("n ", 0) == 0)
            c.notes.push_back(line.substr(2));
        ++lineNumber;
        pos = end + 1;
    }
    return c;
}

// Runs checkConversion in a child process; a crash or a timeout becomes a failure.
ConversionCheck checkInChild(const std::string& path, const PovCliOptions& pov, double timeoutSeconds) {
    ConversionCheck failed;
    failed.outcome = ConversionCheck::Outcome::Failed;
    int fds[2];
    if (::pipe(fds) != 0) {
        failed.reason = "cannot create a pipe";
        return failed;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        failed.reason = "cannot fork";
        return failed;
    }
    if (pid == 0) {
        ::close(fds[0]);
        const std::string text = serialize(checkConversion(path, pov, 40, 30));
        size_t written = 0;
        while (written < text.size()) {
            const ssize_t n = ::write(fds[1], text.data() + written, text.size() - written);
            if (n <= 0)
                break;
            written += size_t(n);
        }
        ::close(fds[1]);
        ::_exit(0);
    }
    ::close(fds[1]);
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    bool timedOut = false;
    while (true) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid)
            break;
        if (done < 0 && errno != EINTR)
            break;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
            timeoutSeconds) {
            ::kill(pid, SIGKILL); // our own child
            ::waitpid(pid, &status, 0);
            timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::string text;
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(fds[0], buffer, sizeof buffer)) > 0)
        text.append(buffer, size_t(n));
    ::close(fds[0]);
    if (timedOut) {
        failed.reason = fmt::format("timed out after {:g} s", timeoutSeconds);
        return failed;
    }
    if (WIFSIGNALED(status)) {
        failed.reason = fmt::format("CRASHED: signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
        return failed;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty()) {
        failed.reason = "the conversion process ended without a result";
        return failed;
    }
    return deserialize(text);
}

std::string percent(int part, int whole) {
    return fmt::format("{:.1f}%", whole ? 100.0 * part / whole : 0.0);
}

int report(const ConvertCommand& command, std::ostream& out, std::ostream& err) {
    std::error_code ec;
    if (!fs::is_directory(command.reportDir, ec)) {
        err << fmt::format("drt: cannot read folder '{}'\n", command.reportDir);
        return kIoError;
    }
    std::vector<fs::path> scenes;
    for (fs::recursive_directory_iterator
             it(command.reportDir, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec)) {
        std::string ext = it->path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if (ext == ".pov" && it->is_regular_file(ec))
            scenes.push_back(it->path());
    }
    std::sort(scenes.begin(), scenes.end());
    out.flush();

    int counts[3] = {0, 0, 0};
    int crashes = 0, timeouts = 0;
    std::map<std::string, int> unsupportedKinds, failureKinds;
    for (const fs::path& scene : scenes) {
        const std::string name = fs::relative(scene, command.reportDir, ec).string();
        const ConversionCheck c = checkInChild(scene.string(), command.pov, command.timeoutSeconds);
        ++counts[int(c.outcome)];
        std::string line;
        switch (c.outcome) {
        case ConversionCheck::Outcome::Clean:
            line = "clean     " + name;
            break;
        case ConversionCheck::Outcome::Warnings:
            line = "warnings  " + name + ":";
            break;
        case ConversionCheck::Outcome::Failed:
            line = "FAILED    " + name + ": " + c.reason;
            break;
        }
        if (c.outcome == ConversionCheck::Outcome::Warnings)
            for (size_t i = 0; i < c.unsupported.size(); ++i)
                line += (i ? "; " : " ") + c.unsupported[i];
        if (c.outcome != ConversionCheck::Outcome::Failed)
            for (const auto& k : c.unsupported)
                ++unsupportedKinds[k];
        if (c.outcome == ConversionCheck::Outcome::Failed) {
            crashes += c.reason.rfind("CRASHED", 0) == 0;
            timeouts += c.reason.rfind("timed out", 0) == 0;
            // The kind of failure: the message without its location.
            static const std::regex location(R"(\S+:\d+:\d+: )");
            ++failureKinds[warningKind(std::regex_replace(c.reason, location, ""))];
        }
        out << line << "\n";
        out.flush();
    }
    const int total = int(scenes.size());
    auto byCount = [](const std::map<std::string, int>& m) {
        std::vector<std::pair<int, std::string>> v;
        for (const auto& [k, n] : m)
            v.emplace_back(-n, k);
        std::sort(v.begin(), v.end());
        return v;
    };
    out << "\nUnsupported features (scenes that converted with warnings):\n";
    for (const auto& [n, k] : byCount(unsupportedKinds))
        out << fmt::format("  {:4}  {}\n", -n, k);
    out << "Failures:\n";
    for (const auto& [n, k] : byCount(failureKinds))
        out << fmt::format("  {:4}  {}\n", -n, k);
    out << fmt::format("\n{} scenes under {}: {} clean ({}), {} with warnings ({}), {} failed ({}); "
                       "{} crashed, {} timed out (limit {:g} s)\n",
                       total, command.reportDir, counts[0], percent(counts[0], total), counts[1],
                       percent(counts[1], total), counts[2], percent(counts[2], total), crashes, timeouts,
                       command.timeoutSeconds);
    return kSuccess;
}

} // namespace

CLI::App* addConvertSubcommand(CLI::App& app, ConvertCommand& c) {
    CLI::App* convert = app.add_subcommand(
        "convert", "Convert a POV-Ray scene to .drt, or report on every .pov under a folder (--report DIR)");
    convert->add_option("scene", c.scene, "POV-Ray scene (.pov)");
    convert->add_option("-o,--output", c.output, "The .drt file to write");
    convert->add_option(
        "--report", c.reportDir,
        "Convert every .pov under this folder and print clean / with warnings / failed per scene");
    convert->add_option("--timeout", c.timeoutSeconds, "--report: time limit per scene, in seconds")
        ->check(CLI::PositiveNumber);
    convert->add_option("-L,--include-path", c.pov.includePaths,
                        "Folder searched by #include (repeatable; after the scene's folder)");
    convert->add_flag("--strict", c.pov.strict, "Unsupported features are errors");
    return convert;
}

int runConvert(const ConvertCommand& command, std::ostream& out, std::ostream& err) {
    if (!command.reportDir.empty()) {
        if (!command.scene.empty()) {
            err << "drt convert: give either a scene or --report DIR, not both\n";
            return kUsageError;
        }
        return report(command, out, err);
    }
    if (command.scene.empty()) {
        err << "drt convert: give a scene (drt convert scene.pov -o scene.drt) or --report DIR\n";
        return kUsageError;
    }
    return convertOne(command, out, err);
}

} // namespace drt::cli

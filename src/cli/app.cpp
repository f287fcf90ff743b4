// CLI11 set-up of drt's subcommands. Parsing problems are usage errors (exit 2);
// the work itself is in cli/commands.h.
#include "cli/app.h"

#include "cli/commands.h"
#include "core/limits.h"
#include "sampling/sampler.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <type_traits>
#include <fmt/format.h>
#include <iostream>
#include <unistd.h>

namespace drt::cli {

namespace {

struct RenderArguments {
    RenderCommand command;
    int width = 0, height = 0, spp = 0, threads = 0, tileSize = 0;
    uint64_t seed = 0;
    std::string sampler;
    bool adaptive = false;
    double adaptiveError = 0;
    int minSpp = 0, maxSpp = 0;
    int lightSamples = 1;
    std::string frames, subset, clock; // "A..B" ranges, or one clock value
    double clockDelta = 1, shutter = 0;
};

// "A..B" (or "A" for "A..A"): two numbers; false if the text is not that.
template <class T>
bool parseRange(const std::string& text, T& a, T& b) {
    const size_t dots = text.find("..");
    const std::string first = dots == std::string::npos ? text : text.substr(0, dots);
    const std::string second = dots == std::string::npos ? text : text.substr(dots + 2);
    try {
        size_t used = 0;
        if constexpr (std::is_integral_v<T>) {
            a = static_cast<T>(std::stoi(first, &used));
            if (used != first.size()) return false;
            b = static_cast<T>(std::stoi(second, &used));
        } else {
            a = std::stod(first, &used);
            if (used != first.size()) return false;
            b = std::stod(second, &used);
        }
        return used == second.size() && std::isfinite(double(a)) && std::isfinite(double(b));
    } catch (const std::exception&) {
        return false;
    }
}

CLI::App* addRender(CLI::App& app, RenderArguments& a) {
    CLI::App* render = app.add_subcommand("render", "Render a scene to an image file");
    render->add_option("scene", a.command.scene, "Scene file (.drt or .pov)")->required();
    render
        ->add_option("-o,--output", a.command.output,
                     "Output image; the extension picks the format (.png .jpg .tif: sRGB, .exr .hdr: linear). "
                     "Required, unless a POV-Ray .ini gives Output_File_Name");
    render->add_option("--width", a.width, "Image width in pixels (overrides the scene)")
        ->check(CLI::PositiveNumber);
    render->add_option("--height", a.height, "Image height in pixels (overrides the scene)")
        ->check(CLI::PositiveNumber);
    render->add_option("--spp", a.spp, "Samples per pixel (overrides the scene)")->check(CLI::PositiveNumber);
    render->add_option("--threads", a.threads, "Worker threads (0: all cores)")
        ->check(CLI::NonNegativeNumber);
    render->add_option("--seed", a.seed, "Random seed, 0 to 2^64-1 (overrides the scene)")
        ->check(CLI::Validator(
            [](std::string& value) {
                return value.find('-') == 0 ? std::string("the seed must be a whole number from 0 to 2^64-1")
                                            : std::string();
            },
            "0..2^64-1"));
    render->add_option("--sampler", a.sampler, "Sampler (overrides the scene)")
        ->check(CLI::IsMember(samplerNames()));
    render->add_option("--tile-size", a.tileSize, "Tile edge in pixels (the image does not depend on it)")
        ->check(CLI::PositiveNumber);
    render->add_option("--variance", a.command.varianceOutput,
                       "Also write the per-pixel variance of the mean to this .exr file");
    render->add_flag("--adaptive,!--no-adaptive", a.adaptive,
                     "Adaptive sampling: each pixel samples until its error is small (overrides the scene)");
    render->add_option("--adaptive-error", a.adaptiveError,
                       "Adaptive target: the relative error (square root of relMSE) each 5x5 neighbourhood of "
                       "pixels aims at, at 16 samples (at n samples: E * sqrt(n / 16))")
        ->check(CLI::PositiveNumber);
    render->add_option("--min-spp", a.minSpp, "Adaptive: samples every pixel takes first")
        ->check(CLI::Range(1, 1 << 24));
    render->add_option("--max-spp", a.maxSpp, "Adaptive: samples no pixel exceeds")->check(CLI::Range(1, 1 << 24));
    render->add_option("--light-samples", a.lightSamples,
                       "Shadow rays each area light sends from a shading point per camera sample, stratified as "
                       "one sequence over the pixel (overrides the scene; default 1, Cook's association)")
        ->check(CLI::Range(1, kMaxLightSamples));
    render->add_option("--spp-image", a.command.sppImageOutput,
                       "Also write the samples taken per pixel to this image (.exr: counts; else scaled to the most)");
    render->add_option("--crop", a.command.crop,
                       "Render only pixels x0..x1-1, y0..y1-1: 'x0,x1,y0,y1' (or fractions: '0.0,0.5,0.0,1.0'); "
                       "the pixels equal a full render's, drt merge assembles crops");
    render->add_flag("--resume", a.command.resume,
                     "Continue an interrupted render from OUTPUT.drt-checkpoint (same scene and settings)");
    render
        ->add_option("--checkpoint-every", a.command.checkpointSeconds,
                     "Save a checkpoint and the image so far every this many seconds (an interruption always saves)")
        ->check(CLI::PositiveNumber);
    render->add_option("--stats", a.command.statsOutput,
                       "Also write the render's times, ray counts and rates to this JSON file");
    render->add_flag("-q,--quiet", a.command.quiet, "No progress line and no summary");
    render->add_flag("--reproducible", a.command.reproducible,
                     "Leave the run's details (command line, threads, time) out of the file's metadata, so the same "
                     "scene and seed give a byte-identical file");
    render->add_option("-L,--include-path", a.command.pov.includePaths,
                       "POV-Ray scenes: folder searched by #include (repeatable; after the scene's folder)");
    render->add_flag("--strict", a.command.pov.strict, "POV-Ray scenes: unsupported features are errors");
    render->add_option("--frames", a.frames,
                       "Animation: frames A..B (initial..final), each rendered alone to OUT with its number "
                       "(a %d or %04d in OUT, else before the extension)");
    render->add_option("--clock", a.clock,
                       "The clock: C0..C1 over the frames (default 0..1), or C for one image");
    render->add_option("--clock-delta", a.clockDelta, "One image: the clock's step per frame (default 1)");
    render->add_option("--subset", a.subset, "Animation: render only frames A..B of the range");
    render->add_flag("--cyclic", a.command.animation.cyclic,
                     "Animation: the last frame stops one step short of the final clock (it loops)");
    render->add_option("--shutter", a.shutter,
                       "Motion blur: the shutter opens at the frame's clock for this fraction of the frame "
                       "interval (overrides the camera's)")
        ->check(CLI::Range(0.0, 1.0));
    render
        ->add_option("--distribute", a.command.animation.distribute,
                     "Under mpirun, an animation's frames: 'frames' (each rank renders whole frames), 'tiles' (each "
                     "frame split over every rank) or 'auto' (frames when there are at least as many as ranks)")
        ->check(CLI::IsMember({"auto", "frames", "tiles"}));
    render->add_option("--ini", a.command.animation.ini,
                       "POV-Ray .ini file with the animation options (a SCENE ending in .ini is read so too)");
    render->add_option("--dialect", a.command.pov.dialect,
                       "Read the scene as .drt or .pov whatever its extension (default: .pov, .inc, .mac are POV-Ray's)")
        ->check(CLI::IsMember({"drt", "pov"}));
    return render;
}

// Copies the options the user gave into the overrides (an option not given
// leaves the scene's value).
void fillOverrides(CLI::App& render, RenderArguments& a) {
    RenderSettings& o = a.command.overrides;
    if (render.count("--width"))
        o.width = a.width;
    if (render.count("--height"))
        o.height = a.height;
    if (render.count("--spp"))
        o.samplesPerPixel = a.spp;
    if (render.count("--threads"))
        o.threads = a.threads;
    if (render.count("--seed"))
        o.seed = a.seed;
    if (render.count("--sampler"))
        o.sampler = a.sampler;
    if (render.count("--tile-size"))
        a.command.tileSize = a.tileSize;
    if (render.count("--adaptive") || render.count("--no-adaptive"))
        o.adaptive = a.adaptive;
    if (render.count("--adaptive-error"))
        o.adaptiveError = a.adaptiveError;
    if (render.count("--min-spp"))
        o.minSamplesPerPixel = a.minSpp;
    if (render.count("--max-spp"))
        o.maxSamplesPerPixel = a.maxSpp;
    if (render.count("--light-samples"))
        o.lightSamples = a.lightSamples;
    if (render.count("--clock-delta"))
        a.command.animation.clockDelta = a.clockDelta;
    if (render.count("--shutter"))
        a.command.animation.shutter = a.shutter;
    a.command.progress = ::isatty(STDERR_FILENO) != 0;
}

// The time options given as ranges; false (with a message) if one is not a range.
bool fillTime(CLI::App& render, RenderArguments& a, std::ostream& err) {
    AnimationRequest& t = a.command.animation;
    const auto frameRange = [&](const char* option, const std::string& text, auto& target) {
        if (!render.count(option)) return true;
        int first = 0, last = 0;
        if (!parseRange(text, first, last)) {
            err << "drt render: " << option << " needs a frame range A..B, not '" << text << "'\n";
            return false;
        }
        target = std::make_pair(first, last);
        return true;
    };
    if (!frameRange("--frames", a.frames, t.frames) || !frameRange("--subset", a.subset, t.subset)) return false;
    if (render.count("--clock")) {
        double c0 = 0, c1 = 0;
        if (!parseRange(a.clock, c0, c1)) {
            err << "drt render: --clock needs a clock value C or a range C0..C1, not '" << a.clock << "'\n";
            return false;
        }
        if (a.clock.find("..") != std::string::npos) t.clockRange = std::make_pair(c0, c1);
        else t.clock = c0;
    }
    const std::string& scene = a.command.scene;
    const bool ini = render.count("--ini") || (scene.size() > 4 && (scene.substr(scene.size() - 4) == ".ini" ||
                                                                    scene.substr(scene.size() - 4) == ".INI"));
    if (t.clockRange && !t.frames && !ini) {
        err << "drt render: a clock range needs a frame range (--frames A..B)\n";
        return false;
    }
    if (t.subset && !t.frames && !ini) {
        err << "drt render: --subset needs a frame range (--frames A..B)\n";
        return false;
    }
    if (a.command.output.empty() && !ini) { // an .ini may name the output
        err << "drt render: --output is required\n";
        return false;
    }
    return true;
}

CLI::App* addCompare(CLI::App& app, CompareCommand& c) {
    CLI::App* compare = app.add_subcommand(
        "compare", "Compare a candidate image with a reference (exit 0 pass, 1 warning, 2 failure, 3 size "
                   "mismatch, 4 file error)");
    compare->add_option("candidate", c.candidate, "Image under test")->required();
    compare->add_option("reference", c.reference, "Reference (golden) image")->required();
    compare
        ->add_option("--fail", c.options.failThreshold,
                     "A pixel fails if a channel differs by more than this")
        ->check(CLI::NonNegativeNumber);
    compare
        ->add_option("--fail-percent", c.options.failPercent,
                     "The image fails if more than this percentage of pixels fail")
        ->check(CLI::Range(0.0, 100.0));
    compare
        ->add_option("--warn", c.options.warnThreshold,
                     "A pixel warns if a channel differs by more than this")
        ->check(CLI::NonNegativeNumber);
    compare
        ->add_option("--warn-percent", c.options.warnPercent,
                     "The image warns if more than this percentage of pixels warn")
        ->check(CLI::Range(0.0, 100.0));
    compare->add_option("--variance", c.referenceVariance,
                        "Per-pixel variance of the mean of the reference: statistical mode");
    compare->add_option("--candidate-variance", c.candidateVariance,
                        "Per-pixel variance of the mean of the candidate: statistical mode");
    compare->add_option("--alpha", c.options.alpha, "False-alarm rate of the statistical tests")
        ->check(CLI::Range(1e-12, 0.5));
    compare->add_option("--diff", c.diffOutput, "Write a false-colour error heatmap");
    compare
        ->add_option("--diff-scale", c.diffScale,
                     "Error shown as white in the heatmap (default: the largest)")
        ->check(CLI::NonNegativeNumber);
    compare->add_option("--zmap", c.zmapOutput, "Write a signed z-score map (statistical mode)");
    compare->add_flag("--json", c.json, "Print the figures as JSON");
    return compare;
}

// Where `cmake --install` put the documentation and examples: share/doc/drt
// beside the bin folder holding this executable ("" when run from a build tree).
std::string installedDocs() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path docs = exe.parent_path().parent_path() / "share" / "doc" / "drt";
    return !ec && std::filesystem::is_regular_file(docs / "README.md", ec) ? docs.string() : "";
}

// --limit NAME=VALUE (repeatable): every limit of core/limits.h (docs/limits.md).
void addLimitOption(CLI::App* command, Limits& limits) {
    std::string names;
    for (const LimitInfo& info : limitTable()) names += std::string(names.empty() ? "" : ", ") + info.name;
    command
        ->add_option_function<std::vector<std::string>>(
            "--limit",
            [&limits](const std::vector<std::string>& assignments) {
                for (const std::string& assignment : assignments)
                    if (std::string problem = setLimit(limits, assignment); !problem.empty())
                        throw CLI::ValidationError(problem);
            },
            "Raise or lower a limit, NAME=VALUE (repeatable; docs/limits.md): " + names)
        ->type_name("NAME=VALUE");
}

} // namespace

int runCommandLine(int argc, char** argv) {
    CLI::App app{"drt: a distribution ray tracer with a POV-Ray-like scene language", "drt"};
    app.set_version_flag("--version", fmt::format("drt {}", DRT_VERSION));
    const std::string docs = installedDocs();
    app.footer(docs.empty() ? "Documentation: README.md and docs/ in drt's source tree."
                            : fmt::format("Documentation: {0}/README.md, {0}/docs; example scenes: {0}/examples.", docs));
    app.require_subcommand(1);

    RenderArguments renderArguments;
    CLI::App* render = addRender(app, renderArguments);
    std::string checkScene;
    CLI::App* check = app.add_subcommand("check", "Parse and validate a scene; print every diagnostic");
    check->add_option("scene", checkScene, "Scene file (.drt or .pov)")->required();
    PovCliOptions checkPov;
    check->add_option("-L,--include-path", checkPov.includePaths,
                      "POV-Ray scenes: folder searched by #include (repeatable; after the scene's folder)");
    check->add_flag("--strict", checkPov.strict, "POV-Ray scenes: unsupported features are errors");
    check->add_option("--dialect", checkPov.dialect,
                      "Read the scene as .drt or .pov whatever its extension (default: .pov, .inc, .mac are POV-Ray's)")
        ->check(CLI::IsMember({"drt", "pov"}));
    BenchCommand benchCommand;
    CLI::App* bench = addBenchSubcommand(app, benchCommand);
    ConvertCommand convertCommand;
    CLI::App* convert = addConvertSubcommand(app, convertCommand);
    CompareCommand compareCommand;
    CLI::App* compare = addCompare(app, compareCommand);
    MergeCommand mergeCommand;
    CLI::App* merge = addMergeSubcommand(app, mergeCommand);
    TestCommand testCommand;
    CLI::App* test = app.add_subcommand(
        "test", "Run the golden-image tests in a folder (exit 0 all pass, 1 a test failed or is missing, 3 I/O "
                "error); see docs/golden-tests.md");
    test->add_option("folder", testCommand.folder, "Folder of NAME.drt / NAME.golden.json / NAME.golden.exr")
        ->required();
    test->add_flag("--update", testCommand.update, "Rewrite the goldens (and variance images) from fresh renders");
    test->add_option("--report", testCommand.reportDir, "Write an HTML page of the failures to this folder");
    test->add_option("--only", testCommand.only, "Run only the test of this name (repeatable)");
    test->add_option("--junit", testCommand.junitFile,
                     "Write JUnit XML (one testcase per scene) to this file, for CI test reports");
    test->add_option("--json", testCommand.jsonFile, "Write every test's outcome and figures as JSON to this file");
    Limits limits;
    for (CLI::App* command : {render, check, bench, convert, test}) addLimitOption(command, limits);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int status = app.exit(e, std::cout, std::cerr);
        return status == 0 ? kSuccess : kUsageError;
    }
    setDefaultLimits(limits);

    if (render->parsed()) {
        fillOverrides(*render, renderArguments);
        if (!fillTime(*render, renderArguments, std::cerr))
            return kUsageError;
        renderArguments.command.commandLine = shellCommandLine(argc, argv);
        return runRender(renderArguments.command, std::cout, std::cerr);
    }
    if (check->parsed())
        return runCheck(checkScene, checkPov, std::cout, std::cerr);
    if (compare->parsed()) {
        if (!compareCommand.zmapOutput.empty() && compareCommand.referenceVariance.empty() &&
            compareCommand.candidateVariance.empty()) {
            std::cerr << "drt compare: --zmap needs --variance or --candidate-variance\n";
            return kUsageError;
        }
        compareCommand.options.thresholdsWithVariance =
            compare->count("--fail") || compare->count("--warn") || compare->count("--fail-percent") ||
            compare->count("--warn-percent");
        return runCompare(compareCommand, std::cout, std::cerr);
    }
    if (bench->parsed())
        return runBenchCommand(benchCommand, std::cout, std::cerr);
    if (merge->parsed()) {
        mergeCommand.commandLine = shellCommandLine(argc, argv);
        return runMerge(mergeCommand, std::cout, std::cerr);
    }
    if (convert->parsed())
        return runConvert(convertCommand, std::cout, std::cerr);
    if (test->parsed())
        return runTest(testCommand, std::cout, std::cerr);
    return kUsageError;
}

} // namespace drt::cli

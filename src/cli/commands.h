// The subcommands of drt as library functions, so tests can call them without
// a process. Each returns the exit status and writes to the given streams.
//
// Exit statuses of render and check: 0 success, 1 scene error (parse or
// validation error, unsupported scene type, render failure), 2 usage error
// (including a checkpoint that does not belong to the render), 3 I/O error
// (scene file missing or unreadable, output not writable, write failed),
// 128 + signal (130 SIGINT, 143 SIGTERM) when render was interrupted and saved
// its finished tiles and a checkpoint. A missing scene file is an I/O error (3); a missing #include inside
// a scene is a scene error (1), reported with its location.
// compare uses idiff's statuses instead (compare/compare.h: CompareStatus).
#pragma once

#include "animation/animation.h"
#include "bench/bench.h"
#include "compare/compare.h"
#include "render/provenance.h"
#include "render/render.h"

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace drt::cli {

enum ExitCode { kSuccess = 0, kSceneError = 1, kUsageError = 2, kIoError = 3 };

// Options of the POV-Ray front end (pov/load.h) for .pov scenes: -L and --strict.
// How the front end reads a scene (both dialects).
struct PovCliOptions {
    std::vector<std::string> includePaths; // searched after the scene's folder
    bool strict = false;                   // warnings become errors
    std::string dialect;                   // "drt", "pov", or "": from the file's extension
};

// Time on the command line (cli/animation_command.cpp): a frame range, the
// clock, the shutter, POV-Ray .ini files.
struct AnimationRequest {
    std::optional<std::pair<int, int>> frames;           // --frames A..B: initial and final frame
    std::optional<std::pair<int, int>> subset;           // --subset A..B: the frames rendered
    std::optional<std::pair<double, double>> clockRange; // --clock C0..C1: the clock over the frames
    std::optional<double> clock;                         // --clock C: one frame at this clock
    std::optional<double> clockDelta;                    // --clock-delta D: that frame's clock step
    bool cyclic = false;                                 // --cyclic: POV-Ray's Cyclic_Animation
    std::optional<double> shutter;                       // --shutter F: fraction of the frame interval
    std::string ini;                                     // --ini FILE (also a SCENE ending in .ini)
    std::optional<FrameClock> frame;                     // one frame of an animation (set by planAnimation)
    // Under MPI, how an animation's frames are shared (--distribute): "frames"
    // whole per rank, "tiles" each over every rank, "auto" (frames when there
    // are at least as many as ranks).
    std::string distribute = "auto";
};

struct RenderCommand {
    std::string scene;
    std::string output;
    std::string varianceOutput; // "" : none; else an .exr path
    std::string sppImageOutput; // "" : none; samples taken per pixel (--spp-image)
    std::string statsOutput;    // "" : none; times, ray counts and rates as JSON (--stats)
    RenderSettings overrides; // what the command line sets over the scene's settings
    std::optional<int> tileSize;
    std::string crop;              // --crop "x0,x1,y0,y1" (pixels) or fractions; "" the whole image
    bool resume = false;           // --resume: continue from OUTPUT.drt-checkpoint
    double checkpointSeconds = 0;  // --checkpoint-every: save a checkpoint this often (0: only when interrupted)
    bool quiet = false;
    bool progress = false; // draw a progress line (the caller checks that stderr is a terminal)
    PovCliOptions pov;
    std::string commandLine; // recorded in the output's metadata ("" : not recorded)
    bool reproducible = false; // --reproducible: metadata without run details (byte-identical files)
    AnimationRequest animation;
};
int runRender(const RenderCommand& command, std::ostream& out, std::ostream& err);

// `drt merge PARTS... -o OUT`: crops (drt render --crop) -> one image
// (distributed/crop_merge.h). Exit statuses: 0 merged, 1 the parts do not
// form one image of one render (refused, nothing written), 2 usage error,
// 3 I/O error.
struct MergeCommand {
    std::vector<std::string> parts;
    std::string output;
    std::string varianceOutput; // where the variance parts go
    std::string sppImageOutput; // where the samples-per-pixel parts go
    std::string commandLine;    // recorded in the outputs' metadata instead of the first part's
};
int runMerge(const MergeCommand& command, std::ostream& out, std::ostream& err);
// Declares the `merge` subcommand and its options (bound to `command`) on `app`.
CLI::App* addMergeSubcommand(CLI::App& app, MergeCommand& command);
// Animation (animation_command.cpp): a frame range, or a scene given as an .ini file.
bool wantsAnimation(const RenderCommand& command);
// One frame of an animation: its number, clock and the one-image render that makes it.
struct AnimationFrame {
    int number = 0;
    double clock = 0;
    RenderCommand command;
};
// The frames an animation renders, in order (usage and .ini errors printed to
// `err`). Returns kSuccess or the exit status to stop with.
int planAnimation(const RenderCommand& command, std::ostream& err, std::vector<AnimationFrame>& frames);
// "frame 3 (clock 0.3)".
std::string describeFrame(const AnimationFrame& frame);
// Renders the frames one after another with `renderFrame` (cli/render_run.cpp:
// in this process, or each over the ranks of an MPI job), stopping at the first
// that fails. runAnimation = planAnimation + renderFramesInTurn.
int renderFramesInTurn(const std::vector<AnimationFrame>& frames, bool quiet, std::ostream& err,
                       const std::function<int(const RenderCommand& frame)>& renderFrame);
int runAnimation(const RenderCommand& command, std::ostream& err,
                 const std::function<int(const RenderCommand& frame)>& renderFrame);
// The clock and shutter of a single render (--clock, --clock-delta, --shutter; or a frame of an animation).
FrameClock stillFrameClock(const RenderCommand& command);
FrameOptions frameOptions(const RenderCommand& command);
// Tells how a frame's motion came from its clock (unless --quiet).
void printFrameReport(const RenderCommand& command, const FrameReport& report, std::ostream& err);

int runCheck(const std::string& scenePath, std::ostream& out, std::ostream& err);
// The same with the POV-Ray front end's options (used for .pov scenes).
int runCheck(const std::string& scenePath, const PovCliOptions& pov, std::ostream& out, std::ostream& err);

struct CompareCommand {
    std::string candidate;
    std::string reference;
    std::string referenceVariance; // --variance
    std::string candidateVariance; // --candidate-variance
    std::string diffOutput;        // --diff
    std::string zmapOutput;        // --zmap
    double diffScale = 0;          // 0: the largest error
    bool json = false;
    CompareOptions options;
};
int runCompare(const CompareCommand& command, std::ostream& out, std::ostream& err);

// `drt test DIR`: the golden-test runner (golden/golden.h, docs/golden-tests.md).
// Exit statuses: 0 every test passed (or, with --update, every golden was
// written), 1 a test failed, is missing its golden, or its scene/sidecar is
// broken, 2 usage error, 3 I/O error (the folder cannot be read, the report
// cannot be written).
struct TestCommand {
    std::string folder;
    bool update = false;            // --update: rewrite the goldens
    std::string reportDir;          // --report: HTML page of the failures
    std::vector<std::string> only;  // --only NAME (repeatable): run these tests
    std::string junitFile;          // --junit: JUnit XML of every test
    std::string jsonFile;           // --json: the same as JSON
};
int runTest(const TestCommand& command, std::ostream& out, std::ostream& err);

// `drt bench SCENE -o DIR`: speed against accuracy (bench/bench.h). Exit
// statuses as render's: 1 scene or render error, 2 usage error, 3 I/O error.
struct BenchCommand {
    bench::BenchOptions options;
    std::string sppList; // --spp "1,4,16"; "" keeps the default
};
int runBenchCommand(const BenchCommand& command, std::ostream& out, std::ostream& err);
// Declares the `bench` subcommand and its options (bound to `command`) on `app`.
CLI::App* addBenchSubcommand(CLI::App& app, BenchCommand& command);

// `drt convert SCENE.pov -o SCENE.drt`: a POV-Ray scene -> .drt (pov/load.h,
// lang/writer.h). Exit statuses as render's (1 also when the written .drt
// cannot be loaded back, e.g. CSG .drt cannot express yet). `--report DIR`
// converts every .pov under DIR, each in a child process with a time limit,
// and prints clean / with warnings / failed per scene and a summary (exit 0
// unless the folder cannot be read).
struct ConvertCommand {
    std::string scene;          // a .pov file
    std::string output;         // -o: the .drt file
    std::string reportDir;      // --report: convert every .pov under this folder
    PovCliOptions pov;
    double timeoutSeconds = 30; // --timeout: per scene, in --report
};
int runConvert(const ConvertCommand& command, std::ostream& out, std::ostream& err);
// Declares the `convert` subcommand and its options (bound to `command`) on `app`.
CLI::App* addConvertSubcommand(CLI::App& app, ConvertCommand& command);

// What --report finds for one scene (run in-process: no time limit).
struct ConversionCheck {
    enum class Outcome { Clean = 0, Warnings = 1, Failed = 2 };
    Outcome outcome = Outcome::Failed;
    std::string reason;                   // why it failed
    std::vector<std::string> unsupported; // kinds of unsupported-feature warning
    std::vector<std::string> notes;       // warnings that are not missing features (#warning, "as POV-Ray")
};
ConversionCheck checkConversion(const std::string& povPath, const PovCliOptions& pov, int width, int height);


} // namespace drt::cli
